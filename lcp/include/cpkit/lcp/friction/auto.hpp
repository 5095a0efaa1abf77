#pragma once
/// \file auto.hpp
/// "auto" for frictional contact problems (friction_problem.hpp): a chain of the registered
/// friction solvers, tried in this order until one returns kSolved:
///   nsgs, prox, fb-soc, lemke-faceted, lemke, ipopt-fc, ipopt
/// (names looked up in cpkit::lcp::solvers() at call time; a name not registered, or whose entry
/// has no solve_fc, is recorded as skipped). nsgs (cheap sweeps; the fastest cpkit solver on
/// every FCLIB file where it converges) comes first, in runs of 50, 50, 100, 200, ... sweeps,
/// each from the last one's answer, for as long as the last run's rate predicts tol within the
/// sweep budget (max_iterations, else 2000): a stalling nsgs stops after a few hundred sweeps
/// (one record "nsgs" for all the runs). prox (prox.hpp: W + alpha I, for the non-isolated
/// solutions of a rank-deficient W where nsgs stalls) then runs from r = 0, then fb-soc from the
/// best r so far and, when that fails, again from r = 0 with the monotone line search (fb_soc.hpp).
/// Issue 35: before, fb-soc came first and stalled for 1.9 s on KaplasTower (570 contacts), prox
/// took 2.75 s more, and nsgs, last, solved it in 0.07 s.
/// Every attempt is recorded in SolveResult::attempts (solver, status, unit-free
/// residual, seconds, message). A kSolvedInaccurate answer is kept while later solvers try for
/// kSolved. An answer of another solver than nsgs accepted with a unit-free residual above
/// tol / 10 is polished by up to
/// 20 nsgs sweeps from it, kept only when they verify with a smaller residual (recorded as an
/// nsgs attempt "polish from ..."): FrictionContact3D_RR_1c at tol 1e-8 went from 3.8e-9 to
/// rounding (1.1e-7 to 5e-15 by Siconos' |q| measure). time_limit_s is shared by the whole chain. The final answer goes through finalize()
/// again; result.solver names the solver that produced it.
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// The chain's registry names, in order (see the file comment).
std::vector<std::string> auto_chain_names();

/// Throws InputError for an invalid problem or options.
SolveResult solve_auto(const FrictionContactProblem& problem, const CommonOptions& options = {});

}  // namespace cpkit::lcp::friction
