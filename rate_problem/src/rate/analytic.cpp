// Route 1: the closed forms of [Stromberg et al. 1996, Sec. 4.3] (docs/model.md, Sec. 2).
#include "cpkit/rate_problem/rate/analytic.hpp"

#include <array>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "exact_signs.hpp"
#include "rate_detail.hpp"
#include "rounded.hpp"

namespace cpkit::rate {
namespace {

using detail::diff_of_products;
using detail::exact;
using detail::kUndecided;
using detail::Rounded;
using detail::sign3;

/// Existence of a piece whose condition `pred` depends on up to three signs, some of which may
/// be undecided (kUndecided: any of -1, 0, +1 is possible): 1 when pred holds for every
/// possible combination, 0 when for none, kUndecided otherwise. An undecided piece is listed
/// when pred holds with the undecided signs taken as 0 (the load on the critical line, the
/// former behaviour), and the set is then marked not complete.
template <class Pred>
int decide(int a, int b, int c, const Pred& pred);

int zero_if_undecided(int x) noexcept { return x == kUndecided ? 0 : x; }

/// 1 (list the piece), 0 (do not), after decide()'s rule for undecided signs.
template <class Pred>
int listed(int a, int b, int c, const Pred& pred) {
  const int d = decide(a, b, c, pred);
  if (d != kUndecided) return d;
  return pred(zero_if_undecided(a), zero_if_undecided(b), zero_if_undecided(c)) ? 1 : 0;
}

template <class Pred>
int decide(int a, int b, int c, const Pred& pred) {
  const auto lo = [](int x) { return x == kUndecided ? -1 : x; };
  const auto hi = [](int x) { return x == kUndecided ? 1 : x; };
  bool any_true = false, any_false = false;
  for (int i = lo(a); i <= hi(a); ++i)
    for (int j = lo(b); j <= hi(b); ++j)
      for (int k = lo(c); k <= hi(c); ++k) (pred(i, j, k) ? any_true : any_false) = true;
  if (any_true && any_false) return kUndecided;
  return any_true ? 1 : 0;
}

SolutionType slip_type(int s) noexcept {
  return s > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
}

RateSolution point(SolutionType type, const Rates& r) noexcept {
  RateSolution p;
  p.type = type;
  p.kind = RateSolution::Kind::kPoint;
  p.start = r;
  p.start_closed = true;
  return p;
}

/// dP = 0: dw = A^-1 dF (state a, and separation in state b); dw_T^i = dw_T, no wear.
/// Cramer with accurately computed 2x2 determinants: correct to a few ulps at any cond(A)
/// (issue 24: at cond(A) = 1e11 the plain formula was 20 % off in dw_N).
Rates zero_force_rates(const ContactParameters& p, const LoadRate& f) noexcept {
  Rates r;
  const double det = diff_of_products(p.a11, p.a22, p.a12, p.a12);
  r.dw_T = diff_of_products(p.a22, f.dF_T, p.a12, f.dF_N) / det;
  r.dw_N = diff_of_products(p.a11, f.dF_N, p.a12, f.dF_T) / det;
  r.dw_Ti = r.dw_T;
  return r;
}

/// Stick (b.ii, c, d.i): dP_T = dF_T / (1 + a11 C_T), dP_N = S / (1 + a11 C_T), dw_N = 0,
/// dw_T^i = 0, dw_T = C_T dP_T.
Rates stick_rates(const ContactParameters& p, const LoadRate& f) noexcept {
  const double c1 = 1.0 + p.a11 * p.C_T;
  Rates r;
  r.dP_T = f.dF_T / c1;
  r.dP_N = (c1 * f.dF_N - p.a12 * p.C_T * f.dF_T) / c1;
  r.dw_T = p.C_T * r.dP_T;
  return r;
}

/// Slip of sign s with plastic multiplier lambda, normal force rate dP_N, friction slope m
/// (dP_T = s m dP_N) and wear kappa (dw_N = dw^w = kappa lambda).
Rates slip_rates(const ContactParameters& p, int s, double m, double kappa, double dP_N,
                 double lambda) noexcept {
  Rates r;
  r.dP_N = dP_N;
  r.dP_T = s * m * dP_N;
  r.dw_Ti = s * lambda;
  r.dw_N = kappa * lambda;
  r.dw_w = kappa * lambda;
  r.dw_T = p.C_T * r.dP_T + s * lambda;
  return r;
}

/// The state-b solutions (b.i-b.iii), including the degenerate line a11 = mu|a12|. Every sign
/// is three-valued (rounded.hpp): a piece whose existence the computed signs do not decide
/// marks the list undecided instead of being guessed.
void state_b(const ContactParameters& p, const LoadRate& f, detail::SmallPieceList& out,
             bool exact_signs) noexcept {
  const Rounded a11 = exact(p.a11), a12 = exact(p.a12), mu = exact(p.mu), CT = exact(p.C_T);
  const Rounded FT = exact(f.dF_T), FN = exact(f.dF_N);
  const Rounded c1 = exact(1.0) + a11 * CT;
  const Rounded N = a11 * FN - a12 * FT;
  // a sign within its rounding bound (data ON a critical load) is evaluated exactly
  // (exact_signs.hpp); kUndecided remains only outside the exact range
  const int sN = sign3(N) != kUndecided || !exact_signs ? sign3(N) : detail::exact_sign_N(p, f);
  ContactState grazing;
  grazing.label = StateLabel::kB;
  Rounded L[2], D[2];
  int sL[2], sD[2];
  for (int k = 0; k < 2; ++k) {
    const double s = k == 0 ? 1.0 : -1.0;
    L[k] = (exact(s) + mu * a12 * CT) * FT - mu * c1 * FN;
    D[k] = a11 - exact(s) * mu * a12;
    sL[k] = sign3(L[k]);
    sD[k] = sign3(D[k]);
    if (!exact_signs) continue;
    if (sL[k] == kUndecided) sL[k] = detail::exact_sign_L(p, grazing, f, k == 0 ? 1 : -1);
    if (sD[k] == kUndecided) sD[k] = detail::exact_sign_D(p, k == 0 ? 1 : -1);
  }
  const auto add = [&](int a, int b, auto pred, const RateSolution& piece) {
    if (decide(a, b, 0, pred) == kUndecided) out.undecided = true;
    if (listed(a, b, 0, pred) == 1) out.push(piece);
  };
  // b.i separation: N < 0.
  add(sN, 0, [](int n, int, int) { return n < 0; },
      point(SolutionType::kSeparation, zero_force_rates(p, f)));
  // b.ii stick: L_+ <= 0 and L_- <= 0 (equivalently |dF_T| <= mu S; implies S >= 0).
  add(sL[0], sL[1], [](int lp, int lm, int) { return lp <= 0 && lm <= 0; },
      point(SolutionType::kStick, stick_rates(p, f)));
  // b.iii slip of sign s: dP_N = N / D_s >= 0, lambda = L_s / D_s > 0; on the degenerate line
  // D_s = 0 (a11 = s mu a12, so s = sgn a12) solutions exist only on N = 0, where the
  // equations reduce to (1 + a11 C_T) dP_N + |a12| lambda = dF_N: with dF_N > 0 the segment
  // from the stick point (lambda = 0, not a slip: open end) to zero-force slip (dP_N = 0,
  // lambda = dF_N / |a12|: closed end); with dF_N <= 0 no slip of sign s.
  for (int k = 0; k < 2; ++k) {
    const int s = k == 0 ? 1 : -1;
    const bool FN_pos = f.dF_N > 0;  // an input: its sign is exact
    const auto point_pred = [](int d, int l, int n) {
      return d != 0 && l == d && (n == 0 || n == d);
    };
    const auto segment_pred = [FN_pos](int d, int n, int) { return d == 0 && n == 0 && FN_pos; };
    if (decide(sD[k], sL[k], sN, point_pred) == kUndecided ||
        decide(sD[k], sN, 0, segment_pred) == kUndecided)
      out.undecided = true;
    if (listed(sD[k], sL[k], sN, point_pred) == 1) {
      const double dP_N = sN == 0 || sN == kUndecided ? 0.0 : N.v / D[k].v;
      out.push(point(slip_type(s), slip_rates(p, s, p.mu, 0.0, dP_N, L[k].v / D[k].v)));
    }
    if (listed(sD[k], sN, 0, segment_pred) == 1) {
      const double c1v = 1.0 + p.a11 * p.C_T;
      RateSolution seg;
      seg.type = slip_type(s);
      seg.kind = RateSolution::Kind::kSegment;
      seg.start = slip_rates(p, s, p.mu, 0.0, f.dF_N / c1v, 0.0);
      seg.start_closed = false;
      seg.end = slip_rates(p, s, p.mu, 0.0, 0.0, f.dF_N / std::abs(p.a12));
      seg.end_closed = true;
      out.push(seg);
      out.infinite = true;
    }
  }
}

/// Lambda of eqn (51) (mu -> m = mu_eff) with its rounding error.
Rounded lambda_51(const ContactParameters& p, int s, Rounded m, Rounded kappa) noexcept {
  const Rounded a11 = exact(p.a11), a12 = exact(p.a12), a22 = exact(p.a22), S = exact(s);
  const Rounded det = a11 * a22 - a12 * a12;
  return a11 - m * S * a12 + kappa * (S * a12 - m * a22) - m * kappa * exact(p.C_T) * det;
}

/// kappa = k_a P_N / (3 P_s) and m = mu_eff (mu, or mu - 2 kappa for (35)) with their errors.
void kappa_and_m(const ContactParameters& p, const ContactState& st, Rounded& kappa,
                 Rounded& m) noexcept {
  kappa = exact(p.k_a) * exact(st.P_N) / (exact(3.0) * exact(p.P_s));
  m = p.criterion == Criterion::kSoftening ? exact(p.mu) - exact(2.0) * kappa : exact(p.mu);
}

/// The state-d solutions (d.i-d.ii) with Lambda of eqn (51) (mu -> mu_eff for (35)).
void state_d(const ContactParameters& p, const ContactState& st, const LoadRate& f,
             detail::SmallPieceList& out, bool exact_signs) noexcept {
  const int s = st.sgn_PT;
  const double kappa = p.kappa(st.P_N);
  const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * kappa : p.mu;
  const double c1 = 1.0 + p.a11 * p.C_T;
  Rounded kr, mr;
  kappa_and_m(p, st, kr, mr);
  const Rounded L = (exact(s) + mr * exact(p.a12) * exact(p.C_T)) * exact(f.dF_T) -
                    mr * (exact(1.0) + exact(p.a11) * exact(p.C_T)) * exact(f.dF_N);
  const Rounded Lam = lambda_51(p, s, mr, kr);
  const double Lambda = Lam.v;
  // a sign within its rounding bound (data ON a critical load) is evaluated exactly
  const int sL =
      sign3(L) != kUndecided || !exact_signs ? sign3(L) : detail::exact_sign_L(p, st, f, s);
  const int sLam =
      sign3(Lam) != kUndecided || !exact_signs ? sign3(Lam) : detail::exact_sign_Lambda(p, st);
  // d.i stick: L_s <= 0.
  const auto stick_pred = [](int l, int, int) { return l <= 0; };
  const auto slip_pred = [](int lam, int l, int) { return lam != 0 && l == lam; };
  const auto ray_pred = [](int lam, int l, int) { return lam == 0 && l == 0; };
  if (decide(sL, 0, 0, stick_pred) == kUndecided || decide(sLam, sL, 0, slip_pred) == kUndecided ||
      decide(sLam, sL, 0, ray_pred) == kUndecided)
    out.undecided = true;
  if (listed(sL, 0, 0, stick_pred) == 1) out.push(point(SolutionType::kStick, stick_rates(p, f)));
  // d.ii slip: lambda = L_s / Lambda > 0 (a point when Lambda != 0); Lambda = 0: the slip
  // equations have rank one, consistent iff L_s = 0, and then a ray.
  const int ray_exists = listed(sLam, sL, 0, ray_pred);
  if (listed(sLam, sL, 0, slip_pred) == 1) {
    const double dP_N =
        ((p.a11 + s * p.a12 * kappa) * f.dF_N - (p.a12 + s * p.a22 * kappa) * f.dF_T) / Lambda;
    out.push(point(slip_type(s), slip_rates(p, s, m, kappa, dP_N, L.v / Lambda)));
  }
  if (ray_exists != 1) return;
  // Lambda = 0: the slip equations have rank one; consistent iff L_s = 0, and then every
  // lambda > 0 solves them: a ray from the stick point (open there) along the null direction.
  // Rows of the slip system in (dP_N, lambda): pick the one with the larger dP_N coefficient
  // (never both zero since mu > 0 or the second row's leading 1).
  const double r1a = s * m * c1, r1b = s * p.a11 + p.a12 * kappa;
  const double r2a = 1.0 + s * m * p.a12 * p.C_T, r2b = s * p.a12 + p.a22 * kappa;
  const double dPN_per_lambda = std::abs(r1a) >= std::abs(r2a) ? -r1b / r1a : -r2b / r2a;
  RateSolution ray;
  ray.type = slip_type(s);
  ray.kind = RateSolution::Kind::kRay;
  ray.start = stick_rates(p, f);
  ray.start_closed = false;
  Rates d;
  d.dP_N = dPN_per_lambda;
  d.dP_T = s * m * dPN_per_lambda;
  d.dw_Ti = s;
  d.dw_N = kappa;
  d.dw_w = kappa;
  d.dw_T = p.C_T * d.dP_T + s;
  ray.direction = d;
  out.push(ray);
  out.infinite = true;
}

}  // namespace

RateIndicators rate_indicators(const ContactParameters& p, const ContactState& st) noexcept {
  RateIndicators r;
  r.detA = p.detA();
  r.D0 = p.D0();
  r.D_plus = p.a11 - p.mu * p.a12;
  r.D_minus = p.a11 + p.mu * p.a12;
  r.mu_eff = p.mu;
  switch (st.label) {
    case StateLabel::kA:
    case StateLabel::kC:
      r.unique_for_all_directions = true;
      break;
    case StateLabel::kB: {
      // a11 > mu |a12|: both D_s decidedly positive (within their rounding: not unique)
      const Rounded Dp = exact(p.a11) - exact(p.mu) * exact(p.a12);
      const Rounded Dm = exact(p.a11) + exact(p.mu) * exact(p.a12);
      r.unique_for_all_directions = sign3(Dp) == 1 && sign3(Dm) == 1;
      break;
    }
    case StateLabel::kD: {
      const int s = st.sgn_PT;
      r.kappa = p.kappa(st.P_N);
      const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * r.kappa : p.mu;
      r.mu_eff = m;
      Rounded kr, mr;
      kappa_and_m(p, st, kr, mr);
      const Rounded Lam = lambda_51(p, s, mr, kr);
      r.Lambda = Lam.v;
      r.unique_for_all_directions = sign3(Lam) == 1;
      break;
    }
  }
  if (st.label == StateLabel::kC) r.kappa = p.kappa(st.P_N);
  return r;
}

namespace detail {

void analytic_pieces(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                     SmallPieceList& out, bool exact) noexcept {
  out.n = 0;
  out.infinite = false;
  out.undecided = false;
  switch (st.label) {
    case StateLabel::kA: {
      // a: dP = 0, dw = A^-1 dF; w_T^r = dw_T^r = 0, so dw_T^i = dw_T.
      Rates r = zero_force_rates(p, f);
      out.push(point(SolutionType::kOpen, r));
      break;
    }
    case StateLabel::kB:
      state_b(p, f, out, exact);
      break;
    case StateLabel::kC:
      out.push(point(SolutionType::kStick, stick_rates(p, f)));
      break;
    case StateLabel::kD:
      state_d(p, st, f, out, exact);
      break;
  }
}

}  // namespace detail

RateSolutionSet solve_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load) {
  detail::validate_inputs(params, state, load);
  detail::SmallPieceList list;
  detail::analytic_pieces(params, state, load, list);
  RateSolutionSet out = detail::make_solution_set(params, state, load, list, true);
  if (list.undecided)
    out.message = "analytic route: a sign that decides a solution is within the rounding error "
                  "of its expression (a load or parameters at a critical value): not decided";
  return out;
}

RateSummary summarize_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load) noexcept {
  // no exact pass: a map's computed critical direction is a rounded point of the line, whose
  // summary the maps want "on the line" (undecided signs taken as 0, flagged unreliable)
  detail::SmallPieceList list;
  detail::analytic_pieces(params, state, load, list, false);
  return detail::summarize(list);
}

}  // namespace cpkit::rate
