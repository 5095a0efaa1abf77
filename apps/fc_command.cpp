// `cpkit fc solve FILE [--solver S] [--tol T] [--measure M] [--max-iter K] [--time-limit S] [--json]`
// `cpkit fc solutions FILE [--starts K] [--seed N] [--tol T] [--measure M] [--time-limit S] [--json]`
// `cpkit fc bench FILE... [--solvers a,b] [--measure M] --out PREFIX` (fc_bench.hpp)
// 3-D frictional contact problems from FCLIB (HDF5) or Siconos FrictionContact .dat files
// (cpkit/core/friction_io.hpp). `solve` runs one solver of cpkit::lcp::solvers() that accepts
// friction problems; `solutions` lists distinct verified solutions (lcp/friction/solutions.hpp).
// The checks, solves, exit codes, text and JSON: cpkit/lcp/friction/fc_request.hpp.
// Exit codes: 0 solved (at least one solution), 1 proved no solution (a re-checked certificate),
// 2 bad input or usage, 5 not solved (nothing proved).
#include <iostream>
#include <memory>
#include <string>

#include "cli_common.hpp"
#include "fc_bench.hpp"
#include "cpkit/lcp/friction/fc_request.hpp"

namespace cpkit::cli {
namespace {

/// The options of `fc solve` and `fc solutions` (the request) and --json.
struct FcArgs : lcp::friction::FcRequest {
  bool json = false;
};

void add_common(CLI::App* cmd, FcArgs& a) {
  cmd->add_option("FILE", a.file, "problem file: FCLIB local or global problem (HDF5) or Siconos "
                                  "FrictionContact / GlobalFrictionContact .dat (chosen by "
                                  "content)")
      ->required();
  cmd->add_flag("--json", a.json, "print one JSON object on stdout");
  cmd->add_option("--tol", a.tol, "tolerance in the measure (default 1e-10, at most 1e-3)");
  cmd->add_option("--measure", a.measure,
                  "the error that decides solved: unit_free (default), relative_q "
                  "(|F_nat|/|q|, FCLIB) or relative_max (Siconos); the unit-free verdict must "
                  "still accept the answer");
  cmd->add_option("--time-limit", a.time_limit_s, "wall-clock limit in seconds");
}

/// The JSON of an outcome with run.measure: the measure that decided "solved".
template <class Outcome, class Json>
auto with_measure(Json to_json) {
  return [to_json](const Outcome& out) {
    nlohmann::json j = to_json(out);
    j["run"] = run_echo();
    j["run"]["measure"] = to_string(out.measure);
    return j;
  };
}

}  // namespace

void add_fc_command(CLI::App& app, Context& ctx) {
  auto* fc = app.add_subcommand("fc", "3-D frictional contact problems (FCLIB, Siconos .dat)");
  fc->require_subcommand(1);
  auto solve = std::make_shared<FcArgs>();
  auto* s = fc->add_subcommand("solve", "Solve a frictional contact problem: local u = W r + q, "
                                        "r in K_mu, u_hat in K*_mu, r . u_hat = 0, or global "
                                        "M v = H r + f, u = H^T v + w (condensed to local)");
  add_common(s, *solve);
  s->add_option("--solver", solve->solver,
                "solver name from the registry (default auto; valid: " + lcp::friction::fc_solver_list() + ")");
  s->add_option("--max-iter", solve->max_iter, "iteration limit (0: the solver's default)");
  s->callback([solve, &ctx]() {
    ctx.exit_code = print_outcome(lcp::friction::run_fc_solve_request(*solve), solve->json,
                                  with_measure<lcp::friction::FcSolveOutcome>(lcp::friction::fc_solve_json),
                                  lcp::friction::fc_solve_text);
  });

  auto sols = std::make_shared<FcArgs>();
  auto* l = fc->add_subcommand("solutions", "List distinct verified solutions (every solution of "
                                            "the faceted problem for small n_c; multistart, "
                                            "complete: false, otherwise)");
  add_common(l, *sols);
  l->add_option("--starts", sols->starts, "seeded starts of the multistart route (default 20, at most " +
                    std::to_string(lcp::friction::FrictionSolutionsOptions::kMaxStarts) + ")");
  l->add_option("--seed", sols->seed, "seed of the starts (default 1)");
  l->callback([sols, &ctx]() {
    ctx.exit_code = print_outcome(lcp::friction::run_fc_solutions_request(*sols), sols->json,
                                  with_measure<lcp::friction::FcSolutionsOutcome>(
                                      lcp::friction::fc_solutions_json),
                                  lcp::friction::fc_solutions_text);
  });

  auto bench = std::make_shared<FcBenchArgs>();
  auto* b = fc->add_subcommand("bench", "Every solver on every file: PREFIX.csv (status, "
                                        "iterations, seconds, the three errors) and PREFIX.png "
                                        "(Dolan-More performance profile)");
  b->add_option("FILE", bench->files, "problem files (FCLIB local HDF5 or Siconos .dat)")
      ->required();
  b->add_option("--solvers", bench->solvers,
                "comma-separated solver names (default: every friction solver: " +
                    lcp::friction::fc_solver_list() + ")")
      ->delimiter(',');
  b->add_option("--out", bench->out, "prefix of PREFIX.csv and PREFIX.png (refused when one is "
                                     "a FILE; PREFIX.lock is held while the bench runs)")
      ->required();
  b->add_option("--tol", bench->tol, "tolerance in the measure (default 1e-10)");
  b->add_option("--measure", bench->measure,
                "the error that decides solved: relative_q (default: |F_nat|/|q|, as FCLIB's "
                "published profiles), relative_max or unit_free");
  b->add_option("--time-limit", bench->time_limit_s, "seconds per solve (default 60)");
  b->add_flag("--no-plot", bench->no_plot, "write the CSV only");
  b->callback([bench, &ctx]() { ctx.exit_code = run_fc_bench(*bench); });
}

}  // namespace cpkit::cli
