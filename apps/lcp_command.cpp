// `cpkit lcp solve|verify|enumerate` (docs/cli.md): the options, one library call
// (cpkit/lcp/lcp_request.hpp: the checks, the run, the exit code, the text and JSON), print.
//
// solve FILE [--q QFILE] [--solver NAME | --all-solvers] [--json] [--tol T] [--max-iter K]
//   [--time-limit S] [--trace]: an LCP (.json, Siconos .dat, Matrix Market or .npy M with its
//   q) by one registered solver (default auto), or every one side by side. Exit 0 solved
//   (solved or solved_inaccurate; --all-solvers: by any), 1 the solve ran but found no solution
//   (a proof that none exists only when the status is infeasible).
// verify FILE [--json] [--skip NAME ...] [--time-limit S]: every solver against the enumerated
//   solution set (cross_verify). Exit 0 complete and consistent, 3 a disagreement, 5
//   inconclusive (the enumeration is incomplete and nothing disagreed: nothing verified).
// enumerate FILE [--json] [--tol T] [--time-limit S] [--max-size N]: the whole solution set
//   (enumerate_all). Exit 0 a solution, 1 none (complete), 5 none found but incomplete.
// Every action: 2 bad input or usage (message on stderr, nothing on stdout).
#include <iostream>
#include <memory>
#include <string>

#include "cli_common.hpp"
#include "cpkit/lcp/lcp_request.hpp"

namespace cpkit::cli {
namespace {

void add_lcp_solve(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<lcp::LcpSolveRequest>();
  auto* cmd = lcp.add_subcommand("solve", "Solve an LCP 0 <= z _|_ Mz + q >= 0 from a .json, "
                                          "Siconos .dat, Matrix Market .mtx or numpy .npy file");
  cmd->add_option("FILE", args->file,
                  "problem file: .json, Siconos .dat, or a Matrix Market (.mtx) or numpy (.npy) M "
                  "whose q is in FILE.q.mtx / FILE.q.npy beside it or given by --q")
      ->required();
  cmd->add_option("--q", args->q_file,
                  "file holding q, for a Matrix Market (.mtx) or numpy (.npy) M");
  CLI::Option* solver_opt = cmd->add_option("--solver", args->solver,
                  "solver name from the registry (default " + std::string(lcp::kDefaultSolver) +
                      ": Lemke, then the other solvers when Lemke finds nothing; valid: " +
                      lcp::lcp_solver_list() + ")");
  cmd->add_flag("--json", args->json, "print one JSON object on stdout");
  cmd->add_option("--tol", args->tol,
                  "tolerance on the unit-free residual (default 1e-10, at most 1e-3)");
  cmd->add_option("--max-iter", args->max_iter,
                  "iteration/pivot limit (0: the solver's documented default)");
  cmd->add_option("--time-limit", args->time_limit_s, "wall-clock limit in seconds (default: none)")
      ->default_str("");
  cmd->add_flag("--trace", args->trace, "record and print the per-iteration (pivot) trace");
  cmd->add_flag("--all-solvers", args->all_solvers,
                "run every registered solver and print the outcomes side by side (JSON: one "
                "object, its `results` one object per solver)")
      ->excludes(solver_opt);  // --solver would have no effect: an error, not silence
  cmd->callback([args, &ctx]() {
    ctx.exit_code = print_outcome(lcp::run_lcp_solve_request(*args), args->json,
                                  lcp::lcp_solve_json, lcp::lcp_solve_text);
  });
}

void add_lcp_enumerate(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<lcp::LcpEnumerateRequest>();
  auto json = std::make_shared<bool>(false);
  auto* cmd = lcp.add_subcommand(
      "enumerate", "All solutions of an LCP (extreme solutions, continua, directions)");
  cmd->add_option("FILE", args->file, "problem file (.json or Siconos .dat)")->required();
  cmd->add_flag("--json", *json, "print one JSON object on stdout");
  cmd->add_option("--tol", args->tol, "relative tolerance of the sign tests (default 1e-12)");
  cmd->add_option("--time-limit", args->time_limit_s,
                  "wall-clock limit in seconds, every phase (default 60; then complete = false)");
  cmd->add_option("--max-size", args->max_size,
                  "largest n the general engine attempts (default and at most 64); a larger problem that is "
                  "not a bimatrix game ends with complete = false");
  cmd->callback([args, json, &ctx]() {
    ctx.exit_code = print_outcome(lcp::run_lcp_enumerate_request(*args), *json,
                                  lcp::lcp_enumerate_json, lcp::lcp_enumerate_text);
  });
}

void add_lcp_verify(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<lcp::LcpVerifyRequest>();
  auto json = std::make_shared<bool>(false);
  auto* cmd = lcp.add_subcommand(
      "verify", "Run every registered solver and check each answer against the full solution set");
  cmd->add_option("FILE", args->file, "problem file (.json or Siconos .dat)")->required();
  cmd->add_flag("--json", *json, "print one JSON object on stdout");
  cmd->add_option("--skip", args->skip, "solver names not to run");
  cmd->add_option("--time-limit", args->time_limit_s,
                  "wall-clock limit per solver and for the enumeration (default 60 s)");
  cmd->callback([args, json, &ctx]() {
    ctx.exit_code = print_outcome(lcp::run_lcp_verify_request(*args), *json,
                                  lcp::lcp_verify_json, lcp::lcp_verify_text);
  });
}

}  // namespace

void add_lcp_command(CLI::App& app, Context& ctx) {
  auto* lcp = app.add_subcommand("lcp", "Linear complementarity problems: solve, enumerate, verify");
  lcp->require_subcommand(1);
  add_lcp_solve(*lcp, ctx);
  add_lcp_enumerate(*lcp, ctx);
  add_lcp_verify(*lcp, ctx);
}

}  // namespace cpkit::cli
