// Every solution of a one-contact frictional problem in closed form (one_contact.hpp).
#include "cpkit/lcp/friction/one_contact.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace cpkit::lcp::friction {
namespace {

using Cplx = std::complex<double>;

struct Candidates {
  Vec3 r[7];
  double res[7];
  int count = 0;
  void add(const Vec3& x, double rs) {
    if (!x.allFinite() || count == 7) return;
    r[count] = x;
    res[count] = rs;
    ++count;
  }
};

// a / b without the overflow guards of std::complex (operands here are moderate).
inline Cplx div(Cplx a, Cplx b) {
  const double d = b.real() * b.real() + b.imag() * b.imag();
  return Cplx((a.real() * b.real() + a.imag() * b.imag()) / d,
              (a.imag() * b.real() - a.real() * b.imag()) / d);
}

// Roots of sum_k c[k] z^k (degree N <= 4, c[N] != 0) by the Aberth-Ehrlich simultaneous
// iteration [Aberth 1973; Bini 1996]: cubically convergent to simple roots, allocation-free, and
// ~10x cheaper than a companion-matrix eigenvalue solve (NSGS calls this once per contact and
// sweep). Starting points: a circle of radius |c0 / cN|^(1/N), rotated off the real axis. Roots
// that do not converge are still returned (the caller checks every candidate anyway).
int poly_roots(const Cplx* c, int N, Cplx* z) {
  const double rad = std::pow(std::abs(c[0] / c[N]), 1.0 / N);
  const double r0 = rad > 0 && std::isfinite(rad) ? rad : 1.0;
  for (int k = 0; k < N; ++k) z[k] = std::polar(r0, 2 * M_PI * k / N + 0.4);
  bool done[4] = {false, false, false, false};
  for (int it = 0; it < 60; ++it) {
    bool all = true;
    for (int k = 0; k < N; ++k) {
      if (done[k]) continue;
      Cplx p = c[N], dp = 0;  // Horner: p(z_k) and p'(z_k)
      for (int j = N - 1; j >= 0; --j) {
        dp = dp * z[k] + p;
        p = p * z[k] + c[j];
      }
      if (p == Cplx(0)) {
        done[k] = true;
        continue;
      }
      // Complex divisions written out (std::complex's operator/ is the slow Annex G one).
      const Cplx ratio = div(p, dp);
      Cplx sum = 0;
      for (int j = 0; j < N; ++j)
        if (j != k) sum += div(Cplx(1), z[k] - z[j]);
      const Cplx w = div(ratio, 1.0 - ratio * sum);
      if (!std::isfinite(w.real()) || !std::isfinite(w.imag())) continue;
      z[k] -= w;
      // Converged: the correction is at the rounding level of z_k (it can no longer improve).
      done[k] = std::norm(w) <= 1e-28 * std::max(std::norm(z[k]), 1e-300);
      all = all && done[k];
    }
    if (all) break;
  }
  return N;
}

// f(phi) = a0 + a1 cos + b1 sin + a2 cos 2phi + b2 sin 2phi and f'(phi), from one sine and
// cosine (the double angles by their identities: Newton's step below calls this up to 8 times
// per root, and the trigonometric calls were most of a one-contact solve).
struct Trig2 {
  double a0, a1, b1, a2, b2;
  void eval(double p, double& f, double& df) const {
    const double c = std::cos(p), s = std::sin(p);
    const double c2 = c * c - s * s, s2 = 2 * s * c;
    f = a0 + a1 * c + b1 * s + a2 * c2 + b2 * s2;
    df = -a1 * s + b1 * c - 2 * a2 * s2 + 2 * b2 * c2;
  }
};

// Roots of f on the circle: the unit-modulus roots of z^2 f(z) (degree <= 4) refined by Newton.
int trig_roots(const Trig2& t, double* phi) {
  Cplx c[5] = {Cplx(t.a2, t.b2) / 2.0, Cplx(t.a1, t.b1) / 2.0, Cplx(t.a0, 0),
               Cplx(t.a1, -t.b1) / 2.0, Cplx(t.a2, -t.b2) / 2.0};
  double big = 0;
  for (const Cplx& x : c) big = std::max(big, std::abs(x));
  if (big == 0) return 0;  // f = 0: every direction (degenerate; not listed)
  // c0 = conj(c4), c1 = conj(c3): trim both ends together (a zero root is not on the circle).
  int lo = 0, hi = 4;
  const double tiny = 1e-14 * big;
  while (hi > lo && std::abs(c[hi]) <= tiny && std::abs(c[lo]) <= tiny) {
    ++lo;
    --hi;
  }
  Cplx roots[4];
  int n = 0;
  if (hi - lo < 1) return 0;  // a constant: no root
  n = poly_roots(c + lo, hi - lo, roots);
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const double mod = std::abs(roots[i]);
    if (!(std::abs(mod - 1) < 1e-3)) continue;
    double p = std::arg(roots[i]);
    for (int it = 0; it < 8; ++it) {  // Newton in phi (the root is real)
      double f, d;
      t.eval(p, f, d);
      if (d == 0) break;
      const double step = f / d;
      if (!std::isfinite(step) || std::abs(step) > 0.1) break;
      p -= step;
      if (std::abs(step) < 1e-16) break;
    }
    phi[m++] = p;
  }
  return m;
}

// |W|_max and the largest row sum of |W|.
void w_sizes(const Mat3& W, double& w_max, double& row_max) {
  const Mat3 A = W.cwiseAbs();
  w_max = A.maxCoeff();
  row_max = A.rowwise().sum().maxCoeff();
}

double residual_with(const Mat3& W, const Vec3& b, double mu, const Vec3& r, double w_max,
                     double row_max) {
  const Vec3 u = W * r + b;
  const double b_inf = b.lpNorm<Eigen::Infinity>(), r_inf = r.lpNorm<Eigen::Infinity>();
  const bool has_ref = b_inf > 0 && w_max > 0;
  const double ref = has_ref ? b_inf / w_max : r_inf;
  const double R = std::max(r_inf, ref);
  const double S = b.norm() + row_max * std::min(r_inf, ref);
  if (R == 0 && S == 0) return 0;  // b = 0, r = 0 (or W = 0)
  const Vec3 rn = R > 0 ? Vec3(r / R) : Vec3::Zero();
  if (!(S > 0)) return u.isZero(0) ? natural_map(rn, Vec3::Zero(), mu).norm()
                                    : std::numeric_limits<double>::infinity();
  const double v = natural_map(rn, u / S, mu).norm();
  return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
}

Candidates candidates(const Mat3& W, const Vec3& b, double mu) {
  Candidates c;
  double w_max, row_max;
  w_sizes(W, w_max, row_max);
  auto add = [&](const Vec3& r) { c.add(r, residual_with(W, b, mu, r, w_max, row_max)); };
  add(Vec3::Zero());  // separation
  // Stick: W r = -b (minimum-norm when W is singular).
  const Eigen::CompleteOrthogonalDecomposition<Mat3> cod(W);
  add(cod.solve(-b));
  if (mu == 0) {
    if (W(0, 0) > 0) add(Vec3(std::max(0.0, -b[0] / W(0, 0)), 0, 0));
    return c;
  }
  // Slip: (W e)_k = A_k + B_k cos + C_k sin with A_k = W_k0, B_k = -mu W_k1, C_k = -mu W_k2;
  // v_j = -b_0 (W e)_j + b_j (W e)_0 = P_j + Q_j cos + R_j sin (j = 1, 2); f = v_1 sin - v_2 cos.
  double P[3], Q[3], R[3];
  for (int j = 1; j < 3; ++j) {
    P[j] = -b[0] * W(j, 0) + b[j] * W(0, 0);
    Q[j] = -b[0] * (-mu * W(j, 1)) + b[j] * (-mu * W(0, 1));
    R[j] = -b[0] * (-mu * W(j, 2)) + b[j] * (-mu * W(0, 2));
  }
  const Trig2 t{(R[1] - Q[2]) / 2, -P[2], P[1], -(R[1] + Q[2]) / 2, (Q[1] - R[2]) / 2};
  double phi[4];
  const int m = trig_roots(t, phi);
  for (int i = 0; i < m; ++i) {
    const Vec3 e(1, -mu * std::cos(phi[i]), -mu * std::sin(phi[i]));
    const double we = W.row(0).dot(e);
    if (we == 0) continue;
    const double rn = -b[0] / we;
    if (rn > 0) add(rn * e);
  }
  return c;
}

bool valid(const Candidates& c, int i) { return c.res[i] <= kOneContactLocalTol; }

}  // namespace

double one_contact_residual(const Mat3& W, const Vec3& b, double mu, const Vec3& r) {
  double w_max, row_max;
  w_sizes(W, w_max, row_max);
  return residual_with(W, b, mu, r, w_max, row_max);
}

OneContactSolutions one_contact_solutions(const Mat3& W, const Vec3& b, double mu) {
  const Candidates c = candidates(W, b, mu);
  OneContactSolutions out;
  for (int i = 0; i < c.count; ++i) {
    if (!valid(c, i)) continue;
    bool dup = false;
    for (int j = 0; j < out.count && !dup; ++j)
      dup = (out.r[j] - c.r[i]).norm() <= 1e-9 * std::max(out.r[j].norm(), c.r[i].norm());
    if (!dup && out.count < 6) out.r[out.count++] = c.r[i];
  }
  return out;
}

Vec3 one_contact_nearest(const Mat3& W, const Vec3& b, double mu, const Vec3& near,
                         double* residual) {
  const Candidates c = candidates(W, b, mu);
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < c.count; ++i) {
    if (!valid(c, i)) continue;
    const double d = (c.r[i] - near).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  if (best < 0)  // nothing passes: the least wrong candidate
    for (int i = 0; i < c.count; ++i)
      if (best < 0 || c.res[i] < c.res[best]) best = i;
  if (residual) *residual = c.res[best];
  return c.r[best];
}

}  // namespace cpkit::lcp::friction
