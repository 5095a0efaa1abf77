// `cpkit map`: non-existence and non-uniqueness maps of the rate problem (docs/maps.md).
// Thin: the options into the request (maps/map_request.hpp), the --system file read once, one
// library call (requests/map_request_run.hpp) with what only the program has (MPI, stderr, the
// lock of --out PREFIX, the plotting script, free memory and disk), the summary printed.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/requests/map_request_run.hpp"
#include "data_files.hpp"
#include "machine_resources.hpp"
#include "output_guard.hpp"
#include "platform/mpi_session.hpp"
#include "run_program.hpp"

namespace cpkit::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kPlotNoMatplotlib = 5;  // exit code of cpkit_plot.py when matplotlib is missing

/// The variables the options of `cpkit map` are bound to, with the defaults --help shows.
struct MapArgs {
  std::string preset, kind, state, method = rate::kMapMethodDefault, out, param, param2, criterion;
  std::string system, format = rate::kMapFormatDefault, max_output = rate::kMapMaxOutputDefault;
  double time_limit = rate::kMapTimeLimitDefault;
  double a11 = 0, a12 = 0, a22 = 0, mu = 0, C_T = 0, k_a = 0, P_s = 1, P_N = 0;
  int sgnPT = 1;
  double from = 0, to = 0, from2 = 0, to2 = 0, theta_from = 0, theta_to = 0;
  int n = 0, n2 = 0, theta_n = 360, threads = 0;
  bool plot = false, json = false, list_presets = false, resume = false;
  int facets = 0, point = 1;
  std::string others;
  double gamma = 0;
};

/// The request as given: the options not given left empty.
rate::MapRequest map_request(const MapArgs& a, const CLI::App& cmd) {
  rate::MapRequest r;
  r.preset = if_given(cmd, "--preset", a.preset);
  r.kind = if_given(cmd, "--kind", a.kind);
  r.state = if_given(cmd, "--state", a.state);
  r.criterion = if_given(cmd, "--criterion", a.criterion);
  r.method = if_given(cmd, "--method", a.method);
  r.out = if_given(cmd, "--out", a.out);
  r.param = if_given(cmd, "--param", a.param);
  r.param2 = if_given(cmd, "--param2", a.param2);
  r.system = if_given(cmd, "--system", a.system);
  r.format = if_given(cmd, "--format", a.format);
  r.time_limit = if_given(cmd, "--time-limit", a.time_limit);
  r.max_output = if_given(cmd, "--max-output", a.max_output);
  r.a11 = if_given(cmd, "--a11", a.a11);
  r.a12 = if_given(cmd, "--a12", a.a12);
  r.a22 = if_given(cmd, "--a22", a.a22);
  r.mu = if_given(cmd, "--mu", a.mu);
  r.C_T = if_given(cmd, "--C_T", a.C_T);
  r.k_a = if_given(cmd, "--k_a", a.k_a);
  r.P_s = if_given(cmd, "--P_s", a.P_s);
  r.P_N = if_given(cmd, "--P_N", a.P_N);
  r.sgnPT = if_given(cmd, "--sgnPT", a.sgnPT);
  r.from = if_given(cmd, "--from", a.from);
  r.to = if_given(cmd, "--to", a.to);
  r.from2 = if_given(cmd, "--from2", a.from2);
  r.to2 = if_given(cmd, "--to2", a.to2);
  r.theta_from = if_given(cmd, "--theta-from", a.theta_from);
  r.theta_to = if_given(cmd, "--theta-to", a.theta_to);
  r.n = if_given(cmd, "--n", a.n);
  r.n2 = if_given(cmd, "--n2", a.n2);
  r.theta_n = if_given(cmd, "--theta-n", a.theta_n);
  r.threads = if_given(cmd, "--threads", a.threads);
  r.resume = if_given(cmd, "--resume", a.resume);
  r.facets = if_given(cmd, "--facets", a.facets);
  r.point = if_given(cmd, "--point", a.point);
  r.others = if_given(cmd, "--others", a.others);
  r.gamma = if_given(cmd, "--gamma", a.gamma);
  std::tie(r.plot, r.json, r.list_presets) = std::tie(a.plot, a.json, a.list_presets);
  return r;
}

/// Runs the plotting script on PREFIX.json; false when no picture was drawn (the data is
/// written either way). Adds "png" and "svg" to `files` on success.
bool run_map_plot(const std::string& prefix, nlohmann::json& files) {
  std::string searched;
  const std::string script = find_data_file("cpkit_plot.py", &searched);
  if (script.empty()) {
    std::cerr << "cpkit map: plotting script cpkit_plot.py not found (looked in " << searched
              << "); the data is in " << prefix << ".json and the files it lists\n";
    return false;
  }
  const std::vector<std::string> argv = {plot_python(), script, prefix + ".json"};
  const std::string cmd = command_text(argv);
  const ProgramRun pr = run_program(argv, true, kPlotTimeLimit);
  const int code = pr.started ? pr.exit_code : -1;
  if (code == 0) {
    files["png"] = fs::path(prefix + ".png").filename().string();
    files["svg"] = fs::path(prefix + ".svg").filename().string();
    std::cerr << "cpkit map: wrote " << prefix << ".png and " << prefix << ".svg\n";
    return true;
  }
  if (code == kPlotNoMatplotlib) {
    std::cerr << "cpkit map: no picture: matplotlib is not available to " << plot_python()
              << ". The data was written (" << prefix
              << ".json and the files it lists). To get the picture install matplotlib (Debian: "
                 "apt-get install python3-matplotlib) and run:\n  "
              << cmd << '\n';
  } else {
    std::cerr << "cpkit map: the plotting script failed ("
              << (pr.error.empty() ? "exit " + std::to_string(code) : pr.error)
              << "); the data was written. Command:\n  " << cmd << '\n';
  }
  return false;
}

/// Everything a map does with --out PREFIX before it writes: refuses a PREFIX whose files or
/// checkpoint folder PREFIX.parts would overwrite or remove an input, creates PREFIX's folder,
/// and on rank 0 locks the prefix for the run (null on other ranks).
std::shared_ptr<void> claim_map_prefix(
    const std::string& prefix, const std::vector<std::pair<std::string, std::string>>& named) {
  std::vector<NamedPath> inputs;
  for (const auto& [what, path] : named) inputs.push_back({what, path});
  if (fs::path(prefix).filename().empty())
    throw InputError("--out needs a file prefix such as out/map (got '" + prefix + "')");
  refuse_outputs_over_inputs("cpkit map", map_output_files(prefix), inputs);
  for (const auto& i : inputs)
    if (inside_folder(i.path, prefix + ".parts"))
      throw InputError("cpkit map: the input '" + i.path + "' (" + i.what +
                       ") lies in the checkpoint folder '" + prefix +
                       ".parts' of --out " + prefix + ", which a map replaces; move it first");
  const fs::path parent = fs::path(prefix).parent_path();
  std::error_code ec;
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) throw InputError("cannot create the output folder '" + parent.string() + "'");
  if (mpi::rank() != 0) return nullptr;
  return std::make_unique<PrefixLock>(prefix);
}

int run_map(const MapArgs& args, const CLI::App& cmd) {
  rate::MapRequest a = map_request(args, cmd);
  // The system file is read once (a pipe can be read only once); the library dispatches on its dim.
  if (a.system && !a.list_presets) a.file = rate::read_system_file(*a.system);
  rate::MapEnvironment env;
  env.transport = mpi::map_transport();
  env.err = &std::cerr;
  env.progress = true;
  env.version = CPKIT_VERSION;
  env.run_echo = run_echo();
  env.claim_prefix = claim_map_prefix;
  env.plot = run_map_plot;
  env.available_memory = available_memory_bytes;
  env.free_disk = free_disk_bytes;
  const rate::MapOutcome o = rate::run_map_request(a, env);
  if (!o.printing) return o.exit_code;  // ranks other than 0: rank 0 writes and prints
  if (a.json && !o.json.is_null())
    print_json(o.json);
  else
    std::cout << o.text;
  return o.exit_code;
}

}  // namespace

void add_map_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<MapArgs>();
  auto* cmd = app.add_subcommand(
      "map",
      "Non-existence / non-uniqueness maps of the rate problem over load directions and "
      "parameters (docs/maps.md)");
  cmd->add_option("--preset", args->preset,
                  "fig5a, fig5b, state-d, state-d-mu-kappa (--list-presets)");
  cmd->add_flag("--list-presets", args->list_presets, "list the presets and exit");
  cmd->add_option("--kind", args->kind,
                  "direction | param-direction | param-param | sphere (3-D systems)");
  cmd->add_option("--state", args->state, "contact state a|b|c|d (default b)");
  cmd->add_option("--a11", args->a11, "stiffness a11 (or the preset's)")->default_str("");
  cmd->add_option("--a12", args->a12, "stiffness a12 (or the preset's)")->default_str("");
  cmd->add_option("--a22", args->a22, "stiffness a22 (or the preset's)")->default_str("");
  cmd->add_option("--mu", args->mu, "friction coefficient (or the preset's)")->default_str("");
  cmd->add_option("--C_T", args->C_T, "tangential compliance (with --preset: the preset's)");
  cmd->add_option("--k_a", args->k_a, "Archard wear coefficient (with --preset: the preset's)");
  cmd->add_option("--P_s", args->P_s, "hardness (with --preset: the preset's)");
  cmd->add_option("--P_N", args->P_N, "normal force (states c, d; with --preset: the preset's)")
      ->default_str("");
  cmd->add_option("--sgnPT", args->sgnPT, "sign of P_T in state d (+1/-1)");
  cmd->add_option("--criterion", args->criterion,
                  "friction-and-wear criterion: 38 (Coulomb, default) or 35 "
                  "(softening; state d uses mu_eff = mu - 2 kappa)");
  cmd->add_option(
      "--param", args->param,
      "first axis: " + rate::map_parameter_names(rate::kMapOnePoint) + " (systems: see --system)");
  cmd->add_option("--from", args->from, "first axis start")->default_str("");
  cmd->add_option("--to", args->to, "first axis end")->default_str("");
  cmd->add_option("--n", args->n,
                  "first axis values (default 200, with --preset the preset's; "
                  "--system: 100; 3-D --kind sphere: 91 elevations)")
      ->default_str("");
  cmd->add_option("--param2", args->param2, "second axis (param-param)");
  cmd->add_option("--from2", args->from2, "second axis start")->default_str("");
  cmd->add_option("--to2", args->to2, "second axis end")->default_str("");
  cmd->add_option("--n2", args->n2,
                  "second axis values (default 200, with --preset the preset's; "
                  "--system: 100; 3-D --kind sphere: 180 azimuths)")
      ->default_str("");
  cmd->add_option("--theta-n", args->theta_n,
                  "directions of a param-direction map (rejected for the "
                  "other kinds)");
  cmd->add_option("--theta-from", args->theta_from,
                  "param-direction: first direction sampled, rad");
  cmd->add_option("--theta-to", args->theta_to,
                  "param-direction: last direction sampled, rad (default 2 pi; "
                  "at most --theta-from + 2 pi)")
      ->default_str("");
  cmd->add_option("--method", args->method,
                  "enumerate | analytic (also cross-checks with enumerate)");
  cmd->add_option("--threads", args->threads, "worker threads (0: all cores)");
  cmd->add_option("--out", args->out,
                  "write PREFIX.json and the cells: grid maps PREFIX_<array>.npy "
                  "(or PREFIX.csv with --format csv) + PREFIX_critical.csv; "
                  "direction maps PREFIX.csv");
  cmd->add_option(
      "--time-limit", args->time_limit,
      "seconds the map may take (default 600): refused up front when its estimated time "
      "exceeds this (one-point grid maps: twice this); a map that reaches it stops there, "
      "flagged incomplete (exit 5; with --out, --resume continues)");
  cmd->add_option(
         "--max-output", args->max_output,
         "grid maps written with --out: refuse up front when the estimated output exceeds SIZE "
         "bytes (suffix K, M, G, T: powers of 1024; e.g. 500M, 10G)")
      ->type_name("SIZE");
  cmd->add_option("--format", args->format,
                  "cells of a grid map: npy (numpy arrays of codes + axis "
                  "vectors) | csv (one line per cell)");
  cmd->add_option("--system", args->system,
                  "N-point system file (docs/file_formats.md): maps of "
                  "dF = cos(theta) e1 + sin(theta) e2; --kind direction (default), "
                  "param-direction, param-param; --param mu, C_T, k_a, P_s, "
                  "P_N, coupling or mu@i, ... (3-D: mu, C_T, k_a, P_s, "
                  "alpha_X, alpha_Y or mu@i, ...)");
  cmd->add_option("--facets", args->facets,
                  "3-D systems: the faceted route with K facets (3..64; required "
                  "for N > 1 points; default for one point: exact)")
      ->default_str("");
  cmd->add_option("--point", args->point,
                  "3-D systems: the loaded point of --kind sphere/param-direction "
                  "and the point whose types are mapped (1..N)");
  cmd->add_option("--others", args->others,
                  "3-D systems, N > 1: the other points' load rates, zero "
                  "or file (the file's dF; default: file when the file has a "
                  "dF, else zero)");
  cmd->add_option("--gamma", args->gamma,
                  "3-D param-direction: azimuth G of the meridian plane of load "
                  "directions, dF = (cos t cos G, cos t sin G, sin t)");
  cmd->add_flag("--plot", args->plot,
                "also draw PREFIX.png and PREFIX.svg (needs --out, matplotlib)");
  cmd->add_flag("--json", args->json, "print the JSON summary on stdout");
  cmd->add_flag("--resume", args->resume,
                "N-point grid maps: continue an interrupted map from the chunks "
                "finished in PREFIX.parts (same map, same --out)");
  cmd->callback([args, cmd, &ctx] { ctx.exit_code = run_map(*args, *cmd); });
}

}  // namespace cpkit::cli
