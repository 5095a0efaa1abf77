#pragma once
/// \file interface_parameters.hpp
/// The data of a contact interface that every point has, in 2-D and 3-D, alone or in a system
/// [Stromberg-Johansson-Klarbring 1996, Sec. 4; docs/model.md]: friction, tangential compliance
/// and Archard wear. The one-point parameters (ContactParameters, ContactParameters3d) and the
/// points of a system (SystemPoint, SystemPoint3d) derive from it, so that `p.mu` is the same
/// field wherever it is held and a point's interface data are copied as one value. Units: any
/// consistent set; C_T a compliance (length/force), P_s a hardness (force/area, the unit of P_N
/// when forces are per unit area), mu and k_a dimensionless.

namespace cpkit::rate {

struct InterfaceParameters {
  double mu = 0.5;  ///< friction coefficient, > 0
  double C_T = 0;   ///< tangential compliance 1/k_T >= 0 (0: Psi_1, rigid)
  double k_a = 0;   ///< Archard wear coefficient >= 0 (0: no wear)
  double P_s = 1;   ///< hardness > 0

  double k() const noexcept { return k_a / (3.0 * P_s); }       ///< Archard k = k_a / (3 P_s)
  double kappa(double P_N) const noexcept { return k() * P_N; } ///< kappa = k_a P_N / (3 P_s)
};

}  // namespace cpkit::rate
