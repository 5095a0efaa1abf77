// The rate problem of one 3-D contact point with the elliptic law (38)-(40):
// docs/contact_3d.md has the derivation; the equation tags (3D.n) below refer to it.
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/spd.hpp"
#include "rate_3d_units.hpp"

namespace cpkit::rate {
namespace {

/// "Zero" for a quantity computed as a sum of terms: |x| <= kTol * (sum of |terms|), as the
/// 2-D rate problem's kRateTol.
constexpr double kTol = 1e-10;
constexpr double kPi = 3.14159265358979323846;
/// A forward result of a solve with matrix M is known to about kRound cond(M) of its size
/// (a generous multiple of the unit roundoff): signs inside that band are not decided.
constexpr double kRound = 64 * 2.220446049250313e-16;
/// |g| at a root relative to g's scale (the rounding of its evaluation, with margin).
constexpr double kRootTol = 1e-9;

/// cond_2(M) by the singular values (inf when singular).
template <class M>
double condition_number(const M& m) {
  const auto sv = m.jacobiSvd().singularValues();
  const double lo = sv(sv.size() - 1);
  return lo > 0 ? sv(0) / lo : INFINITY;
}

bool finite(const Eigen::MatrixXd& m) { return m.allFinite(); }

std::string num(double x) { return num_text(x, 10); }

/// The blocks of A and the ellipse, shared by the states.
struct Blocks {
  Eigen::Matrix2d ATT;
  Eigen::Vector2d ATN;
  double ANN = 0;
  Eigen::Matrix2d D, Dinv;
  Eigen::Matrix2d K;  ///< I + C_T A_TT (SPD)
  double A_scale = 0; ///< max |A_ij|
};

Blocks blocks(const ContactParameters3d& p) {
  Blocks b;
  b.ATT = p.A.topLeftCorner<2, 2>();
  b.ATN = p.A.topRightCorner<2, 1>();
  b.ANN = p.A(2, 2);
  b.D = p.alpha.asDiagonal();
  b.Dinv = p.alpha.cwiseInverse().asDiagonal();
  b.K = Eigen::Matrix2d::Identity() + p.C_T * b.ATT;
  b.A_scale = p.A.cwiseAbs().maxCoeff();
  return b;
}

/// Stick (states b, c): dw_T^i = 0, dw_N = 0 (3D.3).
Rates3d stick_rates(const ContactParameters3d& p, const Blocks& b, const Eigen::Vector3d& dF) {
  Rates3d r;
  r.dP_T = b.K.ldlt().solve(dF.head<2>());
  r.dP_N = dF(2) - p.C_T * b.ATN.dot(r.dP_T);
  r.dw_T = p.C_T * r.dP_T;
  return r;
}

/// |dF - dP - A dw| relative to the terms: the check every listed solution passes.
double equilibrium_residual(const ContactParameters3d& p, const Eigen::Vector3d& dF,
                            const Rates3d& r) {
  const Eigen::Vector3d dP(r.dP_T(0), r.dP_T(1), r.dP_N);
  const Eigen::Vector3d dw(r.dw_T(0), r.dw_T(1), r.dw_N);
  const Eigen::Vector3d Adw = p.A * dw;
  const double scale = dF.cwiseAbs().maxCoeff() + dP.cwiseAbs().maxCoeff() +
                       (p.A.cwiseAbs() * dw.cwiseAbs()).maxCoeff();
  const double res = (dF - dP - Adw).cwiseAbs().maxCoeff();
  return scale > 0 ? res / scale : res;
}

RateSolution3d point_solution(SolutionType type, const Rates3d& r) {
  RateSolution3d s;
  s.type = type;
  s.at = r;
  if (type == SolutionType::kSlip && r.dw_Ti.norm() > 0) {
    s.slip_direction = r.dw_Ti.normalized();
    s.slip_angle = std::atan2(s.slip_direction(1), s.slip_direction(0));
  }
  return s;
}

/// Unit vector of the angle phi.
Eigen::Vector2d unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

/// The columns of the slip system B(t) (3D.5): B(t) [dP_N, lambda] = dF with
/// column 0 = e_N + mu G t and column 1 = H t.
struct SlipSystem {
  Eigen::Matrix<double, 3, 2> G, H;
  double mu = 0;
  Eigen::Matrix<double, 3, 2> at(const Eigen::Vector2d& t) const {
    Eigen::Matrix<double, 3, 2> B;
    B.col(0) = Eigen::Vector3d(0, 0, 1) + mu * G * t;
    B.col(1) = H * t;
    return B;
  }
};

/// g'' (for the width of a double root's band).
double second_derivative(const SlipDirectionFunction& g, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return 2 * (g.d - g.a) * (c * c - s * s) - 4 * g.b * c * s - g.e * c - g.f * s;
}

SlipSystem slip_system(const ContactParameters3d& p, const Blocks& b) {
  SlipSystem s;
  s.mu = p.mu;
  s.G.topRows<2>() = b.K * b.D;
  s.G.row(2) = p.C_T * b.ATN.transpose() * b.D;
  s.H = p.A.leftCols<2>() * b.Dinv;
  return s;
}

/// True when every slip with a direction in [phi - radius, phi + radius] (sampled) is
/// inadmissible: the least-squares (dP_N, lambda) of B(t) z = dF has dP_N or lambda clearly
/// negative. A direction where B(t) has rank one (singular for every load) has no slip when dF
/// is outside its range; near it the slips grow without bound along B's null vector, whose
/// sign pattern the samples see.
bool slips_inadmissible(const SlipSystem& sys, const Eigen::Vector3d& dF, double phi,
                        double radius) {
  constexpr int kSamples = 8;
  for (int j = -kSamples; j <= kSamples; ++j) {
    const double ph = phi + radius * j / kSamples;
    Eigen::Matrix<double, 3, 2> B = sys.at(Eigen::Vector2d(std::cos(ph), std::sin(ph)));
    const Eigen::Vector2d cn(B.col(0).norm(), B.col(1).norm());
    if (!(cn(0) > 0) || !(cn(1) > 0)) return false;
    B.col(0) /= cn(0);
    B.col(1) /= cn(1);
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(B, Eigen::ComputeFullU |
                                                                   Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    if (!(sv(1) > 1e-9 * sv(0))) {
      const Eigen::Vector3d fn = dF.normalized(), u0 = svd.matrixU().col(0);
      if ((fn - u0 * u0.dot(fn)).norm() > 1e-7) continue;  // dF outside the range: no slip
      return false;
    }
    const Eigen::Vector2d z = svd.solve(dF).cwiseQuotient(cn);
    const double margin = 1e-6 * z.cwiseAbs().maxCoeff();
    if (!z.allFinite() || !(z(0) < -margin || z(1) < -margin)) return false;
  }
  return true;
}

double det3(const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  return u.dot(v.cross(w));
}

void not_proved(RateSolutionSet3d& set, const std::string& why) {
  set.complete = false;
  if (set.message.empty()) set.message = why;
}

/// The separation of state b, appended to `set` when dw_N < 0 beyond rounding; `undecided`
/// when dw_N is 0 within the rounding of the solve. Returns dw = A^-1 dF.
Eigen::Vector3d separation_solution(const ContactParameters3d& p, const Eigen::Vector3d& dF,
                                    RateSolutionSet3d& set, bool& undecided) {
  // Separation: dP = 0, dw = A^-1 dF with dw_N < 0 (3D.2). dw_N is a forward result: its sign
  // is decided only outside the rounding band of the solve (cond(A) eps |dw|); inside it the
  // separation is the contact solution with dP = 0 (listed below as a slip with dP_N = 0), or
  // undecided.
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(p.A);
  const Eigen::Vector3d dw_sep = ldlt.solve(dF);
  // The solve is backward stable (residual ~ eps |A| |dw|); the row N of A^-1 carries that
  // into dw_N.
  const Eigen::Vector3d row_N = ldlt.solve(Eigen::Vector3d::UnitZ());
  const double band = std::max(kTol * dw_sep.cwiseAbs().maxCoeff(),
                               kRound * row_N.cwiseAbs().sum() *
                                   (p.A.cwiseAbs() * dw_sep.cwiseAbs()).maxCoeff());
  if (dw_sep(2) < -band) {
    Rates3d r;
    r.dw_T = dw_sep.head<2>();
    r.dw_N = dw_sep(2);
    r.dw_Ti = r.dw_T;
    set.solutions.push_back(point_solution(SolutionType::kSeparation, r));
  } else if (dw_sep(2) <= band) {
    undecided = true;
  }
  return dw_sep;
}

/// The stick of state b, appended to `set` when ||dP_T|| <= mu dP_N to rounding; returns whether.
bool stick_solution(const ContactParameters3d& p, const Blocks& b, const Eigen::Vector3d& dF,
                    RateSolutionSet3d& set) {
  // Stick: ||dP_T|| <= mu dP_N (closed), to the rounding of the 2x2 solve.
  const Rates3d r = stick_rates(p, b, dF);
  const double norm = Eigen::Vector2d(b.Dinv * r.dP_T).stableNorm();
  const double band = std::max(kTol * (norm + p.mu * std::abs(r.dP_N)),
                               kRound * condition_number(b.K) *
                                   (b.Dinv.diagonal().maxCoeff() + p.mu * p.C_T * b.A_scale) *
                                   r.dP_T.cwiseAbs().maxCoeff());
  if (norm - p.mu * r.dP_N <= band) {
    set.solutions.push_back(point_solution(SolutionType::kStick, r));
    return true;
  }
  return false;
}

/// The slip directions of state b: every real root phi of g (3D.6), through the quartic in
/// u = tan(psi / 2) (3D.7) and Newton on g, sorted and deduplicated in (phi0 - pi, phi0 + pi];
/// complex_re gets the real parts of the non-real pairs. Returns false (the reason in `set`)
/// when g cannot be resolved.
bool slip_direction_roots(const SlipDirectionFunction& g, double g_scale, RateSolutionSet3d& set,
                          std::vector<double>& roots, std::vector<double>& complex_re) {
  if (!std::isfinite(g_scale)) {
    set.complete = false;
    set.message = "the slip-direction condition overflows double: slip directions are not resolved";
    return false;
  }
  if (!(g_scale > 0)) {
    set.complete = false;
    set.message = "the slip-direction condition vanishes identically (dF = 0): slip "
                  "directions are not resolved";
    return false;
  }
  // Shift the angle origin so that the quartic's leading coefficient, g at the origin's
  // opposite direction, is as far from zero as possible (no root at u = infinity).
  double phi0 = 0, best = -1;
  for (int k = 0; k < 16; ++k) {
    const double c = k * kPi / 8;
    if (std::abs(g(c + kPi)) > best) best = std::abs(g(c + kPi)), phi0 = c;
  }
  if (best <= 1e-12 * g_scale) {
    set.complete = false;
    set.message = "the slip-direction condition vanishes in every sampled direction (within "
                  "rounding): slip directions are not resolved";
    return false;
  }
  // In psi = phi - phi0 with u = tan(psi / 2): (1 + u^2)^2 g = quartic (3D.7).
  const Eigen::Vector2d c0 = unit(phi0), s0 = unit(phi0 + kPi / 2);
  Eigen::Matrix2d Q;
  Q << g.a, g.b / 2, g.b / 2, g.d;
  Eigen::Matrix2d R;
  R.col(0) = c0;
  R.col(1) = s0;
  const Eigen::Matrix2d Qr = R.transpose() * Q * R;
  const Eigen::Vector2d lr = R.transpose() * Eigen::Vector2d(g.e, g.f);
  const double a = Qr(0, 0), bb = 2 * Qr(0, 1), d = Qr(1, 1), e = lr(0), f = lr(1);
  Eigen::Matrix<double, 5, 1> coeff;
  coeff << a + e, 2 * bb + 2 * f, -2 * a + 4 * d, -2 * bb + 2 * f, a - e;
  Eigen::PolynomialSolver<double, 4> poly(coeff);
  for (const auto& z : poly.roots()) {
    if (std::abs(z.imag()) <= 1e-6 * (1 + std::abs(z.real())))
      roots.push_back(phi0 + 2 * std::atan(z.real()));
    else if (z.imag() > 0)
      complex_re.push_back(phi0 + 2 * std::atan(z.real()));
  }
  // Newton on g itself (not the quartic: no conditioning from the substitution).
  for (double& r : roots)
    for (int it = 0; it < 30; ++it) {
      const double gp = g.derivative(r);
      if (gp == 0) break;
      const double step = g(r) / gp;
      r -= step;
      if (std::abs(step) <= 1e-15 * (1 + std::abs(r))) break;
    }
  // A root that Newton lost (not finite) cannot be trusted: the list is then not proved.
  const std::size_t before = roots.size();
  roots.erase(std::remove_if(roots.begin(), roots.end(), [](double r) { return !std::isfinite(r); }),
              roots.end());
  if (roots.size() != before) {
    set.complete = false;
    set.message = "a slip direction could not be refined (not finite): not proved complete";
  }
  // Angles in (phi0 - pi, phi0 + pi], sorted and deduplicated.
  for (double& r : roots) r = phi0 + std::remainder(r - phi0, 2 * kPi);
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end(),
                          [](double x, double y) { return std::abs(x - y) <= 1e-9; }),
              roots.end());
  return true;
}

/// The completeness certificate of the slip directions (see below); `set` is marked not
/// complete, with the reason, where it fails.
void certify_slip_roots(const SlipDirectionFunction& g, double g_scale, const SlipSystem& sys,
                        const Eigen::Vector3d& dF, const std::vector<double>& roots,
                        const std::vector<double>& complex_re, RateSolutionSet3d& set) {
  // Completeness certificate (docs/contact_3d.md, "Completeness"): every root simple, g clearly
  // away from zero where a non-real pair sits, and the signs between roots alternate. A spot
  // that fails this (a double root, a nearly real pair) is still harmless when every slip in
  // the band of directions where its roots can lie is inadmissible (lambda < 0 or dP_N < 0):
  // no admissible slip can be hidden there (the eigenvector directions of A_TT with
  // mu A_NT . t = its eigenvalue, singular for every load, are such spots).
  auto harmless = [&](double phi) {
    const double g2 = std::abs(second_derivative(g, phi));
    if (!(g2 > 1e-7 * g_scale)) return false;  // a triple root or flatter: not resolved
    const double radius = std::sqrt(2 * kRootTol * g_scale / g2) + 1e-9;
    return slips_inadmissible(sys, dF, phi, radius);
  };
  if (std::any_of(roots.begin(), roots.end(), [&](double r) { return std::abs(g(r)) > kRootTol * g_scale; }))
    not_proved(set, "a slip direction is not resolved (the slip condition does not vanish there to "
               "its rounding): not proved complete");
  const std::size_t m = roots.size();
  std::vector<bool> spot(m, false);  // a harmless double root (no sign test across it)
  for (std::size_t k = 0; k < m; ++k)
    if (std::abs(g.derivative(roots[k])) <= 1e-7 * g_scale) {
      if (harmless(roots[k]))
        spot[k] = true;
      else
        not_proved(set, "a slip direction at phi = " + num(roots[k]) + " is a double root of the slip "
                   "condition (a critical load direction): not proved complete");
    }
  for (double x : complex_re)
    if (std::abs(g(x)) <= 1e-7 * g_scale && !harmless(x))
      not_proved(set, "the slip condition nearly vanishes at phi = " + num(x) +
                 " without a root (a critical load direction): not proved complete");
  for (std::size_t k = 0; m >= 2 && k < m; ++k) {
    if (spot[k]) continue;
    // the arcs before and after roots[k] (cyclic)
    const double prev = k > 0 ? roots[k - 1] : roots[m - 1] - 2 * kPi;
    const double next = k + 1 < m ? roots[k + 1] : roots[0] + 2 * kPi;
    if (!(g((prev + roots[k]) / 2) * g((roots[k] + next) / 2) < 0))
      not_proved(set, "the slip condition does not change sign at phi = " + num(roots[k]) +
                 ": not proved complete");
  }
  // The number of sign changes around the circle is even: an odd count of simple roots means
  // one was lost.
  if (std::count(spot.begin(), spot.end(), false) % 2 != 0)
    not_proved(set, "an odd number of slip directions: the slip condition is not resolved");

}

/// The admissible slips of state b, one per root phi: the 3x2 system for (dP_N, lambda).
void slip_solutions(const ContactParameters3d& p, const Blocks& b, const SlipSystem& sys,
                    const Eigen::Vector3d& dF, const std::vector<double>& roots,
                    bool stick_listed, RateSolutionSet3d& set) {
  const double f_scale = dF.cwiseAbs().maxCoeff();
  const double lambda_scale = f_scale / b.A_scale;
  for (double phi : roots) {
    const Eigen::Vector2d t = unit(phi);
    // Columns in different units (force/force, stiffness): equilibrate them before judging
    // the rank, so that the verdict does not depend on units.
    Eigen::Matrix<double, 3, 2> B = sys.at(t);
    const Eigen::Vector2d col_norm(B.col(0).norm(), B.col(1).norm());
    B.col(0) /= col_norm(0);
    B.col(1) /= col_norm(1);
    if (!B.allFinite()) {
      not_proved(set, "the slip system is not finite in the direction phi = " + num(phi) +
                 ": not resolved");
      continue;
    }
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(B, Eigen::ComputeFullU |
                                                                   Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    if (!(sv(1) > 1e-9 * sv(0))) {  // also NaN
      // B(t) of rank one makes g vanish at t for every dF (e.g. an isotropic A_TT = a I with
      // mu A_NT . t = a). A dF outside B's range has no slip in this direction; inside it, the
      // slips would be a continuum, which is not resolved.
      if (sv(0) > 0 && std::isfinite(sv(0))) {
        const Eigen::Vector3d fn = dF.normalized();
        const Eigen::Vector3d u0 = svd.matrixU().col(0);
        if ((fn - u0 * u0.dot(fn)).norm() > 1e-7) continue;
      }
      not_proved(set, "the slip system is singular in the direction phi = " + num(phi) +
                 " (a continuum of solutions): not resolved");
      continue;
    }
    const Eigen::Vector2d x = svd.solve(dF).cwiseQuotient(col_norm);
    const double dP_N = x(0), lambda = x(1);
    // Signs are decided outside the rounding band of the solve (|dF| eps / sigma_min of the
    // equilibrated B); inside it dP_N is 0 (clamped below) and lambda = 0 is the stick point.
    const double band = std::max(kTol, kRound / sv(1)) * f_scale;
    if (dP_N < -band / col_norm(0)) continue;         // negative normal force rate
    if (lambda < -band / col_norm(1)) continue;       // a negative multiplier
    if (lambda <= std::max(kTol * lambda_scale, band / col_norm(1))) {
      // lambda = 0 within rounding: the stick on the cone's boundary, listed above, or undecided.
      if (!stick_listed)
        not_proved(set, "the slip direction phi = " + num(phi) + " has a multiplier at the rounding "
                   "level while the stick is not admissible: not resolved");
      continue;
    }
    Rates3d r;
    r.dP_N = std::max(dP_N, 0.0);
    r.dP_T = p.mu * r.dP_N * (b.D * t);
    r.dw_Ti = lambda * (b.Dinv * t);
    r.dw_T = p.C_T * r.dP_T + r.dw_Ti;
    if (equilibrium_residual(p, dF, r) > 1e-8) {
      not_proved(set, "the slip direction phi = " + num(phi) + " gives rates that do not satisfy "
                 "the equilibrium to 1e-8: not resolved");
      continue;
    }
    set.solutions.push_back(point_solution(SolutionType::kSlip, r));
  }
}

void solve_state_b(const ContactParameters3d& p, const Blocks& b, const Eigen::Vector3d& dF,
                   RateSolutionSet3d& set) {
  const double f_scale = dF.cwiseAbs().maxCoeff();
  bool separation_undecided = false;
  const Eigen::Vector3d dw_sep = separation_solution(p, dF, set, separation_undecided);
  const bool stick_listed = stick_solution(p, b, dF, set);
  // Slip: every root of g(phi) (3D.6), then the 3x2 system for (dP_N, lambda).
  const SlipDirectionFunction g = slip_direction_function(p, dF);
  const double g_scale = g.scale();
  std::vector<double> roots, complex_re;
  if (!slip_direction_roots(g, g_scale, set, roots, complex_re)) return;
  const SlipSystem sys = slip_system(p, b);
  certify_slip_roots(g, g_scale, sys, dF, roots, complex_re, set);
  slip_solutions(p, b, sys, dF, roots, stick_listed, set);
  if (separation_undecided) {
    // dw_N = 0 within rounding: the separation is then the contact solution with dP = 0.
    const double tol = 1e-8 * f_scale;
    const bool explained = std::any_of(set.solutions.begin(), set.solutions.end(), [&](const RateSolution3d& x) {
      return std::max(x.at.dP_T.cwiseAbs().maxCoeff(), std::abs(x.at.dP_N)) <= tol;
    });
    if (!explained)
      not_proved(set, "the separation's normal rate dw_N = " + num(dw_sep(2)) + " is zero within the "
                 "rounding of the stiffness (cond(A) = " + num(condition_number(p.A)) +
                 "): not decided");
  }
}

void solve_state_d(const ContactParameters3d& p, const ContactState3d& st, const Blocks& b,
                   const Eigen::Vector3d& dF, RateSolutionSet3d& set) {
  // The ellipse's normal at P_T: n0 = D^-1 t0, t0 = D^-1 P_T / |D^-1 P_T| (3D.9).
  const Eigen::Vector2d t0 = (b.Dinv * st.P_T).normalized();
  const Eigen::Vector2d n0 = b.Dinv * t0;
  const double kappa = p.k_a / (3 * p.P_s) * st.P_N;
  const Eigen::LDLT<Eigen::Matrix2d> K = b.K.ldlt();
  // Rates affine in lambda: dP = dP0 + lambda dP1 (3D.10).
  const Eigen::Vector2d dP_T0 = K.solve(dF.head<2>());
  const double dP_N0 = dF(2) - p.C_T * b.ATN.dot(dP_T0);
  const Eigen::Vector2d rhs1 = b.ATT * n0 + b.ATN * kappa;
  const Eigen::Vector2d dP_T1 = -K.solve(rhs1);
  const double dP_N1 = -p.C_T * b.ATN.dot(dP_T1) - (b.ATN.dot(n0) + b.ANN * kappa);
  // w(lambda) = mu dP_N - n0 . dP_T >= 0, lambda >= 0, w lambda = 0: q + M lambda (3D.11).
  double q = p.mu * dP_N0 - n0.dot(dP_T0);
  double M = p.mu * dP_N1 - n0.dot(dP_T1);
  const double q_scale = p.mu * std::abs(dP_N0) + std::abs(n0.dot(dP_T0));
  const double M_scale = p.mu * std::abs(dP_N1) + std::abs(n0.dot(dP_T1));
  if (std::abs(q) <= kTol * q_scale) q = 0;
  if (std::abs(M) <= kTol * M_scale) M = 0;
  auto rates = [&](double lambda) {
    Rates3d r;
    r.dP_T = dP_T0 + lambda * dP_T1;
    r.dP_N = dP_N0 + lambda * dP_N1;
    r.dw_Ti = lambda * n0;
    r.dw_T = p.C_T * r.dP_T + r.dw_Ti;
    r.dw_N = kappa * lambda;
    r.dw_w = kappa * lambda;  // (40): k P_N |D dw_T^i| = k P_N lambda |t0|
    return r;
  };
  if (q >= 0) set.solutions.push_back(point_solution(SolutionType::kStick, rates(0)));
  if (M != 0) {
    const double lambda = -q / M;
    if (lambda > 0) set.solutions.push_back(point_solution(SolutionType::kSlip, rates(lambda)));
  } else if (q == 0) {
    // M = q = 0: every lambda >= 0 solves; the slip ray starts at the stick solution (listed
    // above), which it does not include.
    RateSolution3d s = point_solution(SolutionType::kSlip, rates(0));
    s.ray = true;
    s.origin_included = false;
    Rates3d dir = rates(1);
    dir.dP_T -= s.at.dP_T;
    dir.dP_N -= s.at.dP_N;
    dir.dw_T -= s.at.dw_T;
    s.direction = dir;
    s.slip_direction = n0.normalized();
    s.slip_angle = std::atan2(s.slip_direction(1), s.slip_direction(0));
    set.solutions.push_back(s);
  }
  for (const auto& s : set.solutions)
    if (equilibrium_residual(p, dF, s.at) > 1e-8) {
      set.complete = false;
      set.message = "a state-d solution fails the equilibrium check to 1e-8";
    }
}

}  // namespace

std::string ContactParameters3d::validate() const {
  if (!finite(A)) return "A has a non-finite entry";
  // symmetric to 1e-12 relative, positive definite judged scale-free (core/spd.hpp)
  if (const SpdVerdict spd = check_spd(A, 1e-12, 0.0); !spd.message.empty()) return spd.message;
  if (!std::isfinite(mu) || !(mu > 0)) return "mu must be finite and > 0, got " + num(mu);
  if (!std::isfinite(C_T) || C_T < 0) return "C_T must be finite and >= 0, got " + num(C_T);
  if (!std::isfinite(k_a) || k_a < 0) return "k_a must be finite and >= 0, got " + num(k_a);
  if (!std::isfinite(P_s) || !(P_s > 0)) return "P_s must be finite and > 0, got " + num(P_s);
  if (!alpha.allFinite() || !(alpha(0) > 0) || !(alpha(1) > 0))
    return "alpha must be two finite numbers > 0";
  // The solvers work with the ellipse in its own unit (unit_scaling.hpp, normalize_ellipse).
  const double c = detail::ellipse_unit(alpha);
  if (!(mu * c > 0) || !std::isfinite(mu * c) || !std::isfinite(k_a * c) ||
      !std::isfinite(c / alpha.minCoeff()))
    return "mu x alpha, k_a x alpha or alpha_X / alpha_Y leaves double's range: give the "
           "friction ellipse in units of moderate size";
  return {};
}

std::string ContactState3d::validate(const ContactParameters3d& params) const {
  if (!P_T.allFinite() || !std::isfinite(P_N)) return "P_T and P_N must be finite";
  const double norm = P_T.cwiseQuotient(params.alpha).stableNorm();
  switch (state) {
    case 'a':
    case 'b':
      if (P_T.cwiseAbs().maxCoeff() != 0 || P_N != 0)
        return std::string("state ") + state + " has P = 0 (got P_N = " + num(P_N) + ")";
      return {};
    case 'c':
      if (!(P_N > 0)) return "state c needs P_N > 0, got " + num(P_N);
      if (!(norm < params.mu * P_N)) return "state c needs ||P_T|| < mu P_N";
      return {};
    case 'd':
      if (!(P_N > 0)) return "state d needs P_N > 0, got " + num(P_N);
      if (std::abs(norm - params.mu * P_N) > 1e-9 * params.mu * P_N)
        return "state d needs ||P_T|| = mu P_N (got ||P_T|| = " + num(norm) +
               ", mu P_N = " + num(params.mu * P_N) + ")";
      return {};
    default:
      return std::string("state must be a, b, c or d, got '") + state + "'";
  }
}

double SlipDirectionFunction::operator()(double phi) const noexcept {
  const double c = std::cos(phi), s = std::sin(phi);
  return a * c * c + b * c * s + d * s * s + e * c + f * s;
}

double SlipDirectionFunction::derivative(double phi) const noexcept {
  const double c = std::cos(phi), s = std::sin(phi);
  return -2 * a * c * s + b * (c * c - s * s) + 2 * d * s * c - e * s + f * c;
}

double SlipDirectionFunction::scale() const noexcept {
  return std::abs(a) + std::abs(b) + std::abs(d) + std::abs(e) + std::abs(f);
}

SlipDirectionFunction slip_direction_function(const ContactParameters3d& p,
                                              const Eigen::Vector3d& dF) {
  const SlipSystem s = slip_system(p, blocks(p));
  const Eigen::Vector3d eN(0, 0, 1);
  const Eigen::Vector3d g1 = s.G.col(0), g2 = s.G.col(1), h1 = s.H.col(0), h2 = s.H.col(1);
  SlipDirectionFunction g;
  g.a = p.mu * det3(g1, h1, dF);
  g.b = p.mu * (det3(g1, h2, dF) + det3(g2, h1, dF));
  g.d = p.mu * det3(g2, h2, dF);
  g.e = det3(eN, h1, dF);
  g.f = det3(eN, h2, dF);
  return g;
}

RateSolutionSet3d solve_rate_3d(const ContactParameters3d& user_params, const ContactState3d& state,
                                const Eigen::Vector3d& user_dF) {
  if (const std::string e = user_params.validate(); !e.empty()) throw InputError("parameters: " + e);
  if (const std::string e = state.validate(user_params); !e.empty()) throw InputError("state: " + e);
  if (!user_dF.allFinite()) throw InputError("dF must be finite");
  ContactParameters3d params = user_params;
  Eigen::Vector3d dF = user_dF;
  detail::normalize_ellipse(params);  // the rates hold no multiplier: nothing to scale back
  const detail::Units scaling = detail::normalize(params, dF);
  const Blocks b = blocks(params);
  RateSolutionSet3d set;
  switch (state.state) {
    case 'a': {
      Rates3d r;
      const Eigen::Vector3d dw = params.A.ldlt().solve(dF);
      r.dw_T = dw.head<2>();
      r.dw_N = dw(2);
      r.dw_Ti = r.dw_T;
      set.solutions.push_back(point_solution(SolutionType::kOpen, r));
      break;
    }
    case 'b':
      solve_state_b(params, b, dF, set);
      break;
    case 'c':
      set.solutions.push_back(point_solution(SolutionType::kStick, stick_rates(params, b, dF)));
      break;
    case 'd':
      solve_state_d(params, state, b, dF, set);
      break;
  }
  detail::rescale(set, scaling);
  return set;
}

}  // namespace cpkit::rate
