// `cpkit rate`: the rate problem of the one-point contact problem [Stromberg et al. 1996,
// Sec. 4.3]: every solution for a contact state and a load rate (docs/contact_model.md).
//
//   cpkit rate --state a|b|c|d --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X
//              --P_N X --sgnPT S] --dF DFT DFN [--method enumerate|analytic|lemke|fb-newton|ipopt]
//              [--criterion 38|35] [--json]
//
// Default method: enumerate, cross-checked against analytic. Single solvers (lemke, fb-newton,
// ipopt) find at most one solution: their output says "a solution" with complete = false and
// no count (the set may hold more; the enumerated count is shown for reference, as
// "enumerated_count" in JSON), and their point is checked against the enumerated set. Exit codes: 0 at least one solution, 1 none
// (or the single solver found none), 2 bad input (also: a solution not representable in
// double), 3 the routes disagree (reason on stderr), 5 the enumeration is inconclusive (sign
// tests too close to call; the routes run in normalised units, so this is conditioning, not
// units).
//
// N points (and "dim": 3 files): cpkit rate --system FILE [--dF ... 2N numbers] [--json]
//              [--method enumerate|lemke|fb-newton|ipopt]
// The checks, the routes and the exit code: rate_problem/requests/rate_request.hpp; the text and JSON:
// report/rate_text.hpp, report/json.hpp.
#include <iostream>
#include <memory>
#include <string>

#include "cli_common.hpp"
#include "model_options.hpp"
#include "cpkit/rate_problem/requests/rate_request.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/rate_text.hpp"

namespace cpkit::cli {
namespace {

struct RateArgs {
  rate::RateRequest request;  ///< the options whose value says whether they were given
  ModelArgs model;            ///< the shared model option group
  std::string state;          ///< --state
  int sgn_PT = 1;             ///< --sgnPT
  bool json = false;
};

/// The one library call: the request as given (the options not given left empty), then print.
int run_rate(RateArgs& a, const CLI::App& cmd) {
  rate::RateRequest& r = a.request;
  r.model = given_model_options(cmd, a.model);
  r.state = if_given(cmd, "--state", a.state);
  r.sgn_PT = if_given(cmd, "--sgnPT", a.sgn_PT);
  const rate::RateOutcome out = rate::run_rate_request(
      r, [](const std::string& note) { std::cerr << "cpkit rate: " << note << '\n'; });
  if (a.json)
    print_json(rate::rate_outcome_json(out, CPKIT_VERSION));
  else
    std::cout << rate::rate_outcome_text(out);
  for (const auto& note : out.notes) std::cerr << "cpkit rate: " << note << '\n';
  return out.exit_code;
}

}  // namespace

void add_rate_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<RateArgs>();
  rate::RateRequest& r = args->request;
  auto* cmd = app.add_subcommand(
      "rate", "Rate problem of the one-point contact problem [Stromberg et al. 1996, Sec. 4.3]");
  cmd->add_option("--state", args->state, "contact state: a (open), b (grazing), c (stick), d (sliding)");
  add_model_options(*cmd, args->model);
  // required for one point only; checked by run_rate_request (with --system: from the file)
  for (const char* n : {"--a11", "--a12", "--a22", "--mu"}) cmd->get_option(n)->required(false);
  cmd->add_option("--P_N", r.P_N, "normal force in states c/d (> 0)")->default_str("");
  cmd->add_option("--sgnPT", args->sgn_PT, "sign of P_T in state d (+1 or -1)");
  cmd->add_option("--dF", r.dF,
                  "load rate: DFT DFN (one point); 2N numbers T_1 N_1 T_2 N_2 ... "
                  "with --system (default: the file's dF); --DF is accepted too")
      ->expected(1, -1);
  cmd->add_option("--system", r.system,
                  "N-point system file (JSON, docs/file_formats.md): solve its rate problem");
  cmd->add_option("--method", r.method,
                  "enumerate (cross-checked against analytic), analytic, lemke, "
                  "fb-newton, ipopt");
  cmd->add_option("--facets", r.facets,
                  "3-D system (\"dim\": 3): solve the faceted problem with K facets (3..64) "
                  "instead of the exact elliptic one (docs/contact_3d.md)")
      ->default_str("");
  cmd->add_option_function<double>(
      "--time-limit", [args](const double& v) { args->request.time_limit = v; },
      "3-D system with --facets: wall-clock budget in seconds of the whole solve (default 60); "
      "when it runs out the answer is not complete (exit 5)");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args, &ctx, cmd]() { ctx.exit_code = run_rate(*args, *cmd); });
}

}  // namespace cpkit::cli
