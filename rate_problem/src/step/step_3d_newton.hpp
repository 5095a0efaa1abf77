#pragma once
// Internal: what the semismooth Newton solve of a 3-D step does the same way for one point
// (step_solvers_3d.cpp, fixed-size 4) and N points (system_step_3d.cpp, 4N): the one damped
// Newton loop run with the step's iteration limit (and the status an unverified stop claims),
// and the message of a result the verdict did not accept.
#include <string>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/damped_newton.hpp"

namespace cpkit::rate::detail {

/// Runs lcp::damped_newton_counted from z (normalized; overwritten with the last iterate) with
/// the limit o.max_iterations (0: 100), its counters and final merit recorded in `out`.
/// Returns what the stop claims should the caller's check not verify z: kIterationLimit at the
/// limit, kNumericalFailure for a non-finite Phi, else kStalled.
template <class Vector, class Matrix, class Eval, class Done, class Result>
Status run_newton_3d(Vector& z, Eval&& eval, Done&& done, const CommonOptions& o, Result& out) {
  lcp::DampedNewtonStats st;
  const lcp::DampedNewtonStop stop =
      lcp::damped_newton_counted<Vector, Matrix>(z, eval, done, o.max_iterations, out, st);
  out.merit = st.merit;
  switch (stop) {
    case lcp::DampedNewtonStop::kIterationLimit: return Status::kIterationLimit;
    case lcp::DampedNewtonStop::kNonFinite: return Status::kNumericalFailure;
    default: return Status::kStalled;
  }
}

/// After the verdict: a result that is not kSolved says why (its residual, the iterations and
/// the final merit).
template <class Result>
void explain_unverified(Result& out) {
  if (out.status != Status::kSolved)
    out.message = "no verified solution: residual " + std::to_string(out.solution.residual) +
                  " after " + std::to_string(out.iterations) + " iterations (merit " +
                  std::to_string(out.merit) + ")";
}

}  // namespace cpkit::rate::detail
