#pragma once
/// \file contact_state.hpp
/// Contact states of [Stromberg et al. 1996, Sec. 4.2]:
///   a) open:     P = 0, w_N - w^w < 0
///   b) grazing:  P = 0, w_N - w^w = 0
///   c) stick:    |P_T| < mu P_N, P_N > 0
///   d) sliding:  |P_T| = mu P_N, P_N > 0 (s = sgn P_T)
#include <optional>
#include <string>
#include <string_view>

#include "cpkit/rate_problem/model/parameters.hpp"

namespace cpkit::rate {

enum class StateLabel { kA, kB, kC, kD };
std::string_view to_string(StateLabel s) noexcept;  ///< "a", "b", "c", "d"
std::optional<StateLabel> state_from_string(std::string_view s) noexcept;

/// A contact state as the rate problem needs it: the label, P_N (> 0 in c and d) and, in d,
/// the sign s = sgn P_T of the sliding direction (+1 or -1).
struct ContactState {
  StateLabel label = StateLabel::kB;
  double P_N = 0;
  int sgn_PT = +1;
  /// Empty when usable with `params` (e.g. P_N > 0 in c/d, sgn in {-1, +1}, (46) for (35)).
  std::string validate(const ContactParameters& params) const;
};

/// The full configuration (w_N, w^w, w_T, P_N, P_T) of the one-point problem.
struct ContactConfiguration {
  double w_N = 0, w_w = 0, w_T = 0, P_N = 0, P_T = 0;
};

/// Classifies a configuration into a-d; |values| <= tol * (1 + scale) count as zero
/// (tolerance documented in docs/contact_model.md). Throws InputError for an inadmissible one
/// (P_N < 0, penetration, |P_T| > mu P_N beyond tolerance, P_T != 0 with P_N = 0).
ContactState classify(const ContactConfiguration& c, const ContactParameters& p,
                      double tol = 1e-12);

}  // namespace cpkit::rate
