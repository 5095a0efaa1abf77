// The text of `cpkit map` (report/map_text.hpp), moved out of the program: each summary is
// written to one stream in the order the program printed it (a precision set for one line
// carries over to the next, as it did on std::cout).
#include "cpkit/rate_problem/report/map_text.hpp"

#include <filesystem>
#include <initializer_list>
#include <iomanip>
#include <memory>
#include <sstream>

#include "cpkit/core/number_text.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/report/map_json.hpp"

namespace cpkit::rate {

namespace {

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

void pattern_table_text(std::ostream& o, const SystemPatternTable& t, int n_points) {
  o << "point-type patterns:\n";
  for (std::size_t k = 0; k < t.patterns.size(); ++k)
    o << "  " << k << ": "
      << (t.patterns[k].empty() ? std::string("(no solution)")
                                : joined(type_tuple_names(t.patterns[k], n_points), ", "))
      << " (" << t.cells[k] << " cells)\n";
}

/// The 3-D maps say "infinitely many" where the 2-D ones say "a continuum".
std::string count_text_3d(int count) {
  return count < 0 ? "infinitely many solutions" : map_count_text(count);
}

}  // namespace

std::string map_types_text(unsigned mask) {
  std::string out;
  for (char c : types_to_string(mask)) {
    out += c == '|' ? ',' : c;
    if (c == '|' || c == ',') out += ' ';
  }
  return out;
}

std::string map_count_text(int count) {
  if (count < 0) return "a continuum of solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}

std::string map_model_text(const ContactParameters& p, const ContactState& s,
                           const std::vector<MapParameterRef>& axes) {
  // A value is "(axis)" when an axis varies it, directly or through a row that sets it.
  auto on_axis = [&](std::initializer_list<std::string_view> names) {
    for (const auto& a : axes)
      for (auto q : names)
        if (q == a.row->name) return true;
    return false;
  };
  auto v = [&](const char* name, double x, std::initializer_list<std::string_view> names) {
    return std::string(name) + " = " + (on_axis(names) ? std::string("(axis)") : num_text(x, 4));
  };
  std::string t = "state " + std::string(to_string(s.label)) + ", " + v("a11", p.a11, {"a11"}) +
                  ", " + v("a12", p.a12, {"a12", "a12/a11"}) + ", " + v("a22", p.a22, {"a22"}) +
                  ", " + v("mu", p.mu, {"mu"}) + ", " + v("C_T", p.C_T, {"C_T"});
  if (s.label == StateLabel::kC || s.label == StateLabel::kD)
    t += ", " + v("P_N", s.P_N, {"P_N"}) + ", " + v("k_a", p.k_a, {"k_a", "kappa"}) + ", " +
         v("P_s", p.P_s, {"P_s"}) + ", " +
         v("kappa", p.kappa(s.P_N), {"kappa", "k_a", "P_N", "P_s"}) +
         (s.label == StateLabel::kD ? ", sgn P_T = " + std::to_string(s.sgn_PT) : "");
  if (p.criterion == Criterion::kSoftening)
    t += ", criterion (35)" +
         std::string(s.label == StateLabel::kD ? " (mu_eff = mu - 2 kappa)" : "");
  return t;
}

std::string map_presets_text() {
  std::string t;
  for (const auto& p : map_presets())
    t += p.name + " (" + std::string(to_string(p.kind)) + "): " + p.description + '\n';
  return t;
}

std::string direction_map_text(const DirectionMap& m, const MapSetup& s) {
  std::ostringstream o;
  o << "direction map, " << map_model_text(s.params, s.state) << '\n';
  o << "sectors (theta in rad from +dF_T towards +dF_N; open arcs):\n";
  auto types = [](unsigned t) { return t ? ": " + map_types_text(t) : std::string(); };
  for (const auto& x : m.sectors)
    o << "  (" << std::fixed << std::setprecision(4) << x.theta_from << ", " << x.theta_to << ")"
      << std::defaultfloat << "  " << map_count_text(x.summary.count) << types(x.summary.types)
      << '\n';
  if (!m.critical.empty()) o << "critical directions:\n";
  for (const auto& c : m.critical)
    o << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat << " ("
      << joined(c.conditions, ", ") << ")  " << map_count_text(c.summary.count)
      << types(c.summary.types) << '\n';
  bool all_unique = true;
  for (const auto& x : m.sectors) {
    all_unique = all_unique && x.summary.count == 1;
    if (x.summary.count != 1)
      // An open interval: the sectors are open arcs, their end directions are critical and
      // have their own counts (listed above).
      o << "summary: " << map_count_text(x.summary.count) << " for theta in (" << std::fixed
        << std::setprecision(2) << x.theta_from << ", " << x.theta_to << ")" << std::defaultfloat
        << '\n';
  }
  for (const auto& c : m.critical) {
    all_unique = all_unique && c.summary.count == 1;
    if (c.summary.count <= 0)
      o << "summary: " << map_count_text(c.summary.count) << " at theta = " << std::fixed
        << std::setprecision(4) << c.theta << std::defaultfloat << '\n';
  }
  if (all_unique) o << "summary: exactly one solution for every direction\n";
  return o.str();
}

std::string param_direction_map_text(const nlohmann::json& summary, const MapSetup& s,
                                     bool theta_range) {
  auto num = [](const nlohmann::json& x, int digits = 4) {
    return num_text(x.get<double>(), digits);
  };
  std::ostringstream o;
  const auto& ax = summary["axis"];
  const std::string param = ax["param"].get<std::string>();
  o << "param-direction map, " << map_model_text(s.params, s.state, {s.axis.param}) << "\n  "
    << param << " in [" << num(ax["from"]) << ", " << num(ax["to"]) << "] x theta in "
    << (theta_range ? "[" + num(summary["theta_from"]) + ", " + num(summary["theta_to"]) + "]: "
                    : std::string("[0, 2 pi): "))
    << summary["cells"] << " cells, " << num(summary["seconds"], 3) << " s, "
    << summary["threads"] << " threads\n";
  for (const auto& c : summary["classes"]) {
    const int count = c["count"].is_string() ? -1 : c["count"].get<int>();
    o << "  " << map_count_text(count) << ": " << c["cells"] << " cells, " << param << " in ["
      << num(c["x_min"]) << ", " << num(c["x_max"]) << "], theta in [" << num(c["theta_min"], 3)
      << ", " << num(c["theta_max"], 3) << "]\n";
  }
  for (const auto& c : summary["critical_values"])
    o << "  critical: " << c["name"].get<std::string>() << " at " << param << " = "
      << num(c["x"], 10) << '\n';
  return o.str();
}

std::string param_param_map_text(const nlohmann::json& summary, const MapSetup& s) {
  auto num = [](const nlohmann::json& x) { return num_text(x.get<double>(), 4); };
  std::ostringstream o;
  const std::string x = summary["axis"]["param"].get<std::string>();
  const std::string y = summary["axis2"]["param"].get<std::string>();
  o << "param-param map, " << map_model_text(s.params, s.state, {s.axis.param, s.axis2.param})
    << "\n  " << x << " x " << y << ": " << summary["cells"] << " cells, "
    << num_text(summary["seconds"].get<double>(), 3) << " s\n";
  for (const auto& c : summary["classes"])
    o << "  " << c["class"].get<std::string>() << ": " << c["cells"] << " cells, " << x
      << " in [" << num(c["x_min"]) << ", " << num(c["x_max"]) << "], " << y << " in ["
      << num(c["y_min"]) << ", " << num(c["y_max"]) << "]\n";
  return o.str();
}

std::string system_direction_map_text(const SystemDirectionMap& m, int n_points,
                                      const std::string& path) {
  auto types = [n_points](const SystemRateSummary& s) {
    return s.n_tuples ? ": " + joined(type_tuple_names(s, n_points), ", ") : std::string();
  };
  std::ostringstream o;
  o << "direction map of " << n_points << " points (" << path << "), dF = cos(theta) e1 + "
    << "sin(theta) e2\nsectors (theta in rad; open arcs):\n";
  for (const auto& s : m.sectors)
    o << "  (" << std::fixed << std::setprecision(4) << s.theta_from << ", " << s.theta_to << ")"
      << std::defaultfloat << "  " << map_count_text(s.summary.count) << types(s.summary) << '\n';
  if (!m.critical.empty()) o << "critical directions:\n";
  for (const auto& c : m.critical)
    o << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat << "  "
      << map_count_text(c.summary.count) << types(c.summary) << '\n';
  return o.str();
}

std::string system_param_direction_map_text(const SystemParamDirectionMap& m, int n_points,
                                            const SystemMapRequest& r,
                                            const SystemMapAxis& axis) {
  std::ostringstream o;
  o << "param-direction map of " << n_points << " points (" << r.path << "): "
    << axis.param.name() << " in [" << r.from << ", " << r.to << "] (" << r.n << " values) x "
    << r.theta_n << " directions"
    << (r.theta_range ? " in [" + num_text(r.theta_from, 3) + ", " +
                            num_text(r.theta_to, 3) + "]"
                      : std::string())
    << ", " << static_cast<int64_t>(r.n) * r.theta_n << " cells\ncounts:\n";
  for (const auto& c : m.classes)
    o << "  " << map_count_text(c.code) << ": " << c.cells << " cells, " << axis.param.name()
      << " in [" << c.x_min << ", " << c.x_max << "]\n";
  pattern_table_text(o, m.table, n_points);
  return o.str();
}

std::string system_param_param_map_text(const SystemParamParamMap& m, int n_points,
                                        const SystemMapRequest& r, const SystemMapAxis& a1,
                                        const SystemMapAxis& a2) {
  std::ostringstream o;
  o << "param-param map of " << n_points << " points (" << r.path << "): " << a1.param.name()
    << " in [" << r.from << ", " << r.to << "] (" << r.n << " values) x " << a2.param.name()
    << " in [" << r.from2 << ", " << r.to2 << "] (" << r.n2 << " values), "
    << static_cast<int64_t>(r.n) * r.n2 << " cells\nclasses:\n";
  for (const auto& c : m.classes)
    o << "  " << to_string(static_cast<UniquenessClass>(c.code)) << ": " << c.cells << " cells, "
      << a1.param.name() << " in [" << c.x_min << ", " << c.x_max << "], " << a2.param.name()
      << " in [" << c.y_min << ", " << c.y_max << "]\n";
  pattern_table_text(o, m.table, n_points);
  return o.str();
}

std::string map_3d_text(const Map3dRequest& r, const Map3dPlan& p, const Map3d& m) {
  auto num = [](double x) { return num_text(x, 4); };
  const Map3dOptions& opt = p.options;
  const int N = p.sys.n_points();
  std::ostringstream o;
  o << p.kind << " map of " << N << (N == 1 ? " 3-D point" : " 3-D points") << " (" << r.system.value_or("")
    << "), ";
  if (p.kind != "param-param") o << "load at point " << r.point.value_or(1) << ", ";
  o << (opt.facets ? "faceted with " + std::to_string(opt.facets) + " facets"
                   : std::string("exact"))
    << ": " << m.cells() << " cells\n";
  if (p.kind == "sphere")
    o << "  dF = (sin b cos g, sin b sin g, cos b): b in [" << num(p.grid.beta_from) << ", "
      << num(p.grid.beta_to) << "] (" << m.rows << " values) x g in (-pi, pi] (" << m.cols
      << " values)\n";
  else if (p.kind == "param-direction")
    o << "  " << p.xname << " in [" << num(r.from.value_or(0)) << ", " << num(r.to.value_or(0)) << "] (" << m.rows
      << " values) x theta in [" << num(p.theta_from) << ", " << num(p.theta_to) << "] ("
      << m.cols << " values) at g = " << num(p.gamma) << '\n';
  else
    o << "  " << p.xname << " in [" << num(r.from.value_or(0)) << ", " << num(r.to.value_or(0)) << "] x " << p.yname
      << " in [" << num(r.from2.value_or(0)) << ", " << num(r.to2.value_or(0)) << "]\n";
  o << "counts:\n";
  for (const auto& [c, n] : m.count_cells) o << "  " << count_text_3d(c) << ": " << n << " cells\n";
  o << "types:\n";
  for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
    if (m.type_cells[mask] > 0)
      o << "  " << type_mask_string(mask) << ": " << m.type_cells[mask] << " cells\n";
  o << "not proved complete: " << m.incomplete_cells << " cells\n";
  if (m.timed_out_cells > 0)
    o << "time limit reached: " << m.timed_out_cells << " cells cut short or not computed\n";
  return o.str();
}

std::string map_files_text(const std::string& prefix, const nlohmann::json& files) {
  namespace fs = std::filesystem;
  std::string t = "wrote";
  for (const auto& [k, v] : files.items())
    t += ' ' + (fs::path(prefix).parent_path() / v.get<std::string>()).string();
  return t + '\n';
}

MapProgress map_progress_printer(std::ostream& err) {
  struct State {
    Stopwatch clock;
    std::string phase;
    bool printed = false;
    int percent = -1;
    double last = 0;
  };
  auto st = std::make_shared<State>();
  return [st, &err](std::string_view phase, double f) {
    if (phase != st->phase) {
      st->phase = std::string(phase);
      st->printed = false;
      st->percent = -1;
    }
    const double t = st->clock.seconds();
    const int percent = static_cast<int>(100 * f);
    if (f < 0) {  // the phase stopped before its end (the time limit): end the line
      if (st->printed) err << " stopped\n";
      st->printed = false;
      return;
    }
    // A new line only when the percentage changed (or every 5 s): short logs when redirected.
    if (f < 1.0 && t > 1.0 && (percent != st->percent || t > st->last + 5.0)) {
      st->percent = percent;
      st->last = t;
      err << "\rcpkit map: " << phase << ' ' << std::setw(3) << percent << "% (" << std::fixed
          << std::setprecision(1) << t << " s)" << std::defaultfloat << std::flush;
      st->printed = true;
    } else if (f >= 1.0 && st->printed) {
      err << "\rcpkit map: " << phase << " 100% (" << std::fixed << std::setprecision(1) << t
          << " s)" << std::defaultfloat << '\n';
      st->printed = false;
    }
  };
}

}  // namespace cpkit::rate
