#pragma once
// Internal: the state-b rate LCP (rate_lcp.cpp, state_b_lcp) enumerated by its complementary
// supports with every sign decided against the rounding of the expression that carries it
// (rounded.hpp), from the data (A, C_T, mu, dF) themselves: no tolerance, no units.
//
// Why (issue 24, item 1 of the brief of h19): enumerate_small judges w >= 0, z > 0, merges and
// singular blocks with fixed relative bands (1e-12 .. 1e4 x 1e-12 of the row sizes). At critical
// loads of ill-conditioned contacts the data decide signs far inside those bands (a slip rate of
// 1e-14 relative, a separation whose dw_N is 1e-15 of its terms), and the route printed a wrong
// set as complete. Here a sign that the rounding cannot decide makes the answer undecided
// (complete: false), never a guess.
//
// The structure used (docs/contact_model.md, Sec. 5; u = z0 = dP_N, xi = z1 - z2 = dw_T^i):
//  - columns 2 and 3 of M are opposite, q2 = -q1, and w0 = -D0 dw_N;
//  - a solution with z1, z2 > 0 adds no physical point (fact (i) of summarize_b_core);
//  - with D_+ = c1 det - a12 (mu D0 - a12) and D_- = c1 det + a12 (mu D0 + a12) nonzero the
//    set is finite and its points are the basic solutions of {}, {1}, {2}, {3}, {1,2}, {1,3},
//    which differ in the signs of (u, xi), so no two of them coincide.
// Every feasibility condition below is a sign of a Cramer numerator (denominators c1, det, D0
// are positive), with w_i = 0 on the support exactly by construction.
#include <cmath>
#include <initializer_list>

#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/rate/detail/state_b_terms.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "exact_expansion.hpp"
#include "rounded.hpp"

namespace cpkit::rate::detail {

struct CertifiedB {
  /// false: the structure does not apply (mu = 0, det A or D_+/D_- not decided nonzero: a
  /// continuum or a (nearly) singular block; the caller keeps its general engine)
  bool applies = false;
  bool undecided = false;  ///< some candidate's existence or type hangs on an undecided sign
  int n = 0;               ///< decided solution points (at most 4: a finite set)
  SolutionType type[6] = {};
  double u[6] = {}, xi[6] = {};  ///< dP_N and dw_T^i of each point (computed values)
};

/// The fast pre-pass in Mag (state_b_terms.hpp: a value and the magnitude of the terms it was
/// formed from). An expression of at most a dozen roundings is within
/// 12 u m of its exact value, so |v| > 1e-13 m decides its sign with a margin of 30; closer
/// (or v = 0 with m > 0) is undecided here and certified_b reruns with Rounded.
inline Mag exact_mag(double x) noexcept { return {x, std::abs(x)}; }
inline Mag operator+(Mag a, Mag b) noexcept { return {a.v + b.v, a.m + b.m}; }
inline Mag operator-(Mag a) noexcept { return {-a.v, a.m}; }
inline Mag operator-(Mag a, Mag b) noexcept { return {a.v - b.v, a.m + b.m}; }
inline Mag operator*(Mag a, Mag b) noexcept { return {a.v * b.v, a.m * b.m}; }
inline int sign3(Mag x) noexcept {
  if (x.m == 0) return 0;
  // the relative bound needs normal numbers: near underflow or overflow Rounded decides
  if (!(x.m >= 1e-250 && x.m <= 1e250)) return kUndecided;
  if (std::abs(x.v) > 1e-13 * x.m) return x.v > 0 ? 1 : -1;
  return kUndecided;
}
inline Mag abs_of(Mag x) noexcept { return {std::abs(x.v), x.m}; }
inline Rounded abs_of(Rounded x) noexcept { return {std::abs(x.v), x.e}; }
inline Rounded make(double x, const Rounded*) noexcept { return exact(x); }
inline Mag make(double x, const Mag*) noexcept { return exact_mag(x); }
inline Expansion make(double x, const Expansion*) noexcept { return Expansion(x); }

/// Three-valued verdict of "x > 0" (strict) and "x >= 0": 1 true, 0 false, kUndecided.
template <class T>
int certified_pos(T x) noexcept {
  const int s = sign3(x);
  return s == kUndecided ? kUndecided : (s > 0 ? 1 : 0);
}
template <class T>
int certified_nonneg(T x) noexcept {
  const int s = sign3(x);
  return s == kUndecided ? kUndecided : (s >= 0 ? 1 : 0);
}

/// The load-independent terms of certified_b_in (A, C_T and mu only; state_b_terms.hpp).
template <class T>
BTerms<T> b_terms(const ContactParameters& p) noexcept {
  BTerms<T> t;
  auto exact = [](double x) { return make(x, static_cast<const T*>(nullptr)); };
  t.a11 = exact(p.a11), t.a12 = exact(p.a12), t.a22 = exact(p.a22);
  const T ct = exact(p.C_T), mu = exact(p.mu);
  const T det = t.a11 * t.a22 - t.a12 * t.a12;
  const T D0 = t.a22 + ct * det;
  t.c1 = exact(1.0) + t.a11 * ct;
  t.a12ct = t.a12 * ct;
  // The Cramer numerators and D_+/- carry the factor D0 > 0 (expanded by hand, checked with
  // sympy): D_+/- = D0 (a11 -/+ mu a12), the numerator of u is D0 N with N = a11 dF_N -
  // a12 dF_T, those of xi on {1,2} / {1,3} are D0 L_+ and -D0 L_- with L_s = (s + mu a12 C_T)
  // dF_T - mu c1 dF_N. Their signs are decided on the reduced forms: the factor det of an
  // ill-conditioned A would add its own rounding (1e-4 relative at cond 1e12) to every bound.
  t.Dp = t.a11 - mu * t.a12, t.Dm = t.a11 + mu * t.a12;
  const T mua12ct = mu * t.a12 * ct;
  t.kp = exact(1.0) + mua12ct;
  t.km = exact(-1.0) + mua12ct;
  t.muc1 = mu * t.c1;
  if (!(p.mu > 0) || sign3(det) != 1 || sign3(D0) != 1 || sign3(t.c1) != 1) return t;
  t.sp = sign3(t.Dp), t.sm = sign3(t.Dm);
  // a singular block, or one within its rounding of singular (the degenerate line
  // a11 = mu |a12| of the presets, exact only up to the rounding of mu): a continuum is
  // possible; the general engine keeps deciding those (left open: its bands, issue 24)
  if (t.sp == 0 || t.sm == 0 || t.sp == kUndecided || t.sm == kUndecided) return t;
  // the general engine's own near-singular band (1e-6 of the terms): the
  // two routes of the N = 1 system and of one point must meet the same continua there
  const double mua12 = std::abs(p.mu * p.a12);
  if (std::abs(t.Dp.v) <= 1e-6 * (p.a11 + mua12) || std::abs(t.Dm.v) <= 1e-6 * (p.a11 + mua12))
    return t;
  t.applies = true;
  return t;
}

/// The decided solution points of the state-b rate problem of (p, f), signs judged in T, from
/// the load-independent terms `b` of p; with kValues false the points' values (u, xi) are
/// left 0 (the map summaries need only the types: the 2-ulp determinants cost three std::fma,
/// which are library calls without -mfma).
template <class T, bool kValues>
CertifiedB certified_b_with(const BTerms<T>& b, const ContactParameters& p,
                            const LoadRate& f) noexcept {
  CertifiedB out;
  if (!b.applies) return out;
  auto exact = [](double x) { return make(x, static_cast<const T*>(nullptr)); };
  const T fT = exact(f.dF_T), fN = exact(f.dF_N);
  const T S = b.c1 * fN - b.a12ct * fT;      // D0 dw_N at dP = 0
  const T r = b.a22 * fT - b.a12 * fN;       // det dw_T^i at dP = 0, dw_N = 0
  const T N = b.a11 * fN - b.a12 * fT;
  const T Lp = b.kp * fT - b.muc1 * fN;
  const T Lm = b.km * fT - b.muc1 * fN;
  const int sp = b.sp, sm = b.sm;
  const T& Dp = b.Dp;
  const T& Dm = b.Dm;
  out.applies = true;
  // a candidate: all conditions 1 -> a point; any 0 -> none; else undecided
  auto add = [&](std::initializer_list<int> conds, SolutionType t, double uu, double xx) {
    bool und = false;
    for (const int c : conds) {
      if (c == 0) return;
      und = und || c == kUndecided;
    }
    if (und) {
      out.undecided = true;
      return;
    }
    out.type[out.n] = t;
    out.u[out.n] = uu;
    out.xi[out.n] = xx;
    ++out.n;
  };
  const int r0 = sign3(r), S0 = sign3(S), N0 = sign3(N);
  // values (not signs) of the 2x2 determinants to 2 ulps, as state_b_lcp has them
  double xi_sep = 0, Nv = 0;
  if (kValues) {
    xi_sep = diff_of_products(p.a22, f.dF_T, p.a12, f.dF_N) /
             diff_of_products(p.a11, p.a22, p.a12, p.a12);
    Nv = diff_of_products(p.a11, f.dF_N, p.a12, f.dF_T);
  }
  // {}: z = 0 needs w1 = -r >= 0 and w2 = r >= 0 (r = 0) and w0 = -S >= 0
  if (r0 != kUndecided && S0 != kUndecided) {
    if (r0 == 0 && S0 <= 0) add({1}, S0 < 0 ? SolutionType::kSeparation : SolutionType::kStick, 0, 0);
  } else {
    add({r0 == kUndecided ? kUndecided : (r0 == 0 ? 1 : 0),
         S0 == kUndecided ? kUndecided : (S0 <= 0 ? 1 : 0)},
        SolutionType::kStick, 0, 0);
  }
  // {2} / {3}: u = 0, xi = r / det != 0, w0 = -D0 N / det >= 0 (> 0: separation)
  {
    const int slip = certified_pos(abs_of(r));
    const int w0 = certified_nonneg(-N);
    const SolutionType t = N0 == -1 ? SolutionType::kSeparation
                                    : (r.v > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus);
    if (N0 == kUndecided && slip == 1 && w0 == 1) out.undecided = true;  // type undecided
    else add({slip, w0}, t, 0.0, xi_sep);
  }
  // {1}: u = S / c1 > 0, xi = 0, w1 c1 = -D0 L_+ >= 0, w2 c1 = -D0 L_- >= 0
  add({certified_pos(S), certified_nonneg(-Lp), certified_nonneg(-Lm)}, SolutionType::kStick,
      S.v / b.c1.v, 0.0);
  // {1,2}: u = N / (a11 - mu a12) > 0, xi = L_+ / (a11 - mu a12) > 0 (w2 = 2 mu D0 u >= 0)
  add({certified_pos(sp > 0 ? N : -N), certified_pos(sp > 0 ? Lp : -Lp)},
      SolutionType::kSlipPlus, Nv / Dp.v, Lp.v / Dp.v);
  // {1,3}: u = N / (a11 + mu a12) > 0, xi = -L_- / (a11 + mu a12) < 0 (w1 = 2 mu D0 u >= 0)
  add({certified_pos(sm > 0 ? N : -N), certified_pos(sm > 0 ? Lm : -Lm)},
      SolutionType::kSlipMinus, Nv / Dm.v, -Lm.v / Dm.v);
  return out;
}


/// The decided solution points of the state-b rate problem of (p, f), signs judged in T.
template <class T, bool kValues>
CertifiedB certified_b_in(const ContactParameters& p, const LoadRate& f) noexcept {
  return certified_b_with<T, kValues>(b_terms<T>(p), p, f);
}

/// certified_b_in with the fast magnitude pass first, Rounded when it cannot decide, and (kExact)
/// the exact expansion (exact_expansion.hpp) when the rounding bound cannot: a load ON a
/// critical direction of binary data (N = 0 or L_s = 0 exactly) is decided exactly (issue 34).
/// The maps' summaries ask without the exact pass: at a computed (rounded) critical direction
/// they want the set on the line, from the signs left undecided.
template <bool kValues = true, bool kExact = true>
CertifiedB certified_b(const ContactParameters& p, const LoadRate& f) noexcept {
  const CertifiedB fast = certified_b_in<Mag, kValues>(p, f);
  if (fast.applies && !fast.undecided) return fast;
  const CertifiedB bounded = certified_b_in<Rounded, kValues>(p, f);
  if (!kExact || (bounded.applies && !bounded.undecided)) return bounded;
  const CertifiedB exact_signs = certified_b_in<Expansion, kValues>(p, f);
  return exact_signs.applies && !exact_signs.undecided ? exact_signs : bounded;
}

}  // namespace cpkit::rate::detail
