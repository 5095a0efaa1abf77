// CSV and JSON forms of the maps (docs/maps.md).
#include "cpkit/rate_problem/maps/map_output.hpp"

#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <string>

#include "cpkit/core/number_text.hpp"
#include "grid_cells.hpp"

namespace cpkit::rate {

namespace {
constexpr SolutionType kTypes[] = {SolutionType::kOpen, SolutionType::kSeparation,
                                   SolutionType::kStick, SolutionType::kSlipPlus,
                                   SolutionType::kSlipMinus};

/// Grid cells: 12 significant digits (the grid values themselves are not exact anyway).
constexpr int kGridDigits = 12;
/// Critical directions and values: round-trip precision.
constexpr int kRoundTripDigits = 17;

const std::array<std::string, 32>& type_strings() {
  static const std::array<std::string, 32> t = [] {
    std::array<std::string, 32> a;
    for (unsigned m = 0; m < 32; ++m) a[m] = types_to_string(m);
    return a;
  }();
  return t;
}
}  // namespace

std::string count_to_string(int count) { return count < 0 ? "inf" : std::to_string(count); }

nlohmann::json count_to_json(int count) {
  return count < 0 ? nlohmann::json("inf") : nlohmann::json(count);
}

std::string types_to_string(unsigned mask) {
  std::string s;
  for (const auto t : kTypes)
    if (mask & (1u << static_cast<unsigned>(t)))
      s += (s.empty() ? "" : "|") + std::string(to_string(t));
  return s.empty() ? "none" : s;
}

nlohmann::json types_to_json(unsigned mask) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto t : kTypes)
    if (mask & (1u << static_cast<unsigned>(t))) j.push_back(std::string(to_string(t)));
  return j;
}

nlohmann::json model_to_json(const ContactParameters& p, const ContactState& s) {
  nlohmann::json j = {{"a11", p.a11}, {"a12", p.a12}, {"a22", p.a22}, {"mu", p.mu},
                      {"C_T", p.C_T}, {"k_a", p.k_a}, {"P_s", p.P_s},
                      {"criterion", std::string(to_string(p.criterion))},
                      {"state", std::string(to_string(s.label))}, {"P_N", s.P_N},
                      {"sgnPT", s.sgn_PT}, {"kappa", p.kappa(s.P_N)}};
  nlohmann::json crit = nlohmann::json::object();
  for (const auto& c : uniqueness_criteria(p, s)) crit[c.name] = c.value;
  j["criteria"] = crit;
  return j;
}

nlohmann::json to_json(const DirectionMap& map) {
  nlohmann::json sectors = nlohmann::json::array(), critical = nlohmann::json::array();
  std::map<int, double> measure;  // count -> total angle
  for (const auto& s : map.sectors) {
    nlohmann::json j = {{"theta_from", s.theta_from}, {"theta_to", s.theta_to},
                        {"count", count_to_json(s.summary.count)},
                        {"types", types_to_json(s.summary.types)}};
    if (!s.consistent) j["consistent"] = false;
    if (map.cross_checked && !same_solution_set(s.check, s.summary))
      j["enumerate"] = {{"count", count_to_json(s.check.count)},
                        {"types", types_to_json(s.check.types)}};
    sectors.push_back(j);
    measure[s.summary.count] += s.theta_to - s.theta_from;
  }
  for (const auto& c : map.critical) {
    const double r = std::hypot(c.load.dF_T, c.load.dF_N);
    nlohmann::json j = {{"theta", c.theta},
                        {"dF_T", c.load.dF_T / r},
                        {"dF_N", c.load.dF_N / r},
                        {"conditions", c.conditions},
                        {"count", count_to_json(c.summary.count)},
                        {"types", types_to_json(c.summary.types)}};
    if (map.cross_checked && !same_solution_set(c.check, c.summary))
      j["enumerate"] = {{"count", count_to_json(c.check.count)},
                        {"types", types_to_json(c.check.types)}};
    critical.push_back(j);
  }
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [c, w] : measure) counts[count_to_string(c)] = {{"radians", w}};
  return {{"sectors", sectors},
          {"critical", critical},
          {"counts", counts},
          {"evaluations", map.evaluations},
          {"cross_checked", map.cross_checked},
          {"disagreements", map.disagreements},
          {"inconsistent_sectors", map.inconsistent_sectors},
          {"unreliable", map.unreliable}};
}

void write_csv(const DirectionMap& map, std::ostream& out) {
  out << "kind,theta_from,theta_to,count,types,conditions\n";
  for (const auto& s : map.sectors)
    out << "sector," << num_text(s.theta_from, kRoundTripDigits) << ','
        << num_text(s.theta_to, kRoundTripDigits) << ','
        << count_to_string(s.summary.count) << ',' << types_to_string(s.summary.types) << ",\n";
  for (const auto& c : map.critical) {
    std::string cond;
    for (const auto& x : c.conditions) cond += (cond.empty() ? "" : "|") + x;
    out << "critical," << num_text(c.theta, kRoundTripDigits) << ','
        << num_text(c.theta, kRoundTripDigits) << ','
        << count_to_string(c.summary.count) << ',' << types_to_string(c.summary.types) << ','
        << cond << '\n';
  }
}

nlohmann::json to_json(const ParamDirectionMap& map) {
  nlohmann::json counts = nlohmann::json::object(), cls = nlohmann::json::array(),
                 types = nlohmann::json::object();
  for (const auto& b : map.classes) {
    counts[count_to_string(b.code)] = b.cells;
    cls.push_back({{"count", count_to_json(b.code)}, {"cells", b.cells}, {"x_min", b.x_min},
                   {"x_max", b.x_max}, {"theta_min", b.y_min}, {"theta_max", b.y_max}});
  }
  for (unsigned m = 0; m < map.type_cells.size(); ++m)
    if (map.type_cells[m] > 0) types[types_to_string(m)] = map.type_cells[m];
  nlohmann::json cv = nlohmann::json::array();
  for (const auto& c : map.critical_values) cv.push_back({{"name", c.name}, {"x", c.x}});
  return {{"axis", axis_json(map.axis)},
          {"theta_n", map.theta_n},
          {"theta_from", map.theta_from},
          {"theta_to", map.theta_to},
          {"cells", map.cells()},
          {"counts", counts},
          {"classes", cls},
          {"types", types},
          {"critical_values", cv},
          {"critical_direction_points", map.critical_directions.size()},
          {"cross_checked", map.cross_checked},
          {"disagreements", map.disagreements},
          {"unreliable", map.unreliable},
          {"threads", map.threads},
          {"seconds", map.seconds}};
}

void write_csv_header(const MapAxis& axis, bool cross_checked, std::ostream& out) {
  out << axis.param.name() << ",theta,count,types" << (cross_checked ? ",disagree" : "")
      << '\n';
}

void write_csv_rows(const MapAxis& axis, const std::vector<double>& theta_values,
                    const ParamDirectionRows& rows, std::ostream& out) {
  const auto& ts = type_strings();
  const std::size_t theta_n = theta_values.size();
  std::vector<std::string> theta(theta_n);
  for (std::size_t j = 0; j < theta_n; ++j) theta[j] = num_text(theta_values[j], kGridDigits);
  std::string text;
  for (int i = rows.row_begin; i < rows.row_end; ++i) {
    const std::string x = num_text(axis.value(i), kGridDigits);
    text.clear();
    for (std::size_t j = 0; j < theta_n; ++j) {
      const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * theta_n + j;
      text += x;
      text += ',';
      text += theta[j];
      text += ',';
      text += count_to_string(rows.count[k]);
      text += ',';
      text += ts[rows.types[k] & 31u];
      if (rows.disagree) text += rows.disagree[k] ? ",1" : ",0";
      text += '\n';
    }
    out << text;
  }
}

void write_csv(const ParamDirectionMap& map, std::ostream& out) {
  write_csv_header(map.axis, map.cross_checked, out);
  ParamDirectionRows rows;
  rows.row_begin = 0;
  rows.row_end = map.axis.n;
  rows.count = map.count.data();
  rows.types = map.types.data();
  rows.disagree = map.cross_checked ? map.disagree.data() : nullptr;
  write_csv_rows(map.axis, map.theta, rows, out);
}

void write_critical_csv(const ParamDirectionMap& map, std::ostream& out) {
  out << "curve,x,theta,conditions,count,types\n";
  for (const auto& c : map.critical_values)
    out << c.name << ',' << num_text(c.x, kRoundTripDigits) << ",,,,\n";
  for (const auto& c : map.critical_directions)
    out << "direction," << num_text(c.x, kRoundTripDigits) << ','
        << num_text(c.theta, kRoundTripDigits) << ',' << c.conditions << ','
        << count_to_string(c.summary.count) << ',' << types_to_string(c.summary.types) << '\n';
}

nlohmann::json to_json(const ParamParamMap& map) {
  nlohmann::json counts = nlohmann::json::object(), cls = nlohmann::json::array();
  for (const auto& b : map.classes) {
    const std::string name(to_string(static_cast<UniquenessClass>(b.code)));
    counts[name] = b.cells;
    cls.push_back({{"class", name}, {"cells", b.cells}, {"x_min", b.x_min}, {"x_max", b.x_max},
                   {"y_min", b.y_min}, {"y_max", b.y_max}});
  }
  return {{"axis", axis_json(map.axis1)},
          {"axis2", axis_json(map.axis2)},
          {"cells", map.cells()},
          {"counts", counts},
          {"classes", cls},
          {"critical_curve_points", map.critical_curve.size()},
          {"cross_checked", map.cross_checked},
          {"disagreements", map.disagreements},
          {"inconsistent_sectors", map.inconsistent_sectors},
          {"unreliable", map.unreliable},
          {"threads", map.threads},
          {"seconds", map.seconds}};
}

void write_csv_header(const MapAxis& axis1, const MapAxis& axis2, bool cross_checked,
                      std::ostream& out) {
  out << axis1.param.name() << ',' << axis2.param.name()
      << ",class,min_count,max_count,types" << (cross_checked ? ",disagree" : "") << '\n';
}

void write_csv_rows(const MapAxis& axis1, const MapAxis& axis2, const ParamParamRows& rows,
                    std::ostream& out) {
  const auto& ts = type_strings();
  const std::size_t n2 = static_cast<std::size_t>(axis2.n);
  std::string text;
  for (int i = rows.row_begin; i < rows.row_end; ++i) {
    const std::string x = num_text(axis1.value(i), kGridDigits);
    text.clear();
    for (std::size_t j = 0; j < n2; ++j) {
      const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * n2 + j;
      text += x;
      text += ',';
      text += num_text(axis2.value(static_cast<int>(j)), kGridDigits);
      text += ',';
      text += to_string(static_cast<UniquenessClass>(rows.cls[k]));
      text += ',';
      text += count_to_string(rows.min_count[k]);
      text += ',';
      text += count_to_string(rows.max_count[k]);
      text += ',';
      text += ts[rows.types[k] & 31u];
      if (rows.disagree) text += rows.disagree[k] ? ",1" : ",0";
      text += '\n';
    }
    out << text;
  }
}

void write_csv(const ParamParamMap& map, std::ostream& out) {
  write_csv_header(map.axis1, map.axis2, map.cross_checked, out);
  ParamParamRows rows;
  rows.row_begin = 0;
  rows.row_end = map.axis1.n;
  rows.cls = map.cls.data();
  rows.min_count = map.min_count.data();
  rows.max_count = map.max_count.data();
  rows.types = map.types.data();
  rows.disagree = map.cross_checked ? map.disagree.data() : nullptr;
  write_csv_rows(map.axis1, map.axis2, rows, out);
}

void write_critical_csv(const ParamParamMap& map, std::ostream& out) {
  out << "curve,x,y\n";
  for (const auto& c : map.critical_curve)
    out << c.name << ',' << num_text(c.x, kRoundTripDigits) << ','
        << num_text(c.y, kRoundTripDigits) << '\n';
}

void write_system_csv_header(const SystemMapAxis& axis, std::ostream& out) {
  out << std::setprecision(17) << axis.param.name() << ",theta,count,pattern\n";
}

void write_system_csv_rows(const SystemMapAxis& axis, const std::vector<double>& theta,
                           const SystemParamDirectionRows& rows, std::ostream& out) {
  const std::size_t cols = theta.size();
  out << std::setprecision(17);
  for (int i = rows.row_begin; i < rows.row_end; ++i)
    for (std::size_t jj = 0; jj < cols; ++jj) {
      const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * cols + jj;
      out << axis.value(i) << ',' << theta[jj] << ',' << count_to_string(rows.count[k]) << ','
          << rows.pattern[k] << '\n';
    }
}

void write_system_csv_header(const SystemMapAxis& axis1, const SystemMapAxis& axis2,
                             std::ostream& out) {
  out << std::setprecision(17) << axis1.param.name() << ',' << axis2.param.name()
      << ",class,min_count,max_count,pattern\n";
}

void write_system_csv_rows(const SystemMapAxis& axis1, const SystemMapAxis& axis2,
                           const SystemParamParamRows& rows, std::ostream& out) {
  const std::size_t cols = static_cast<std::size_t>(axis2.n);
  out << std::setprecision(17);
  for (int i = rows.row_begin; i < rows.row_end; ++i)
    for (int jj = 0; jj < axis2.n; ++jj) {
      const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * cols + jj;
      out << axis1.value(i) << ',' << axis2.value(jj) << ','
          << to_string(static_cast<UniquenessClass>(rows.cls[k])) << ','
          << count_to_string(rows.min_count[k]) << ',' << count_to_string(rows.max_count[k])
          << ',' << rows.pattern[k] << '\n';
    }
}

}  // namespace cpkit::rate
