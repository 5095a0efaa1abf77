// `cpkit map --system FILE --kind direction`: the direction map of N contact points
// (docs/maps.md, "N points"): sectors and exact critical directions of
// dF(theta) = cos(theta) e1 + sin(theta) e2. Exit codes: 0 map computed, 2 bad input,
// 5 inconclusive (an evaluation too close to call or a sector that is not uniform; the map is
// then printed with complete: false).
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "map_system.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

namespace cpkit::cli {

namespace {

using namespace cpkit::rate;

std::vector<double> as_list(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::vector<std::string> tuple_names(const SystemRateSummary& s, int n_points) {
  std::vector<std::string> out;
  for (int i = 0; i < std::min(s.n_tuples, SystemRateSummary::kCap); ++i)
    out.push_back(types_string(decode_types(s.tuples[static_cast<std::size_t>(i)], n_points)));
  return out;
}

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

std::string count_text(int count) {
  if (count < 0) return "a continuum of solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}

std::vector<std::string> pattern_names(const std::vector<TypeTuple>& tuples, int n_points) {
  std::vector<std::string> out;
  for (TypeTuple t : tuples) out.push_back(types_string(decode_types(t, n_points)));
  return out;
}

/// `--kind param-direction`: count and point-type pattern per (parameter, direction) cell.
int run_param_direction(const SystemMapRequest& r) {
  const ContactSystem sys = read_contact_system(r.path);
  const int N = sys.n_points();
  const SystemMapParameter param = parse_system_map_parameter(r.param, N);
  const SystemParamDirectionMap m =
      compute_system_param_direction_map(sys, param, r.from, r.to, r.n, r.theta_n, r.threads);
  Eigen::VectorXd e1, e2;
  system_map_patterns(sys, e1, e2);
  const bool complete = m.unreliable == 0;
  nlohmann::json counts = nlohmann::json::array(), patterns = nlohmann::json::array();
  for (const auto& c : m.classes)
    counts.push_back({{"count", count_to_json(c.code)}, {"cells", c.cells},
                      {"param_min", c.x_min}, {"param_max", c.x_max},
                      {"theta_min", c.y_min}, {"theta_max", c.y_max}});
  for (std::size_t k = 0; k < m.patterns.size(); ++k)
    patterns.push_back({{"id", k}, {"types", pattern_names(m.patterns[k], N)},
                        {"cells", m.pattern_cells[k]}});
  nlohmann::json j = {{"cpkit_version", CPKIT_VERSION},
                      {"kind", "param-direction"},
                      {"input", {{"system", r.path}, {"name", sys.name}, {"n_points", N},
                                 {"param", param.name()}, {"from", r.from}, {"to", r.to},
                                 {"n", r.n}, {"theta_n", r.theta_n},
                                 {"patterns", {as_list(e1), as_list(e2)}}}},
                      {"cells", m.cells()},
                      {"counts", counts},
                      {"patterns", patterns},
                      {"lcp_size_max", m.m_max},
                      {"unreliable", m.unreliable},
                      {"complete", complete},
                      {"threads", m.threads},
                      {"seconds", m.seconds}};
  if (!complete)
    std::cerr << "cpkit map: " << m.unreliable
              << " cells too close to call: the map is not proved complete\n";
  if (!r.out.empty()) {
    std::ofstream f(r.out + ".csv");
    if (!f) throw InputError("--out: cannot write '" + r.out + ".csv'");
    f << std::setprecision(17) << param.name() << ",theta,count,pattern\n";
    for (int i = 0; i < m.n; ++i)
      for (int jj = 0; jj < m.theta_n; ++jj) {
        const std::size_t k = static_cast<std::size_t>(i) * m.theta_n + jj;
        f << m.value(i) << ',' << m.theta[jj] << ',' << count_to_string(m.count[k]) << ','
          << m.pattern[k] << '\n';
      }
    if (!f) throw InputError("--out: writing '" + r.out + ".csv' failed");
    j["files"] = {{"csv", r.out + ".csv"}, {"json", r.out + ".json"}};
    std::ofstream fj(r.out + ".json");
    if (!fj) throw InputError("--out: cannot write '" + r.out + ".json'");
    nlohmann::json jj = j;
    jj["run"] = run_echo();
    fj << json_text(jj) << "\n";
  }
  if (r.json) {
    print_json(j);
  } else {
    std::cout << "param-direction map of " << N << " points (" << r.path << "): " << param.name()
              << " in [" << r.from << ", " << r.to << "] (" << r.n << " values) x " << r.theta_n
              << " directions, " << m.cells() << " cells\ncounts:\n";
    for (const auto& c : m.classes)
      std::cout << "  " << count_text(c.code) << ": " << c.cells << " cells, " << param.name()
                << " in [" << c.x_min << ", " << c.x_max << "]\n";
    std::cout << "point-type patterns:\n";
    for (std::size_t k = 0; k < m.patterns.size(); ++k)
      std::cout << "  " << k << ": "
                << (m.patterns[k].empty() ? std::string("(no solution)")
                                          : joined(pattern_names(m.patterns[k], N), ", "))
                << " (" << m.pattern_cells[k] << " cells)\n";
  }
  return complete ? kExitOk : kExitInconclusive;
}

}  // namespace

int run_map_system(const SystemMapRequest& r) {
  if (r.kind == "param-direction") return run_param_direction(r);
  if (r.kind != "direction")
    throw InputError("--kind with --system must be direction or param-direction (param-param "
                     "maps of N points are not implemented yet), got '" + r.kind + "'");
  const std::string& path = r.path;
  const std::string& out = r.out;
  const bool json = r.json;
  const ContactSystem sys = read_contact_system(path);
  const int N = sys.n_points();
  const SystemDirectionMap m = compute_system_direction_map(sys);
  const bool complete = m.unreliable == 0 && m.inconsistent_sectors == 0;

  nlohmann::json sectors = nlohmann::json::array(), critical = nlohmann::json::array();
  std::map<int, double> measure;  // count -> total angle
  for (const auto& s : m.sectors) {
    nlohmann::json j = {{"theta_from", s.theta_from}, {"theta_to", s.theta_to},
                        {"count", count_to_json(s.summary.count)},
                        {"types", tuple_names(s.summary, N)}};
    if (!s.consistent) j["consistent"] = false;
    sectors.push_back(j);
    measure[s.summary.count] += s.theta_to - s.theta_from;
  }
  for (const auto& c : m.critical)
    critical.push_back({{"theta", c.theta}, {"dF", as_list(c.dF)},
                        {"count", count_to_json(c.summary.count)},
                        {"types", tuple_names(c.summary, N)}});
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [c, w] : measure) counts[count_to_string(c)] = {{"radians", w}};
  nlohmann::json j = {{"cpkit_version", CPKIT_VERSION},
                      {"kind", "direction"},
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
  if (!complete)
    std::cerr << "cpkit map: " << m.unreliable << " evaluations too close to call and "
              << m.inconsistent_sectors << " sectors not uniform: the map is not proved complete\n";
  if (!out.empty()) {
    std::ofstream f(out + ".csv");
    if (!f) throw InputError("--out: cannot write '" + out + ".csv'");
    f << std::setprecision(17) << "kind,theta_from,theta_to,count,types\n";
    for (const auto& s : m.sectors)
      f << "sector," << s.theta_from << ',' << s.theta_to << ',' << count_to_string(s.summary.count)
        << ',' << joined(tuple_names(s.summary, N), "|") << '\n';
    for (const auto& c : m.critical)
      f << "critical," << c.theta << ',' << c.theta << ',' << count_to_string(c.summary.count) << ','
        << joined(tuple_names(c.summary, N), "|") << '\n';
    j["files"] = {{"csv", out + ".csv"}};
    std::ofstream fj(out + ".json");
    if (!fj) throw InputError("--out: cannot write '" + out + ".json'");
    nlohmann::json jj = j;
    jj["run"] = run_echo();
    fj << json_text(jj) << "\n";
  }
  if (json) {
    print_json(j);
  } else {
    std::cout << "direction map of " << N << " points (" << path << "), dF = cos(theta) e1 + "
              << "sin(theta) e2\nsectors (theta in rad; open arcs):\n";
    for (const auto& s : m.sectors)
      std::cout << "  (" << std::fixed << std::setprecision(4) << s.theta_from << ", "
                << s.theta_to << ")" << std::defaultfloat << "  " << count_text(s.summary.count)
                << (s.summary.n_tuples ? ": " + joined(tuple_names(s.summary, N), ", ") : "")
                << '\n';
    if (!m.critical.empty()) std::cout << "critical directions:\n";
    for (const auto& c : m.critical)
      std::cout << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat
                << "  " << count_text(c.summary.count)
                << (c.summary.n_tuples ? ": " + joined(tuple_names(c.summary, N), ", ") : "")
                << '\n';
  }
  return complete ? kExitOk : kExitInconclusive;
}

}  // namespace cpkit::cli
