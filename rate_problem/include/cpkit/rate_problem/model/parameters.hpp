#pragma once
/// \file parameters.hpp
/// Parameters of the one-point contact problem of [Stromberg-Johansson-Klarbring 1996, Sec. 4]
/// (working equations: docs/model.md). Units: any consistent set; A is a stiffness
/// (force/length), C_T a compliance (length/force), P_s a hardness (force/area, same unit as
/// P_N when forces are per unit area), k_a dimensionless.
#include <string>
#include <string_view>
#include <optional>

#include "cpkit/rate_problem/model/interface_parameters.hpp"

namespace cpkit::rate {

/// Friction-and-wear criterion.
enum class Criterion {
  kCoulomb,    ///< eqn (38): |P_T| <= mu P_N (exact Coulomb; the paper's Sec. 4 choice)
  kSoftening,  ///< eqn (35): |P_T| <= mu P_N - k P_N^2, needs P_N <= 3 P_s mu / k_a (46)
};
std::string_view to_string(Criterion c) noexcept;  ///< "coulomb" / "softening"
std::optional<Criterion> criterion_from_string(std::string_view s) noexcept;  ///< also "38"/"35"

/// One 2-D point alone: its interface data (mu, C_T, k_a, P_s, k(), kappa()), its stiffness
/// block and the friction criterion, which in 2-D is the point's cone.
struct ContactParameters : InterfaceParameters {
  double a11 = 1, a12 = 0, a22 = 1;  ///< A = [[a11, a12], [a12, a22]], symmetric positive definite
  Criterion criterion = Criterion::kCoulomb;

  double detA() const noexcept { return a11 * a22 - a12 * a12; }
  double D0() const noexcept { return a22 + C_T * detA(); }     ///< model.md Sec. 2
  /// Empty when usable; else names the field (A not SPD, mu <= 0, C_T < 0, NaN, ...).
  std::string validate() const;
};

}  // namespace cpkit::rate
