// A whole `cpkit map` request (requests/map_request_run.hpp), moved out of the program: the checks
// in the order the program made them (the first message a user sees is unchanged), the
// refusals before any cell is computed, the map, its files, its JSON and text, the exit code.
#include "cpkit/rate_problem/requests/map_request_run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <regex>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/memory_limit.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"
#include "cpkit/rate_problem/maps/map_files.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"
#include "cpkit/rate_problem/report/map_json.hpp"
#include "cpkit/rate_problem/report/map_text.hpp"
#include "../model/options_given.hpp"

namespace cpkit::rate {

namespace fs = std::filesystem;

namespace {

/// A stream that drops what it is given (no err in the environment).
std::ostream& err_of(const MapEnvironment& env) {
  static std::ostream null_stream(nullptr);
  return env.err ? *env.err : null_stream;
}

MapProgress progress_of(const MapEnvironment& env) {
  return env.progress && env.err ? map_progress_printer(*env.err) : MapProgress{};
}

std::shared_ptr<void> claim(const MapEnvironment& env, const std::string& prefix,
                            const std::vector<std::pair<std::string, std::string>>& inputs) {
  if (prefix.empty() || !env.claim_prefix) return nullptr;
  return env.claim_prefix(prefix, inputs);
}

/// The JSON text of the program (indent 1; bytes that are not UTF-8 replaced).
std::string json_text(const nlohmann::json& j) {
  return j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// A library message in options: the whole words `field` become `option`.
std::string in_options(std::string message,
                       std::initializer_list<std::pair<const char*, const char*>> names) {
  for (const auto& [field, option] : names)
    message = std::regex_replace(message, std::regex(std::string("\\b") + field + "\\b"), option);
  return message;
}

void throw_in_options(const std::string& message,
                      std::initializer_list<std::pair<const char*, const char*>> names) {
  if (!message.empty()) throw InputError(in_options(message, names));
}

/// Writes PREFIX.json (files["json"] added) and, with `plot`, draws the picture and writes
/// PREFIX.json again with its files. False when the picture was asked for and not drawn.
bool write_map_json(const std::string& prefix, bool plot, nlohmann::json& j,
                    nlohmann::json& files, const MapEnvironment& env) {
  files["json"] = fs::path(prefix).filename().string() + ".json";
  j["files"] = files;
  write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
  if (!plot) return true;
  const bool drawn = env.plot && env.plot(prefix, files);
  j["files"] = files;
  write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
  return drawn;
}

/// A map kind's chunked run (`call`) with the files discarded if it fails; false on ranks other
/// than 0 (rank 0 writes and prints).
template <class Result, class Call>
bool run_to_files(GridFiles& out, Result& res, const MapEnvironment& env, Call&& call) {
  try {
    res = call();
    if (env.rank() != 0) return false;
    // A run stopped by the time limit has part of the rows: no map file (their finished
    // chunks stay in PREFIX.parts for --resume).
    if (res.stats.complete)
      out.finish();
    else
      out.discard();
  } catch (...) {
    out.discard();
    throw;
  }
  return true;
}

MapOutcome other_rank() {
  MapOutcome o;
  o.printing = false;
  return o;
}

void report_count(std::ostream& err, int64_t n, const std::string& what, const char* why) {
  if (n > 0) err << "cpkit map: " << n << ' ' << what << why;
}

void report_unreliable(std::ostream& err, int64_t n, const std::string& what) {
  report_count(err, n, what,
               " where the enumeration met sign tests too close to call (their count may be "
               "wrong near a type boundary; 'unreliable' in the JSON)\n");
}

void report_disagreements(std::ostream& err, int64_t n, const std::string& what) {
  report_count(err, n, what,
               " where the analytic and the enumeration routes disagree (see 'disagree' in the "
               "CSV / 'enumerate' in the JSON)\n");
}

/// A grid map stopped by --time-limit after `done` of its `rows` rows: flagged in its JSON
/// (complete, time_limit_reached, rows_done), said on stderr; returns the head line of its text.
std::string report_time_limit(nlohmann::json& j, double limit, int done, int rows,
                              const std::string& prefix, const MapEnvironment& env) {
  j["complete"] = false;
  j["time_limit_reached"] = true;
  j["rows_done"] = done;
  const std::string what = "time limit reached (--time-limit " + num_text(limit, 4) +
                           " s) after " + std::to_string(done) + " of " + std::to_string(rows) +
                           " rows";
  err_of(env) << "cpkit map: " << what << ": the map is incomplete ('complete': false)"
              << (prefix.empty() ? std::string(". Use a smaller --n")
                                 : "; no map file was written, the finished rows are kept in " +
                                       prefix + ".parts: run the same command with --resume to "
                                       "continue")
              << " (or raise --time-limit)\n";
  return "INCOMPLETE: " + what + "; the summary below covers those rows only\n";
}

// ---- one point -------------------------------------------------------------------------------

/// What the parts of a one-point map run share.
struct OnePointRun {
  OnePointRun(const MapRequest& request, const MapSetup& setup, const MapEnvironment& e)
      : a(request), s(setup), env(e) {}
  const MapRequest& a;
  const MapSetup& s;
  const MapEnvironment& env;
  MapOptions options;
  bool csv = false;
  double max_output = 0;
  std::string prefix, name;
  nlohmann::json j, files = nlohmann::json::object();
  int64_t disagreements = 0;
  Stopwatch clock;
  std::string text;
  ChunkRunStats stats;  ///< of a grid map's run (stopped by the time limit: complete = false)
  // The request's values, defaults filled in
  std::string method = a.method.value_or(kMapMethodDefault);
  std::string format = a.format.value_or(kMapFormatDefault);
  double time_limit = a.time_limit.value_or(kMapTimeLimitDefault);
};

/// A grid map's summary into the run's JSON, its disagreements and unreliable cells on stderr.
template <class Map>
void record_grid_result(OnePointRun& p, Map& m, const ChunkRunStats& stats,
                        const char* unreliable_what) {
  m.seconds = p.clock.seconds();
  p.j.update(to_json(m));
  add_run_figures(p.j, stats);
  p.stats = stats;
  p.disagreements = m.disagreements;
  report_disagreements(err_of(p.env), m.disagreements, "cells");
  report_unreliable(err_of(p.env), m.unreliable, unreliable_what);
}

template <class Map>
void write_critical(OnePointRun& p, const Map& m) {
  if (p.prefix.empty() || !p.stats.complete) return;
  write_text_file(p.prefix + "_critical.csv", [&](std::ostream& o) { write_critical_csv(m, o); });
  p.files["critical_csv"] = p.name + "_critical.csv";
}

/// A parameter x direction map in chunks (grid_map_run.hpp), its cells streamed to the files.
bool run_param_direction_grid(OnePointRun& p, GridFiles& out, const GridRunOptions& run) {
  const MapSetup& s = p.s;
  const bool writing = !p.prefix.empty(), cross = p.options.method != RateMethod::kEnumerate;
  const std::vector<double> theta =
      map_theta_values(s.theta_n, p.options.theta_from, p.options.theta_to);
  // Rank 0 alone writes: the files are opened when the first chunk arrives.
  const ParamDirectionSink write_rows =
      param_direction_files(out, s.axis, theta, writing && !p.csv, writing && p.csv, cross);
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
  ParamDirectionRun res;
  if (!run_to_files(out, res, p.env, [&] {
        return run_param_direction_map(s.params, s.state, s.axis, s.theta_n, p.options, run, sink);
      }))
    return false;
  ParamDirectionMap& m = res.map;
  record_grid_result(p, m, res.stats, "cells");
  for (const auto& [i, k] : shown)
    err_of(p.env) << "  " << m.axis.param.name() << " = " << m.axis.value(i)
                  << ", theta = " << m.theta[k] << '\n';
  write_critical(p, m);
  p.text = param_direction_map_text(p.j, s, p.a.theta_from || p.a.theta_to);
  return true;
}

/// A parameter x parameter map, as run_param_direction_grid.
bool run_param_param_grid(OnePointRun& p, GridFiles& out, const GridRunOptions& run) {
  const MapSetup& s = p.s;
  const bool writing = !p.prefix.empty(), cross = p.options.method != RateMethod::kEnumerate;
  if (writing && !p.csv)
    p.j["class_codes"] = {{"unique", 0}, {"non-unique", 1}, {"no-solution", 2},
                          {"none-and-several", 3}};
  // Rank 0 alone writes, from the first chunk on.
  const ParamParamSink sink =
      param_param_files(out, s.axis, s.axis2, writing && !p.csv, writing && p.csv, cross);
  ParamParamRun res;
  if (!run_to_files(out, res, p.env, [&] {
        return run_param_param_map(s.params, s.state, s.axis, s.axis2, p.options, run, sink);
      }))
    return false;
  record_grid_result(p, res.map, res.stats, "direction-map evaluations");
  write_critical(p, res.map);
  p.text = param_param_map_text(p.j, s);
  return true;
}

/// Grid maps: estimate, refuse what cannot fit, then stream the cells to the files; false on
/// ranks other than 0.
bool run_grid_map(OnePointRun& p) {
  const MapRequest& a = p.a;
  const MapSetup& s = p.s;
  const std::string& prefix = p.prefix;
  nlohmann::json& j = p.j;
  GridEstimate est = estimate_grid(s, p.options, p.csv, !prefix.empty());
  est.seconds /= p.env.size();  // the ranks share the cells
  check_grid_fits(s, est, prefix.empty() ? "" : fs::path(prefix).parent_path().string(), p.csv,
                  p.time_limit, p.max_output, p.env);
  // Every grid value next (cheaper than a cell; after the refusals, which need no pass over
  // the grid): the first invalid one is named before any cell is computed, whichever rank
  // or chunk would meet it first.
  validate_map_grid(s.params, s.state, s.axis,
                    s.kind == MapKind::kParamParam ? &s.axis2 : nullptr);
  j["estimate"] = {{"seconds", est.seconds}, {"memory_bytes", est.memory},
                   {"output_bytes", est.output}, {"threads", est.threads},
                   {"sample_seconds", est.sample_seconds}};
  if (est.seconds > 1.0 || est.output > 1e9)
    err_of(p.env) << "cpkit map: " << num_text(est.cells, 3) << " cells: about "
                  << num_text(est.seconds, 2) << " s of cells on " << est.threads
                  << " threads, " << byte_text(est.memory) << " of memory"
                  << (prefix.empty() ? std::string()
                                     : ", " + byte_text(est.output) + " of output (" + p.format +
                                           ")")
                  << '\n';
  j["format"] = p.format;
  nlohmann::json bits = nlohmann::json::object();
  for (unsigned b = 0; b < 8; ++b)
    if (types_to_string(1u << b) != "none") bits[types_to_string(1u << b)] = 1u << b;
  j["type_bits"] = bits;
  GridFiles out(prefix, p.files);

  // The rows are computed in chunks (maps/grid_map_run.hpp): spread over the ranks of a job,
  // kept in PREFIX.parts for --resume, consumed in row order; the outputs are those of one
  // pass over the map.
  GridRunOptions run;
  run.checkpoint_prefix = prefix;
  run.resume = a.resume.value_or(false);
  run.manifest = {{"cpkit_version", p.env.version}, {"kind", j["kind"]}, {"model", j["model"]},
                  {"method", p.method}, {"format", p.format}};
  run.transport = p.env.transport;
  run.progress = progress_of(p.env);
  // One deadline for the whole command (the sample of the estimate included): no chunk is
  // begun after it; the chunks running then are finished (a chunk is at most 1/64 of the map's
  // rows, or 2^20 cells).
  const Stopwatch& clock = p.clock;
  const double limit = p.time_limit;
  run.stop = [&clock, limit] { return clock.seconds() >= limit; };
  const bool ok = s.kind == MapKind::kParamDirection ? run_param_direction_grid(p, out, run)
                                                     : run_param_param_grid(p, out, run);
  if (ok && !p.stats.complete)
    p.text = report_time_limit(p.j, p.time_limit, p.stats.rows_done, s.axis.n, p.prefix, p.env) +
             p.text;
  return ok;
}

/// The options of a one-point map beyond its model and axes (the program's order of checks).
MapOptions one_point_options(const MapRequest& a, const MapSetup& s, const MapEnvironment& env) {
  const bool no_out = a.out.value_or("").empty();
  if (s.kind == MapKind::kDirection && env.size() > 1)
    throw InputError("a direction map is one exact computation, not a grid of cells: run it "
                     "without mpirun");
  if (a.resume.value_or(false) && (s.kind == MapKind::kDirection || no_out))
    throw InputError("--resume applies to grid maps written with --out PREFIX (the finished "
                     "chunks are kept in PREFIX.parts)");
  MapOptions options;
  const std::string method_name = a.method.value_or(kMapMethodDefault);
  const auto method = rate_method_from_string(method_name);
  if (!method)
    throw InputError("--method must be enumerate or analytic, got '" + method_name + "'");
  options.method = *method;
  const int threads = a.threads.value_or(0);
  if (threads > 1024)
    throw InputError("--threads must be at most 1024 (0: all cores), got " +
                     std::to_string(threads));
  options.threads = threads;
  // Zoom on a thin band of directions (sampled directions of a param-direction map only).
  if (s.kind != MapKind::kParamDirection)
    detail::refuse_given({detail::option("--theta-from", a.theta_from),
                          detail::option("--theta-to", a.theta_to)},
                         " applies to --kind param-direction only (a " +
                             std::string(to_string(s.kind)) +
                             " map computes the critical directions exactly, without sampling)");
  options.theta_from = a.theta_from.value_or(options.theta_from);
  options.theta_to = a.theta_to.value_or(options.theta_to);
  throw_in_options(options.validate(), {{"theta_from", "--theta-from"},
                                        {"theta_to", "--theta-to"},
                                        {"threads", "--threads"}});
  if (a.plot && no_out) throw InputError("--plot needs --out PREFIX");
  const std::string format = a.format.value_or(kMapFormatDefault);
  if (format != "npy" && format != "csv")
    throw InputError("--format must be npy or csv, got '" + format + "'");
  if (a.format && s.kind == MapKind::kDirection && format != "csv")
    throw InputError("--format npy applies to the grid maps (param-direction, param-param); a "
                     "direction map is written as CSV and JSON");
  if (a.format && no_out)
    throw InputError("--format needs --out PREFIX (without --out only the summary is printed)");
  const double time_limit = a.time_limit.value_or(kMapTimeLimitDefault);
  if (!(time_limit > 0) || !std::isfinite(time_limit))
    throw InputError("--time-limit must be a positive number of seconds");
  return options;
}

/// The exact direction map of one point, its CSV.
void run_direction(OnePointRun& r) {
  const DirectionMap m = compute_direction_map(r.s.params, r.s.state, r.options);
  std::ostream& err = err_of(r.env);
  r.j.update(to_json(m));
  r.j["seconds"] = r.clock.seconds();
  r.disagreements = m.disagreements;
  report_disagreements(err, m.disagreements, "directions");
  report_unreliable(err, m.unreliable, "evaluations");
  if (m.inconsistent_sectors > 0)
    err << "cpkit map: " << m.inconsistent_sectors
        << " sectors are not uniform (a missed critical direction?)\n";
  if (!r.prefix.empty()) {
    write_text_file(r.prefix + ".csv", [&](std::ostream& o) { write_csv(m, o); });
    r.files["csv"] = r.name + ".csv";
  }
  r.text = direction_map_text(m, r.s);
}

// ---- N points --------------------------------------------------------------------------------

/// Refuses up front (exit 2) a map whose estimated cell time exceeds --time-limit or whose
/// files would not fit the disk (`npy_bytes_per_cell` as written: .npy codes).
nlohmann::json check_estimate(const SystemMapEstimate& e, const SystemMapRequest& r,
                              const SystemGridPlan& p, double npy_bytes_per_cell,
                              const MapEnvironment& env) {
  // Rank 0 decides for the job (an estimate differs between ranks); if it refuses, mpirun
  // ends the others.
  if (env.rank() != 0) return nlohmann::json::object();
  if (!r.out.empty())
    // A CSV line holds two numbers at 17 digits, the count and the pattern id.
    // The finished chunks are kept in PREFIX.parts until the outputs are complete: twice.
    check_output_fits(p.cells_text, p.fewer,
                      2 * e.cells * (r.format == "csv" ? 45.0 : npy_bytes_per_cell),
                      r.max_output, fs::path(r.out).parent_path().string(),
                      r.format == "csv" ? ", drop --format csv" : "",
                      r.format == "csv" ? ", or drop --format csv" : "", env, true);
  const double seconds = e.seconds / env.size();  // the ranks share the cells
  const std::string procs = std::to_string(env.size());
  if (seconds > r.time_limit)
    throw InputError("the map has " + p.cells_text + " and would need about " +
                     num_text(seconds, 3) + " s of computing on " +
                     std::to_string(e.threads) + " threads x " + procs +
                     " processes (estimated from " + std::to_string(e.sampled) +
                     " timed cells), more than --time-limit " + num_text(r.time_limit, 3) +
                     ": " + p.fewer + ", or raise --time-limit");
  if (seconds > 1.0)
    err_of(env) << "cpkit map: " << p.cells_text << ": about " << num_text(seconds, 3)
                << " s on " << e.threads << " threads x " << procs << " processes (estimate)\n";
  return {{"seconds", seconds}, {"threads", e.threads}, {"sampled_cells", e.sampled}};
}

/// How an N-point grid map runs: checkpointed under PREFIX.parts when writing; the manifest
/// names the version, kind, input echo (axes included) and the system's data.
GridRunOptions grid_run_options(const SystemMapRequest& r, const SystemGridPlan& p,
                                const MapEnvironment& env, const Stopwatch& clock) {
  GridRunOptions o;
  o.checkpoint_prefix = r.out;
  o.resume = r.resume;
  o.manifest = {{"cpkit_version", env.version}, {"kind", r.kind}, {"input", p.input},
                {"system_data_fnv1a", system_data_fingerprint(p.sys)}, {"format", r.format}};
  o.describe_grid = false;  // "input" holds the axes
  o.transport = env.transport;
  o.progress = progress_of(env);
  // One deadline for the whole command: no chunk is begun after it.
  const double limit = r.time_limit;
  o.stop = [&clock, limit] { return clock.seconds() >= limit; };
  return o;
}

/// The result of an N-point grid map: the library's document and what the program adds, the
/// files, the text, the exit code.
MapOutcome finish_system_grid(const SystemMapRequest& r, nlohmann::json j, nlohmann::json& files,
                              const ChunkRunStats& stats, const nlohmann::json& estimate,
                              const Stopwatch& clock, const std::string& incomplete,
                              const std::string& text, const MapEnvironment& env, int rows) {
  j["cpkit_version"] = env.version;
  j["threads"] = map_worker_threads(r.threads, std::numeric_limits<int>::max());
  j["estimate"] = estimate;
  add_run_figures(j, stats);
  if (!r.out.empty()) j["format"] = r.format;
  // Stopped by --time-limit: no map file, the chunks kept for --resume.
  const std::string head =
      stats.complete ? std::string()
                     : report_time_limit(j, r.time_limit, stats.rows_done, rows, r.out, env);
  const bool complete = j["complete"].get<bool>();
  if (!complete && stats.complete) err_of(env) << incomplete;
  j["seconds"] = clock.seconds();
  bool plot_failed = false;
  const bool write = !r.out.empty() && stats.complete;
  if (write) {
    j["run"] = env.run_echo;
    plot_failed = !write_map_json(r.out, r.plot, j, files, env);
  }
  MapOutcome o;
  o.text = head + text + (write ? map_files_text(r.out, files) : "");
  o.json = std::move(j);
  o.exit_code = !complete ? kExitInconclusive : plot_failed ? kExitInternal : kExitOk;
  if (write) remove_checkpoint(r.out + ".parts");
  return o;
}

/// `--kind param-direction` (count and point-type pattern per (parameter, direction) cell) and
/// `--kind param-param` (per cell, the class of its exact direction map and the union pattern).
MapOutcome run_system_grid(const SystemMapRequest& r, const MapEnvironment& env) {
  const Stopwatch clock;
  const SystemGridPlan p = make_system_grid_plan(r);
  const int N = p.sys.n_points();
  const bool pd = r.kind == "param-direction";
  const bool npy = !r.out.empty() && r.format == "npy", csv = !r.out.empty() && r.format == "csv";
  nlohmann::json files = nlohmann::json::object();
  GridFiles out(r.out, files);
  const nlohmann::json estimate = check_estimate(
      pd ? estimate_system_param_direction_map(p.sys, p.axis, r.theta_n, p.options)
         : estimate_system_param_param_map(p.sys, p.axis, p.axis2, p.options),
      r, p, pd ? 3 : 5, env);
  if (pd) {
    const std::vector<double> theta = map_theta_values(r.theta_n, r.theta_from, r.theta_to);
    SystemParamDirectionRun res;
    if (!run_to_files(out, res, env, [&] {
          return run_system_param_direction_map(
              p.sys, p.axis, r.theta_n, p.options, grid_run_options(r, p, env, clock),
              system_param_direction_files(out, p.axis, theta, npy, csv));
        }))
      return other_rank();
    return finish_system_grid(r, system_param_direction_json(res.map, N, p.input), files,
                              res.stats, estimate, clock,
                              "cpkit map: " + std::to_string(res.map.unreliable) +
                                  " cells too close to call: the map is not proved complete\n",
                              system_param_direction_map_text(res.map, N, r, p.axis), env,
                              p.axis.n);
  }
  SystemParamParamRun res;
  if (!run_to_files(out, res, env, [&] {
        return run_system_param_param_map(p.sys, p.axis, p.axis2, p.options,
                                          grid_run_options(r, p, env, clock),
                                          system_param_param_files(out, p.axis, p.axis2, npy, csv));
      }))
    return other_rank();
  return finish_system_grid(
      r, system_param_param_json(res.map, N, p.input), files, res.stats, estimate, clock,
      "cpkit map: " + std::to_string(res.map.unreliable) + " evaluations too close to call and " +
          std::to_string(res.map.inconsistent_sectors) +
          " sectors not uniform: the map is not proved complete\n",
      system_param_param_map_text(res.map, N, r, p.axis, p.axis2), env, p.axis.n);
}

/// The exact direction map of N points (sectors and critical directions), its CSV.
MapOutcome run_system_direction(const SystemMapRequest& r, const MapEnvironment& env) {
  const ContactSystem sys = parse_contact_system(r.file);
  check_system_map_lcp_size(sys, "the direction map");
  const int N = sys.n_points();
  MapOptions options;
  options.threads = r.threads;
  const SystemDirectionMap m = compute_system_direction_map(sys, options);
  MapOutcome o;
  o.json = system_direction_map_json(m, sys, r.path);
  nlohmann::json& j = o.json;
  j["cpkit_version"] = env.version;
  const bool complete = j["complete"].get<bool>();
  if (!complete)
    err_of(env) << "cpkit map: " << m.unreliable << " evaluations too close to call and "
                << m.inconsistent_sectors
                << " sectors not uniform: the map is not proved complete\n";
  if (!r.out.empty()) {
    std::ofstream f(r.out + ".csv");
    if (!f) throw InputError("--out: cannot write '" + r.out + ".csv'");
    write_system_direction_csv(m, N, f);
    j["files"] = {{"csv", r.out + ".csv"}};
    std::ofstream fj(r.out + ".json");
    if (!fj) throw InputError("--out: cannot write '" + r.out + ".json'");
    nlohmann::json jj = j;
    jj["run"] = env.run_echo;
    fj << json_text(jj) << "\n";
  }
  o.text = system_direction_map_text(m, N, r.path);
  o.exit_code = complete ? kExitOk : kExitInconclusive;
  return o;
}

// ---- 3-D systems -----------------------------------------------------------------------------

/// Writes the cells of a 3-D map to PREFIX_<array>.npy (discarded if writing fails).
void write_map_3d_files(const std::string& prefix, const Map3d& m, nlohmann::json& files) {
  GridFiles out(prefix, files);
  try {
    out.add_npy("count", "|i1", m.rows, m.cols);
    out.add_npy("types", "|u1", m.rows, m.cols);
    out.add_npy("complete", "|u1", m.rows, m.cols);
    out.write_vector("x", m.x);
    out.write_vector("y", m.y);
    out.append({m.count.data(), m.types.data(), m.complete.data()}, m.cells());
    out.finish();
  } catch (...) {
    out.discard();
    throw;
  }
}

}  // namespace

MapSetup checked_map_setup(const MapRequest& a, const MapEnvironment& env) {
  MapSetup s = make_map_setup(a, [&env](const std::string& note) {
    if (env.rank() == 0) err_of(env) << "cpkit map: note: " << note << '\n';
  });
  // MapAxis::validate() names the fields n, from, to: here they are options.
  if (s.kind != MapKind::kDirection)
    throw_in_options(s.axis.validate(), {{"n", "--n"}, {"from", "--from"}, {"to", "--to"}});
  if (s.kind == MapKind::kParamParam)
    throw_in_options(s.axis2.validate(), {{"n", "--n2"}, {"from", "--from2"}, {"to", "--to2"}});
  if (s.kind == MapKind::kParamDirection && (s.theta_n < 1 || s.theta_n > 1000000))
    throw InputError("--theta-n must be in [1, 1000000]");
  return s;
}

GridEstimate estimate_grid(const MapSetup& s, const MapOptions& options, bool csv, bool writing) {
  return s.kind == MapKind::kParamDirection
             ? estimate_param_direction_map(s.params, s.state, s.axis, s.theta_n, options, csv,
                                            writing)
             : estimate_param_param_map(s.params, s.state, s.axis, s.axis2, options, csv, writing);
}

void check_output_fits(const std::string& cells, const std::string& fewer, double output,
                       double max_output, const std::string& dir, const std::string& limit_hint,
                       const std::string& disk_hint, const MapEnvironment& env, bool gb) {
  const std::string head = "the map has " + cells + " and its output would take about ";
  if (output > max_output)
    throw InputError(head + byte_text(output) + " (estimated), more than --max-output " +
                     byte_text(max_output) + ": " + fewer + limit_hint + ", or raise --max-output");
  if (!(output > 0) || !env.free_disk) return;
  const double free = env.free_disk(dir);
  if (free < 0 || !(output > 0.95 * free)) return;
  std::ostringstream gbs;  // the N-point maps' wording: "1.23 GB but only 0.5 GB"
  gbs << std::setprecision(3) << output / 1e9 << " GB but only " << free / 1e9 << " GB";
  throw InputError(head + (gb ? gbs.str() : byte_text(output) + " but only " + byte_text(free)) +
                   " is free in '" + (dir.empty() ? "." : dir) + "': " + fewer + disk_hint);
}

/// A one-point grid map is refused up front when its estimate exceeds the time limit by more
/// than this factor (the estimate's accuracy); below it, the limit stops it part-way.
constexpr double kTimeLimitFactor = 2;

void check_grid_fits(const MapSetup& s, const GridEstimate& e, const std::string& out_dir,
                     bool csv, double time_limit, double max_output, const MapEnvironment& env) {
  // Rank 0 decides for the job (an estimate differs between ranks); if it refuses, mpirun
  // ends the others.
  if (env.rank() != 0) return;
  const bool pd = s.kind == MapKind::kParamDirection;
  const std::string cells =
      std::to_string(s.axis.n) + " x " + std::to_string(pd ? s.theta_n : s.axis2.n) +
      (pd ? " cells (--n x --theta-n)" : " cells (--n x --n2)");
  const std::string fewer = pd ? "use a smaller --n or --theta-n" : "use a smaller --n or --n2";
  // The estimate is within a factor 2 of the run (a wall-clock sample on the map's threads):
  // beyond twice the limit the map cannot finish; up to it, it runs and stops at the limit
  // with the rows done, flagged incomplete (and resumable with --out).
  if (e.seconds > kTimeLimitFactor * time_limit)
    throw InputError("the map has " + cells + " and would need about " +
                     num_text(e.seconds, 3) + " s of computing on " +
                     std::to_string(e.threads) +
                     " threads (estimated from a timed sample), far more than --time-limit " +
                     num_text(time_limit, 4) + ": " + fewer + ", or raise --time-limit");
  if (e.seconds > time_limit)
    err_of(env) << "cpkit map: the map would need about " << num_text(e.seconds, 3)
                << " s (estimate), more than --time-limit " << num_text(time_limit, 4)
                << ": it stops at the limit with the rows done so far, flagged incomplete\n";
  double limit = static_cast<double>(kMemoryLimitBytes);
  const double avail = env.available_memory ? env.available_memory() : -1;
  if (avail > 0) limit = std::min(limit, 0.8 * avail);
  if (e.memory > limit)
    throw InputError("the map has " + cells + " and would need about " + byte_text(e.memory) +
                     " of memory; " + byte_text(limit) + " is available: " + fewer);
  const std::string drop = csv ? " drop --format csv (the .npy output takes 1-5 bytes per cell)" : "";
  check_output_fits(cells, fewer, e.output, max_output, out_dir, csv ? "," + drop : "",
                    csv ? ", or" + drop : "", env);
}

MapOutcome run_one_point_map(const MapRequest& a, const MapEnvironment& env) {
  const MapSetup s = checked_map_setup(a, env);
  const double max_output =
      parse_byte_size(a.max_output.value_or(kMapMaxOutputDefault), "--max-output");
  const MapOptions options = one_point_options(a, s, env);
  const std::string out = a.out.value_or("");
  const std::shared_ptr<void> lock = claim(env, out, {});  // held until the map is written

  OnePointRun r(a, s, env);
  r.options = options;
  r.csv = r.format == "csv";
  r.max_output = max_output;
  r.prefix = out;
  r.name = out.empty() ? "" : fs::path(out).filename().string();
  nlohmann::json& j = r.j;
  j["kind"] = std::string(to_string(s.kind));
  if (!a.preset.value_or("").empty()) j["preset"] = *a.preset;
  j["cpkit_version"] = env.version;
  j["method"] = r.method;
  j["run"] = env.run_echo;
  j["model"] = model_to_json(s.params, s.state);
  if (s.kind == MapKind::kDirection)
    run_direction(r);
  else if (!run_grid_map(r))
    return other_rank();  // rank 0 writes and prints
  bool plot_failed = false;
  // A grid map stopped by the time limit writes no map file (its chunks stay for --resume).
  const bool complete = s.kind == MapKind::kDirection || r.stats.complete;
  if (!r.prefix.empty() && complete) {
    plot_failed = !write_map_json(r.prefix, a.plot, j, r.files, env);
    // The outputs are complete: the finished chunks kept for --resume are no longer needed.
    if (s.kind != MapKind::kDirection) remove_checkpoint(r.prefix + ".parts");
  }
  MapOutcome o;
  o.text = r.text + (r.prefix.empty() || !complete ? "" : map_files_text(r.prefix, r.files));
  o.json = std::move(j);
  // The picture was asked for and is missing: exit 4. Stopped by the time limit: 5.
  o.exit_code = r.disagreements > 0 ? kExitDisagreement
                : !complete         ? kExitInconclusive
                : plot_failed       ? kExitInternal
                                    : kExitOk;
  return o;
}

MapOutcome run_system_map(const SystemMapRequest& r, const MapEnvironment& env) {
  const std::shared_ptr<void> lock = claim(env, r.out, {{"--system", r.path}});
  if (r.kind == "param-direction" || r.kind == "param-param") return run_system_grid(r, env);
  return run_system_direction(r, env);
}

MapOutcome run_map_3d(const MapRequest& r, const MapEnvironment& env) {
  const double max_output =
      parse_byte_size(r.max_output.value_or(kMapMaxOutputDefault), "--max-output");
  check_map_3d_request(r, env.size());
  const std::string out = r.out.value_or("");
  const double time_limit = r.time_limit.value_or(kMapTimeLimitDefault);
  const std::shared_ptr<void> lock = claim(env, out, {{"--system", r.system.value_or("")}});
  const Stopwatch clock;
  Map3dPlan p = make_map_3d_plan(r);
  Map3dOptions& opt = p.options;
  std::ostream& err = err_of(env);
  if (p.cells > kMaxMap3dCells)
    throw InputError("the map has " + p.cells_text + ", more than the " +
                     std::to_string(kMaxMap3dCells) + " cells a 3-D map holds: " + p.fewer);
  if (!out.empty())  // before any cell is computed
    check_output_fits(p.cells_text, p.fewer, map_3d_output_bytes(p), max_output,
                      fs::path(out).parent_path().string(), "", "", env);
  // Up-front cost from a timed sample (which also reports invalid input before the long run).
  const int threads = map_worker_threads(r.threads.value_or(0), p.rows());
  int64_t sampled = 0;
  const double seconds = estimate_map_3d_seconds(p, threads, sampled, clock, time_limit);
  if (seconds > time_limit)
    throw InputError("the map has " + p.cells_text + " and would need about " +
                     num_text(seconds, 3) + " s on " + std::to_string(threads) +
                     " threads (estimated from " + std::to_string(sampled) +
                     " timed cells), more than --time-limit " + num_text(time_limit, 4) +
                     ": " + p.fewer + (opt.facets ? ", fewer --facets" : "") +
                     ", or raise --time-limit");
  if (seconds > 1.0)
    err << "cpkit map: " << p.cells_text << ": about " << num_text(seconds, 3) << " s on "
        << threads << " threads (estimate)\n";
  // One deadline for the whole command (issue 24, item 11): the estimate was within it; the
  // cells get what is left, and the ones it does not cover are flagged, never dropped.
  opt.time_limit_s = std::max(1e-3, time_limit - clock.seconds());
  const MapProgress progress = progress_of(env);
  const Map3d m = compute_map_3d(p, opt, [progress](double f) {
    if (progress) progress("cells", f);
  });

  MapOutcome o;
  nlohmann::json& j = o.json;
  j = map_3d_json(m, p.kind, p.input, p.xname, p.yname);
  j["cpkit_version"] = env.version;
  const bool complete = m.incomplete_cells == 0;
  j["estimate"] = {{"seconds", seconds >= 0 ? nlohmann::json(seconds) : nlohmann::json()},
                   {"sampled_cells", sampled}};
  j["seconds"] = clock.seconds();
  bool plot_failed = false;
  nlohmann::json files = nlohmann::json::object();
  if (!out.empty()) {
    write_map_3d_files(out, m, files);
    j["run"] = env.run_echo;
    plot_failed = !write_map_json(out, r.plot, j, files, env);
  }
  if (m.timed_out_cells > 0)
    err << "cpkit map: time limit reached (--time-limit " << num_text(time_limit, 4)
        << " s): " << m.timed_out_cells << " cells cut short (their count is what was found) or "
        << "not computed (count 0), flagged 0 in 'complete'\n";
  if (!complete)
    err << "cpkit map: " << m.incomplete_cells
        << " cells not proved complete (a merging pair of slip directions, an "
           "undecided enumeration, or the time limit): flagged 0 in 'complete'\n";
  o.text = map_3d_text(r, p, m) + (out.empty() ? "" : map_files_text(out, files));
  o.exit_code = !complete ? kExitInconclusive : plot_failed ? kExitInternal : kExitOk;
  return o;
}

MapOutcome run_map_request(const MapRequest& a, const MapEnvironment& env) {
  MapOutcome o;
  if (a.list_presets) {
    o.text = map_presets_text();
    return o;
  }
  // The system file was read once (a pipe can be read only once): dispatched on its dim.
  const bool system = a.system.has_value();
  if (system && a.file.dim == 3) return run_map_3d(a, env);
  detail::refuse_given({detail::option("--facets", a.facets), detail::option("--point", a.point),
                        detail::option("--others", a.others), detail::option("--gamma", a.gamma)},
                       " applies to maps of 3-D systems (--system FILE with \"dim\": 3)");
  if (system) return run_system_map(system_map_request(a, a.file, env.size()), env);
  return run_one_point_map(a, env);
}

}  // namespace cpkit::rate
