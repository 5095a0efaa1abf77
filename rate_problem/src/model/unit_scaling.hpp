#pragma once
// Internal: the 3-D rate problems are solved in normalized units (|dF|_max = 1, |A|_max = 1) so
// that no intermediate overflows or underflows near the ends of double's range and the verdict
// cannot depend on the user's units; the solutions are scaled back (forces by |dF|, displacement
// rates by |dF| / |A|).
#include <cmath>
#include <cstdio>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"

namespace cpkit::rate3d::detail {

/// The unit of the friction ellipse: its larger half-axis. Multiplying alpha by c and dividing
/// mu by c leaves the friction set ||D^-1 P_T|| <= mu P_N and the flow direction D^-2 P_T
/// unchanged (only the plastic multiplier lambda = |D dw_T^i| scales, by c), so every 3-D
/// solver works with max(alpha) = 1 and the verdict cannot depend on that choice of units.
inline double ellipse_unit(const Eigen::Vector2d& alpha) noexcept {
  const double c = alpha.maxCoeff();
  return c > 0 && std::isfinite(c) ? c : 1.0;
}

/// Puts the friction ellipse of a point (Point3dParameters or SystemPoint3d: fields alpha, mu,
/// k_a) in the unit c = ellipse_unit(alpha): alpha / c, mu c, k_a c (Archard's wear
/// k P_N |D dw_T^i| = k P_N lambda keeps its value; Mroz-Stupkiewicz's c_w = k_M mu follows mu).
/// Returns c: a plastic multiplier of the normalized problem times c is the user's.
/// Point3dParameters::validate() refuses data whose normalized values leave double's range.
template <class Point>
double normalize_ellipse(Point& p) noexcept {
  const double c = ellipse_unit(p.alpha);
  p.alpha /= c;
  p.mu *= c;
  p.k_a *= c;
  return c;
}

struct UnitScaling {
  double force = 1, disp = 1;  ///< multiply normalized forces / displacement rates by these
};

/// Refuses a problem whose own force scale or length scale (force / stiffness) is subnormal:
/// its solution would have to be written with a few significant bits, so that no residual in
/// the user's units could verify it (every 3-D step route calls this, so they agree).
inline void require_representable(double force, double length, const char* what) {
  constexpr double kMin = 2.2250738585072014e-308;  // DBL_MIN, the smallest normal double
  if ((force != 0 && std::abs(force) < kMin) || (length != 0 && std::abs(length) < kMin))
  {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g, length scale %.3g", force, length);
    throw InputError(std::string(what) + ": the force scale of the data (" + buf +
                     ") is a subnormal double: the solution is not representable to the "
                     "solver's accuracy; give the data in units of moderate size");
  }
}

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
