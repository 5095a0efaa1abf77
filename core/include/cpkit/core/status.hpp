#pragma once
/// \file status.hpp
/// The one outcome enum shared by every cpkit solver.
#include <optional>
#include <string_view>

namespace cpkit {

/// Outcome of a solve. Only finalize() grants kSolved / kSolvedInaccurate, and only finalize()
/// grants kInfeasible (after re-checking a certificate from the problem data).
enum class Status {
  kNotRun,             ///< no solver ran (e.g. an empty chain)
  kSolved,             ///< verified: scaled natural residual <= CommonOptions::tol
  kSolvedInaccurate,   ///< verified: residual in (tol, tol_acceptable]
  kInfeasible,         ///< proven: result.certificate holds a re-checked Farkas proof
  kRayTermination,     ///< Lemke ended on a secondary ray; no proof of infeasibility for this M
  kIterationLimit,     ///< iteration or pivot limit reached
  kTimeLimit,          ///< CommonOptions::time_limit_s reached
  kStalled,            ///< no progress possible (e.g. line search failed repeatedly)
  kNumericalFailure,   ///< breakdown, non-finite values, or a claim the data refute
  kInterrupted,        ///< stopped by the caller
  kUnsupported,        ///< the solver does not accept this problem (e.g. storage or kind)
  kCycleDetected,      ///< a pivoting method revisited a basis (a bug: reported, not looped)
};

/// Stable lower-case names used by the CLI and JSON ("solved", "ray_termination", ...).
std::string_view to_string(Status s) noexcept;
/// Inverse of to_string; std::nullopt for an unknown name.
std::optional<Status> status_from_string(std::string_view name) noexcept;
/// True for kSolved and kSolvedInaccurate.
constexpr bool is_solution(Status s) noexcept {
  return s == Status::kSolved || s == Status::kSolvedInaccurate;
}

}  // namespace cpkit
