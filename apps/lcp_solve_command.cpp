// `cpkit lcp solve FILE [--q QFILE] [--solver NAME] [--json] [--tol T] [--max-iter K]
//                       [--time-limit S] [--trace]`
// Reads an LCP (.json, Siconos .dat, or a Matrix Market M with its q), runs one solver from cpkit::lcp::solvers() and prints the result
// (JSON object with --json, a short text report otherwise). Exit codes: 0 solved (solved or
// solved_inaccurate), 1 the solve ran but found no solution, 2 bad input or usage (message on
// stderr, nothing on stdout).
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cli_options.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/report.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "lcp_actions.hpp"

namespace cpkit::cli {
namespace {

/// Command-line arguments of `lcp solve` (owned by the callback, alive during parse()).
struct LcpSolveArgs {
  std::string file;
  std::string q_file;  ///< --q: the q of a Matrix Market or .npy M (default FILE.q.mtx/.q.npy)
  std::string solver = "lemke";
  bool json = false;
  double tol = CommonOptions{}.tol;
  int max_iter = 0;
  double time_limit_s = std::numeric_limits<double>::infinity();
  bool trace = false;
  bool all_solvers = false;  ///< --all-solvers: every registered LCP solver side by side
};

/// "a, b, c": the registered LCP solver names (for error messages and help).
std::string lcp_solver_list() {
  std::string out;
  for (const auto& name : cpkit::lcp::solvers().names(ProblemKind::kLcp))
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

/// Looks `name` up in the registry; InputError listing the valid names when unknown or when the
/// solver does not accept this problem's storage.
const SolverEntry& find_lcp_solver(const std::string& name, const LcpProblem& problem) {
  const SolverEntry* entry = cpkit::lcp::solvers().find(name);
  if (entry == nullptr || !entry->accepts(ProblemKind::kLcp))
    throw InputError("unknown solver '" + name + "' (valid: " + lcp_solver_list() + ")");
  if (!entry->accepts(problem))
    throw InputError("solver '" + name + "' does not accept " +
                     (problem.is_sparse() ? "sparse" : "dense") + " LCPs");
  return *entry;
}

/// Common options from the command line; InputError naming the bad option.
CommonOptions common_options(const LcpSolveArgs& a) {
  CommonOptions o;
  // A scaled residual near 1 accepts almost any z as "solved": keep --tol meaningful.
  if (!(a.tol <= 1e-3))
    throw InputError("--tol must be at most 1e-3 (a larger tolerance on the scaled residual "
                     "would call almost any z solved), got " + num_text(a.tol));
  o.tol = a.tol;
  if (o.tol_acceptable < o.tol) o.tol_acceptable = o.tol;  // --tol above 1e-6 widens both
  o.max_iterations = a.max_iter;
  o.time_limit_s = a.time_limit_s;
  o.record_trace = a.trace;
  throw_if_invalid_option(o.validate(), {{"tol", "--tol"},
                                         {"max_iterations", "--max-iter"},
                                         {"time_limit_s", "--time-limit"}});
  return o;
}

/// Runs one solver on the problem. The result has been through cpkit::finalize() (every
/// registered solver returns through it).
SolveResult run_one_solver(const SolverEntry& entry, const LcpProblem& problem,
                           const CommonOptions& options) {
  SolveResult r = entry.solve_lcp(problem, options);
  if (r.solver.empty()) r.solver = entry.info.name;
  return r;
}

/// The JSON object printed for one result (to_json plus the problem's name when known).
nlohmann::json result_json(const SolveResult& r, const LcpProblem& problem) {
  nlohmann::json j = to_json(r);
  if (!problem.name.empty()) j["problem"] = problem.name;
  return j;
}

/// The text report printed for one result (with the pivot/iteration trace when recorded).
std::string result_text(const SolveResult& r, const LcpProblem& problem) {
  std::ostringstream s;
  if (!problem.name.empty()) s << "problem:    " << problem.name << " (n = " << problem.size()
                               << ")\n";
  s << to_text(r);
  if (!r.trace.empty()) {
    // Pivoting methods number the variables 0..n-1 = z_i, n = z0, n+1+i = w_i.
    const Eigen::Index n = problem.size();
    auto var = [n](int id) {
      if (id < n) return "z" + std::to_string(id + 1);
      if (id == n) return std::string("z0");
      return "w" + std::to_string(id - n);
    };
    s << "trace:\n";
    for (const auto& e : r.trace) {
      s << "  " << e.iteration << ' ' << e.kind;
      if (e.entering >= 0 && e.leaving >= 0)
        s << ": " << var(e.entering) << " enters, " << var(e.leaving) << " leaves";
      s << " (step " << e.step << ", residual " << e.residual << ")\n";
    }
  }
  return s.str();
}

/// Exit code of one result: 0 when it is a (verified) solution, else 1.
int exit_code_of(const SolveResult& r) { return is_solution(r.status) ? kExitOk : kExitNoSolution; }

/// --all-solvers: runs every registered solver that accepts the problem and prints the
/// outcomes side by side (JSON: one object whose `results` holds one result object per solver;
/// or a text table). Exit code 0 when at
/// least one solver returned a verified solution, else 1.
int run_all_lcp_solvers(const LcpSolveArgs& a, const LcpProblem& problem,
                        const CommonOptions& options) {
  std::vector<SolveResult> results;
  std::vector<std::string> names;
  for (const auto& entry : cpkit::lcp::solvers().entries())
    if (entry.accepts(problem)) {
      results.push_back(run_one_solver(entry, problem, options));
      names.push_back(entry.info.name);
    }
  bool any = false;
  for (const auto& r : results) any |= is_solution(r.status);
  if (a.json) {
    // One object, like every --json output: the problem, then one result per solver.
    nlohmann::json arr = nlohmann::json::array();
    for (std::size_t k = 0; k < results.size(); ++k) {
      nlohmann::json j = result_json(results[k], problem);
      j["entry"] = names[k];  // the registry entry run ("solver" is who produced z)
      arr.push_back(j);
    }
    nlohmann::json out;
    if (!problem.name.empty()) out["problem"] = problem.name;
    out["n"] = problem.size();
    out["solved_by_any"] = any;
    out["results"] = arr;
    print_json(out);
  } else {
    std::ostringstream s;
    if (!problem.name.empty()) s << "problem: " << problem.name << " (n = " << problem.size() << ")\n";
    char line[160];
    std::snprintf(line, sizeof line, "%-12s %-18s %-12s %-10s %-10s %s\n", "solver", "status",
                  "residual", "iterations", "seconds", "answered by");
    s << line;
    for (std::size_t k = 0; k < results.size(); ++k) {
      const SolveResult& r = results[k];
      std::snprintf(line, sizeof line, "%-12s %-18s %-12.3g %-10d %-10.4f %s\n",
                    names[k].c_str(),
                    std::string(to_string(r.status)).c_str(), r.residuals.natural, r.iterations,
                    r.seconds, r.solver.c_str());
      s << line;
    }
    std::cout << s.str() << std::flush;
  }
  return any ? kExitOk : kExitNoSolution;
}

/// The whole action. Everything that can be bad input is checked before anything is printed.
int run_lcp_solve(const LcpSolveArgs& a) {
  const LcpProblem problem = read_lcp_file(a.file, a.q_file);  // validates; names file/line
  const CommonOptions options = common_options(a);
  if (a.all_solvers && a.trace && !a.json)
    throw InputError("--trace with --all-solvers needs --json (the table has no room for the "
                     "traces; or trace one solver with --solver NAME --trace)");
  if (a.all_solvers) return run_all_lcp_solvers(a, problem, options);
  const SolverEntry& entry = find_lcp_solver(a.solver, problem);
  const SolveResult r = run_one_solver(entry, problem, options);
  if (a.json)
    print_json(result_json(r, problem));
  else
    std::cout << result_text(r, problem) << std::flush;
  return exit_code_of(r);
}

}  // namespace

void add_lcp_solve(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<LcpSolveArgs>();
  auto* cmd = lcp.add_subcommand("solve", "Solve an LCP 0 <= z _|_ Mz + q >= 0 from a .json, "
                                          "Siconos .dat, Matrix Market .mtx or numpy .npy file");
  cmd->add_option("FILE", args->file,
                  "problem file: .json, Siconos .dat, or a Matrix Market (.mtx) or numpy (.npy) M "
                  "whose q is in FILE.q.mtx / FILE.q.npy beside it or given by --q")
      ->required();
  cmd->add_option("--q", args->q_file,
                  "file holding q, for a Matrix Market (.mtx) or numpy (.npy) M");
  CLI::Option* solver_opt = cmd->add_option("--solver", args->solver,
                  "solver name from the registry (default lemke; valid: " + lcp_solver_list() +
                      ")");
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
  cmd->callback([args, &ctx]() { ctx.exit_code = run_lcp_solve(*args); });
}

}  // namespace cpkit::cli
