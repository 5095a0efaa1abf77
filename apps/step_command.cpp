// `cpkit step`: one implicit time step of the one-point contact problem (the incremental
// problem, docs/model.md Sec. 3, docs/simulation.md).
//
//   cpkit step --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X] [--criterion 38|35]
//              [--wear-law archard|mroz --k_M X] --P_T0 X --P_N0 X --g0 X --dF DFT DFN
//              [--all] [--chain active-set,lemke,fb-newton,ipopt] [--json]
//   cpkit step --system FILE --dF <2N numbers> --all [--json]      (N points, system_step.hpp)
//   cpkit step --system FILE3D --dF X Y N [--all|--chain|--facets K|--multistart N]
//                                        ("dim": 3, one point or N coupled points)
//
// The checks, the routes and the exit code are library work (requests/step_request.hpp), so is the
// text and JSON of the answer (report/step_text.hpp, report/json.hpp); this file registers the
// options, fills the request, makes the one call and prints.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "model_options.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/step_text.hpp"
#include "cpkit/rate_problem/requests/step_request.hpp"

namespace cpkit::cli {
namespace {

/// The values the options are bound to (defaults: those --help shows).
struct StepArgs {
  ModelArgs model;
  std::string wear_law = "archard";
  double k_M = 0, P_T0 = 0, P_N0 = 0, g0 = 0;
  std::vector<double> DF;
  bool all = false;
  std::string chain = rate::kDefaultStepChain;
  std::string system;
  int facets = 0, multistart = 0;
};

/// The request: the options given, no other.
rate::StepRequest step_request(const CLI::App& cmd, const StepArgs& a) {
  rate::StepRequest r;
  r.model = given_model_options(cmd, a.model);
  r.wear_law = if_given(cmd, "--wear-law", a.wear_law);
  r.k_M = if_given(cmd, "--k_M", a.k_M);
  r.P_T0 = if_given(cmd, "--P_T0", a.P_T0);
  r.P_N0 = if_given(cmd, "--P_N0", a.P_N0);
  r.g0 = if_given(cmd, "--g0", a.g0);
  r.DF = a.DF;
  r.all = a.all;
  r.chain = if_given(cmd, "--chain", a.chain);
  r.system = a.system;
  r.facets = if_given(cmd, "--facets", a.facets);
  r.multistart = if_given(cmd, "--multistart", a.multistart);
  return r;
}

}  // namespace

void add_step_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<StepArgs>();
  auto json = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand(
      "step", "One implicit time step of the one-point contact problem with friction and wear "
              "(the incremental problem, docs/simulation.md)");
  add_model_options(*cmd, args->model);
  // With --system the file gives the model: the one-point options are checked in the callback.
  for (const char* o : {"--a11", "--a12", "--a22", "--mu"}) cmd->get_option(o)->required(false);
  cmd->add_option("--system", args->system,
                  "N-point system file (JSON, docs/file_formats.md); needs --all and 2N --dF values");
  cmd->add_option("--wear-law", args->wear_law,
                  "archard (37) or mroz (Mroz-Stupkiewicz (41), with --k_M)");
  cmd->add_option("--k_M", args->k_M, "Mroz-Stupkiewicz wear constant (>= 0)")->default_str("");
  cmd->add_option("--P_T0", args->P_T0, "tangential force at the start of the step")
      ->default_str("");
  cmd->add_option("--P_N0", args->P_N0, "normal force at the start (>= 0)")->default_str("");
  cmd->add_option("--g0", args->g0, "gap function w_N - w^w at the start (<= 0; 0 in contact)")
      ->default_str("");
  cmd->add_option("--dF", args->DF,
                  "load increment: DFT DFN (2N values with --system); --DF is accepted too")
      ->expected(1, 1 << 20)
      ->required();
  cmd->add_flag("--all", args->all, "every solution (complete active-set enumeration)");
  cmd->add_option("--chain", args->chain,
                  "solver chain for one solution (comma-separated; a 3-D file has its own "
                  "chains, docs/contact_3d.md)");
  cmd->add_flag("--json", *json, "print one JSON object");
  cmd->add_option("--facets", args->facets,
                  "3-D file: every solution of the faceted step with K facets (no wear)")
      ->default_str("");
  cmd->add_option("--multistart", args->multistart,
                  "3-D file: distinct verified solutions from N + 1 starts (FB-SOC, Ipopt)")
      ->default_str("");
  cmd->callback([args, json, &ctx, cmd]() {
    const rate::StepOutcome out = rate::run_step_request(step_request(*cmd, *args));
    if (*json) print_json(rate::step_outcome_json(out, CPKIT_VERSION));
    else std::cout << rate::step_text(out);
    for (const auto& e : out.errors) std::cerr << "cpkit step: " << e << '\n';
    ctx.exit_code = out.exit_code;
  });
}

}  // namespace cpkit::cli
