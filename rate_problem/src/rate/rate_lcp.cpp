// The state's rate problem as an LCP and the maps back to physical rates (docs/model.md,
// "The rate problem as an LCP"). [Stromberg et al. 1996, Sec. 4.3]
#include "cpkit/rate_problem/rate/rate_lcp.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "rate_detail.hpp"
#include "rounded.hpp"

namespace cpkit::rate {

StateBLcp state_b_lcp(const ContactParameters& p, const LoadRate& f) noexcept {
  // det A and r to 2 ulps (detail::diff_of_products): at cond(A) 1e11 their plain evaluation
  // lost 5 digits, and the separation's rates with them (issue 24)
  const double det = detail::diff_of_products(p.a11, p.a22, p.a12, p.a12);
  const double D0 = p.a22 + p.C_T * det;
  const double c1 = 1.0 + p.a11 * p.C_T;
  const double S = c1 * f.dF_N - p.a12 * p.C_T * f.dF_T;
  const double r = detail::diff_of_products(p.a22, f.dF_T, p.a12, f.dF_N);
  StateBLcp l;
  l.M << c1, p.a12, -p.a12,                 //
      p.mu * D0 - p.a12, det, -det,          //
      p.mu * D0 + p.a12, -det, det;
  l.q << -S, -r, r;
  return l;
}

Rates state_b_rates(const ContactParameters& p, const LoadRate& f,
                    const Eigen::Vector3d& z) noexcept {
  const double det = detail::diff_of_products(p.a11, p.a22, p.a12, p.a12);
  const double D0 = p.a22 + p.C_T * det;
  const double c1 = 1.0 + p.a11 * p.C_T;
  const double S = c1 * f.dF_N - p.a12 * p.C_T * f.dF_T;
  const double xi = z(1) - z(2);
  Rates r;
  r.dP_N = z(0);
  r.dP_T = (detail::diff_of_products(p.a22, f.dF_T, p.a12, f.dF_N) + p.a12 * z(0) - det * xi) / D0;
  r.dw_N = (S - c1 * z(0) - p.a12 * xi) / D0;
  r.dw_T = p.C_T * r.dP_T + xi;
  r.dw_Ti = xi;
  r.dw_w = 0;  // state b: P_N = 0, no wear
  return r;
}

namespace {

/// Solves the rate form of (47), eqn (50), with the two extra equations
///   row 3: dw_T - C_T dP_T = xi        (dw_T = C_T dP_T + dw_T^i, from (27))
///   row 4: e4 . x = b4                 (the state's normal condition)
/// for x = (dP_T, dP_N, dw_T, dw_N) by LU with partial pivoting.
Eigen::Vector4d solve_rate_equations(const ContactParameters& p, const LoadRate& f, double xi,
                                     const Eigen::RowVector4d& e4, double b4) noexcept {
  Eigen::Matrix4d K;
  K << 1, 0, p.a11, p.a12,  //
      0, 1, p.a12, p.a22,   //
      -p.C_T, 0, 1, 0,      //
      e4;
  Eigen::Vector4d rhs(f.dF_T, f.dF_N, xi, b4);
  return K.partialPivLu().solve(rhs);
}

double mu_eff(const ContactParameters& p, const ContactState& st) noexcept {
  return p.criterion == Criterion::kSoftening ? p.mu - 2.0 * p.kappa(st.P_N) : p.mu;
}

}  // namespace

Rates state_d_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                    double lambda) noexcept {
  const int s = st.sgn_PT;
  const double kappa = p.kappa(st.P_N);
  // row 4: dw_N = kappa lambda (= dw^w, the wear keeps the gap closed: w_N - w^w = 0)
  const Eigen::Vector4d x =
      solve_rate_equations(p, f, s * lambda, Eigen::RowVector4d(0, 0, 0, 1), kappa * lambda);
  Rates r;
  r.dP_T = x(0);
  r.dP_N = x(1);
  r.dw_T = x(2);
  r.dw_N = x(3);
  r.dw_Ti = s * lambda;
  r.dw_w = kappa * lambda;
  return r;
}

StateDLcp state_d_lcp(const ContactParameters& p, const ContactState& st,
                      const LoadRate& f) noexcept {
  // w(lambda) = (1 + a11 C_T) (mu_eff dP_N - s dP_T) is affine in lambda: q = w(0),
  // M = w(1) - w(0), evaluated from the rate equations.
  const double c1 = 1.0 + p.a11 * p.C_T;
  const double m = mu_eff(p, st);
  const int s = st.sgn_PT;
  const Rates r0 = state_d_rates(p, st, f, 0.0);
  const Rates r1 = state_d_rates(p, st, LoadRate{}, 1.0);  // the linear part
  StateDLcp l;
  l.q = c1 * (m * r0.dP_N - s * r0.dP_T);
  l.M = c1 * (m * r1.dP_N - s * r1.dP_T);
  // A 1x1 block has no relative size of its own: judge M and q against the size of the terms
  // they are made of (the cancellation that makes Lambda = 0 or L_s = 0 leaves rounding noise
  // of that size), and snap such noise to an exact zero for the enumeration.
  constexpr double kSnap = 1e-10;  // a nonzero value snapped here is reported (`snapped`)
  if (std::abs(l.q) <= kSnap * c1 * (std::abs(m * r0.dP_N) + std::abs(r0.dP_T))) {
    l.snapped = l.snapped || l.q != 0;
    l.q = 0;
  }
  // M ~ Lambda depends on the parameters only. Within the rounding of its LU evaluation
  // (64 u of its terms) it is the degenerate line Lambda = 0 of the presets and tests (exact
  // there, computed with noise) and snapped silently; above that, still inside the band, the
  // data say Lambda != 0 and snapping it is reported (issue 24: mu = a11/|a12| (1 + 1e-12)
  // lost the slip with its large lambda and said complete)
  const double M_terms = c1 * (std::abs(m * r1.dP_N) + std::abs(r1.dP_T));
  if (std::abs(l.M) <= kSnap * M_terms) {
    l.snapped = l.snapped || std::abs(l.M) > 64 * 2.220446049250313e-16 * M_terms;
    l.M = 0;
  }
  return l;
}

namespace detail {

/// States a and c: the linear system (no LCP), solved numerically.
Rates linear_state_rates(const ContactParameters& p, const ContactState& st,
                         const LoadRate& f) noexcept {
  Rates r;
  if (st.label == StateLabel::kA) {
    // dP = 0: A dw = dF; w_T^r = 0 so dw_T^i = dw_T.
    Eigen::Matrix2d A;
    A << p.a11, p.a12, p.a12, p.a22;
    const Eigen::Vector2d dw = A.llt().solve(Eigen::Vector2d(f.dF_T, f.dF_N));
    r.dw_T = dw(0);
    r.dw_N = dw(1);
    r.dw_Ti = r.dw_T;
    return r;
  }
  // c: dw_N = 0, dw_T^i = 0.
  const Eigen::Vector4d x =
      solve_rate_equations(p, f, 0.0, Eigen::RowVector4d(0, 0, 0, 1), 0.0);
  r.dP_T = x(0);
  r.dP_N = x(1);
  r.dw_T = x(2);
  r.dw_N = x(3);
  return r;
}

Rates rate_scale(const ContactParameters& p, const LoadRate& f) noexcept {
  double sF = std::abs(f.dF_T) + std::abs(f.dF_N);
  if (!(sF > 0)) sF = 1.0;
  const double sW = sF * (p.C_T + 1.0 / p.a11 + 1.0 / p.a22);
  Rates s;
  s.dP_T = s.dP_N = sF;
  s.dw_T = s.dw_N = s.dw_Ti = s.dw_w = sW;
  return s;
}

}  // namespace detail

SolutionType classify_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                            const Rates& r) noexcept {
  constexpr double kTol = 1e-9;
  if (st.label == StateLabel::kA) return SolutionType::kOpen;
  const Rates sc = detail::rate_scale(p, f);
  const double force = sc.dP_N + std::abs(r.dP_N) + std::abs(r.dP_T);
  const double disp = sc.dw_T + std::abs(r.dw_T) + std::abs(r.dw_N);
  if (st.label == StateLabel::kB && r.dw_N < -kTol * disp) return SolutionType::kSeparation;
  const double xi_zero = kTol * (disp + force * (p.C_T + 1.0 / p.a11));
  if (r.dw_Ti > xi_zero) return SolutionType::kSlipPlus;
  if (r.dw_Ti < -xi_zero) return SolutionType::kSlipMinus;
  return SolutionType::kStick;
}

LcpProblem rate_lcp_problem(const ContactParameters& p, const ContactState& st,
                            const LoadRate& f) {
  detail::validate_inputs(p, st, f);
  LcpProblem lcp;
  if (st.label == StateLabel::kB) {
    const StateBLcp l = state_b_lcp(p, f);
    lcp.M = l.M;
    lcp.q = l.q;
    lcp.name = "rate problem, state b";
  } else if (st.label == StateLabel::kD) {
    const StateDLcp l = state_d_lcp(p, st, f);
    lcp.M = Mat::Constant(1, 1, l.M);
    lcp.q = Vec::Constant(1, l.q);
    lcp.name = "rate problem, state d";
  } else {
    throw InputError(std::string("state ") + std::string(to_string(st.label)) +
                     " has no rate LCP (its rate problem is a linear system)");
  }
  return lcp;
}

Rates rates_from_lcp_solution(const ContactParameters& p, const ContactState& st,
                              const LoadRate& f, const Vec& z) {
  if (st.label == StateLabel::kB) {
    if (z.size() != 3) throw InputError("state b: the LCP solution must have size 3");
    return state_b_rates(p, f, Eigen::Vector3d(z(0), z(1), z(2)));
  }
  if (st.label == StateLabel::kD) {
    if (z.size() != 1) throw InputError("state d: the LCP solution must have size 1");
    return state_d_rates(p, st, f, z(0));
  }
  throw InputError("states a and c have no rate LCP");
}

}  // namespace cpkit::rate
