#include "cpkit/rate_problem/model/heat.hpp"

#include <cmath>
#include <sstream>

namespace cpkit::rate {

std::string HeatOptions::validate() const {
  std::ostringstream msg;
  if (!std::isfinite(heat_capacity) || heat_capacity < 0)
    msg << "heat_capacity = " << heat_capacity << " must be finite and >= 0";
  else if (!std::isfinite(T_ref) || !(T_ref > 0))
    msg << "T_ref = " << T_ref << " must be a positive absolute temperature";
  else if (!std::isfinite(T_initial) || !(T_initial > 0))
    msg << "T_initial = " << T_initial << " must be a positive absolute temperature";
  else if (!std::isfinite(T_body[0]) || !(T_body[0] > 0) || !std::isfinite(T_body[1]) ||
           !(T_body[1] > 0))
    msg << "body temperatures (" << T_body[0] << ", " << T_body[1]
        << ") must be positive absolute temperatures";
  else if (!std::isfinite(conductance[0]) || conductance[0] < 0 ||
           !std::isfinite(conductance[1]) || conductance[1] < 0)
    msg << "conductances (" << conductance[0] << ", " << conductance[1] << ") must be >= 0";
  else if (enabled && heat_capacity == 0 && conductance[0] + conductance[1] == 0)
    msg << "heat_capacity = 0 needs a positive conductance (else the temperature is undefined)";
  return msg.str();
}

double heat_step(const HeatOptions& h, double T, double D, double dt) noexcept {
  const double th = h.conductance[0] + h.conductance[1];
  const double inflow = D + dt * (h.conductance[0] * h.T_body[0] + h.conductance[1] * h.T_body[1]);
  if (h.heat_capacity == 0) return inflow / (dt * th);
  // a T1^2 + b T1 + c = 0, a > 0, c = -inflow < 0 (D >= 0): one positive root.
  const double a = h.heat_capacity / h.T_ref;
  const double b = -a * T + dt * th;
  const double c = -inflow;
  const double disc = b * b - 4 * a * c;
  const double sq = std::sqrt(std::max(disc, 0.0));
  const double q = -0.5 * (b + (b < 0 ? -sq : sq));
  // b >= 0: q < 0 and the positive root is c/q; b < 0: q > 0 and it is q/a.
  return b >= 0 ? c / q : q / a;
}

double thermal_dissipation(const HeatOptions& h, double T, double dt) noexcept {
  double s = 0;
  for (int l = 0; l < 2; ++l) {
    const double th = T - h.T_body[l];
    s += h.conductance[l] * th * th / h.T_body[l];
  }
  return dt * s;
}

}  // namespace cpkit::rate
