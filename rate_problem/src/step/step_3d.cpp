// One implicit step of one 3-D contact point (step_3d.hpp); the derivation and the equation
// tags (3D.20)-(3D.27) are in docs/contact_3d.md, "The implicit step".
#include "cpkit/rate_problem/step/step_3d.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "step_3d_terms.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAcceptTol = 1e-9;  ///< step_3d_residual of every listed solution
/// A forward result of a solve with matrix M is known to about kRound cond(M) of its size (a
/// generous multiple of the unit roundoff): inequalities inside that band are not decided.
constexpr double kRound = 64 * 2.220446049250313e-16;

std::string num(double x) { return num_text(x, 10); }

/// The problem's own units (step_3d_units) and its friction ellipse's unit.
detail::Units scales_of(const Step3dProblem& p) noexcept {
  detail::Units s = detail::step_3d_units(p.params.A, p.DF, &p.state, 1);
  s.ellipse = detail::ellipse_unit(p.params.alpha);
  return s;
}

Step3dValues to_user_units(const Step3dValues& v, const detail::Units& s) noexcept {
  return detail::scaled_values(v, s.force, s.length, s.length * s.ellipse);
}

Step3dValues to_normalized(const Step3dValues& v, const detail::Units& s) noexcept {
  const double force = 1 / s.force, length = force / (1 / s.stiffness);
  return detail::scaled_values(v, force, length, length * (1 / s.ellipse));
}

using detail::project_soc;

double det3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

/// The slip system of (3D.24): x u(t) + l v(t) + x l m = r with x = P_N1, l = lambda, in
/// normalized units.
struct SlipSystem {
  Eigen::Matrix3d A;
  Eigen::Vector2d alpha;
  double mu = 0, C_T = 0;
  Eigen::Vector3d m, r;
  Eigen::Vector3d u(const Eigen::Vector2d& t) const {
    const Eigen::Vector2d Dt = alpha.cwiseProduct(t);
    Eigen::Vector3d col(mu * Dt(0), mu * Dt(1), 1.0);
    col += A.leftCols<2>() * (C_T * mu * Dt);
    return col;
  }
  Eigen::Vector3d v(const Eigen::Vector2d& t) const {
    return A.leftCols<2>() * t.cwiseQuotient(alpha);
  }
  Eigen::Vector3d du(const Eigen::Vector2d& dt) const {  // u is affine: derivative
    const Eigen::Vector2d Dt = alpha.cwiseProduct(dt);
    return Eigen::Vector3d(mu * Dt(0), mu * Dt(1), 0.0) + A.leftCols<2>() * (C_T * mu * Dt);
  }
  /// The scalar condition whose zeros are the slip directions: det[u v r] without wear
  /// (3D.25), Dx Dl - Dm D with wear (3D.26).
  double condition(double phi, bool wear) const {
    const Eigen::Vector2d t(std::cos(phi), std::sin(phi));
    const Eigen::Vector3d U = u(t), V = v(t);
    if (!wear) return det3(U, V, r);
    return det3(r, V, m) * det3(U, r, m) - det3(U, V, r) * det3(U, V, m);
  }
  /// The magnitude of the terms of `condition` (for relative zero tests).
  double condition_terms(double phi, bool wear) const {
    const Eigen::Vector2d t(std::cos(phi), std::sin(phi));
    const double U = u(t).norm(), V = v(t).norm(), R = r.norm(), M = m.norm();
    return wear ? 2 * U * V * R * R * M * M + U * U * V * V * R * M + 1e-300 : U * V * R + 1e-300;
  }
};

SlipSystem slip_system(const Step3dProblem& n) {
  SlipSystem s;
  s.A = n.params.A;
  s.alpha = n.params.alpha;
  s.mu = n.params.mu;
  s.C_T = n.params.C_T;
  s.m = n.wear_coefficient() * n.params.A.col(2);
  const Eigen::Vector3d P0(n.state.P_T0(0), n.state.P_T0(1), n.state.P_N0);
  const Eigen::Vector3d w0(n.params.C_T * n.state.P_T0(0), n.params.C_T * n.state.P_T0(1),
                           n.state.g0);
  s.r = n.DF + P0 + n.params.A * w0;
  return s;
}

/// A real trigonometric polynomial h(phi) = a0 + sum_k (a_k cos k phi + b_k sin k phi).
struct TrigPoly {
  int degree = 0;
  std::array<double, 5> a{}, b{};
  double operator()(double phi) const noexcept {
    // cos k phi, sin k phi by the angle-addition recurrence (two trigonometric calls).
    const double c1 = std::cos(phi), s1 = std::sin(phi);
    double s = a[0], ck = 1, sk = 0;
    for (int k = 1; k <= degree; ++k) {
      const double c = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = c;
      s += a[k] * ck + b[k] * sk;
    }
    return s;
  }
  /// Sets coefficients at or below `floor` (rounding noise of the samples) to zero and lowers
  /// the degree past them.
  void drop_noise(double floor) noexcept {
    for (int k = 0; k <= degree; ++k) {
      if (std::abs(a[k]) <= floor) a[k] = 0;
      if (std::abs(b[k]) <= floor) b[k] = 0;
    }
    while (degree > 0 && a[degree] == 0 && b[degree] == 0) --degree;
  }
  double derivative(double phi) const noexcept {
    double s = 0;
    for (int k = 1; k <= degree; ++k)
      s += k * (-a[k] * std::sin(k * phi) + b[k] * std::cos(k * phi));
    return s;
  }
  double second_derivative(double phi) const noexcept {
    double s = 0;
    for (int k = 1; k <= degree; ++k)
      s -= k * k * (a[k] * std::cos(k * phi) + b[k] * std::sin(k * phi));
    return s;
  }
  double scale() const noexcept {
    double s = std::abs(a[0]);
    for (int k = 1; k <= degree; ++k) s += std::abs(a[k]) + std::abs(b[k]);
    return s;
  }
};

/// The coefficients of a trigonometric polynomial of degree <= max_degree from 16 samples
/// (a discrete Fourier transform: exact up to rounding for degree <= 7).
template <class F>
TrigPoly fourier(F&& h, int max_degree) {
  constexpr int kN = 16;
  std::array<double, kN> y{};
  for (int j = 0; j < kN; ++j) y[j] = h(2 * kPi * j / kN);
  TrigPoly p;
  p.degree = max_degree;
  for (int k = 0; k <= max_degree; ++k) {
    double c = 0, s = 0;
    for (int j = 0; j < kN; ++j) {
      c += y[j] * std::cos(2 * kPi * k * j / kN);
      s += y[j] * std::sin(2 * kPi * k * j / kN);
    }
    p.a[k] = (k == 0 ? 1.0 : 2.0) * c / kN;
    p.b[k] = k == 0 ? 0.0 : 2 * s / kN;
  }
  // The degree is where the coefficients stop being rounding noise.
  const double sc = p.scale();
  while (p.degree > 0 && std::abs(p.a[p.degree]) + std::abs(p.b[p.degree]) <= 1e-13 * sc) {
    p.a[p.degree] = p.b[p.degree] = 0;
    --p.degree;
  }
  return p;
}

/// The sign changes of h on a dense scan (1440 samples), each bisected to a double's
/// resolution: the candidates of slip directions when the root list is not proved complete.
std::vector<double> sign_changes(const TrigPoly& h) {
  constexpr int kScan = 1440;
  std::vector<double> out;
  const double step = 2 * kPi / kScan;
  for (int j = 0; j < kScan; ++j) {
    double a = step * j, b = step * (j + 1);
    double ha = h(a);
    if ((ha > 0) == (h(b) > 0)) continue;
    for (int it = 0; it < 60 && b - a > 1e-15; ++it) {
      const double c = (a + b) / 2, hc = h(c);
      if ((hc > 0) == (ha > 0)) a = c, ha = hc; else b = c;
    }
    out.push_back(std::remainder((a + b) / 2, 2 * kPi));
  }
  return out;
}

/// Every real zero of h on the circle: the unit-circle roots of z^n h (a polynomial of degree
/// 2n in z = e^{i phi}) by the eigenvalues of its companion matrix, refined by Newton's method
/// on h, with a certificate (docs/contact_3d.md, "Every solution of a step"). A root is simple
/// (|h'| clearly nonzero) or exactly double (h' = 0 there too, refined by Newton on h', with
/// |h''| clearly nonzero): symmetric problems have double roots where two solutions share a
/// slip direction. Returns false with `why` when the list is not proved complete; `roots` then
/// holds the unproved candidates (the roots found and the sign changes of h, issue 34: at
/// cond(A) >= 1e8 a slip far from any critical load was not even tried).
bool trig_roots_proved(const TrigPoly& h, double noise, std::vector<double>& roots,
                       std::string& why, std::vector<double>& candidates);

bool trig_roots(const TrigPoly& h, double noise, std::vector<double>& roots, std::string& why) {
  std::vector<double> candidates;
  if (trig_roots_proved(h, noise, roots, why, candidates)) return true;
  roots = sign_changes(h);
  roots.insert(roots.end(), candidates.begin(), candidates.end());
  std::sort(roots.begin(), roots.end());
  std::vector<double> u;  // one start per direction
  for (double r : roots)
    if (u.empty() || std::abs(r - u.back()) > 1e-9) u.push_back(r);
  roots = u;
  return false;
}

bool trig_roots_proved(const TrigPoly& h, double noise, std::vector<double>& roots,
                       std::string& why, std::vector<double>& candidates) {
  roots.clear();
  const int n = h.degree;
  const double sc = h.scale();
  if (n == 0) {
    if (std::abs(h.a[0]) > 0) return true;  // a nonzero constant: no zero
    why = "the slip condition vanishes for every direction";
    return false;
  }
  // P(z) = sum_{j=0}^{2n} c_{j-n} z^j, c_0 = a0, c_k = (a_k - i b_k)/2, c_-k = conj(c_k).
  using C = std::complex<double>;
  std::vector<C> c(2 * n + 1);
  c[n] = h.a[0];
  for (int k = 1; k <= n; ++k) {
    c[n + k] = C(h.a[k], -h.b[k]) / 2.0;
    c[n - k] = std::conj(c[n + k]);
  }
  const int m = 2 * n;
  Eigen::MatrixXcd comp = Eigen::MatrixXcd::Zero(m, m);
  for (int i = 1; i < m; ++i) comp(i, i - 1) = 1;
  for (int i = 0; i < m; ++i) comp(i, m - 1) = -c[i] / c[m];
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(comp, false);
  if (es.info() != Eigen::Success) {
    why = "the eigenvalue solver did not converge";
    return false;
  }
  // h is known to about `noise` (rounding in the terms of its samples): a root is where h is
  // within 100 noise (or 1e-11 of its scale), and h must stand well above the noise.
  if (sc <= 1e4 * noise) {
    why = "the slip condition is at the rounding level of its terms: slip directions are not resolved";
    return false;
  }
  const double zero = std::max(1e-11 * sc, 100 * noise), flat = 1e-7 * sc;
  auto newton = [](auto&& f, auto&& df, double phi) {
    for (int it = 0; it < 60; ++it) {
      const double d = df(phi);
      if (d == 0 || !std::isfinite(d)) break;
      const double stp = f(phi) / d;
      if (!std::isfinite(stp) || std::abs(stp) > 0.5) break;
      phi -= stp;
      if (std::abs(stp) <= 1e-14) break;
    }
    return phi;
  };
  std::vector<double> simple, twice, near;
  for (int i = 0; i < m; ++i) {
    const C z = es.eigenvalues()(i);
    if (std::abs(std::abs(z) - 1) > 1e-2) continue;
    const double start = std::arg(z);
    // A double root first (Newton on h converges only slowly there and stops at a point with a
    // small but nonzero h'); an extremum that is not a root falls through to Newton on h.
    const double phi2 = newton([&](double x) { return h.derivative(x); },
                               [&](double x) { return h.second_derivative(x); }, start);
    if (std::abs(phi2 - start) < 1e-3 && std::abs(h(phi2)) <= zero &&
        std::abs(h.derivative(phi2)) <= 1e-12 * sc &&
        std::abs(h.second_derivative(phi2)) > flat) {
      twice.push_back(std::remainder(phi2, 2 * kPi));
      continue;
    }
    const double phi = newton([&](double x) { return h(x); },
                              [&](double x) { return h.derivative(x); }, start);
    if (std::abs(h(phi)) <= zero && std::abs(h.derivative(phi)) > flat) {
      simple.push_back(std::remainder(phi, 2 * kPi));
      continue;
    }
    near.push_back(start);
  }
  // Double roots do not change the sign of h, so no sign test can see a lost one: every local
  // minimum of |h| on a dense scan (neighbours of one sign) is also followed by Newton on h'.
  {
    constexpr int kScan = 1440;
    const double step = 2 * kPi / kScan;
    std::array<double, kScan> hv;
    for (int j = 0; j < kScan; ++j) hv[j] = h(step * j);
    for (int j = 0; j < kScan; ++j) {
      const double l = hv[(j + kScan - 1) % kScan], hc = hv[j], r = hv[(j + 1) % kScan];
      if (!(std::abs(hc) <= std::abs(l) && std::abs(hc) < std::abs(r))) continue;
      if ((l > 0) != (hc > 0) || (r > 0) != (hc > 0)) continue;  // a sign change: simple roots
      const double start = step * j;
      const double phi2 = newton([&](double x) { return h.derivative(x); },
                                 [&](double x) { return h.second_derivative(x); }, start);
      if (std::abs(phi2 - start) <= step && std::abs(h(phi2)) <= zero &&
          std::abs(h.derivative(phi2)) <= 1e-9 * sc && std::abs(h.second_derivative(phi2)) > flat)
        twice.push_back(std::remainder(phi2, 2 * kPi));
    }
  }
  auto unique = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    std::vector<double> u;
    for (double r : v)
      if (u.empty() || std::abs(r - u.back()) > 1e-7) u.push_back(r);
    if (u.size() > 1 && std::abs(u.front() + 2 * kPi - u.back()) <= 1e-7) u.pop_back();
    v = u;
  };
  unique(simple);
  unique(twice);
  candidates = simple;
  candidates.insert(candidates.end(), twice.begin(), twice.end());
  candidates.insert(candidates.end(), near.begin(), near.end());
  for (double r : twice)
    for (double q : simple)
      if (std::abs(std::remainder(r - q, 2 * kPi)) <= 1e-7) {
        why = "a slip direction is a (nearly) multiple root of the slip condition (phi = " + num(r) + ")";
        return false;
      }
  for (double a : near) {
    bool explained = false;
    for (const auto* v : {&simple, &twice})
      for (double r : *v) explained = explained || std::abs(std::remainder(a - r, 2 * kPi)) <= 1e-5;
    // h is computed to about 1e-15 of its terms: a pair of non-real roots whose h stays above
    // 1e-10 of the scale has no real root nearby (a near-tangency, resolved).
    if (!explained && std::abs(h(a)) <= 1e-10 * sc) {
      why = "a root of the slip condition near phi = " + num(a) + " could not be resolved";
      return false;
    }
  }
  if (simple.size() % 2 != 0) {
    why = "an odd number of simple slip directions was found: one may be lost";
    return false;
  }
  if (simple.size() + 2 * twice.size() > static_cast<std::size_t>(m)) {
    why = "more roots than the degree of the slip condition allows";
    return false;
  }
  // Signs alternate across the simple roots and not across the double ones, and h keeps its
  // sign inside every arc between neighbouring roots: sampled densely (at least 8 points an
  // arc, 1440 around the circle), so that a lost pair of roots would show.
  std::vector<std::pair<double, bool>> all;  // (angle, simple)
  for (double r : simple) all.emplace_back(r, true);
  for (double r : twice) all.emplace_back(r, false);
  std::sort(all.begin(), all.end());
  if (all.empty()) {
    const double h0 = h(0.0);
    for (int j = 1; j < 1440; ++j)
      if ((h(2 * kPi * j / 1440) > 0) != (h0 > 0)) {
        why = "the slip condition changes sign, but no root was found";
        return false;
      }
  }
  int arc_sign_prev = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double a = all[i].first;
    const double b = i + 1 < all.size() ? all[i + 1].first : all[0].first + 2 * kPi;
    const int samples = 8 + static_cast<int>((b - a) / (2 * kPi) * 1440);
    int sign = 0;
    for (int j = 0; j < samples; ++j) {
      const double v = h(a + (b - a) * (j + 0.5) / samples);
      const int sg = v > 0 ? 1 : -1;
      if (sign != 0 && sg != sign) {
        why = "the slip condition changes sign between two of its roots: a root may be lost";
        return false;
      }
      sign = sg;
    }
    // Across the root that starts this arc: a simple root flips the sign, a double keeps it.
    if (i > 0 && (sign != arc_sign_prev) != all[i].second) {
      why = "the signs of the slip condition do not match the roots' multiplicities";
      return false;
    }
    arc_sign_prev = sign;
  }
  // (The wrap-around root is covered by the evenness of the number of simple roots.)
  roots = simple;
  roots.insert(roots.end(), twice.begin(), twice.end());
  std::sort(roots.begin(), roots.end());
  return true;
}

/// Refines (x, l, phi) of a slip candidate by Newton's method on the three equations
/// x u(t) + l v(t) + x l m - r = 0; `error_x` and `error_l` bound the errors of x and l at the
/// end: the rounding of F (and what is left of it) through the rows of the inverse Jacobian.
/// The direction is the root's (phi moves by rounding only); x and l may move more (from a
/// candidate computed from two rows only). False when Newton does not converge there.
/// Issue 34: the iteration runs in long double on the scaled unknowns (x / |x|, l / |l|, phi),
/// and each unknown has its own bound. At cond(A) >= 1e8 a slip can have lambda ~ 1e8 with
/// P_N1 ~ 1: one bound for both (rounding / the smallest singular value of the (x, l) columns,
/// mostly along l) was larger than P_N1, and the slip was dropped as "P_N1 at the rounding level".
bool refine_slip(const SlipSystem& s, double& x, double& l, double& phi, double& error_x,
                 double& error_l) {
  using LD = long double;
  using V2 = Eigen::Matrix<LD, 2, 1>;
  using V3 = Eigen::Matrix<LD, 3, 1>;
  const Eigen::Matrix<LD, 3, 3> A = s.A.cast<LD>();
  const V3 m = s.m.cast<LD>(), r = s.r.cast<LD>();
  const V2 alpha = s.alpha.cast<LD>();
  const LD mu = s.mu, C_T = s.C_T;
  auto u = [&](const V2& t) -> V3 {  // SlipSystem::u, affine; du without its constant 1
    const V2 Dt = alpha.cwiseProduct(t);
    return V3(mu * Dt(0), mu * Dt(1), 1) + A.leftCols<2>() * (C_T * mu * Dt);
  };
  auto du = [&](const V2& dt) -> V3 {
    const V2 Dt = alpha.cwiseProduct(dt);
    return V3(mu * Dt(0), mu * Dt(1), 0) + A.leftCols<2>() * (C_T * mu * Dt);
  };
  auto v = [&](const V2& t) -> V3 { return A.leftCols<2>() * t.cwiseQuotient(alpha); };
  const double phi0 = phi;
  const LD xs = std::max(1.0, std::abs(x)), ls = std::max(1.0, std::abs(l));
  LD X = x, L = l, P = phi, res = INFINITY, size = 0;
  Eigen::Matrix<LD, 3, 3> J;
  for (int it = 0; it < 40; ++it) {
    const V2 t(std::cos(P), std::sin(P)), dt(-std::sin(P), std::cos(P));
    const V3 U = u(t), V = v(t);
    const V3 F = X * U + L * V + X * L * m - r;
    res = F.cwiseAbs().maxCoeff();
    size = std::abs(X) * U.norm() + std::abs(L) * V.norm() + std::abs(X * L) * m.norm() + r.norm();
    J.col(0) = (U + L * m) * xs;
    J.col(1) = (V + X * m) * ls;
    J.col(2) = X * du(dt) + L * v(dt);
    const V3 d = J.fullPivLu().solve(F);
    if (!d.allFinite()) return false;
    X -= d(0) * xs;
    L -= d(1) * ls;
    P -= d(2);
    if (std::abs(d(0)) + std::abs(d(1)) + std::abs(d(2)) <= 1e-18L) break;
  }
  // The rounding of F (in double, where the values are used) and what is left of it, each
  // component up to `delta`, moves x and l by at most |row of J^-1| delta (scaled back).
  const LD delta = kRound * size + res;
  const Eigen::Matrix<LD, 3, 3> Jinv = J.fullPivLu().inverse();
  error_x = static_cast<double>(xs * Jinv.row(0).cwiseAbs().sum() * delta);
  error_l = static_cast<double>(ls * Jinv.row(1).cwiseAbs().sum() * delta);
  if (!std::isfinite(error_x) || !std::isfinite(error_l)) return false;
  x = static_cast<double>(X);
  l = static_cast<double>(L);
  phi = static_cast<double>(P);
  return std::isfinite(x) && std::isfinite(l) && std::isfinite(phi) && res <= 1e-9L * size &&
         std::abs(phi - phi0) <= 1e-4;
}

/// The end-of-step forces, their increments and lambda; the displacements are left to the caller.
Step3dValues force_values(const Step3dProblem& p, const Eigen::Vector2d& P_T1, double P_N1,
                          double lambda) noexcept {
  Step3dValues v;
  v.P_T1 = P_T1;
  v.P_N1 = P_N1;
  v.lambda = lambda;
  v.DP_T = P_T1 - p.state.P_T0;
  v.DP_N = P_N1 - p.state.P_N0;
  return v;
}

/// A contact solution (P_N1 >= 0, g1 = 0) from its own unknowns: Dw_T = C_T DP_T + Dw_T^i,
/// Dw_N = -g0 + Dw^w. Equilibrium is then what the residual checks (a backward error); solving
/// A Dw = DF - DP instead would carry cond(A) eps into g1.
Step3dValues contact_values(const Step3dProblem& p, const Eigen::Vector2d& P_T1, double P_N1,
                            double lambda, const Eigen::Vector2d& Dw_Ti) noexcept {
  Step3dValues v = force_values(p, P_T1, P_N1, lambda);
  v.Dw_Ti = Dw_Ti;
  v.Dw_T = p.params.C_T * v.DP_T + Dw_Ti;
  v.Dw_w = p.wear_coefficient() * P_N1 * lambda;
  v.Dw_N = v.Dw_w - p.state.g0;
  v.g1 = 0;
  return v;
}

/// cond_2(M) (inf when singular).
double condition_number(const Eigen::Matrix3d& m) {
  const Eigen::Vector3d sv = m.jacobiSvd().singularValues();
  return sv(2) > 0 ? sv(0) / sv(2) : INFINITY;
}

/// The (x, l) of the slip direction phi (at most two: x u + l v + x l m = r). Without wear the
/// 3x2 system [u v] (x, l) = r (consistent at a root). With wear the two rows orthogonal to m
/// are linear in (x, l): a regular 2x2 system gives one candidate; a singular one (two
/// solutions sharing the direction, a double root) leaves a line of (x, l) on which the row
/// along m is a quadratic. Returns false when the direction cannot be resolved.
bool slip_amounts(const SlipSystem& s, bool wear, double phi, std::vector<Eigen::Vector2d>& out) {
  out.clear();
  const Eigen::Vector2d t(std::cos(phi), std::sin(phi));
  const Eigen::Vector3d U = s.u(t), V = s.v(t);
  const double nu = U.norm(), nv = V.norm();
  if (!(nu > 0) || !(nv > 0)) return false;
  if (!wear) {
    Eigen::Matrix<double, 3, 2> B;
    B.col(0) = U / nu;
    B.col(1) = V / nv;
    // [u v] of rank one: r outside its range has no slip in this direction; inside it the
    // slips form a continuum (not resolved).
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
    if (!(svd.singularValues()(1) > 1e-9 * svd.singularValues()(0))) {
      const Eigen::Vector3d rn = s.r.normalized();
      const Eigen::Vector3d u0 = svd.matrixU().col(0);
      return (rn - u0 * u0.dot(rn)).norm() > 1e-7;
    }
    const Eigen::Vector2d z = svd.solve(s.r);
    if (!z.allFinite()) return false;
    out.emplace_back(z(0) / nu, z(1) / nv);
    return true;
  }
  // An orthonormal basis (n1, n2) of the plane orthogonal to m, and m's unit vector.
  const Eigen::Vector3d mh = s.m.normalized();
  const Eigen::Vector3d n1 = mh.unitOrthogonal(), n2 = mh.cross(n1);
  Eigen::Matrix2d M;
  M << n1.dot(U) / nu, n1.dot(V) / nv, n2.dot(U) / nu, n2.dot(V) / nv;
  const Eigen::Vector2d b(n1.dot(s.r), n2.dot(s.r));
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector2d sv = svd.singularValues();
  if (!(sv(0) > 0)) return false;
  const double mn = s.m.norm();
  if (sv(1) > 1e-7 * sv(0)) {
    const Eigen::Vector2d z = svd.solve(b);
    out.emplace_back(z(0) / nu, z(1) / nv);
    return z.allFinite();
  }
  // Rank one: z = z0 + sigma d (scaled variables), then the row along m is quadratic in sigma.
  const Eigen::Vector2d d = svd.matrixV().col(1);
  const Eigen::Vector2d z0 = svd.matrixV().col(0) * (svd.matrixU().col(0).dot(b) / sv(0));
  if (std::abs(svd.matrixU().col(1).dot(b)) > 1e-7 * (b.norm() + sv(0) * z0.norm())) {
    // The two rows are inconsistent. Exactly singular (to rounding): a root that the
    // elimination (3D.26) adds where the 2x2 determinant vanishes, no slip in this direction.
    // Only nearly singular (an ill-conditioned stiffness): the regular solution, for Newton
    // and the residual to judge.
    if (sv(1) > 1e-12 * sv(0)) {
      const Eigen::Vector2d z = svd.solve(b);
      out.emplace_back(z(0) / nu, z(1) / nv);
    }
    return true;
  }
  const double pu = mh.dot(U) / nu, pv = mh.dot(V) / nv, pr = mh.dot(s.r);
  // (z0x + sig dx) pu + (z0l + sig dl) pv + mn/(nu nv) (z0x + sig dx)(z0l + sig dl) = pr.
  const double k = mn / (nu * nv);
  const double c2 = k * d(0) * d(1);
  const double c1 = pu * d(0) + pv * d(1) + k * (z0(0) * d(1) + z0(1) * d(0));
  const double c0 = pu * z0(0) + pv * z0(1) + k * z0(0) * z0(1) - pr;
  double roots[2];
  const double sc2 = std::abs(k), sc1 = std::abs(pu) + std::abs(pv) + k * z0.norm(),
               sc0 = std::abs(pu * z0(0)) + std::abs(pv * z0(1)) + k * std::abs(z0(0) * z0(1)) +
                     std::abs(pr);
  const int nroots = rate::stable_quadratic_roots(c2, c1, c0, sc2, sc1, sc0, 1e-12, roots);
  if (nroots < 0) return false;  // a continuum along the line
  for (int i = 0; i < nroots; ++i) {
    const Eigen::Vector2d z = z0 + roots[i] * d;
    out.emplace_back(z(0) / nu, z(1) / nv);
  }
  return true;
}

/// The distance between two solutions in normalized units (forces and multiplier).
double distance(const Step3dValues& a, const Step3dValues& b) {
  return std::max({(a.P_T1 - b.P_T1).cwiseAbs().maxCoeff(), std::abs(a.P_N1 - b.P_N1),
                   std::abs(a.lambda - b.lambda)});
}

}  // namespace

std::string Step3dProblem::validate() const {
  if (std::string e = params.validate(); !e.empty()) return e;
  if (!std::isfinite(wear.k_M) || wear.k_M < 0)
    return "k_M = " + num(wear.k_M) + ": the Mroz-Stupkiewicz wear constant must be finite and >= 0";
  const double vals[] = {state.P_T0(0), state.P_T0(1), state.P_N0, state.g0, DF(0), DF(1), DF(2)};
  const char* names[] = {"P_T0[0]", "P_T0[1]", "P_N0", "g0", "DF[0]", "DF[1]", "DF[2]"};
  for (int i = 0; i < 7; ++i)
    if (!std::isfinite(vals[i])) return std::string(names[i]) + " is not finite";
  if (state.P_N0 < 0) return "P_N0 = " + num(state.P_N0) + " < 0: the normal force is compressive";
  if (state.g0 > 0) return "g0 = " + num(state.g0) + " > 0: the start state penetrates";
  if (state.P_N0 > 0 && state.g0 < 0)
    return "P_N0 > 0 with g0 < 0: a force across an open gap (P_N0 g0 = 0)";
  const double norm = params.alpha.cwiseInverse().cwiseProduct(state.P_T0).stableNorm();
  if (!std::isfinite(norm) || norm - params.mu * state.P_N0 > 1e-10 * (norm + params.mu * state.P_N0))
    return "||P_T0|| = " + num(norm) + " exceeds mu P_N0 = " + num(params.mu * state.P_N0) +
           ": the start state violates the friction criterion (38)";
  if (!std::isfinite(wear_coefficient()))
    return "the wear coefficient is not finite";
  return {};
}

double Step3dProblem::wear_coefficient() const noexcept {
  return wear.law == rate::WearLaw::kArchard ? params.k_a / (3 * params.P_s)
                                             : wear.k_M * params.mu;
}

Step3dValues step_3d_values(const Step3dProblem& p, const Eigen::Vector2d& P_T1, double P_N1,
                            double lambda) noexcept {
  Step3dValues v = force_values(p, P_T1, P_N1, lambda);
  const Eigen::Vector3d DP(v.DP_T(0), v.DP_T(1), v.DP_N);
  const Eigen::Vector3d Dw = p.params.A.ldlt().solve(p.DF - DP);
  v.Dw_T = Dw.head<2>();
  v.Dw_N = Dw(2);
  v.Dw_Ti = v.Dw_T - p.params.C_T * v.DP_T;
  v.Dw_w = p.wear_coefficient() * std::max(P_N1, 0.0) * lambda;
  v.g1 = p.state.g0 + v.Dw_N - v.Dw_w;
  return v;
}

double step_3d_residual(const Step3dProblem& user, const Step3dValues& uv) noexcept {
  const detail::Units s = scales_of(user);
  const Step3dProblem p = detail::normalized_step_3d(user, s);
  const Step3dValues v = to_normalized(uv, s);
  const Eigen::Vector3d DP(v.DP_T(0), v.DP_T(1), v.DP_N);
  const Eigen::Vector3d Dw(v.Dw_T(0), v.Dw_T(1), v.Dw_N);
  double res = detail::local_step_3d_residual(p, v);
  const Eigen::Vector3d eq = p.DF - DP - p.params.A * Dw;
  const double r = eq.cwiseAbs().maxCoeff() /
                   (1 + DP.cwiseAbs().maxCoeff() + (p.params.A.cwiseAbs() * Dw.cwiseAbs()).maxCoeff());
  res = std::isfinite(r) ? std::max(res, r) : INFINITY;
  return res;
}

SolutionType classify_step_3d(const Step3dProblem& user, const Step3dValues& uv) noexcept {
  const detail::Units s = scales_of(user);
  return detail::classify_normalized_step_3d(to_normalized(uv, s), user.state.g0);
}

Step3dSolution make_step_3d_solution(const Step3dProblem& p, const Step3dValues& v) {
  Step3dSolution s;
  s.values = v;
  s.type = classify_step_3d(p, v);
  s.residual = step_3d_residual(p, v);
  detail::set_slip_direction(s);
  return s;
}

Step3dSolutionSet enumerate_step_3d(const Step3dProblem& user) {
  if (const std::string e = user.validate(); !e.empty()) throw InputError("step: " + e);
  const detail::Units sc = scales_of(user);
  detail::require_representable(sc.force, sc.length, "step");
  const Step3dProblem p = detail::normalized_step_3d(user, sc);
  if (!p.params.A.allFinite() || !std::isfinite(p.params.C_T) || !std::isfinite(p.wear_coefficient()))
    throw InputError("step: the stiffness, compliance or wear constant overflows double in the "
                     "problem's own units: give them in units of moderate size");
  const Eigen::Vector2d alpha = p.params.alpha;
  const double mu = p.params.mu;

  std::vector<Step3dValues> found;  // normalized units
  Step3dSolutionSet set;
  auto not_proved = [&](const std::string& why) {
    set.complete = false;
    if (set.message.empty()) set.message = why;
  };
  // Every candidate that is not clearly inadmissible (outside the rounding band of its own
  // computation) is either listed -- its residual is a backward error, at the rounding level
  // for a solution whatever cond(A) is -- or makes the list incomplete: a computed root never
  // disappears silently.
  auto add = [&](const Step3dValues& v, const std::string& what) {
    for (const auto& f : found)
      if (distance(f, v) <= 1e-8 * (1 + std::abs(v.P_N1) + std::abs(v.lambda))) return;
    const double res = step_3d_residual(p, v);
    if (res <= kAcceptTol)
      found.push_back(v);
    else
      not_proved("the " + what + " candidate has residual " + num(res) + " > " +
                 num(kAcceptTol) + " (cond(A) = " + num(condition_number(p.params.A)) +
                 "): not accepted, so the list is not proved complete");
  };

  // Separation / open (3D.23): P1 = 0, admissible when g1 <= 0. Dw = A^-1 (DF + P0) is a
  // forward result: the sign of g1 is decided outside cond(A) eps |Dw|.
  {
    Step3dValues v = step_3d_values(p, Eigen::Vector2d::Zero(), 0, 0);
    v.lambda = alpha.cwiseProduct(v.Dw_Ti).stableNorm();  // any lambda >= |D Dw_Ti| fits P = 0
    // The solve is backward stable (residual ~ eps |A| |Dw|); the row N of A^-1 carries that
    // into Dw_N.
    const Eigen::Vector3d Dw(v.Dw_T(0), v.Dw_T(1), v.Dw_N);
    const Eigen::Vector3d row_N = p.params.A.ldlt().solve(Eigen::Vector3d::UnitZ());
    const double band =
        1e-12 * (std::abs(p.state.g0) + Dw.cwiseAbs().maxCoeff()) +
        kRound * (std::abs(p.state.g0) +
                  row_N.cwiseAbs().sum() * (p.params.A.cwiseAbs() * Dw.cwiseAbs()).maxCoeff());
    if (v.g1 <= band) add(v, "separation");
  }
  // Stick (3D.23): lambda = 0, g1 = 0: (I + A S) DP = DF + g0 A e_N, S = diag(C_T, C_T, 0).
  // Dw is the stick's own (C_T DP_T, -g0), not A^-1 of the load: that would carry cond(A)
  // eps into g1.
  {
    Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
    K.leftCols<2>() += p.params.C_T * p.params.A.leftCols<2>();
    const Eigen::Vector3d DP = K.partialPivLu().solve(p.DF + p.state.g0 * p.params.A.col(2));
    const Eigen::Vector2d P_T1 = p.state.P_T0 + DP.head<2>();
    const double P_N1 = p.state.P_N0 + DP(2);
    const double norm = P_T1.cwiseQuotient(alpha).stableNorm();
    const double size = DP.cwiseAbs().maxCoeff() + std::abs(P_N1) + P_T1.cwiseAbs().maxCoeff();
    const double band = std::max(1e-12, kRound * condition_number(K)) * size;
    if (P_N1 >= -band && norm - mu * P_N1 <= band * (1 / alpha.minCoeff() + mu))
      add(contact_values(p, P_T1, std::max(P_N1, 0.0), 0, Eigen::Vector2d::Zero()), "stick");
  }
  // Slip (3D.24)-(3D.27): every zero of the slip condition.
  const SlipSystem s = slip_system(p);
  const bool wear = p.wear_coefficient() > 0;
  TrigPoly h = fourier([&](double phi) { return s.condition(phi, wear); }, wear ? 4 : 2);
  double terms = 0;
  for (int j = 0; j < 16; ++j) terms = std::max(terms, s.condition_terms(2 * kPi * j / 16, wear));
  // The samples carry rounding errors of about 1e-16 of their terms (and the transform adds a
  // few more): coefficients below 1e-14 of the terms are noise, not structure.
  const double noise = 1e-14 * terms;
  if (std::isfinite(noise)) h.drop_noise(noise);
  std::vector<double> roots;
  std::string why;
  if (!std::isfinite(h.scale())) {
    not_proved("the slip condition overflows double: slip solutions are not resolved");
  } else if (h.scale() <= 1e-12 * terms) {
    not_proved("the slip condition vanishes for every direction (e.g. no load and no "
               "stored force): slip solutions are not resolved");
  } else if (!trig_roots(h, noise, roots, why)) {
    not_proved(why);
  }
  std::vector<Eigen::Vector2d> amounts;
  for (double root : roots) {
    if (!slip_amounts(s, wear, root, amounts)) {
      not_proved("the slip system cannot be resolved at the slip direction phi = " + num(root));
      continue;
    }
    for (const Eigen::Vector2d& xl : amounts) {
      double x = xl(0), l = xl(1), phi = root;
      // Newton on the three equations polishes (x, l, phi) to a backward error at the rounding
      // level (the root of h is only as good as h's rounding); it also gives the rounding bands
      // of x and l (through the rows of its inverse Jacobian, one band each). Two solutions sharing
      // a direction (a double root) are taken as slip_amounts gives them.
      double band_x = 1e-8 * (1 + std::abs(x) + std::abs(l)), band_l = band_x;
      bool resolved = true;  // (x, l) known well enough to read their signs
      if (amounts.size() == 1) {
        double x1 = x, l1 = l, phi1 = phi, error_x = 0, error_l = 0;
        resolved = refine_slip(s, x1, l1, phi1, error_x, error_l);
        if (resolved) {
          x = x1, l = l1, phi = phi1;
          const double floor = 1e-12 * (1 + std::abs(x) + std::abs(l));
          band_x = std::max(floor, error_x);
          band_l = std::max(floor, error_l);
        }
      }
      if (x < -band_x || l < -band_l) {  // not a slip (x, l must be positive)
        if (!resolved)
          not_proved("the slip at phi = " + num(phi) + " could not be polished by Newton's "
                     "method (an ill-conditioned slip system): its sign is not decided");
        continue;
      }
      if (x <= band_x) {
        // P1 = 0 within rounding: the separation (P1 = 0, g1 = 0) listed above, or undecided.
        const bool listed = std::any_of(found.begin(), found.end(), [](const Step3dValues& f) {
          return f.P_N1 == 0 && f.P_T1.cwiseAbs().maxCoeff() == 0;
        });
        if (!listed)
          not_proved("a slip at phi = " + num(phi) + " has P_N1 = " + num(x) + " at the "
                     "rounding level while no separation is listed: not resolved");
        continue;
      }
      const Eigen::Vector2d t(std::cos(phi), std::sin(phi));
      x = std::max(x, 0.0);
      l = std::max(l, 0.0);
      add(contact_values(p, mu * x * alpha.cwiseProduct(t), x, l, l * t.cwiseQuotient(alpha)),
          "slip at phi = " + num(phi));
    }
  }
  for (const auto& v : found) set.solutions.push_back(make_step_3d_solution(user, to_user_units(v, sc)));
  for (const auto& sol : set.solutions) {
    const Step3dValues& v = sol.values;
    if (!v.P_T1.allFinite() || !std::isfinite(v.P_N1) || !v.Dw_T.allFinite() ||
        !std::isfinite(v.Dw_N) || !std::isfinite(v.lambda))
      throw InputError("step: a solution does not fit a double in the problem's units");
  }
  std::stable_sort(set.solutions.begin(), set.solutions.end(),
                   [](const Step3dSolution& a, const Step3dSolution& b) {
                     if (a.type != b.type) return static_cast<int>(a.type) < static_cast<int>(b.type);
                     return a.slip_angle < b.slip_angle;
                   });
  return set;
}

}  // namespace cpkit::rate
