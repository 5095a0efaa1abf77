#pragma once
// Internal: the units a problem is solved in. Every route (rate, step; one point and N points;
// 2-D and 3-D) divides the user's data by its own units so that no intermediate overflows or
// underflows near the ends of double's range and no verdict depends on the user's units; the
// solutions are scaled back. Each route chooses its units (its own function, next to it); the
// type is this one.
#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/model/parameters_3d.hpp"

namespace cpkit::rate::detail {

/// A problem's units: a normalized force is force / `force`, a stiffness / `stiffness`, a length
/// (displacement) / `length` (usually force / stiffness; a route may keep it apart), a 3-D
/// point's plastic multiplier / (`length` x `ellipse`). Routes that scale by exact powers of two
/// (the one-point 2-D step enumeration) keep the exponents instead: force 2^force_exp, stiffness
/// 2^stiffness_exp, length 2^length_exp() (2^exp itself may lie outside double's range).
struct Units {
  double force = 1, stiffness = 1, length = 1;
  double ellipse = 1;  ///< 3-D, one point: ellipse_unit(alpha)
  int force_exp = 0, stiffness_exp = 0;
  int length_exp() const noexcept { return force_exp - stiffness_exp; }
};

/// The unit of the friction ellipse: its larger half-axis. Multiplying alpha by c and dividing
/// mu by c leaves the friction set ||D^-1 P_T|| <= mu P_N and the flow direction D^-2 P_T
/// unchanged (only the plastic multiplier lambda = |D dw_T^i| scales, by c), so every 3-D
/// solver works with max(alpha) = 1 and the verdict cannot depend on that choice of units.
inline double ellipse_unit(const Eigen::Vector2d& alpha) noexcept {
  const double c = alpha.maxCoeff();
  return c > 0 && std::isfinite(c) ? c : 1.0;
}

/// Puts the friction ellipse of a point (ContactParameters3d or SystemPoint3d: fields alpha, mu,
/// k_a) in the unit c = ellipse_unit(alpha): alpha / c, mu c, k_a c (Archard's wear
/// k P_N |D dw_T^i| = k P_N lambda keeps its value; Mroz-Stupkiewicz's c_w = k_M mu follows mu).
/// Returns c: a plastic multiplier of the normalized problem times c is the user's.
/// ContactParameters3d::validate() refuses data whose normalized values leave double's range.
template <class Point>
double normalize_ellipse(Point& p) noexcept {
  const double c = ellipse_unit(p.alpha);
  p.alpha /= c;
  p.mu *= c;
  p.k_a *= c;
  return c;
}

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

/// The normalized 3-D rate problem: A / |A|, C_T |A| (the same compliance), dF / |dF| (dF = 0
/// stays 0); units force |dF|, stiffness |A|, length |dF| / |A|.
inline Units normalize(ContactParameters3d& p, Eigen::Vector3d& dF) {
  const double a = p.A.cwiseAbs().maxCoeff();
  double f = dF.cwiseAbs().maxCoeff();
  if (f == 0) f = 1;
  p.A /= a;
  p.C_T *= a;
  dF /= f;
  if (!std::isfinite(p.C_T))
    throw InputError("C_T x |A| overflows double: give the stiffness and the compliance in "
                     "units of moderate size");
  Units u;
  u.force = f;
  u.stiffness = a;
  u.length = f / a;
  return u;
}

}  // namespace cpkit::rate::detail
