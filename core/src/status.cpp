#include "cpkit/core/status.hpp"

#include <array>

namespace cpkit {

std::string_view to_string(Status s) noexcept {
  switch (s) {
    case Status::kNotRun: return "not_run";
    case Status::kSolved: return "solved";
    case Status::kSolvedInaccurate: return "solved_inaccurate";
    case Status::kInfeasible: return "infeasible";
    case Status::kRayTermination: return "ray_termination";
    case Status::kIterationLimit: return "iteration_limit";
    case Status::kTimeLimit: return "time_limit";
    case Status::kStalled: return "stalled";
    case Status::kNumericalFailure: return "numerical_failure";
    case Status::kInterrupted: return "interrupted";
    case Status::kUnsupported: return "unsupported";
    case Status::kCycleDetected: return "cycle_detected";
  }
  return "unknown";
}

std::optional<Status> status_from_string(std::string_view name) noexcept {
  constexpr std::array all = {Status::kNotRun,         Status::kSolved,
                              Status::kSolvedInaccurate, Status::kInfeasible,
                              Status::kRayTermination, Status::kIterationLimit,
                              Status::kTimeLimit,      Status::kStalled,
                              Status::kNumericalFailure, Status::kInterrupted,
                              Status::kUnsupported,    Status::kCycleDetected};
  for (Status s : all)
    if (to_string(s) == name) return s;
  return std::nullopt;
}

}  // namespace cpkit
