#pragma once
// Internal: the exact signs of the one-point rate problem's critical quantities (docs/model.md,
// Sec. 2; [Stromberg et al. 1996, Sec. 4.3]) on the data as given (doubles taken as exact
// binary numbers), in exact expansion arithmetic (exact_expansion.hpp):
//   N = a11 dF_N - a12 dF_T,  D_s = a11 - s mu a12,
//   L_s = (s + m a12 C_T) dF_T - m (1 + a11 C_T) dF_N,
//   Lambda = a11 - m s a12 + kappa (s a12 - m a22) - m kappa C_T det A   (eqn (51)),
// with kappa = k_a P_N / (3 P_s) and m = mu (criterion 38) or mu - 2 kappa (35) in state d,
// kappa = 0 and m = mu in state b. The division by 3 P_s > 0 is cleared: L_s is judged as
// Q L_s and Lambda as Q^2 Lambda with Q = 3 P_s, which have the same signs and are polynomials
// in the data. Each returns -1, 0, +1, or kUndecided outside the exact range (exact_expansion.hpp).
// The routes call these where a rounding bound cannot decide (a load ON a critical direction).
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "exact_expansion.hpp"

namespace cpkit::rate::detail {

inline int exact_sign_N(const ContactParameters& p, const LoadRate& f) noexcept {
  using E = Expansion;
  return sign3(E(p.a11) * E(f.dF_N) - E(p.a12) * E(f.dF_T));
}

inline int exact_sign_D(const ContactParameters& p, int s) noexcept {
  using E = Expansion;
  return sign3(E(p.a11) - E(s) * E(p.mu) * E(p.a12));
}

namespace exact_signs_detail {
/// Q = 3 P_s, K = k_a P_N (kappa = K / Q) and mQ = m Q of state `st` (m = mu in state b).
struct WearTerms {
  Expansion Q, K, mQ;
};
inline WearTerms wear_terms(const ContactParameters& p, const ContactState& st) noexcept {
  using E = Expansion;
  WearTerms w;
  if (st.label != StateLabel::kD) {  // P_N = 0 (state b): kappa = 0, m = mu, Q = 1
    w.Q = E(1.0);
    w.mQ = E(p.mu);
    return w;
  }
  w.Q = E(3.0) * E(p.P_s);
  w.K = E(p.k_a) * E(st.P_N);
  w.mQ = E(p.mu) * w.Q;
  if (p.criterion == Criterion::kSoftening) w.mQ = w.mQ - E(2.0) * w.K;
  return w;
}
}  // namespace exact_signs_detail

/// The sign of L_s (state b: s = +-1 and st.label = kB; state d: s = st.sgn_PT).
inline int exact_sign_L(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                        int s) noexcept {
  using E = Expansion;
  const exact_signs_detail::WearTerms w = exact_signs_detail::wear_terms(p, st);
  const E c1 = E(1.0) + E(p.a11) * E(p.C_T);
  return sign3((E(s) * w.Q + w.mQ * E(p.a12) * E(p.C_T)) * E(f.dF_T) - w.mQ * c1 * E(f.dF_N));
}

/// The sign of Lambda of eqn (51) for state d with s = st.sgn_PT.
inline int exact_sign_Lambda(const ContactParameters& p, const ContactState& st) noexcept {
  using E = Expansion;
  const exact_signs_detail::WearTerms w = exact_signs_detail::wear_terms(p, st);
  const E a11(p.a11), a12(p.a12), a22(p.a22), S(st.sgn_PT);
  const E det = a11 * a22 - a12 * a12;
  return sign3(a11 * w.Q * w.Q - S * a12 * w.mQ * w.Q + w.K * (S * a12 * w.Q - w.mQ * a22) -
               w.mQ * w.K * E(p.C_T) * det);
}

}  // namespace cpkit::rate::detail
