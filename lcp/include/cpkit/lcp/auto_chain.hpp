#pragma once
/// \file auto_chain.hpp
/// The automatic solver chain "auto": try solvers in a fixed order until one returns a
/// verified solution, with an honest account of every attempt.
///
/// Order, by cost (looked up by name in cpkit::lcp::solvers() at call time; a name that is not
/// registered, or whose entry does not accept the problem, is recorded as skipped):
///   LCP:            lemke, fb-newton, [enumeration], [farkas-search], ipopt, nlopt
///   box LCP, MCP:   fb-newton, ipopt, nlopt
/// (nlopt, the same MPCC solved by SLSQP, is a last resort beyond the chain: on the
/// robustness benchmark it solves indefinite LCPs on which the Ipopt MPCC stalls.)
/// The chain stops at the first kSolved answer, or at a kInfeasible one (whose certificate
/// finalize() re-checked). A kSolvedInaccurate answer is kept while later solvers try for
/// kSolved. For LCPs with n <= 12, once the cheap solvers have failed, the complete enumeration
/// (enumerate.hpp, time-limited to 1 s) is tried first (attempt "enumeration"): its first extreme
/// solution, decided by finalize(). For LCPs, once the cheap solvers (Lemke, FB Newton: microseconds) have failed and
/// before the first expensive one (the Ipopt/NLopt MPCC: ~0.1-1 s), a Farkas certificate
/// y >= 0, M^T y <= 0, q^T y < 0 is searched once with Ipopt (the LP min q^T y, M^T y <= 0,
/// sum y = 1, y >= 0); kInfeasible is reported only when check_certificate() accepts it
/// [CPS 1992, Sec. 3.8] (attempt "farkas-search"). It is skipped when a kSolvedInaccurate answer
/// is at hand, and run at the end when every solver was cheap or skipped.
/// Otherwise the status is that of the last attempt (never "infeasible" without a proof).
///
/// result.solver names the solver that produced the answer (e.g. "fb-newton"), or the last
/// solver tried when none did; result.attempts lists every attempt in order (skips included,
/// status kNotRun with message "not registered" / "does not accept this problem").
/// A "solution" with ||z||_inf > 1e10 ||q||_inf / ||M||_max (MCP: 1e10 (1 + largest finite bound or
/// |x0|)) is rejected as diverged (defence in depth: a residual scale that grows with |M| |z|
/// would let a runaway z with w = -1 pass). time_limit_s is shared by the whole chain. The final answer goes through finalize() again.
#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp {

/// The chain's solver names for a problem kind (in order; the farkas-search step is not a
/// registered solver and is not listed).
const std::vector<std::string>& auto_chain_names(ProblemKind kind);

/// Each throws InputError for an invalid problem or options.
SolveResult solve_auto(const LcpProblem& problem, const CommonOptions& options = {});
SolveResult solve_auto(const BoxLcpProblem& problem, const CommonOptions& options = {});
SolveResult solve_auto(const McpProblem& problem, const CommonOptions& options = {});

/// Registry entry ("auto").
SolverEntry auto_entry();

}  // namespace cpkit::lcp
