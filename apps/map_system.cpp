// `cpkit map --system FILE`: the maps of N contact points (docs/maps.md, "N points"):
// --kind direction (sectors and exact critical directions of dF(theta) = cos(theta) e1 +
// sin(theta) e2), param-direction and param-param (grid maps streamed to .npy or CSV files).
// Exit codes: 0 map computed, 2 bad input, 4 a requested picture not drawn, 5 inconclusive (an
// evaluation too close to call or a sector that is not uniform; the map is then printed with
// complete: false).
#include <cstring>
#include <filesystem>
#include <thread>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"
#include "map_files.hpp"
#include "platform/mpi_session.hpp"
#include "machine_resources.hpp"
#include "map_system.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "memory_limit.hpp"
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

std::string pattern_text(const std::vector<TypeTuple>& tuples, int n_points) {
  return tuples.empty() ? std::string("(no solution)") : joined(pattern_names(tuples, n_points), ", ");
}

nlohmann::json pattern_table_json(const SystemPatternTable& t, int n_points) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < t.patterns.size(); ++k)
    out.push_back({{"id", k}, {"types", pattern_names(t.patterns[k], n_points)},
                   {"cells", t.cells[k]}});
  return out;
}

void print_pattern_table(const SystemPatternTable& t, int n_points) {
  std::cout << "point-type patterns:\n";
  for (std::size_t k = 0; k < t.patterns.size(); ++k)
    std::cout << "  " << k << ": " << pattern_text(t.patterns[k], n_points) << " ("
              << t.cells[k] << " cells)\n";
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o << std::setprecision(3) << s;
  return o.str();
}

/// Refuses up front (exit 2) a map whose estimated cell time exceeds --time-limit or whose
/// files would not fit the disk (`bytes_per_cell` as written: .npy codes or CSV lines).
nlohmann::json check_estimate(const SystemMapEstimate& e, const SystemMapRequest& r,
                              const std::string& cells, const std::string& fewer,
                              double npy_bytes_per_cell) {
  // Rank 0 decides for the job (an estimate differs between ranks); if it refuses, mpirun
  // ends the others.
  if (mpi::rank() != 0) return nlohmann::json::object();
  if (!r.out.empty()) {
    // A CSV line holds two numbers at 17 digits, the count and the pattern id.
    // The finished chunks are kept in PREFIX.parts until the outputs are complete: twice.
    const double output = 2 * e.cells * (r.format == "csv" ? 45.0 : npy_bytes_per_cell);
    const std::string dir = std::filesystem::path(r.out).parent_path().string();
    if (output > r.max_output)
      throw InputError("the map has " + cells + " and its output would take about " +
                       byte_text(output) + " (estimated), more than --max-output " +
                       byte_text(r.max_output) + ": " + fewer +
                       (r.format == "csv" ? ", drop --format csv" : "") + ", or raise --max-output");
    const double free = free_disk_bytes(dir);
    if (free >= 0 && output > 0.95 * free)
      throw InputError("the map has " + cells + " and its output would take about " +
                       seconds_text(output / 1e9) + " GB but only " + seconds_text(free / 1e9) +
                       " GB is free in '" + (dir.empty() ? "." : dir) + "': " + fewer +
                       (r.format == "csv" ? ", or drop --format csv" : ""));
  }
  const double seconds = e.seconds / mpi::size();  // the ranks share the cells
  if (seconds > r.time_limit)
    throw InputError("the map has " + cells + " and would need about " + seconds_text(seconds) +
                     " s of computing on " + std::to_string(e.threads) + " threads x " +
                     std::to_string(mpi::size()) + " processes (estimated from " +
                     std::to_string(e.sampled) +
                     " timed cells), more than --time-limit " + seconds_text(r.time_limit) +
                     ": " + fewer + ", or raise --time-limit");
  if (seconds > 1.0 && mpi::rank() == 0)
    std::cerr << "cpkit map: " << cells << ": about " << seconds_text(seconds) << " s on "
              << e.threads << " threads x " << mpi::size() << " processes (estimate)\n";
  return {{"seconds", seconds}, {"threads", e.threads}, {"sampled_cells", e.sampled}};
}

std::vector<double> axis_values(const SystemMapAxis& a) {
  std::vector<double> v(static_cast<std::size_t>(a.n));
  for (int i = 0; i < a.n; ++i) v[static_cast<std::size_t>(i)] = a.value(i);
  return v;
}

/// The parts of a grid map's run every kind shares: the JSON head, files, plot, exit code.
struct GridRun {
  const SystemMapRequest& r;
  nlohmann::json j;
  nlohmann::json files = nlohmann::json::object();
  GridFiles out;
  explicit GridRun(const SystemMapRequest& req) : r(req), out(req.out, files) {}
  bool writing_npy() const { return !r.out.empty() && r.format == "npy"; }
  bool writing_csv() const { return !r.out.empty() && r.format == "csv"; }
  /// Writes PREFIX.json (and the picture); prints; returns the exit code.
  int finish(bool complete, const std::function<void()>& print_text) {
    bool plot_failed = false;
    if (!r.out.empty()) {
      const std::string name = std::filesystem::path(r.out).filename().string();
      files["json"] = name + ".json";
      j["files"] = files;
      j["run"] = run_echo();
      write_text_file(r.out + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
      if (r.plot) {
        plot_failed = !run_map_plot(r.out, files);
        j["files"] = files;
        write_text_file(r.out + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
      }
    }
    if (r.json) {
      print_json(j);
    } else {
      print_text();
      if (!r.out.empty()) {
        std::cout << "wrote";
        for (const auto& [k, v] : files.items())
          std::cout << ' '
                    << (std::filesystem::path(r.out).parent_path() / v.get<std::string>()).string();
        std::cout << '\n';
      }
    }
    if (!complete) return kExitInconclusive;
    return plot_failed ? kExitInternal : kExitOk;
  }
};

MapOptions request_options(const SystemMapRequest& r) {
  MapOptions o;
  o.threads = r.threads;
  o.theta_from = r.theta_from;
  o.theta_to = r.theta_to;
  if (std::string e = o.validate(); !e.empty())
    throw InputError("--theta-from/--theta-to: " + e);
  return o;
}

/// FNV-1a of the system's data (A, every point's parameters and state, criterion, dF,
/// patterns) as read: a resumed map must read the same system. Taken from the parsed system,
/// not by reading the file again (a --system <(...) pipe can be read once only).
std::string system_fingerprint(const ContactSystem& sys) {
  uint64_t h = 1469598103934665603ull;
  auto bytes = [&](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  };
  auto real = [&](double x) { bytes(&x, sizeof x); };
  auto vec = [&](const std::optional<Eigen::VectorXd>& v) {
    const int64_t n = v ? v->size() : -1;
    bytes(&n, sizeof n);
    if (v) bytes(v->data(), sizeof(double) * static_cast<std::size_t>(v->size()));
  };
  const int64_t rows = sys.A.rows(), cols = sys.A.cols();
  bytes(&rows, sizeof rows);
  bytes(&cols, sizeof cols);
  bytes(sys.A.data(), sizeof(double) * static_cast<std::size_t>(sys.A.size()));
  for (const SystemPoint& p : sys.points) {
    for (double x : {p.mu, p.C_T, p.k_a, p.P_s, p.state.P_N, p.P_T, p.P_N, p.g}) real(x);
    const int ints[] = {static_cast<int>(p.state.label), p.state.sgn_PT, p.values_given ? 1 : 0};
    bytes(ints, sizeof ints);
  }
  const int crit = static_cast<int>(sys.criterion);
  bytes(&crit, sizeof crit);
  vec(sys.dF);
  vec(sys.pattern1);
  vec(sys.pattern2);
  std::ostringstream o;
  o << std::hex << h;
  return o.str();
}

int resolved_threads(int requested) {
  return requested > 0 ? requested
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// How a grid map of the request runs (grid_map_run.hpp): checkpointed under PREFIX.parts when
/// writing; the manifest names the version, kind, input echo (axes included) and the system's data.
rate::GridRunOptions grid_run_options(const SystemMapRequest& r, const ContactSystem& sys,
                                      const nlohmann::json& input) {
  rate::GridRunOptions o;
  o.checkpoint_prefix = r.out;
  o.resume = r.resume;
  o.manifest = {{"cpkit_version", CPKIT_VERSION}, {"kind", r.kind}, {"input", input},
                {"system_data_fnv1a", system_fingerprint(sys)}, {"format", r.format}};
  o.describe_grid = false;  // "input" holds the axes
  o.transport = mpi::map_transport();
  o.progress = make_map_progress();
  return o;
}

/// An axis of the request: NAME (checked against the map parameter table), from, to, n.
SystemMapAxis axis_of(const std::string& param, double from, double to, int n, int n_points) {
  SystemMapAxis a;
  a.param = parse_system_map_parameter(param, n_points);
  a.from = from;
  a.to = to;
  a.n = n;
  return a;
}

/// `--kind param-direction`: count and point-type pattern per (parameter, direction) cell.
int run_param_direction(const SystemMapRequest& r) {
  const Stopwatch clock;
  const ContactSystem sys = parse_contact_system(r.file);
  // Limits that depend on N and the states, before any work in proportion to N.
  check_system_map_lcp_size(sys, "a map of its cells");
  const int N = sys.n_points();
  const SystemMapAxis axis = axis_of(r.param, r.from, r.to, r.n, N);
  const MapOptions options = request_options(r);
  Eigen::VectorXd e1, e2;
  system_map_patterns(sys, e1, e2);
  GridRun run(r);
  const std::string cells = std::to_string(r.n) + " x " + std::to_string(r.theta_n) +
                            " cells (--n x --theta-n)";
  const nlohmann::json estimate =
      check_estimate(estimate_system_param_direction_map(sys, axis, r.theta_n, options), r,
                     cells, "use a smaller --n or --theta-n", 3);
  const nlohmann::json input = {
      {"system", r.path}, {"name", sys.name}, {"n_points", N}, {"param", axis.param.name()},
      {"from", r.from}, {"to", r.to}, {"n", r.n}, {"theta_n", r.theta_n},
      {"theta_from", r.theta_from}, {"theta_to", r.theta_to},
      {"patterns", {as_list(e1), as_list(e2)}}};
  const std::vector<double> theta = map_theta_values(r.theta_n, r.theta_from, r.theta_to);
  bool opened = false;
  auto open_files = [&] {
    if (run.writing_npy()) {
      run.out.add_npy("count", "|i1", r.n, r.theta_n);
      run.out.add_npy("pattern", "<u2", r.n, r.theta_n, 2);
      run.out.write_vector("x", axis_values(axis));
      run.out.write_vector("theta", theta);
    } else if (run.writing_csv()) {
      run.out.open_csv() << std::setprecision(17) << axis.param.name() << ",theta,count,pattern\n";
    }
    opened = true;
  };
  auto sink = [&](const SystemParamDirectionRows& rows) {
    if (!opened) open_files();
    const std::size_t n_cells =
        static_cast<std::size_t>(rows.row_end - rows.row_begin) * static_cast<std::size_t>(r.theta_n);
    run.out.append({rows.count, rows.pattern}, static_cast<int64_t>(n_cells));
    if (!run.out.has_csv()) return;
    for (int i = rows.row_begin; i < rows.row_end; ++i)
      for (int jj = 0; jj < r.theta_n; ++jj) {
        const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * r.theta_n + jj;
        run.out.csv() << axis.value(i) << ',' << theta[static_cast<std::size_t>(jj)] << ','
                      << count_to_string(rows.count[k]) << ',' << rows.pattern[k] << '\n';
      }
  };
  rate::SystemParamDirectionRun res;
  if (!run_to_files(run.out, res, [&] {
        return rate::run_system_param_direction_map(sys, axis, r.theta_n, options,
                                                    grid_run_options(r, sys, input), sink);
      }))
    return kExitOk;  // rank 0 writes and prints
  const SystemParamDirectionMap& merge = res.map;
  const rate::ChunkRunStats& stats = res.stats;
  const bool complete = merge.unreliable == 0;
  nlohmann::json counts = nlohmann::json::array();
  for (const auto& c : merge.classes)
    counts.push_back({{"count", count_to_json(c.code)}, {"cells", c.cells},
                      {"param_min", c.x_min}, {"param_max", c.x_max},
                      {"theta_min", c.y_min}, {"theta_max", c.y_max}});
  run.j = {{"cpkit_version", CPKIT_VERSION},
           {"kind", "param-direction"},
           {"input", input},
           {"cells", static_cast<int64_t>(r.n) * r.theta_n},
           {"counts", counts},
           {"patterns", pattern_table_json(merge.table, N)},
           {"lcp_size_max", merge.m_max},
           {"unreliable", merge.unreliable},
           {"complete", complete},
           {"threads", resolved_threads(r.threads)},
           {"estimate", estimate}};
  rate::add_run_figures(run.j, stats);
  if (!r.out.empty()) run.j["format"] = r.format;
  if (!complete)
    std::cerr << "cpkit map: " << merge.unreliable
              << " cells too close to call: the map is not proved complete\n";
  run.j["seconds"] = clock.seconds();
  const int code = run.finish(complete, [&] {
    std::cout << "param-direction map of " << N << " points (" << r.path << "): "
              << axis.param.name() << " in [" << r.from << ", " << r.to << "] (" << r.n
              << " values) x " << r.theta_n << " directions"
              << (r.theta_range ? " in [" + seconds_text(r.theta_from) + ", " +
                                      seconds_text(r.theta_to) + "]"
                                : std::string())
              << ", " << static_cast<int64_t>(r.n) * r.theta_n << " cells\ncounts:\n";
    for (const auto& c : merge.classes)
      std::cout << "  " << count_text(c.code) << ": " << c.cells << " cells, "
                << axis.param.name() << " in [" << c.x_min << ", " << c.x_max << "]\n";
    print_pattern_table(merge.table, N);
  });
  if (!r.out.empty()) rate::remove_checkpoint(r.out + ".parts");
  return code;
}

/// `--kind param-param`: per cell, the class of its exact direction map and the union pattern.
int run_param_param(const SystemMapRequest& r) {
  const Stopwatch clock;
  const ContactSystem sys = parse_contact_system(r.file);
  // Limits that depend on N and the states, before any work in proportion to N.
  check_system_map_lcp_size(sys, "a map of its cells");
  const int N = sys.n_points();
  const SystemMapAxis a1 = axis_of(r.param, r.from, r.to, r.n, N);
  const SystemMapAxis a2 = axis_of(r.param2, r.from2, r.to2, r.n2, N);
  MapOptions options;
  options.threads = r.threads;
  Eigen::VectorXd e1, e2;
  system_map_patterns(sys, e1, e2);
  GridRun run(r);
  const std::string cells =
      std::to_string(r.n) + " x " + std::to_string(r.n2) + " cells (--n x --n2)";
  const nlohmann::json estimate = check_estimate(
      estimate_system_param_param_map(sys, a1, a2, options), r, cells, "use a smaller --n or --n2", 5);
  const nlohmann::json input = {
      {"system", r.path}, {"name", sys.name}, {"n_points", N}, {"param", a1.param.name()},
      {"from", r.from}, {"to", r.to}, {"n", r.n}, {"param2", a2.param.name()},
      {"from2", r.from2}, {"to2", r.to2}, {"n2", r.n2}, {"patterns", {as_list(e1), as_list(e2)}}};
  bool opened = false;
  auto open_files = [&] {
    if (run.writing_npy()) {
      run.out.add_npy("class", "|u1", r.n, r.n2);
      run.out.add_npy("min_count", "|i1", r.n, r.n2);
      run.out.add_npy("max_count", "|i1", r.n, r.n2);
      run.out.add_npy("pattern", "<u2", r.n, r.n2, 2);
      run.out.write_vector("x", axis_values(a1));
      run.out.write_vector("y", axis_values(a2));
    } else if (run.writing_csv()) {
      run.out.open_csv() << std::setprecision(17) << a1.param.name() << ',' << a2.param.name()
                         << ",class,min_count,max_count,pattern\n";
    }
    opened = true;
  };
  auto sink = [&](const SystemParamParamRows& rows) {
    if (!opened) open_files();
    const std::size_t n_cells = static_cast<std::size_t>(rows.row_end - rows.row_begin) * r.n2;
    run.out.append({rows.cls, rows.min_count, rows.max_count, rows.pattern},
                   static_cast<int64_t>(n_cells));
    if (!run.out.has_csv()) return;
    for (int i = rows.row_begin; i < rows.row_end; ++i)
      for (int jj = 0; jj < r.n2; ++jj) {
        const std::size_t k = static_cast<std::size_t>(i - rows.row_begin) * r.n2 + jj;
        run.out.csv() << a1.value(i) << ',' << a2.value(jj) << ','
                      << to_string(static_cast<UniquenessClass>(rows.cls[k])) << ','
                      << count_to_string(rows.min_count[k]) << ','
                      << count_to_string(rows.max_count[k]) << ',' << rows.pattern[k] << '\n';
      }
  };
  rate::SystemParamParamRun res;
  if (!run_to_files(run.out, res, [&] {
        return rate::run_system_param_param_map(sys, a1, a2, options,
                                                grid_run_options(r, sys, input), sink);
      }))
    return kExitOk;
  const SystemParamParamMap& merge = res.map;
  const rate::ChunkRunStats& stats = res.stats;
  const bool complete = merge.unreliable == 0 && merge.inconsistent_sectors == 0;
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : merge.classes)
    classes.push_back({{"class", to_string(static_cast<UniquenessClass>(c.code))},
                       {"code", c.code}, {"cells", c.cells},
                       {"x_min", c.x_min}, {"x_max", c.x_max},
                       {"y_min", c.y_min}, {"y_max", c.y_max}});
  run.j = {{"cpkit_version", CPKIT_VERSION},
           {"kind", "param-param"},
           {"input", input},
           {"cells", static_cast<int64_t>(r.n) * r.n2},
           {"classes", classes},
           {"class_codes", {{"unique", 0}, {"non-unique", 1}, {"no-solution", 2},
                            {"none-and-several", 3}}},
           {"patterns", pattern_table_json(merge.table, N)},
           {"lcp_size_max", merge.m_max},
           {"unreliable", merge.unreliable},
           {"inconsistent_sectors", merge.inconsistent_sectors},
           {"complete", complete},
           {"threads", resolved_threads(r.threads)},
           {"estimate", estimate}};
  rate::add_run_figures(run.j, stats);
  if (!r.out.empty()) run.j["format"] = r.format;
  if (!complete)
    std::cerr << "cpkit map: " << merge.unreliable << " evaluations too close to call and "
              << merge.inconsistent_sectors << " sectors not uniform: the map is not proved complete\n";
  run.j["seconds"] = clock.seconds();
  const int code = run.finish(complete, [&] {
    std::cout << "param-param map of " << N << " points (" << r.path << "): "
              << a1.param.name() << " in [" << r.from << ", " << r.to << "] (" << r.n
              << " values) x " << a2.param.name() << " in [" << r.from2 << ", " << r.to2
              << "] (" << r.n2 << " values), " << static_cast<int64_t>(r.n) * r.n2
              << " cells\nclasses:\n";
    for (const auto& c : merge.classes)
      std::cout << "  " << to_string(static_cast<UniquenessClass>(c.code)) << ": " << c.cells
                << " cells, " << a1.param.name() << " in [" << c.x_min << ", " << c.x_max
                << "], " << a2.param.name() << " in [" << c.y_min << ", " << c.y_max << "]\n";
    print_pattern_table(merge.table, N);
  });
  if (!r.out.empty()) rate::remove_checkpoint(r.out + ".parts");
  return code;
}

}  // namespace

int run_map_system(const SystemMapRequest& r) {
  if (r.kind == "param-direction") return run_param_direction(r);
  if (r.kind == "param-param") return run_param_param(r);
  const std::string& path = r.path;
  const std::string& out = r.out;
  const bool json = r.json;
  const ContactSystem sys = parse_contact_system(r.file);
  check_system_map_lcp_size(sys, "the direction map");
  const int N = sys.n_points();
  MapOptions options;
  options.threads = r.threads;
  const SystemDirectionMap m = compute_system_direction_map(sys, options);
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
