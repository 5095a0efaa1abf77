// `cpkit map --system FILE`: the maps of N contact points (docs/maps.md, "N points"):
// --kind direction (sectors and exact critical directions of dF(theta) = cos(theta) e1 +
// sin(theta) e2), param-direction and param-param (grid maps streamed to .npy or CSV files).
// Exit codes: 0 map computed, 2 bad input, 4 a requested picture not drawn, 5 inconclusive (an
// evaluation too close to call or a sector that is not uniform; the map is then printed with
// complete: false).
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "map_args.hpp"
#include "map_files.hpp"
#include "map_system.hpp"
#include "platform/mpi_session.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"
#include "cpkit/rate_problem/report/map_json.hpp"

namespace cpkit::cli {

namespace {

using namespace cpkit::rate;

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

void print_pattern_table(const SystemPatternTable& t, int n_points) {
  std::cout << "point-type patterns:\n";
  for (std::size_t k = 0; k < t.patterns.size(); ++k)
    std::cout << "  " << k << ": "
              << (t.patterns[k].empty() ? std::string("(no solution)")
                                        : joined(type_tuple_names(t.patterns[k], n_points), ", "))
              << " (" << t.cells[k] << " cells)\n";
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
  if (!r.out.empty())
    // A CSV line holds two numbers at 17 digits, the count and the pattern id.
    // The finished chunks are kept in PREFIX.parts until the outputs are complete: twice.
    check_output_fits(cells, fewer, 2 * e.cells * (r.format == "csv" ? 45.0 : npy_bytes_per_cell),
                      r.max_output, std::filesystem::path(r.out).parent_path().string(),
                      r.format == "csv" ? ", drop --format csv" : "",
                      r.format == "csv" ? ", or drop --format csv" : "", true);
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

/// The parts of a grid map's run every kind shares: the JSON head, files, plot, exit code.
struct GridRun {
  const SystemMapRequest& r;
  nlohmann::json j;
  nlohmann::json files = nlohmann::json::object();
  GridFiles out;
  explicit GridRun(const SystemMapRequest& req) : r(req), out(req.out, files) {}
  bool writing_npy() const { return !r.out.empty() && r.format == "npy"; }
  bool writing_csv() const { return !r.out.empty() && r.format == "csv"; }
  /// The result: the library's document and what the program adds; true when complete.
  bool set_result(nlohmann::json doc, const rate::ChunkRunStats& stats,
                  const nlohmann::json& estimate) {
    j = std::move(doc);
    j["cpkit_version"] = CPKIT_VERSION;
    j["threads"] = map_worker_threads(r.threads, std::numeric_limits<int>::max());
    j["estimate"] = estimate;
    rate::add_run_figures(j, stats);
    if (!r.out.empty()) j["format"] = r.format;
    return j["complete"].get<bool>();
  }
  /// Writes PREFIX.json (and the picture); prints; returns the exit code.
  int finish(bool complete, const std::function<void()>& print_text) {
    bool plot_failed = false;
    if (!r.out.empty()) {
      j["run"] = run_echo();
      plot_failed = !write_map_json(r.out, r.plot, j, files);
    }
    if (r.json) {
      print_json(j);
    } else {
      print_text();
      if (!r.out.empty()) print_written(r.out, files);
    }
    if (!complete) return kExitInconclusive;
    return plot_failed ? kExitInternal : kExitOk;
  }
};

/// How a grid map of the request runs (grid_map_run.hpp): checkpointed under PREFIX.parts when
/// writing; the manifest names the version, kind, input echo (axes included) and the system's data.
rate::GridRunOptions grid_run_options(const SystemMapRequest& r, const ContactSystem& sys,
                                      const nlohmann::json& input) {
  rate::GridRunOptions o;
  o.checkpoint_prefix = r.out;
  o.resume = r.resume;
  o.manifest = {{"cpkit_version", CPKIT_VERSION}, {"kind", r.kind}, {"input", input},
                {"system_data_fnv1a", system_data_fingerprint(sys)}, {"format", r.format}};
  o.describe_grid = false;  // "input" holds the axes
  o.transport = mpi::map_transport();
  o.progress = make_map_progress();
  return o;
}

/// `--kind param-direction`: count and point-type pattern per (parameter, direction) cell.
int run_param_direction(const SystemMapRequest& r) {
  const Stopwatch clock;
  const SystemGridPlan p = make_system_grid_plan(r);
  const ContactSystem& sys = p.sys;
  const int N = sys.n_points();
  const SystemMapAxis& axis = p.axis;
  const MapOptions& options = p.options;
  const nlohmann::json& input = p.input;
  GridRun run(r);
  const nlohmann::json estimate =
      check_estimate(estimate_system_param_direction_map(sys, axis, r.theta_n, options), r,
                     p.cells_text, p.fewer, 3);
  const std::vector<double> theta = map_theta_values(r.theta_n, r.theta_from, r.theta_to);
  const SystemParamDirectionSink sink =
      system_param_direction_files(run.out, axis, theta, run.writing_npy(), run.writing_csv());
  rate::SystemParamDirectionRun res;
  if (!run_to_files(run.out, res, [&] {
        return rate::run_system_param_direction_map(sys, axis, r.theta_n, options,
                                                    grid_run_options(r, sys, input), sink);
      }))
    return kExitOk;  // rank 0 writes and prints
  const SystemParamDirectionMap& merge = res.map;
  const rate::ChunkRunStats& stats = res.stats;
  const bool complete = run.set_result(system_param_direction_json(merge, N, input), stats, estimate);
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
  const SystemGridPlan p = make_system_grid_plan(r);
  const ContactSystem& sys = p.sys;
  const int N = sys.n_points();
  const SystemMapAxis &a1 = p.axis, &a2 = p.axis2;
  const MapOptions& options = p.options;
  const nlohmann::json& input = p.input;
  GridRun run(r);
  const nlohmann::json estimate = check_estimate(
      estimate_system_param_param_map(sys, a1, a2, options), r, p.cells_text, p.fewer, 5);
  const SystemParamParamSink sink =
      system_param_param_files(run.out, a1, a2, run.writing_npy(), run.writing_csv());
  rate::SystemParamParamRun res;
  if (!run_to_files(run.out, res, [&] {
        return rate::run_system_param_param_map(sys, a1, a2, options,
                                                grid_run_options(r, sys, input), sink);
      }))
    return kExitOk;
  const SystemParamParamMap& merge = res.map;
  const rate::ChunkRunStats& stats = res.stats;
  const bool complete = run.set_result(system_param_param_json(merge, N, input), stats, estimate);
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
  nlohmann::json j = system_direction_map_json(m, sys, path);
  j["cpkit_version"] = CPKIT_VERSION;
  const bool complete = j["complete"].get<bool>();
  if (!complete)
    std::cerr << "cpkit map: " << m.unreliable << " evaluations too close to call and "
              << m.inconsistent_sectors << " sectors not uniform: the map is not proved complete\n";
  if (!out.empty()) {
    std::ofstream f(out + ".csv");
    if (!f) throw InputError("--out: cannot write '" + out + ".csv'");
    write_system_direction_csv(m, N, f);
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
                << (s.summary.n_tuples ? ": " + joined(type_tuple_names(s.summary, N), ", ") : "")
                << '\n';
    if (!m.critical.empty()) std::cout << "critical directions:\n";
    for (const auto& c : m.critical)
      std::cout << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat
                << "  " << count_text(c.summary.count)
                << (c.summary.n_tuples ? ": " + joined(type_tuple_names(c.summary, N), ", ") : "")
                << '\n';
  }
  return complete ? kExitOk : kExitInconclusive;
}

}  // namespace cpkit::cli
