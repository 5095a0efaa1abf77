#pragma once
/// \file wear.hpp
/// The wear laws of the model [Stromberg, Johansson & Klarbring 1996]: one enum for the 2-D
/// point, N points and the 3-D point (the 3-D forms are (40) and (41) with the elliptic norm,
/// docs/contact_3d.md). A new wear law is a new WearLaw value and its names (kWearLawNames) here,
/// then its term in each step.
///
/// Units: k_M is a length/force (wear gap per unit of frictional work); the Archard
/// coefficient k = k_a / (3 P_s) comes from the contact parameters (k_a dimensionless, P_s a
/// force/area like the hardness).
#include <optional>
#include <string_view>

#include "cpkit/core/enum_names.hpp"

namespace cpkit::rate {

/// Which wear law closes the step.
enum class WearLaw {
  kArchard,          ///< eqn (37): dw^w = k_a/(3 P_s) p_N |dw_T^i| (from normality of (35)/(38))
  kMrozStupkiewicz,  ///< eqn (41): dw^w = k_M p_T . dw_T^i (needs the Coulomb criterion (38))
};

/// The names of the laws, each first, then its aliases ("mroz", and the paper's equation
/// numbers "37", "41"), for to_string and wear_law_from_string.
inline constexpr EnumName<WearLaw> kWearLawNames[] = {
    {WearLaw::kArchard, "archard"},
    {WearLaw::kArchard, "37"},
    {WearLaw::kMrozStupkiewicz, "mroz-stupkiewicz"},
    {WearLaw::kMrozStupkiewicz, "mroz"},
    {WearLaw::kMrozStupkiewicz, "41"},
};

/// "archard" / "mroz-stupkiewicz"
inline std::string_view to_string(WearLaw w) noexcept { return name_of(kWearLawNames, w); }

/// Also accepts "mroz", "37", "41".
inline std::optional<WearLaw> wear_law_from_string(std::string_view s) noexcept {
  return value_of(kWearLawNames, s);
}

/// The wear model of a step. For kArchard the coefficient comes from ContactParameters
/// (k = k_a / (3 P_s)); for kMrozStupkiewicz it is k_M (length/force, >= 0).
struct WearModel {
  WearLaw law = WearLaw::kArchard;
  double k_M = 0;
};

}  // namespace cpkit::rate
