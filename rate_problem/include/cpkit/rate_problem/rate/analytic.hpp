#pragma once
/// \file analytic.hpp
/// Route 1 of the rate problem: the closed forms of [Stromberg et al. 1996, Sec. 4.3]
/// (a, b.i-b.iii, c, d.i-d.ii, Lambda of eqn (51)) with the derived state-d slip rates and the
/// degenerate cases a11 = mu|a12| (state b) and Lambda = 0 (state d) as checked in
/// docs/model.md. Independent of the LCP routes (no matrices, no enumeration).
///
/// Criterion (35) (friction softening): states a, b, c are as for (38) (P_N = 0 in a/b, the
/// second-order term of the cone's rate vanishes). In state d the cone is
/// |P_T| = mu P_N - k P_N^2, whose rate is s dP_T <= (mu - 2 kappa) dP_N, while the flow rule
/// (dw_T^i = s lambda, dw^w = kappa lambda) is the same as for (38). Every formula of state d
/// therefore holds with mu replaced by mu_eff = mu - 2 kappa (docs/contact_model.md, Sec. 3).
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

/// Relative band of the enumeration route's snapping of its 1x1 state-d LCP (a nonzero value
/// snapped is reported: the set is then not complete). The analytic route no longer uses a
/// band: each sign it decides (D_s, Lambda, N, L_s) carries the bound of its own rounding, and
/// a value within that bound leaves the set not complete (issue 24).
inline constexpr double kRateTol = 1e-10;

/// The parameter-and-state quantities that decide existence and uniqueness.
struct RateIndicators {
  double detA = 0;     ///< a11 a22 - a12^2
  double D0 = 0;       ///< a22 + C_T det A
  double kappa = 0;    ///< k_a P_N / (3 P_s) (0 in states a, b)
  double mu_eff = 0;   ///< mu for (38); mu - 2 kappa for (35) (only differs in state d)
  double D_plus = 0;   ///< D_+ = a11 - mu a12   (state b, slip+)
  double D_minus = 0;  ///< D_- = a11 + mu a12   (state b, slip-)
  double Lambda = 0;   ///< eqn (51) with s = sgn P_T (state d; 0 otherwise)
  bool unique_for_all_directions = true;  ///< b: a11 > mu|a12|; c, a: true; d: Lambda > 0
};

/// Indicators for a valid (params, state); no validation here.
RateIndicators rate_indicators(const ContactParameters& params, const ContactState& state) noexcept;

/// All solutions by the closed forms. Throws InputError for invalid input.
RateSolutionSet solve_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load);

/// Count and types by the closed forms; inputs must be valid; allocation-free.
RateSummary summarize_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load) noexcept;

}  // namespace cpkit::rate
