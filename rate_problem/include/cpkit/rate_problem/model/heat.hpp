#pragma once
/// \file heat.hpp
/// Interface temperature from the energy balance [Stromberg et al. 1996, eqns (29)/(30), (33),
/// (43)]: with the entropy (28) S = (C/T0)(T - T0) and the heat fluxes (33)
/// q^l . n^l = vartheta^l (T^l - T) from the bodies l = 1, 2 into the interface,
///   (C/T0) T dT/dt = D + sum_l vartheta^l (T^l - T),
/// where D = p_T . dw_T^i/dt + p_N dw^w/dt is the mechanical dissipation rate (for (38) with
/// Archard: mu p_N |dw_T^i| + k p_N^2 |dw_T^i|, eqn (43)); for Psi_2 the term
/// k_T w_T^r . dw_T^r appears on both sides of (30) and cancels.
/// Units: C heat capacity per area (energy / (area temperature)), temperatures absolute (> 0),
/// vartheta conductance (energy / (time area temperature)), D energy per area.
#include <string>

namespace cpkit::rate {

struct HeatOptions {
  bool enabled = false;
  double heat_capacity = 1;       ///< C >= 0 (C = 0: quasi-steady, needs a conductance > 0)
  double T_ref = 293.15;          ///< T0 of (28), > 0
  double T_initial = 293.15;      ///< interface temperature at the start, > 0
  double T_body[2] = {293.15, 293.15};  ///< T^1, T^2 > 0
  double conductance[2] = {0, 0};       ///< vartheta^1, vartheta^2 >= 0
  std::string validate() const;
};

/// One backward-Euler step of the energy balance over dt > 0 with the step's dissipation
/// D >= 0: (C/T0) T1 (T1 - T) = D + dt sum_l vartheta^l (T^l - T1), a quadratic in T1 with
/// exactly one positive root, taken without cancellation. With C = 0: the quasi-steady value.
double heat_step(const HeatOptions& h, double T, double D, double dt) noexcept;

/// The thermal part of the dissipation (42) over the step: dt sum_l vartheta^l (T^l - T)^2/T^l.
double thermal_dissipation(const HeatOptions& h, double T, double dt) noexcept;

}  // namespace cpkit::rate
