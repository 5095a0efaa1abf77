#pragma once
/// \file step_outcome.hpp
/// What `cpkit step` answered (requests/step_request.hpp runs it): the route, its results and
/// the exit code. Here, beside its text and JSON (report/step_text.hpp, report/json.hpp), so
/// that report/ does not include requests/.
#include <string>
#include <vector>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

enum class StepRoute { kPointAll, kPointChain, kSystem, kPoint3d, kSystem3d };

/// A 3-D step's answer, one point or N coupled points.
struct Step3dOutcome {
  ContactSystem3d system;
  std::vector<Step3dState> states;  ///< per point, as the step started
  WearModel wear;
  std::string mode;                 ///< "all", "facets", "multistart" or "chain"
  std::vector<std::string> chain;   ///< mode chain: the links ({"fb-soc"} for N points)
  Step3dSolutionSet set;            ///< one point: the solutions (chain: the one found)
  SystemStep3dSolutionSet system_set;  ///< N points: the solutions
  Status status = Status::kNotRun;  ///< mode chain: the chain's verdict
  std::string solver;               ///< mode chain: the link that solved ("" if none)
  std::vector<Attempt> attempts;    ///< mode chain: every link tried
  int iterations = 0;               ///< mode chain, N points: FB-SOC Newton iterations
  int n_points() const noexcept { return system.n_points(); }
};

/// The answer of a request: the route's results and the exit code (0 at least one solution,
/// 1 none, 5 none found and not proved complete or, 3-D --all/--facets, not proved complete).
struct StepOutcome {
  StepRoute route = StepRoute::kPointAll;
  ExitCode exit_code = kExitOk;
  std::string system;               ///< --system as given (echoed)
  std::vector<double> DF;           ///< --dF as given (echoed)
  int facets = 0, multistart = 0;   ///< echoed by the 3-D routes
  StepSolutionSet set;              ///< one 2-D point: --all's set, or the enumeration an
                                    ///< active-set answer was picked from (has_enumeration)
  bool has_enumeration = false;
  StepSolveResult one;              ///< one 2-D point without --all: the chain's answer
  SystemStepProblem system_problem; ///< N 2-D points
  SystemStepSolutionSet system_set;
  Step3dOutcome step_3d;            ///< one 3-D point or N coupled 3-D points
  std::vector<std::string> errors;  ///< lines for stderr (the program prefixes "cpkit step: ")
};

}  // namespace cpkit::rate
