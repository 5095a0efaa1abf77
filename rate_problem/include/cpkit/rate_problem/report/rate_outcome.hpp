#pragma once
/// \file rate_outcome.hpp
/// What `cpkit rate` answered (requests/rate_request.hpp runs it): the route's result, the echo
/// of its input, the exit code and the notes for stderr. Here, beside its text and JSON
/// (report/rate_text.hpp, report/json.hpp), so that report/ does not include requests/.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::rate {

/// The answer to a RateRequest: the route's result, the echo of its input, the exit code and
/// the lines for stderr (without the "cpkit rate: " the program puts before each).
struct RateOutcome {
  enum class Route { kOnePoint, kSystem, kSystem3d };
  Route route = Route::kOnePoint;
  std::string method;  ///< as given
  std::string state;   ///< one point: the state as given
  std::optional<CheckedRateSolution> one_point;
  // --system: the file, its name, its points and the load rate used (--dF or the file's)
  std::string path, name;
  int n_points = 0;
  Eigen::VectorXd dF;
  std::optional<SystemRateSolutionSet> system;     ///< a 2-D system
  std::optional<SystemRateRoute3d> system_3d;      ///< a 3-D system
  int facets = 0;                                  ///< 3-D: --facets (0: exact)
  char first_state = 0;                            ///< 3-D: the state of point 1
  ExitCode exit_code = kExitOk;  ///< 0 a solution, 1 none, 3 disagreement, 5 inconclusive
  std::vector<std::string> notes;  ///< why the exit code is 3 or 5, for stderr
};

}  // namespace cpkit::rate
