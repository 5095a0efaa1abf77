// `cpkit simulate`: quasi-static fretting simulation with friction, wear and heat
// (docs/simulation.md; library: cpkit/rate_problem/requests/simulate_request.hpp).
//
//   cpkit simulate --config FILE.json [options overriding the file]
//   cpkit simulate --a11 X --a12 X --a22 X --mu X [--C_T X --k_a X --P_s X --criterion 38|35]
//                  [--load fretting|ramp|csv] [--F_N X --amplitude X --cycles N
//                  --steps-per-cycle N --period X --ramp-steps N] [--load-csv FILE]
//                  [--heat --heat-capacity X --T-ref X --T-initial X --T-body T1 T2
//                  --conductance C1 C2] [--branch-rule closest|stop]
//                  [--csv OUT.csv] [--summary OUT.json] [--plot PREFIX] [--every N] [--json]
//   cpkit simulate --system POINTS.json ...   (N points, docs/simulation.md "N points")
//   cpkit simulate --system POINT3D.json --orbit aX aY [--orbit-angle RAD] [--lead-steps N]
//                  ("dim": 3: fretting of one 3-D point, docs/contact_3d.md)
//
// Exit codes: 0 the run completed, 1 it stopped (no solution, a continuum, a branch point
// with --branch-rule stop, or numerical_failure: values beyond the range of double; the reason
// on stdout/in the summary), 5 it stopped at a step whose enumeration is not proved complete
// (N points, 3-D), 2 bad input (also an output file that cannot be written), 4 the figures
// were asked for and are missing.
#include <memory>
#include <optional>
#include <string>

#include "cli_common.hpp"
#include "cpkit/rate_problem/requests/simulate_request.hpp"
#include "simulation_outputs.hpp"

namespace cpkit::cli {
namespace {

struct SimArgs {
  rate::SimulateRequest request;
  bool json = false;  ///< --json: print the JSON summary
};

int run(rate::SimulateRequest& a, bool json) {
  // No output may be an input (issue 24, item 8): refused before anything is read or written,
  // and again for what a config names (its system, load and outputs).
  refuse_outputs_over_inputs("cpkit simulate", simulation_output_files(a.csv, a.summary, a.plot),
                             {{"--config", a.config}, {"--system", a.system},
                              {"--load-csv", a.load_csv}});
  a.run = run_echo();
  a.version = CPKIT_VERSION;
  const rate::SimulateOutcome o =
      rate::run_simulate_request(a, [&a](const rate::SimulateSettings& s) {
        refuse_outputs_over_inputs("cpkit simulate",
                                   simulation_output_files(s.csv, s.summary, s.plot),
                                   {{"--config", a.config}, {"system", s.system},
                                    {"load csv", s.load_csv}});
      });
  if (json) print_json(o.summary);  // N points: "run" is added here, not in the file
  else std::cout << o.text;
  if (!draw_and_name_outputs(o.plot_script, o.csv, o.summary_file, o.plot, o.figures))
    return kExitInternal;  // the figures were asked for and are missing
  return o.exit_code;
}

}  // namespace

void add_simulate_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<SimArgs>();
  rate::SimulateRequest* a = &args->request;
  auto* cmd = app.add_subcommand(
      "simulate", "Quasi-static fretting simulation with friction, wear and heat "
                  "(docs/simulation.md)");
  cmd->add_option("--config", a->config, "JSON settings (docs/examples/fretting.json)");
  cmd->add_option("--system", a->system,
                  "N-point system file (docs/file_formats.md): simulate N points (docs/simulation.md)");
  using N = rate::SimulateNumbers;
  struct NumOpt {
    const char* name;
    const char* help;
    std::optional<double> N::*field;
  };
  static const NumOpt nums[] = {
      {"--a11", "stiffness A11", &N::a11}, {"--a12", "stiffness A12", &N::a12},
      {"--a22", "stiffness A22", &N::a22}, {"--mu", "friction coefficient", &N::mu},
      {"--C_T", "tangential compliance", &N::C_T},
      {"--k_a", "Archard wear coefficient", &N::k_a}, {"--P_s", "hardness", &N::P_s},
      {"--k_M", "Mroz-Stupkiewicz wear constant", &N::k_M},
      {"--F_N", "fretting: normal load", &N::F_N},
      {"--amplitude", "fretting: tangential load amplitude", &N::amplitude},
      {"--period", "fretting/csv: period", &N::period},
      {"--cycles", "fretting: number of cycles", &N::cycles},
      {"--steps-per-cycle", "fretting: steps per cycle", &N::steps_per_cycle},
      {"--ramp-steps", "fretting: steps of the initial normal-load ramp", &N::ramp_steps},
      {"--F_T0", "ramp: initial F_T", &N::F_T0}, {"--F_N0", "ramp: initial F_N", &N::F_N0},
      {"--F_T1", "ramp: final F_T", &N::F_T1}, {"--F_N1", "ramp: final F_N", &N::F_N1},
      {"--duration", "ramp: duration", &N::duration}, {"--steps", "ramp: steps", &N::steps},
      {"--heat-capacity", "heat capacity per area C", &N::heat_capacity},
      {"--T-ref", "reference temperature T0", &N::T_ref},
      {"--T-initial", "initial interface temperature", &N::T_initial}};
  for (const auto& n : nums) {
    const auto field = n.field;
    cmd->add_option_function<double>(
        n.name, [a, field](const double& v) { a->numbers.*field = v; }, n.help);
  }
  cmd->add_option("--criterion", a->criterion, "38 (Coulomb, default) or 35 (softening)");
  cmd->add_option("--wear-law", a->wear_law, "archard (default) or mroz");
  cmd->add_option("--load", a->load, "fretting (default), ramp or csv");
  cmd->add_option("--load-csv", a->load_csv, "load history CSV: t, F_T, F_N");
  cmd->add_flag("--heat", a->heat, "compute the interface temperature");
  cmd->add_option("--T-body", a->T_body, "body temperatures T1 T2")->expected(2);
  cmd->add_option("--conductance", a->conductance, "contact conductances c1 c2")->expected(2);
  cmd->add_option("--branch-rule", a->branch_rule, "closest (default) or stop");
  cmd->add_option("--csv", a->csv, "write the time series here");
  cmd->add_option("--summary", a->summary, "write the JSON summary here");
  cmd->add_option("--plot", a->plot, "figures PREFIX_loop/_wear/_state .png/.svg");
  cmd->add_option_function<int>("--every", [a](const int& v) { a->every = v; },
                                "keep every n-th step in the series (default 1; 0: none)");
  cmd->add_flag("--json", args->json, "print the JSON summary");
  // A "dim": 3 system file only (fretting of one 3-D point, docs/contact_3d.md).
  cmd->add_option("--orbit", a->orbit,
                  "dim 3: half-axes aX aY of the elliptic tangential load orbit "
                  "F_T = R(angle) (aX cos, aY sin) (aY < 0: clockwise)")
      ->expected(2);
  cmd->add_option_function<double>(
      "--orbit-angle", [a](const double& v) { a->orbit_angle = v; },
      "dim 3: rotation of the orbit in the tangential plane (rad, default 0)");
  cmd->add_option_function<int>(
      "--lead-steps", [a](const int& v) { a->lead_steps = v; },
      "dim 3: steps of the tangential lead-in from 0 to the orbit's start (default "
      "steps-per-cycle / 4)");
  cmd->callback([args, &ctx]() { ctx.exit_code = run(args->request, args->json); });
}

}  // namespace cpkit::cli
