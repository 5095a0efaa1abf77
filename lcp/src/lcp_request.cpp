// `cpkit lcp solve|verify|enumerate`: the option checks (in the user's words), the runs and the
// exit codes. The text and JSON of the outcomes: lcp_report.cpp.
#include "cpkit/lcp/lcp_request.hpp"

#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/option_words.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp {
namespace {

/// Looks `name` up in the registry; InputError listing the valid names when unknown or when the
/// solver does not accept this problem's storage.
const SolverEntry& find_lcp_solver(const std::string& name, const LcpProblem& problem) {
  const SolverEntry* entry = solvers().find(name);
  if (entry == nullptr || !entry->accepts(ProblemKind::kLcp))
    throw InputError("unknown solver '" + name + "' (valid: " + lcp_solver_list() + ")");
  if (!entry->accepts(problem))
    throw InputError("solver '" + name + "' does not accept " +
                     (problem.is_sparse() ? "sparse" : "dense") + " LCPs");
  return *entry;
}

/// The common options of a solve; InputError naming the bad option.
CommonOptions common_options(const LcpSolveRequest& a) {
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

/// One registered solver on the problem (every entry returns through finalize()).
SolveResult run_one_solver(const SolverEntry& entry, const LcpProblem& problem,
                           const CommonOptions& options) {
  SolveResult r = entry.solve_lcp(problem, options);
  if (r.solver.empty()) r.solver = entry.info.name;
  return r;
}

/// The hint of LcpSolveOutcome: empty when some result is a solution or a proof (infeasible).
std::string next_step_hint(const LcpSolveRequest& a, const std::vector<SolveResult>& results) {
  for (const auto& r : results)
    if (is_solution(r.status) || r.status == Status::kInfeasible) return {};
  const Status s = results.front().status;
  std::string h;
  if (!a.all_solvers && s == Status::kRayTermination)
    h = "Lemke's secondary ray proves nothing here (M is not known copositive-plus): the "
        "problem may have solutions. ";
  else
    h = "no solution was found and none was proved impossible. ";
  h += "Try ";
  if (!a.all_solvers && a.solver != kDefaultSolver)
    h += "--solver " + std::string(kDefaultSolver) + " (Lemke, FB Newton, the enumeration, "
         "Ipopt, NLopt), or ";
  if (!a.all_solvers && (s == Status::kIterationLimit || s == Status::kTimeLimit))
    h += "a larger --max-iter / --time-limit, or ";
  return h + "`cpkit lcp enumerate " + a.file + "` (every solution, or a proof that there is "
         "none; n <= 64 and bimatrix games)";
}

}  // namespace

std::string lcp_solver_list() {
  std::string out;
  for (const auto& name : solvers().names(ProblemKind::kLcp))
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

LcpSolveOutcome run_lcp_solve_request(const LcpSolveRequest& a) {
  LcpSolveOutcome out;
  out.problem = read_lcp_file(a.file, a.q_file);  // validates; names file/line
  const CommonOptions options = common_options(a);
  if (a.all_solvers && a.trace && !a.json)
    throw InputError("--trace with --all-solvers needs --json (the table has no room for the "
                     "traces; or trace one solver with --solver NAME --trace)");
  out.all_solvers = a.all_solvers;
  if (a.all_solvers) {
    for (const auto& entry : solvers().entries())
      if (entry.accepts(out.problem)) {
        out.results.push_back(run_one_solver(entry, out.problem, options));
        out.entries.push_back(entry.info.name);
      }
  } else {
    const SolverEntry& entry = find_lcp_solver(a.solver, out.problem);
    out.results.push_back(run_one_solver(entry, out.problem, options));
    out.entries.push_back(entry.info.name);
  }
  bool any = false;
  for (const auto& r : out.results) any |= is_solution(r.status);
  out.exit_code = any ? kExitOk : kExitNoSolution;
  out.hint = next_step_hint(a, out.results);
  return out;
}

LcpVerifyOutcome run_lcp_verify_request(const LcpVerifyRequest& a) {
  LcpVerifyOutcome out;
  out.problem = read_lcp_file(a.file);
  CrossVerifyOptions opt;
  for (const auto& name : a.skip) {
    // A misspelt name would silently run the solver it meant to skip.
    const SolverEntry* e = solvers().find(name);
    if (e == nullptr || !e->accepts(ProblemKind::kLcp))
      throw InputError("--skip: unknown solver '" + name + "' (valid: " + lcp_solver_list() + ")");
  }
  opt.skip = a.skip;
  opt.solve.time_limit_s = a.time_limit_s;
  opt.enumeration.time_limit_s = a.time_limit_s;
  throw_if_invalid_option(opt.validate(), {{"EnumerationOptions::time_limit_s", "--time-limit"},
                                           {"time_limit_s", "--time-limit"}});
  out.result = cross_verify(out.problem, opt);
  if (!out.result.consistent()) out.exit_code = kExitDisagreement;
  else out.exit_code = out.result.set.complete ? kExitOk : kExitInconclusive;
  return out;
}

LcpEnumerateOutcome run_lcp_enumerate_request(const LcpEnumerateRequest& a) {
  LcpEnumerateOutcome out;
  out.problem = read_lcp_file(a.file);
  EnumerationOptions opt;
  opt.tol = a.tol;
  opt.time_limit_s = a.time_limit_s;
  opt.max_size = a.max_size;
  throw_if_invalid_option(opt.validate(), {{"EnumerationOptions::max_size", "--max-size"},
                                           {"EnumerationOptions::tol", "--tol"},
                                           {"EnumerationOptions::time_limit_s", "--time-limit"}});
  out.result = enumerate_all(out.problem, opt);
  if (!out.result.solutions.empty()) out.exit_code = kExitOk;
  else out.exit_code = out.result.complete ? kExitNoSolution : kExitInconclusive;
  return out;
}

}  // namespace cpkit::lcp
