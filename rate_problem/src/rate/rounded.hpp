#pragma once
// Internal: a double together with a bound on its rounding error, for three-valued sign tests.
//
// Every operation adds the exact error of its own rounding (TwoSum, fma), so a quantity formed
// without rounding (exact products of small integers, a load of zero) carries a zero bound and
// its zero is a decided zero, while a quantity formed by cancellation carries the rounding of
// every term it was formed from. The sign of x is decided when |x.v| exceeds the bound: no
// relative tolerance, no units (issue 24: a fixed band of 1e-10 decided signs that the data do
// not decide, and called a nonzero quantity zero).
#include <cmath>

namespace cpkit::rate::detail {

struct Rounded {
  double v = 0;  ///< computed value
  double e = 0;  ///< bound on |v - exact value of the expression on the (exact) inputs|
};

inline Rounded exact(double x) noexcept { return {x, 0.0}; }

inline Rounded operator+(Rounded a, Rounded b) noexcept {
  const double s = a.v + b.v;
  const double bb = s - a.v;
  const double err = (a.v - (s - bb)) + (b.v - bb);  // TwoSum: exact rounding error of s
  return {s, a.e + b.e + std::abs(err)};
}
inline Rounded operator-(Rounded a) noexcept { return {-a.v, a.e}; }
inline Rounded operator-(Rounded a, Rounded b) noexcept { return a + (-b); }
inline Rounded operator*(Rounded a, Rounded b) noexcept {
  const double p = a.v * b.v;
  const double err = std::fma(a.v, b.v, -p);  // exact rounding error of p
  return {p, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + std::abs(err)};
}
/// a / b for |b.v| > b.e (b bounded away from zero); otherwise an unbounded error.
inline Rounded operator/(Rounded a, Rounded b) noexcept {
  const double q = a.v / b.v;
  const double den = std::abs(b.v) - b.e;
  if (!(den > 0)) return {q, HUGE_VAL};
  const double rem = std::fma(-q, b.v, a.v);  // a - q b, exact: the local error is rem / b
  return {q, (std::abs(rem) + a.e + std::abs(q) * b.e) / den};
}

/// a b - c d to within 2 ulps (Kahan's algorithm with fma): the cancellation of an
/// ill-conditioned A (det A) or of a load near a critical direction leaves no rounding noise.
inline double diff_of_products(double a, double b, double c, double d) noexcept {
  const double w = c * d;
  const double e = std::fma(-c, d, w);  // exact: w - c d
  const double f = std::fma(a, b, -w);
  return f + e;
}

/// Three-valued sign: -1, 0, +1 when decided, kUndecided when |v| is within the bound.
inline constexpr int kUndecided = 2;
inline int sign3(Rounded x) noexcept {
  // the bound is itself rounded (a few ulps per operation): inflate it slightly
  if (std::abs(x.v) > x.e * (1.0 + 0x1p-40)) return x.v > 0 ? 1 : -1;
  if (x.v == 0 && x.e == 0) return 0;
  return kUndecided;
}

}  // namespace cpkit::rate::detail
