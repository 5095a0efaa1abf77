#pragma once
/// \file step_result.hpp
/// The results of a step, one family for one point and N points, 2-D and 3-D: the set of its
/// solutions and the outcome of one iterative solve, each a template over the route's solution
/// (Step3dSolution, SystemStep3dSolution, StepSolution, SystemStepSolution, the 2-D chain's
/// StepPoint). The old names are aliases (Step3dSolutionSet, SystemStep3dSolutionSet,
/// Step3dSolveResult, SystemStep3dSolveResult, Step3dChainResult, StepSolveResult); a route
/// with more to say derives and adds it (StepSolutionSet: pieces and jumps;
/// SystemStepSolutionSet: its notes and the active sets examined).
#include <string>
#include <vector>

#include "cpkit/core/result.hpp"

namespace cpkit::rate {

/// The solutions of a step found by one route. `complete` says whether every solution is
/// listed; only a complete enumeration sets it (a multistart never does), and when it is false
/// `message` says why.
template <class Solution>
struct StepSolutionSetOf {
  std::vector<Solution> solutions;
  bool complete = true;
  std::string message;
  int count() const noexcept { return static_cast<int>(solutions.size()); }
};

/// The outcome of one iterative solve of a step: the common SolveResult (status granted only by
/// the route's verdict, iterations, seconds, message, z and residuals) with the step's solution.
template <class Solution>
struct StepSolveResultOf : SolveResult {
  Solution solution;  ///< the final iterate (a solution when status == kSolved)
  double merit = 0;   ///< 0.5 |Phi|^2 at the end of a Newton solve (normalized units; a chain: 0)
};

}  // namespace cpkit::rate
