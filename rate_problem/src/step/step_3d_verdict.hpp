#pragma once
// Internal: the verdict of a 3-D step, shared by the one-point step (finalize_step_3d,
// step_solvers_3d.cpp) and the N-point step (system_step_3d.cpp), so that "solved" means the
// same for both (as core/finalize.hpp's decision for an LCP).
#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <string>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"

namespace cpkit::rate::detail {

/// Sets r.z to (P_T1, P_N1, lambda) of each of the `points` values in turn, r.residuals to the
/// step residual recomputed from those values and the data (`residual`, unit-free), and decides
/// r.status from it: kSolved when <= tol, kSolvedInaccurate up to tol_acceptable, whatever was
/// claimed; a claimed solution the residual refutes becomes kNumericalFailure (the reason is
/// appended to r.message); other claimed failures are kept.
inline void decide_step_3d(SolveResult& r, const Step3dValues* values, std::size_t points,
                           double residual, const CommonOptions& o) {
  const bool claimed = is_solution(r.status);
  r.z.resize(static_cast<Eigen::Index>(4 * points));
  for (std::size_t i = 0; i < points; ++i)
    r.z.segment<4>(static_cast<Eigen::Index>(4 * i)) << values[i].P_T1, values[i].P_N1,
        values[i].lambda;
  r.residuals = Residuals{};
  r.residuals.natural = residual;
  r.residuals.finite = std::isfinite(residual);
  if (residual <= o.tol) {
    r.status = Status::kSolved;
  } else if (residual <= o.tol_acceptable) {
    r.status = Status::kSolvedInaccurate;
  } else if (claimed) {
    r.status = Status::kNumericalFailure;
    r.message += (r.message.empty() ? "" : "; ") +
                 std::string("claimed solution refuted: residual ") + std::to_string(residual);
  }
}

}  // namespace cpkit::rate::detail
