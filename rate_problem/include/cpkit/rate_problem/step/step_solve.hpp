#pragma once
/// \file step_solve.hpp
/// One solution of an incremental step (incremental_step.hpp) by a solver chain
/// [Stromberg et al. 1996, Sec. 4; docs/model.md Sec. 3; docs/simulation.md].
///
/// Links, tried in order until one is verified:
/// - "active-set": the closed-form active-set enumeration (step_enumeration.hpp); among its
///   point solutions the one closest to the start state (smallest |DP_T| + |DP_N|) is taken;
/// - "lemke": Lemke's method, only when the step is an LCP (no wear term, Coulomb criterion);
/// - "fb-newton", "ipopt" (or any registry name accepting MCPs): the general NCP solvers from
///   cpkit::lcp::solvers(), started at z = (P_N0, 0, 0).
/// A name not registered (yet) is skipped with a message in SolveResult::message; every link
/// that runs is recorded in SolveResult::attempts. Every claim goes through cpkit::finalize()
/// against step_as_mcp() (or step_as_lcp() for Lemke), which alone grants "solved".
/// The result is the step family's StepSolveResultOf (step_result.hpp) over the 2-D point
/// solution StepPoint (step_enumeration.hpp).
#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_result.hpp"

namespace cpkit::rate {

struct StepSolveOptions {
  CommonOptions common;
  std::vector<std::string> chain = {"active-set", "lemke", "fb-newton", "ipopt"};
  /// Empty when usable; names the bad field (empty chain, empty name, common options).
  std::string validate() const;
};

/// The chain's outcome: the common SolveResult (z = (P_N1, l+, l-), status decided by
/// finalize(), every link in attempts) with the point's type and physical values in
/// `solution` (meaningful when is_solution(status); merit unused, 0).
using StepSolveResult = StepSolveResultOf<StepPoint>;

/// Solves one step. Throws InputError for an invalid problem or options.
StepSolveResult solve_step(const StepProblem& problem, const StepSolveOptions& options = {});

}  // namespace cpkit::rate
