#include "polynomial_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cpkit/rate_problem/step/step_enumeration.hpp"

namespace cpkit::rate {
namespace {

double sgn1(double v) noexcept { return v < 0 ? -1.0 : 1.0; }

/// Horner evaluation of c[3] x^3 + ... + c[0] and of the bound on its rounding.
double poly(const double c[4], double x) noexcept {
  return ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
}
double poly_scale(const double s[4], double x) noexcept {
  const double ax = std::abs(x);
  return ((s[3] * ax + s[2]) * ax + s[1]) * ax + s[0];
}

}  // namespace

namespace detail {

int cubic_roots_in(const double c[4], const double sc[4], double lo, double hi,
                   double roots[4]) noexcept {
  double crit[2];
  const double dc2 = 3 * c[3], dc1 = 2 * c[2], dc0 = c[1];
  int nc = stable_quadratic_roots(dc2, dc1, dc0, 3 * sc[3], 2 * sc[2], sc[1], 0.0, crit);
  if (nc < 0) nc = 0;
  double brk[4];
  int nb = 0;
  brk[nb++] = lo;
  if (nc == 2 && crit[0] > crit[1]) std::swap(crit[0], crit[1]);
  for (int i = 0; i < nc; ++i)
    if (crit[i] > lo && crit[i] < hi) brk[nb++] = crit[i];
  brk[nb++] = hi;
  int n = 0;
  auto add = [&](double x) {
    for (int i = 0; i < n; ++i)
      if (std::abs(roots[i] - x) <= 1e-12 * (1 + std::abs(x))) return;
    if (n < 4) roots[n++] = x;
  };
  for (int i = 0; i < nb; ++i) {
    const double fx = poly(c, brk[i]);
    if (std::abs(fx) <= 1e-13 * poly_scale(sc, brk[i])) add(brk[i]);
  }
  for (int i = 0; i + 1 < nb; ++i) {
    double u = brk[i], v = brk[i + 1];
    double fu = poly(c, u), fv = poly(c, v);
    if (fu == 0 || fv == 0 || (fu < 0) == (fv < 0)) continue;
    // Safeguarded Newton (rtsafe): keep the bracket, fall back to bisection.
    double x = 0.5 * (u + v);
    for (int it = 0; it < 200; ++it) {
      const double fx = poly(c, x);
      if (fx == 0) break;
      if ((fx < 0) == (fu < 0)) {
        u = x;
        fu = fx;
      } else {
        v = x;
      }
      const double dfx = (3 * c[3] * x + 2 * c[2]) * x + c[1];
      double xn = (dfx != 0) ? x - fx / dfx : 0.5 * (u + v);
      if (!(xn > u && xn < v)) xn = 0.5 * (u + v);
      if (std::abs(xn - x) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(x) ||
          v - u <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(u), std::abs(v))) {
        x = xn;
        break;
      }
      x = xn;
    }
    add(x);
  }
  return n;
}

}  // namespace detail

int stable_quadratic_roots(double c2, double c1, double c0, double scale2, double scale1,
                           double scale0, double deg_tol, double roots[2]) noexcept {
  const bool z2 = std::abs(c2) <= deg_tol * scale2;
  if (z2) {
    const bool z1 = std::abs(c1) <= deg_tol * scale1;
    if (z1) return (std::abs(c0) <= deg_tol * scale0) ? -1 : 0;
    roots[0] = -c0 / c1;
    return 1;
  }
  double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) {
    if (disc >= -1e-12 * (c1 * c1 + 4 * std::abs(c2 * c0))) {
      disc = 0;
    } else {
      return 0;
    }
  }
  const double q = -0.5 * (c1 + sgn1(c1) * std::sqrt(disc));
  if (q == 0) {  // c1 = 0 and c0 = 0: double root at 0
    roots[0] = 0;
    return 1;
  }
  roots[0] = q / c2;
  if (disc == 0) return 1;
  roots[1] = c0 / q;
  return 2;
}

}  // namespace cpkit::rate
