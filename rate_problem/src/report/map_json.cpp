// The JSON and CSV of the N-point and 3-D maps (report/map_json.hpp), moved out of the program
// so that Python and the tests get the documents the program prints.
#include "cpkit/rate_problem/report/map_json.hpp"

#include <algorithm>
#include <iomanip>
#include <map>

#include "cpkit/rate_problem/maps/map_output.hpp"

namespace cpkit::rate {

namespace {

std::vector<double> as_list(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

}  // namespace

std::vector<std::string> type_tuple_names(const std::vector<TypeTuple>& tuples, int n_points) {
  std::vector<std::string> out;
  for (TypeTuple t : tuples) out.push_back(types_string(decode_types(t, n_points)));
  return out;
}

std::vector<std::string> type_tuple_names(const SystemRateSummary& s, int n_points) {
  std::vector<std::string> out;
  for (int i = 0; i < std::min(s.n_tuples, SystemRateSummary::kCap); ++i)
    out.push_back(types_string(decode_types(s.tuples[static_cast<std::size_t>(i)], n_points)));
  return out;
}

nlohmann::json pattern_table_json(const SystemPatternTable& t, int n_points) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < t.patterns.size(); ++k)
    out.push_back({{"id", k}, {"types", type_tuple_names(t.patterns[k], n_points)},
                   {"cells", t.cells[k]}});
  return out;
}

nlohmann::json system_direction_map_json(const SystemDirectionMap& m, const ContactSystem& sys,
                                         const std::string& path) {
  const int N = sys.n_points();
  const bool complete = m.unreliable == 0 && m.inconsistent_sectors == 0;
  nlohmann::json sectors = nlohmann::json::array(), critical = nlohmann::json::array();
  std::map<int, double> measure;  // count -> total angle
  for (const auto& s : m.sectors) {
    nlohmann::json j = {{"theta_from", s.theta_from}, {"theta_to", s.theta_to},
                        {"count", count_to_json(s.summary.count)},
                        {"types", type_tuple_names(s.summary, N)}};
    if (!s.consistent) j["consistent"] = false;
    sectors.push_back(j);
    measure[s.summary.count] += s.theta_to - s.theta_from;
  }
  for (const auto& c : m.critical)
    critical.push_back({{"theta", c.theta}, {"dF", as_list(c.load)},
                        {"count", count_to_json(c.summary.count)},
                        {"types", type_tuple_names(c.summary, N)}});
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [c, w] : measure) counts[count_to_string(c)] = {{"radians", w}};
  return {{"kind", "direction"},
          {"input", {{"system", path}, {"name", sys.name}, {"n_points", N},
                     {"patterns", {as_list(m.e1), as_list(m.e2)}}}},
          {"sectors", sectors},
          {"critical", critical},
          {"counts", counts},
          {"candidates", m.candidates},
          {"evaluations", m.evaluations},
          {"unreliable", m.unreliable},
          {"inconsistent_sectors", m.inconsistent_sectors},
          {"complete", complete}};
}

void write_system_direction_csv(const SystemDirectionMap& m, int n_points, std::ostream& out) {
  out << std::setprecision(17) << "kind,theta_from,theta_to,count,types\n";
  for (const auto& s : m.sectors)
    out << "sector," << s.theta_from << ',' << s.theta_to << ','
        << count_to_string(s.summary.count) << ','
        << joined(type_tuple_names(s.summary, n_points), "|") << '\n';
  for (const auto& c : m.critical)
    out << "critical," << c.theta << ',' << c.theta << ',' << count_to_string(c.summary.count)
        << ',' << joined(type_tuple_names(c.summary, n_points), "|") << '\n';
}

nlohmann::json system_param_direction_json(const SystemParamDirectionMap& m, int n_points,
                                           const nlohmann::json& input) {
  nlohmann::json counts = nlohmann::json::array();
  for (const auto& c : m.classes)
    counts.push_back({{"count", count_to_json(c.code)}, {"cells", c.cells},
                      {"param_min", c.x_min}, {"param_max", c.x_max},
                      {"theta_min", c.y_min}, {"theta_max", c.y_max}});
  return {{"kind", "param-direction"},
          {"input", input},
          {"cells", m.cells()},
          {"counts", counts},
          {"patterns", pattern_table_json(m.table, n_points)},
          {"lcp_size_max", m.m_max},
          {"unreliable", m.unreliable},
          {"complete", m.unreliable == 0}};
}

nlohmann::json system_param_param_json(const SystemParamParamMap& m, int n_points,
                                       const nlohmann::json& input) {
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : m.classes)
    classes.push_back({{"class", to_string(static_cast<UniquenessClass>(c.code))},
                       {"code", c.code}, {"cells", c.cells},
                       {"x_min", c.x_min}, {"x_max", c.x_max},
                       {"y_min", c.y_min}, {"y_max", c.y_max}});
  return {{"kind", "param-param"},
          {"input", input},
          {"cells", m.cells()},
          {"classes", classes},
          {"class_codes", {{"unique", 0}, {"non-unique", 1}, {"no-solution", 2},
                           {"none-and-several", 3}}},
          {"patterns", pattern_table_json(m.table, n_points)},
          {"lcp_size_max", m.m_max},
          {"unreliable", m.unreliable},
          {"inconsistent_sectors", m.inconsistent_sectors},
          {"complete", m.unreliable == 0 && m.inconsistent_sectors == 0}};
}

nlohmann::json map_3d_json(const Map3d& m, const std::string& kind, const nlohmann::json& input,
                           const std::string& xname, const std::string& yname) {
  nlohmann::json j;
  j["kind"] = kind;
  j["dim"] = 3;
  j["input"] = input;
  j["axes"] = {{"x", xname}, {"y", yname}};
  j["cells"] = m.cells();
  nlohmann::json counts = nlohmann::json::array();
  for (const auto& [c, n] : m.count_cells)
    counts.push_back(
        {{"count", c < 0 ? nlohmann::json("infinite") : nlohmann::json(c)}, {"cells", n}});
  j["counts"] = counts;
  nlohmann::json types = nlohmann::json::array();
  for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
    if (m.type_cells[mask] > 0)
      types.push_back(
          {{"mask", mask}, {"types", type_mask_string(mask)}, {"cells", m.type_cells[mask]}});
  j["types"] = types;
  j["type_bits"] = {{"open", type_bit(SolutionType::kOpen)},
                    {"separation", type_bit(SolutionType::kSeparation)},
                    {"stick", type_bit(SolutionType::kStick)},
                    {"slip", type_bit(SolutionType::kSlip)}};
  j["incomplete_cells"] = m.incomplete_cells;
  j["timed_out_cells"] = m.timed_out_cells;
  j["time_limit_reached"] = m.timed_out_cells > 0;
  j["complete"] = m.incomplete_cells == 0;
  j["threads"] = m.threads;
  return j;
}

}  // namespace cpkit::rate
