#pragma once
// Private to system_step.cpp: the units the N-point step is enumerated in, and the way back.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate::detail {

/// The units the enumeration works in: force unit f (the largest force of the data) and length
/// unit l = f / max|A_ij| (so that A is O(1)). The step is invariant under a change of units
/// (forces / f, lengths / l, A l / f, C_T f / l, k_a f), so enumerating in these units makes
/// every tolerance unit-free and keeps loads near the ends of double's range representable
/// (issue 24, items 4 and 5).
inline Units step_units(const SystemStepProblem& p) {
  const ContactSystem& s = p.system;
  const double amax = s.A.cwiseAbs().maxCoeff();
  double f = p.DF.cwiseAbs().maxCoeff(), gmax = 0;
  for (const auto& q : s.points) {
    f = std::max({f, std::abs(q.P_N), std::abs(q.P_T)});
    gmax = std::max(gmax, std::abs(q.g));
  }
  if (!(f > 0)) f = amax * gmax;  // no force at all: the force that closes the largest gap
  if (!(f > 0) || !std::isfinite(f)) f = amax;  // nothing but A: every unknown is zero
  Units u;
  u.force = f;
  u.stiffness = amax;
  // f / amax beyond double's range: the nearest representable length unit (the solution may
  // still fit; from_units says when it does not)
  u.length = std::min(std::max(f / amax, std::numeric_limits<double>::min()),
                 std::numeric_limits<double>::max());
  return u;
}

[[noreturn]] inline void not_representable(const std::string& what) {
  throw InputError("the step is not representable in double precision: " + what +
                   " (rescale the data: forces and displacements beyond about 1e308 or below "
                   "1e-308 in the units of the problem)");
}

inline SystemStepProblem to_units(const SystemStepProblem& p, const Units& u) {
  SystemStepProblem q = p;
  q.system.A = p.system.A * (u.length / u.force);
  q.DF = p.DF / u.force;
  for (auto& x : q.system.points) {
    x.P_N /= u.force;
    x.P_T /= u.force;
    x.g /= u.length;
    x.C_T *= u.force / u.length;
    x.k_a *= u.force;
  }
  if (!q.system.A.allFinite() || !q.DF.allFinite()) not_representable("A or DF in units of the load");
  for (const auto& x : q.system.points)
    if (!std::isfinite(x.P_N) || !std::isfinite(x.P_T) || !std::isfinite(x.g) ||
        !std::isfinite(x.C_T) || !std::isfinite(x.k_a))
      not_representable("a point's data in units of the load");
  return q;
}

inline void from_units(StepValues& v, const Units& u) {
  for (double* x : {&v.DP_T, &v.DP_N, &v.P_T1, &v.P_N1}) *x *= u.force;
  for (double* x : {&v.Dw_T, &v.Dw_N, &v.Dw_Ti, &v.Dw_w, &v.g1}) *x *= u.length;
  for (double x : {v.DP_T, v.DP_N, v.P_T1, v.P_N1, v.Dw_T, v.Dw_N, v.Dw_Ti, v.Dw_w, v.g1})
    if (!std::isfinite(x)) not_representable("a solution's forces or displacements overflow");
}

}  // namespace cpkit::rate::detail
