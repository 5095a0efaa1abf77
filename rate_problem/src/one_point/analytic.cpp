// Route 1: the closed forms of [Stromberg et al. 1996, Sec. 4.3] (docs/model.md, Sec. 2).
#include "cpkit/rate_problem/one_point/analytic.hpp"

#include <array>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "rate_detail.hpp"

namespace cpkit::rate {
namespace {

/// -1, 0, +1 with "zero" meaning |x| <= kRateTol * scale (scale: sum of |terms| of x).
int sign_tol(double x, double scale) noexcept {
  if (std::abs(x) <= kRateTol * scale) return 0;
  return x > 0 ? 1 : -1;
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
Rates zero_force_rates(const ContactParameters& p, const LoadRate& f) noexcept {
  Rates r;
  const double det = p.detA();
  r.dw_T = (p.a22 * f.dF_T - p.a12 * f.dF_N) / det;
  r.dw_N = (p.a11 * f.dF_N - p.a12 * f.dF_T) / det;
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

/// The state-b solutions (b.i-b.iii), including the degenerate line a11 = mu|a12|.
void state_b(const ContactParameters& p, const LoadRate& f, detail::SmallPieceList& out) noexcept {
  const double c1 = 1.0 + p.a11 * p.C_T;
  const double N = p.a11 * f.dF_N - p.a12 * f.dF_T;
  const int sN = sign_tol(N, std::abs(p.a11 * f.dF_N) + std::abs(p.a12 * f.dF_T));
  int sL[2], sD[2];
  for (int k = 0; k < 2; ++k) {
    const int s = k == 0 ? 1 : -1;
    const double L = (s + p.mu * p.a12 * p.C_T) * f.dF_T - p.mu * c1 * f.dF_N;
    sL[k] = sign_tol(L, (1.0 + p.mu * std::abs(p.a12) * p.C_T) * std::abs(f.dF_T) +
                            p.mu * c1 * std::abs(f.dF_N));
    const double D = p.a11 - s * p.mu * p.a12;
    sD[k] = sign_tol(D, p.a11 + p.mu * std::abs(p.a12));
  }
  // b.i separation: N < 0.
  if (sN < 0) out.push(point(SolutionType::kSeparation, zero_force_rates(p, f)));
  // b.ii stick: L_+ <= 0 and L_- <= 0 (equivalently |dF_T| <= mu S; implies S >= 0).
  if (sL[0] <= 0 && sL[1] <= 0) out.push(point(SolutionType::kStick, stick_rates(p, f)));
  // b.iii slip of sign s: dP_N = N / D_s >= 0, lambda = L_s / D_s > 0.
  for (int k = 0; k < 2; ++k) {
    const int s = k == 0 ? 1 : -1;
    const double L = (s + p.mu * p.a12 * p.C_T) * f.dF_T - p.mu * c1 * f.dF_N;
    const double D = p.a11 - s * p.mu * p.a12;
    if (sD[k] != 0) {
      if (sL[k] == sD[k] && (sN == 0 || sN == sD[k])) {
        const double dP_N = sN == 0 ? 0.0 : N / D;
        out.push(point(slip_type(s), slip_rates(p, s, p.mu, 0.0, dP_N, L / D)));
      }
      continue;
    }
    // Degenerate D_s = 0 (a11 = s mu a12, so s = sgn a12): solutions only on N = 0, where the
    // equations reduce to (1 + a11 C_T) dP_N + |a12| lambda = dF_N. With dF_N > 0 this is the
    // segment from the stick point (lambda = 0, not a slip: open end) to zero-force slip
    // (dP_N = 0, lambda = dF_N / |a12|: closed end). With dF_N <= 0 there is no slip of sign s.
    const double scale = std::abs(f.dF_T) + std::abs(f.dF_N);
    if (sN == 0 && f.dF_N > kRateTol * scale) {
      RateSolution seg;
      seg.type = slip_type(s);
      seg.kind = RateSolution::Kind::kSegment;
      seg.start = slip_rates(p, s, p.mu, 0.0, f.dF_N / c1, 0.0);
      seg.start_closed = false;
      seg.end = slip_rates(p, s, p.mu, 0.0, 0.0, f.dF_N / std::abs(p.a12));
      seg.end_closed = true;
      out.push(seg);
      out.infinite = true;
    }
  }
}

/// The state-d solutions (d.i-d.ii) with Lambda of eqn (51) (mu -> mu_eff for (35)).
void state_d(const ContactParameters& p, const ContactState& st, const LoadRate& f,
             detail::SmallPieceList& out) noexcept {
  const int s = st.sgn_PT;
  const double kappa = p.kappa(st.P_N);
  const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * kappa : p.mu;
  const double am = std::abs(m);
  const double c1 = 1.0 + p.a11 * p.C_T;
  const double det = p.detA();
  const double L = (s + m * p.a12 * p.C_T) * f.dF_T - m * c1 * f.dF_N;
  const int sL = sign_tol(L, (1.0 + am * std::abs(p.a12) * p.C_T) * std::abs(f.dF_T) +
                                 am * c1 * std::abs(f.dF_N));
  const double Lambda = p.a11 - m * s * p.a12 + kappa * (s * p.a12 - m * p.a22) -
                        m * kappa * p.C_T * det;
  const int sLam = sign_tol(Lambda, p.a11 + am * std::abs(p.a12) +
                                        kappa * (std::abs(p.a12) + am * p.a22) +
                                        am * kappa * p.C_T * (p.a11 * p.a22 + p.a12 * p.a12));
  // d.i stick: L_s <= 0.
  if (sL <= 0) out.push(point(SolutionType::kStick, stick_rates(p, f)));
  // d.ii slip: lambda = L_s / Lambda > 0.
  if (sLam != 0) {
    if (sL == sLam) {
      const double dP_N =
          ((p.a11 + s * p.a12 * kappa) * f.dF_N - (p.a12 + s * p.a22 * kappa) * f.dF_T) / Lambda;
      out.push(point(slip_type(s), slip_rates(p, s, m, kappa, dP_N, L / Lambda)));
    }
    return;
  }
  // Lambda = 0: the slip equations have rank one; consistent iff L_s = 0, and then every
  // lambda > 0 solves them: a ray from the stick point (open there) along the null direction.
  if (sL != 0) return;
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
      // a11 > mu |a12|, with the degenerate line judged by the same tolerance as the solver.
      const double dmin = std::min(r.D_plus, r.D_minus);
      r.unique_for_all_directions = sign_tol(dmin, p.a11 + p.mu * std::abs(p.a12)) > 0;
      break;
    }
    case StateLabel::kD: {
      const int s = st.sgn_PT;
      r.kappa = p.kappa(st.P_N);
      const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * r.kappa : p.mu;
      const double am = std::abs(m);
      r.mu_eff = m;
      r.Lambda = p.a11 - m * s * p.a12 + r.kappa * (s * p.a12 - m * p.a22) -
                 m * r.kappa * p.C_T * r.detA;
      r.unique_for_all_directions =
          sign_tol(r.Lambda, p.a11 + am * std::abs(p.a12) + r.kappa * (std::abs(p.a12) + am * p.a22) +
                                 am * r.kappa * p.C_T * (p.a11 * p.a22 + p.a12 * p.a12)) > 0;
      break;
    }
  }
  if (st.label == StateLabel::kC) r.kappa = p.kappa(st.P_N);
  return r;
}

namespace detail {

void analytic_pieces(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                     SmallPieceList& out) noexcept {
  out.n = 0;
  out.infinite = false;
  switch (st.label) {
    case StateLabel::kA: {
      // a: dP = 0, dw = A^-1 dF; w_T^r = dw_T^r = 0, so dw_T^i = dw_T.
      Rates r = zero_force_rates(p, f);
      out.push(point(SolutionType::kOpen, r));
      break;
    }
    case StateLabel::kB:
      state_b(p, f, out);
      break;
    case StateLabel::kC:
      out.push(point(SolutionType::kStick, stick_rates(p, f)));
      break;
    case StateLabel::kD:
      state_d(p, st, f, out);
      break;
  }
}

}  // namespace detail

RateSolutionSet solve_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load) {
  detail::validate_inputs(params, state, load);
  detail::SmallPieceList list;
  detail::analytic_pieces(params, state, load, list);
  return detail::make_solution_set(params, state, load, list, true);
}

RateSummary summarize_rate_analytic(const ContactParameters& params, const ContactState& state,
                                    const LoadRate& load) noexcept {
  detail::SmallPieceList list;
  detail::analytic_pieces(params, state, load, list);
  return detail::summarize(list);
}

}  // namespace cpkit::rate
