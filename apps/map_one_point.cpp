// `cpkit map` of one contact point (docs/maps.md): the checks of the options, then one library
// call (direction_map.hpp; grid_estimate.hpp and grid_map_run.hpp for the grid maps), the
// files, the summary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <initializer_list>
#include <map>
#include <vector>
#include <memory>
#include <thread>
#include <sstream>

#include "cli_common.hpp"
#include "map_args.hpp"
#include "cpkit/rate_problem/maps/grid_estimate.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "map_files.hpp"
#include "map_system.hpp"
#include "map_system_3d.hpp"
#include "platform/mpi_session.hpp"
#include "cli_options.hpp"
#include "cpkit/core/errors.hpp"
#include "data_files.hpp"
#include "run_program.hpp"
#include "machine_resources.hpp"
#include "memory_limit.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/npy_writer.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::cli {

namespace {

namespace fs = std::filesystem;
using namespace cpkit::rate;

/// The model in one line; quantities that vary along a map axis are shown as "(axis)".
std::string model_text(const ContactParameters& p, const ContactState& s,
                       const std::vector<MapParameter>& axes = {}) {
  auto on_axis = [&](std::initializer_list<MapParameter> ps) {
    for (auto a : axes)
      for (auto q : ps)
        if (a == q) return true;
    return false;
  };
  auto v = [&](const char* name, double x, std::initializer_list<MapParameter> ps) {
    return std::string(name) + " = " + (on_axis(ps) ? std::string("(axis)") : fmt(x));
  };
  using P = MapParameter;
  std::string t = "state " + std::string(to_string(s.label)) + ", " +
                  v("a11", p.a11, {P::kA11}) + ", " + v("a12", p.a12, {P::kA12, P::kA12OverA11}) +
                  ", " + v("a22", p.a22, {P::kA22}) + ", " + v("mu", p.mu, {P::kMu}) + ", " +
                  v("C_T", p.C_T, {P::kCT});
  if (s.label == StateLabel::kC || s.label == StateLabel::kD)
    t += ", " + v("P_N", s.P_N, {P::kPN}) + ", " + v("k_a", p.k_a, {P::kKa, P::kKappa}) + ", " +
         v("P_s", p.P_s, {P::kPs}) + ", " +
         v("kappa", p.kappa(s.P_N), {P::kKappa, P::kKa, P::kPN, P::kPs}) +
         (s.label == StateLabel::kD ? ", sgn P_T = " + std::to_string(s.sgn_PT) : "");
  if (p.criterion == Criterion::kSoftening)
    t += ", criterion (35)" +
         std::string(s.label == StateLabel::kD ? " (mu_eff = mu - 2 kappa)" : "");
  return t;
}

void print_direction_text(const DirectionMap& m) {
  std::cout << "sectors (theta in rad from +dF_T towards +dF_N; open arcs):\n";
  for (const auto& s : m.sectors)
    std::cout << "  (" << std::fixed << std::setprecision(4) << s.theta_from << ", " << s.theta_to
              << ")" << std::defaultfloat << "  " << count_text(s.summary.count)
              << (s.summary.types ? ": " + types_text(s.summary.types) : "") << '\n';
  if (!m.critical.empty()) std::cout << "critical directions:\n";
  for (const auto& c : m.critical) {
    std::string cond;
    for (const auto& x : c.conditions) cond += (cond.empty() ? "" : ", ") + x;
    std::cout << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat
              << " (" << cond << ")  " << count_text(c.summary.count)
              << (c.summary.types ? ": " + types_text(c.summary.types) : "") << '\n';
  }
  for (const auto& s : m.sectors)
    if (s.summary.count != 1)
      // An open interval: the sectors are open arcs, their end directions are critical and
      // have their own counts (listed above).
      std::cout << "summary: " << count_text(s.summary.count) << " for theta in (" << std::fixed
                << std::setprecision(2) << s.theta_from << ", " << s.theta_to << ")"
                << std::defaultfloat << '\n';
  for (const auto& c : m.critical)
    if (c.summary.count <= 0)
      std::cout << "summary: " << count_text(c.summary.count) << " at theta = " << std::fixed
                << std::setprecision(4) << c.theta << std::defaultfloat << '\n';
  bool all_unique = true;
  for (const auto& s : m.sectors) all_unique = all_unique && s.summary.count == 1;
  for (const auto& c : m.critical) all_unique = all_unique && c.summary.count == 1;
  if (all_unique) std::cout << "summary: exactly one solution for every direction\n";
}

void report_unreliable(int64_t n, const std::string& what) {
  if (n == 0) return;
  std::cerr << "cpkit map: " << n << ' ' << what
            << " where the enumeration met sign tests too close to call (their count may be "
               "wrong near a type boundary; 'unreliable' in the JSON)\n";
}

void report_disagreements(int64_t n, const std::string& what) {
  if (n == 0) return;
  std::cerr << "cpkit map: " << n << ' ' << what
            << " where the analytic and the enumeration routes disagree (see 'disagree' in the "
               "CSV / 'enumerate' in the JSON)\n";
}

/// Up-front cost of a grid map (the library's timed sample, grid_estimate.hpp).
GridEstimate estimate_grid(const MapSetup& s, const MapOptions& options, bool csv, bool writing) {
  return s.kind == MapKind::kParamDirection
             ? estimate_param_direction_map(s.params, s.state, s.axis, s.theta_n, options, csv,
                                            writing)
             : estimate_param_param_map(s.params, s.state, s.axis, s.axis2, options, csv, writing);
}

/// Refuses (exit 2) a grid map that cannot fit this machine's memory or the output's disk.
void check_grid_fits(const MapSetup& s, const GridEstimate& e, const std::string& out_dir,
                     bool csv, double time_limit, double max_output) {
  // Rank 0 decides for the job (an estimate differs between ranks); if it refuses, mpirun
  // ends the others.
  if (mpi::rank() != 0) return;
  const std::string cells =
      s.kind == MapKind::kParamDirection
          ? std::to_string(s.axis.n) + " x " + std::to_string(s.theta_n) + " cells (--n x --theta-n)"
          : std::to_string(s.axis.n) + " x " + std::to_string(s.axis2.n) + " cells (--n x --n2)";
  const std::string fewer =
      s.kind == MapKind::kParamDirection ? "use a smaller --n or --theta-n" : "use a smaller --n or --n2";
  if (e.seconds > time_limit)
    throw InputError("the map has " + cells + " and would need about " + fmt(e.seconds, 3) +
                     " s of computing on " + std::to_string(e.threads) +
                     " threads (estimated from a timed sample), more than --time-limit " +
                     fmt(time_limit) + ": " + fewer + ", or raise --time-limit");
  double limit = static_cast<double>(kMemoryLimitBytes);
  const double avail = available_memory_bytes();
  if (avail > 0) limit = std::min(limit, 0.8 * avail);
  if (e.memory > limit)
    throw InputError("the map has " + cells + " and would need about " + byte_text(e.memory) +
                     " of memory; " + byte_text(limit) + " is available: " + fewer);
  const std::string drop = csv ? " drop --format csv (the .npy output takes 1-5 bytes per cell)" : "";
  check_output_fits(cells, fewer, e.output, max_output, out_dir, csv ? "," + drop : "",
                    csv ? ", or" + drop : "");
}

/// What the parts of a one-point map run share (run_map_one_point, run_grid_map).
struct OnePointRun {
  OnePointRun(const MapArgs& args, const MapSetup& setup) : a(args), s(setup) {}
  const MapArgs& a;
  const MapSetup& s;
  MapOptions options;
  bool csv = false;
  double max_output = 0;
  std::string prefix, name;
  nlohmann::json j, files = nlohmann::json::object();
  int64_t disagreements = 0;
  Stopwatch clock;
  std::function<void()> print_text;
};

/// A grid map's summary into the run's JSON, its disagreements and unreliable evaluations on
/// stderr.
template <class Map>
void record_grid_result(OnePointRun& p, Map& m, const rate::ChunkRunStats& stats,
                        const char* unreliable_what) {
  m.seconds = p.clock.seconds();
  p.j.update(to_json(m));
  rate::add_run_figures(p.j, stats);
  p.disagreements = m.disagreements;
  report_disagreements(m.disagreements, "cells");
  report_unreliable(m.unreliable, unreliable_what);
}

/// A parameter x direction map through the library's chunked run (grid_map_run.hpp), its cells
/// streamed to the files; false on ranks other than 0.
bool run_param_direction_grid(OnePointRun& p, GridFiles& out, const rate::GridRunOptions& run) {
  const MapArgs& a = p.a;
  const MapSetup& s = p.s;
  const MapOptions& options = p.options;
  const std::string& prefix = p.prefix;
  const std::string& name = p.name;
  nlohmann::json& j = p.j;
  nlohmann::json& files = p.files;
  const bool csv = p.csv, cross = options.method != RateMethod::kEnumerate;
  std::function<void()>& print_text = p.print_text;
  const std::vector<double> theta =
      map_theta_values(s.theta_n, options.theta_from, options.theta_to);
  // Rank 0 alone writes: the files are opened when the first chunk arrives.
  const ParamDirectionSink write_rows = param_direction_files(
      out, s.axis, theta, !prefix.empty() && !csv, !prefix.empty() && csv, cross);
  std::vector<std::pair<int, int>> shown;  // the first disagreeing cells (for stderr)
  auto sink = [&](const ParamDirectionRows& r) {
    write_rows(r);
    const std::size_t cells = static_cast<std::size_t>(r.row_end - r.row_begin) *
                              static_cast<std::size_t>(s.theta_n);
    for (std::size_t k = 0; r.disagree && k < cells && shown.size() < 10; ++k)
      if (r.disagree[k])
        shown.emplace_back(r.row_begin + static_cast<int>(k / s.theta_n),
                           static_cast<int>(k % s.theta_n));
  };
  rate::ParamDirectionRun res;
  if (!run_to_files(out, res, [&] {
        return rate::run_param_direction_map(s.params, s.state, s.axis, s.theta_n, options, run,
                                             sink);
      }))
    return false;  // rank 0 writes and prints
  ParamDirectionMap& m = res.map;
  record_grid_result(p, m, res.stats, "cells");
  for (const auto& [i, k] : shown)
    std::cerr << "  " << to_string(m.axis.param) << " = " << m.axis.value(i)
              << ", theta = " << m.theta[k] << '\n';
  if (!prefix.empty()) {
    write_text_file(prefix + "_critical.csv", [&](std::ostream& o) { write_critical_csv(m, o); });
    files["critical_csv"] = name + "_critical.csv";
  }
  const nlohmann::json summary = j;
  print_text = [summary, &s, &a] {
    const auto& ax = summary["axis"];
    std::cout << "param-direction map, " << model_text(s.params, s.state, {s.axis.param})
              << "\n  "
              << ax["param"].get<std::string>() << " in [" << fmt(ax["from"].get<double>())
              << ", " << fmt(ax["to"].get<double>()) << "] x theta in "
              << (a.given("--theta-from") || a.given("--theta-to")
                      ? "[" + fmt(summary["theta_from"].get<double>()) + ", " +
                            fmt(summary["theta_to"].get<double>()) + "]: "
                      : std::string("[0, 2 pi): "))
              << summary["cells"] << " cells, " << fmt(summary["seconds"].get<double>(), 3)
              << " s, " << summary["threads"] << " threads\n";
    for (const auto& c : summary["classes"]) {
      const int count = c["count"].is_string() ? -1 : c["count"].get<int>();
      std::cout << "  " << count_text(count) << ": " << c["cells"] << " cells, "
                << ax["param"].get<std::string>() << " in [" << fmt(c["x_min"].get<double>())
                << ", " << fmt(c["x_max"].get<double>()) << "], theta in ["
                << fmt(c["theta_min"].get<double>(), 3) << ", "
                << fmt(c["theta_max"].get<double>(), 3) << "]\n";
    }
    for (const auto& c : summary["critical_values"])
      std::cout << "  critical: " << c["name"].get<std::string>() << " at "
                << ax["param"].get<std::string>() << " = " << fmt(c["x"].get<double>(), 10)
                << '\n';
  };
  return true;
}

/// A parameter x parameter map, as run_param_direction_grid.
bool run_param_param_grid(OnePointRun& p, GridFiles& out, const rate::GridRunOptions& run) {
  const MapSetup& s = p.s;
  const MapOptions& options = p.options;
  const std::string& prefix = p.prefix;
  const std::string& name = p.name;
  nlohmann::json& j = p.j;
  nlohmann::json& files = p.files;
  const bool csv = p.csv, cross = options.method != RateMethod::kEnumerate;
  std::function<void()>& print_text = p.print_text;
  if (!prefix.empty() && !csv)
    j["class_codes"] = {{"unique", 0}, {"non-unique", 1}, {"no-solution", 2},
                        {"none-and-several", 3}};
  // Rank 0 alone writes, from the first chunk on.
  const ParamParamSink sink = param_param_files(out, s.axis, s.axis2, !prefix.empty() && !csv,
                                                !prefix.empty() && csv, cross);
  rate::ParamParamRun res;
  if (!run_to_files(out, res, [&] {
        return rate::run_param_param_map(s.params, s.state, s.axis, s.axis2, options, run, sink);
      }))
    return false;
  ParamParamMap& m = res.map;
  record_grid_result(p, m, res.stats, "direction-map evaluations");
  if (!prefix.empty()) {
    write_text_file(prefix + "_critical.csv", [&](std::ostream& o) { write_critical_csv(m, o); });
    files["critical_csv"] = name + "_critical.csv";
  }
  const nlohmann::json summary = j;
  print_text = [summary, &s] {
    const auto& ax = summary["axis"];
    const auto& ay = summary["axis2"];
    std::cout << "param-param map, "
              << model_text(s.params, s.state, {s.axis.param, s.axis2.param}) << "\n  "
              << ax["param"].get<std::string>() << " x " << ay["param"].get<std::string>()
              << ": " << summary["cells"] << " cells, "
              << fmt(summary["seconds"].get<double>(), 3) << " s\n";
    for (const auto& c : summary["classes"])
      std::cout << "  " << c["class"].get<std::string>() << ": " << c["cells"] << " cells, "
                << ax["param"].get<std::string>() << " in [" << fmt(c["x_min"].get<double>())
                << ", " << fmt(c["x_max"].get<double>()) << "], "
                << ay["param"].get<std::string>() << " in [" << fmt(c["y_min"].get<double>())
                << ", " << fmt(c["y_max"].get<double>()) << "]\n";
  };
  return true;
}

/// Grid maps: estimate, refuse what cannot fit, then stream the cells to the files; false on
/// ranks other than 0.
bool run_grid_map(OnePointRun& p) {
  const MapArgs& a = p.a;
  const MapSetup& s = p.s;
  const MapOptions& options = p.options;
  const std::string& prefix = p.prefix;
  nlohmann::json& j = p.j;
  nlohmann::json& files = p.files;
  const bool csv = p.csv;
  // Grid maps: estimate, refuse what cannot fit, then stream the cells to the files.
  GridEstimate est = estimate_grid(s, options, csv, !prefix.empty());
  est.seconds /= mpi::size();  // the ranks share the cells
  check_grid_fits(s, est, prefix.empty() ? "" : fs::path(prefix).parent_path().string(), csv,
                  a.time_limit, p.max_output);
  // Every grid value next (cheaper than a cell; after the refusals, which need no pass over
  // the grid): the first invalid one is named before any cell is computed, whichever rank
  // or chunk would meet it first.
  validate_map_grid(s.params, s.state, s.axis,
                    s.kind == MapKind::kParamParam ? &s.axis2 : nullptr);
  j["estimate"] = {{"seconds", est.seconds}, {"memory_bytes", est.memory},
                   {"output_bytes", est.output}, {"threads", est.threads}};
  if (est.seconds > 1.0 || est.output > 1e9)
    std::cerr << "cpkit map: " << fmt(est.cells, 3) << " cells: about " << fmt(est.seconds, 2)
              << " s of cells on " << est.threads << " threads, " << byte_text(est.memory)
              << " of memory"
              << (prefix.empty() ? std::string()
                                 : ", " + byte_text(est.output) + " of output (" + a.format + ")")
              << '\n';
  j["format"] = a.format;
  nlohmann::json bits = nlohmann::json::object();
  for (unsigned b = 0; b < 8; ++b)
    if (types_to_string(1u << b) != "none") bits[types_to_string(1u << b)] = 1u << b;
  j["type_bits"] = bits;
  GridFiles out(prefix, files);

  // The rows are computed in chunks (maps/grid_map_run.hpp): spread over the ranks of an MPI
  // job, kept in PREFIX.parts for --resume, consumed in row order; the outputs are those of
  // one pass over the map.
  rate::GridRunOptions run;
  run.checkpoint_prefix = prefix;
  run.resume = a.resume;
  run.manifest = {{"cpkit_version", CPKIT_VERSION}, {"kind", j["kind"]}, {"model", j["model"]},
                  {"method", a.method}, {"format", a.format}};
  run.transport = mpi::map_transport();
  run.progress = make_map_progress();
  return s.kind == MapKind::kParamDirection ? run_param_direction_grid(p, out, run)
                                            : run_param_param_grid(p, out, run);
}

}  // namespace

/// `cpkit map` of one contact point (a preset or the model options).
int run_map_one_point(const MapArgs& a) {
  const MapSetup s = build_setup(a);
  const double max_output = parse_byte_size(a.max_output, "--max-output");
  if (s.kind == MapKind::kDirection && mpi::size() > 1)
    throw InputError("a direction map is one exact computation, not a grid of cells: run it "
                     "without mpirun");
  if (a.resume && (s.kind == MapKind::kDirection || a.out.empty()))
    throw InputError("--resume applies to grid maps written with --out PREFIX (the finished "
                     "chunks are kept in PREFIX.parts)");
  MapOptions options;
  const auto method = rate_method_from_string(a.method);
  if (!method) throw InputError("--method must be enumerate or analytic, got '" + a.method + "'");
  options.method = *method;
  if (a.threads > 1024)
    throw InputError("--threads must be at most 1024 (0: all cores), got " +
                     std::to_string(a.threads));
  options.threads = a.threads;
  // Zoom on a thin band of directions (sampled directions of a param-direction map only).
  for (const char* o : {"--theta-from", "--theta-to"})
    if (a.given(o) && s.kind != MapKind::kParamDirection)
      throw InputError(std::string(o) + " applies to --kind param-direction only (a " +
                       std::string(to_string(s.kind)) +
                       " map computes the critical directions exactly, without sampling)");
  if (a.given("--theta-from")) options.theta_from = a.theta_from;
  if (a.given("--theta-to")) options.theta_to = a.theta_to;
  throw_if_invalid_option(options.validate(), {{"theta_from", "--theta-from"},
                                               {"theta_to", "--theta-to"},
                                               {"threads", "--threads"}});
  if (a.plot && a.out.empty()) throw InputError("--plot needs --out PREFIX");
  if (a.format != "npy" && a.format != "csv")
    throw InputError("--format must be npy or csv, got '" + a.format + "'");
  if (a.given("--format") && s.kind == MapKind::kDirection && a.format != "csv")
    throw InputError("--format npy applies to the grid maps (param-direction, param-param); a "
                     "direction map is written as CSV and JSON");
  if (a.given("--format") && a.out.empty())
    throw InputError("--format needs --out PREFIX (without --out only the summary is printed)");
  const bool csv = a.format == "csv";
  if (!(a.time_limit > 0) || !std::isfinite(a.time_limit))
    throw InputError("--time-limit must be a positive number of seconds");
  std::unique_ptr<PrefixLock> lock;  // held until the map is written
  if (!a.out.empty()) lock = claim_map_prefix(a.out, {});

  OnePointRun r(a, s);
  r.options = options;
  r.csv = csv;
  r.max_output = max_output;
  r.prefix = a.out;
  r.name = a.out.empty() ? "" : fs::path(a.out).filename().string();
  nlohmann::json& j = r.j;
  j["kind"] = std::string(to_string(s.kind));
  if (!a.preset.empty()) j["preset"] = a.preset;
  j["cpkit_version"] = CPKIT_VERSION;
  j["method"] = a.method;
  j["run"] = run_echo();
  j["model"] = model_to_json(s.params, s.state);
  nlohmann::json& files = r.files;
  const std::string& prefix = r.prefix;
  const std::string& name = r.name;
  int64_t& disagreements = r.disagreements;
  const Stopwatch& clock = r.clock;
  std::function<void()>& print_text = r.print_text;

  if (s.kind == MapKind::kDirection) {
    const DirectionMap m = compute_direction_map(s.params, s.state, options);
    j.update(to_json(m));
    j["seconds"] = clock.seconds();
    disagreements = m.disagreements;
    report_disagreements(m.disagreements, "directions");
    report_unreliable(m.unreliable, "evaluations");
    if (m.inconsistent_sectors > 0)
      std::cerr << "cpkit map: " << m.inconsistent_sectors
                << " sectors are not uniform (a missed critical direction?)\n";
    if (!prefix.empty()) {
      write_text_file(prefix + ".csv", [&](std::ostream& o) { write_csv(m, o); });
      files["csv"] = name + ".csv";
    }
    print_text = [m, &s] {
      std::cout << "direction map, " << model_text(s.params, s.state) << '\n';
      print_direction_text(m);
    };
  } else if (!run_grid_map(r)) {
    return kExitOk;  // ranks other than 0: rank 0 writes and prints
  }
  bool plot_failed = false;
  if (!prefix.empty()) {
    plot_failed = !write_map_json(prefix, a.plot, j, files);
    // The outputs are complete: the finished chunks kept for --resume are no longer needed.
    if (s.kind != MapKind::kDirection) rate::remove_checkpoint(prefix + ".parts");
  }
  if (a.json) {
    print_json(j);
  } else {
    print_text();
    if (!prefix.empty()) print_written(prefix, files);
  }
  if (disagreements > 0) return kExitDisagreement;
  return plot_failed ? kExitInternal : kExitOk;  // the picture was asked for and is missing
}

}  // namespace cpkit::cli
