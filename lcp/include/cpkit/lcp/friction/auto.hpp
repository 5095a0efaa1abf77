#pragma once
/// \file auto.hpp
/// "auto" for frictional contact problems (friction_problem.hpp): a chain of the registered
/// friction solvers, tried in this order until one returns kSolved:
///   fb-soc, nsgs, prox, lemke-faceted, lemke, ipopt-fc, ipopt
/// (names looked up in cpkit::lcp::solvers() at call time; a name not registered, or whose entry
/// has no solve_fc, is recorded as skipped). fb-soc (Newton: fast when it converges) comes first,
/// with its non-monotone line search and, when that fails, again from r = 0 with the monotone
/// one (fb_soc.hpp: neither wins on every FCLIB file). When the first fb-soc stops by itself
/// without kSolved (kStalled, or kSolvedInaccurate: stagnation, the non-isolated solutions of a
/// rank-deficient W), prox (prox.hpp: W + alpha I) runs next from fb-soc's best iterate, before
/// the monotone retry, and is not run again at its place in the chain (Capsules-i125-1213: 1.9 s
/// through nsgs before, 0.5 s now); nsgs then starts from the best r seen so far (the smallest
/// unit-free residual), as does a second fb-soc run after nsgs when nsgs ends short of tol (Newton polishing a Gauss-Seidel
/// iterate). Every attempt is recorded in SolveResult::attempts (solver, status, unit-free
/// residual, seconds, message). A kSolvedInaccurate answer is kept while later solvers try for
/// kSolved. An answer accepted with a unit-free residual above tol / 10 is polished by up to
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
