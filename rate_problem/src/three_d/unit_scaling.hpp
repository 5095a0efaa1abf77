#pragma once
// Internal: the 3-D rate problems are solved in normalized units (|dF|_max = 1, |A|_max = 1) so
// that no intermediate overflows or underflows near the ends of double's range and the verdict
// cannot depend on the user's units; the solutions are scaled back (forces by |dF|, displacement
// rates by |dF| / |A|).
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/three_d/point_rate_3d.hpp"

namespace cpkit::rate3d::detail {

struct UnitScaling {
  double force = 1, disp = 1;  ///< multiply normalized forces / displacement rates by these
};

/// The normalized problem: A / |A|, C_T |A| (the same compliance), dF / |dF| (dF = 0 stays 0).
inline UnitScaling normalize(Point3dParameters& p, Eigen::Vector3d& dF) {
  const double a = p.A.cwiseAbs().maxCoeff();
  double f = dF.cwiseAbs().maxCoeff();
  if (f == 0) f = 1;
  p.A /= a;
  p.C_T *= a;
  dF /= f;
  if (!std::isfinite(p.C_T))
    throw InputError("C_T x |A| overflows double: give the stiffness and the compliance in "
                     "units of moderate size");
  return {f, f / a};
}

inline void rescale(Rates3d& r, const UnitScaling& s) {
  r.dP_T *= s.force;
  r.dP_N *= s.force;
  r.dw_T *= s.disp;
  r.dw_N *= s.disp;
  r.dw_Ti *= s.disp;
  r.dw_w *= s.disp;
}

/// Scales the solutions back; throws InputError when a rate does not fit a double.
inline void rescale(RateSolutionSet3d& set, const UnitScaling& s) {
  for (auto& x : set.solutions) {
    rescale(x.at, s);
    rescale(x.direction, s);
    for (const Rates3d* r : {&x.at, &x.direction})
      if (!r->dP_T.allFinite() || !std::isfinite(r->dP_N) || !r->dw_T.allFinite() ||
          !std::isfinite(r->dw_N) || !r->dw_Ti.allFinite() || !std::isfinite(r->dw_w))
        throw InputError("the rates overflow double (|dF| / |A| is too large): give the load "
                         "rate and the stiffness in units of moderate size");
  }
}

}  // namespace cpkit::rate3d::detail
