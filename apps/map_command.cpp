// `cpkit map`: non-existence and non-uniqueness maps of the rate problem (docs/maps.md).
// Thin: parse, call the library (cpkit/rate_problem/{direction_map,grid_map,map_output}.hpp),
// write CSV/JSON, run the plotting script.
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
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
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

std::string fmt(double x, int digits) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

std::string types_text(unsigned mask) {
  std::string s = rate::types_to_string(mask);
  for (auto& c : s)
    if (c == '|') c = ',';
  std::string out;
  for (char c : s) {
    out += c;
    if (c == ',') out += ' ';
  }
  return out;
}

std::string count_text(int count) {
  if (count < 0) return "a continuum of solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}



namespace {

namespace fs = std::filesystem;
using namespace cpkit::rate;


}  // namespace

MapSetup build_setup(const MapArgs& a) {
  MapSetup s = rate::make_map_setup(a, [](const std::string& note) {
    if (mpi::rank() == 0) std::cerr << "cpkit map: note: " << note << '\n';
  });
  // MapAxis::validate() names the fields n, from, to: here they are options.
  if (s.kind != MapKind::kDirection)
    throw_if_invalid_option(s.axis.validate(), {{"n", "--n"}, {"from", "--from"}, {"to", "--to"}});
  if (s.kind == MapKind::kParamParam)
    throw_if_invalid_option(s.axis2.validate(),
                            {{"n", "--n2"}, {"from", "--from2"}, {"to", "--to2"}});
  if (s.kind == MapKind::kParamDirection && (s.theta_n < 1 || s.theta_n > 1000000))
    throw InputError("--theta-n must be in [1, 1000000]");
  return s;
}

namespace {

/// `cpkit map --system FILE` of N 2-D points.
int run_map_n_points(const MapArgs& a, rate::SystemFile file) {
  const SystemMapRequest r = rate::system_map_request(a, std::move(file), mpi::size());
  std::unique_ptr<PrefixLock> lock;  // held until the map is written
  if (!r.out.empty()) lock = claim_map_prefix(r.out, {{"--system", r.path}});
  return run_map_system(r);
}

int run_map(const MapArgs& a) {
  if (a.list_presets) {
    for (const auto& p : map_presets())
      std::cout << p.name << " (" << to_string(p.kind) << "): " << p.description << '\n';
    return kExitOk;
  }
  // The system file is read once (a pipe can be read only once) and dispatched on its dim.
  std::optional<rate::SystemFile> file;
  if (a.given("--system")) file = rate::read_system_file(a.system);
  if (file && file->dim == 3) {
    rate::MapRequest r = a;
    r.file = std::move(*file);
    return run_map_system_3d(r);
  }
  for (const char* o : {"--facets", "--point", "--others", "--gamma"})
    if (a.given(o))
      throw InputError(std::string(o) + " applies to maps of 3-D systems (--system FILE with "
                       "\"dim\": 3)");
  if (file) return run_map_n_points(a, std::move(*file));
  return run_map_one_point(a);
}

}  // namespace

void add_map_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<MapArgs>();
  auto* cmd = app.add_subcommand(
      "map", "Non-existence / non-uniqueness maps of the rate problem over load directions and "
             "parameters (docs/maps.md)");
  auto& o = args->opt;
  o["--preset"] = cmd->add_option("--preset", args->preset,
                                  "fig5a, fig5b, state-d, state-d-mu-kappa (--list-presets)");
  cmd->add_flag("--list-presets", args->list_presets, "list the presets and exit");
  o["--kind"] = cmd->add_option("--kind", args->kind, "direction | param-direction | param-param | sphere (3-D systems)");
  o["--state"] = cmd->add_option("--state", args->state, "contact state a|b|c|d (default b)");
  o["--a11"] = cmd->add_option("--a11", args->a11, "stiffness a11 (or the preset's)")->default_str("");
  o["--a12"] = cmd->add_option("--a12", args->a12, "stiffness a12 (or the preset's)")->default_str("");
  o["--a22"] = cmd->add_option("--a22", args->a22, "stiffness a22 (or the preset's)")->default_str("");
  o["--mu"] = cmd->add_option("--mu", args->mu, "friction coefficient (or the preset's)")
                   ->default_str("");
  o["--C_T"] = cmd->add_option("--C_T", args->C_T, "tangential compliance (with --preset: the preset's)");
  o["--k_a"] = cmd->add_option("--k_a", args->k_a, "Archard wear coefficient (with --preset: the preset's)");
  o["--P_s"] = cmd->add_option("--P_s", args->P_s, "hardness (with --preset: the preset's)");
  o["--P_N"] = cmd->add_option("--P_N", args->P_N, "normal force (states c, d; with --preset: the preset's)")
                    ->default_str("");
  o["--sgnPT"] = cmd->add_option("--sgnPT", args->sgnPT, "sign of P_T in state d (+1/-1)");
  o["--criterion"] = cmd->add_option("--criterion", args->criterion,
                                     "friction-and-wear criterion: 38 (Coulomb, default) or 35 "
                                     "(softening; state d uses mu_eff = mu - 2 kappa)");
  o["--param"] = cmd->add_option("--param", args->param,
                                 "first axis: " + map_parameter_names(kMapOnePoint) +
                                     " (systems: see --system)");
  o["--from"] = cmd->add_option("--from", args->from, "first axis start")->default_str("");
  o["--to"] = cmd->add_option("--to", args->to, "first axis end")->default_str("");
  o["--n"] = cmd->add_option("--n", args->n,
                             "first axis values (default 200, with --preset the preset's; "
                             "--system: 100; 3-D --kind sphere: 91 elevations)")
                 ->default_str("");
  o["--param2"] = cmd->add_option("--param2", args->param2, "second axis (param-param)");
  o["--from2"] = cmd->add_option("--from2", args->from2, "second axis start")->default_str("");
  o["--to2"] = cmd->add_option("--to2", args->to2, "second axis end")->default_str("");
  o["--n2"] = cmd->add_option("--n2", args->n2,
                              "second axis values (default 200, with --preset the preset's; "
                              "--system: 100; 3-D --kind sphere: 180 azimuths)")
                  ->default_str("");
  o["--theta-n"] = cmd->add_option("--theta-n", args->theta_n,
                                   "directions of a param-direction map (rejected for the "
                                   "other kinds)");
  o["--theta-from"] = cmd->add_option("--theta-from", args->theta_from,
                                      "param-direction: first direction sampled, rad");
  o["--theta-to"] = cmd->add_option("--theta-to", args->theta_to,
                                    "param-direction: last direction sampled, rad (default 2 pi; "
                                    "at most --theta-from + 2 pi)")
                        ->default_str("");
  o["--method"] = cmd->add_option("--method", args->method,
                                  "enumerate | analytic (also cross-checks with enumerate)");
  o["--threads"] = cmd->add_option("--threads", args->threads, "worker threads (0: all cores)");
  o["--out"] = cmd->add_option("--out", args->out,
                               "write PREFIX.json and the cells: grid maps PREFIX_<array>.npy "
                               "(or PREFIX.csv with --format csv) + PREFIX_critical.csv; "
                               "direction maps PREFIX.csv");
  o["--time-limit"] = cmd->add_option(
      "--time-limit", args->time_limit,
      "grid maps: refuse up front when the estimated time of the cells exceeds this many "
      "seconds");
  o["--max-output"] = cmd->add_option(
      "--max-output", args->max_output,
      "grid maps written with --out: refuse up front when the estimated output exceeds SIZE "
      "bytes (suffix K, M, G, T: powers of 1024; e.g. 500M, 10G)")
                             ->type_name("SIZE");
  o["--format"] = cmd->add_option("--format", args->format,
                                  "cells of a grid map: npy (numpy arrays of codes + axis "
                                  "vectors) | csv (one line per cell)");
  o["--system"] = cmd->add_option("--system", args->system,
                                  "N-point system file (docs/file_formats.md): maps of "
                                  "dF = cos(theta) e1 + sin(theta) e2; --kind direction (default), "
                                  "param-direction, param-param; --param mu, C_T, k_a, P_s, "
                                  "P_N, coupling or mu@i, ... (3-D: mu, C_T, k_a, P_s, "
                                  "alpha_X, alpha_Y or mu@i, ...)");
  o["--facets"] = cmd->add_option("--facets", args->facets,
                                  "3-D systems: the faceted route with K facets (3..64; required "
                                  "for N > 1 points; default for one point: exact)")
                        ->default_str("");
  o["--point"] = cmd->add_option("--point", args->point,
                                 "3-D systems: the loaded point of --kind sphere/param-direction "
                                 "and the point whose types are mapped (1..N)");
  o["--others"] = cmd->add_option("--others", args->others,
                                  "3-D systems, N > 1: the other points' load rates, zero "
                                  "or file (the file's dF; default: file when the file has a "
                                  "dF, else zero)");
  o["--gamma"] = cmd->add_option("--gamma", args->gamma,
                                 "3-D param-direction: azimuth G of the meridian plane of load "
                                 "directions, dF = (cos t cos G, cos t sin G, sin t)");
  cmd->add_flag("--plot", args->plot, "also draw PREFIX.png and PREFIX.svg (needs --out, matplotlib)");
  cmd->add_flag("--json", args->json, "print the JSON summary on stdout");
  o["--resume"] = cmd->add_flag("--resume", args->resume,
                                "N-point grid maps: continue an interrupted map from the chunks "
                                "finished in PREFIX.parts (same map, same --out)");
  cmd->callback([args, &ctx] {
    for (const auto& [name, option] : args->opt)
      if (option->count() > 0) args->options_given.push_back(name);
    ctx.exit_code = run_map(*args);
  });
}

}  // namespace cpkit::cli
