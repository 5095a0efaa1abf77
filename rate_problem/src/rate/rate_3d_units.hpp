#pragma once
// Internal: the solutions of a 3-D rate problem solved in normalized units
// (model/unit_scaling.hpp, normalize) scaled back to the user's, and the distance of two rates
// in given units.
#include <algorithm>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate::detail {

inline void rescale(Rates3d& r, const Units& s) {
  r.dP_T *= s.force;
  r.dP_N *= s.force;
  r.dw_T *= s.length;
  r.dw_N *= s.length;
  r.dw_Ti *= s.length;
  r.dw_w *= s.length;
}

/// How far apart two rates are: the largest difference of their forces per `force` and of
/// their displacement rates per `disp` (the one-point faceted route and the N-point route
/// deduplicate solutions by it).
inline double rates_distance(const Rates3d& a, const Rates3d& b, double force, double disp) {
  return std::max({(a.dP_T - b.dP_T).cwiseAbs().maxCoeff() / force, std::abs(a.dP_N - b.dP_N) / force,
                   (a.dw_T - b.dw_T).cwiseAbs().maxCoeff() / disp, std::abs(a.dw_N - b.dw_N) / disp});
}

/// Scales the solutions back; throws InputError when a rate does not fit a double.
inline void rescale(RateSolutionSet3d& set, const Units& s) {
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

}  // namespace cpkit::rate::detail
