#pragma once
// Internal: the exact value of a polynomial in doubles as a floating-point expansion (a sum of
// nonoverlapping doubles, J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast
// robust geometric predicates", Discrete Comput. Geom. 18, 1997: Grow-Expansion, Scale-Expansion,
// Compress), so that its sign is the sign of its largest component: decided, never within a band.
//
// Why (issue 34): Rounded (rounded.hpp) decides a sign when the value exceeds its rounding bound.
// ON a critical load (the paper's exact critical loads on binary data: L_s = 0 or N = 0 in the
// data) the value is an exact 0 formed from rounded products, so the bound can never decide it
// and the certified routes answered "not complete". An expansion carries every rounding error
// as a further component and decides that 0 exactly.
//
// Exact unless a product leaves the range where fma's error term is exact (|a b| below 2^-960 or
// above 2^1000) or an expansion outgrows kCap components: then sign3 says kUndecided.
#include <cmath>

#include "rounded.hpp"

namespace cpkit::rate::detail {

class Expansion {
 public:
  static constexpr int kCap = 48;  ///< components kept (O(1) data need fewer than ten)

  Expansion() = default;
  explicit Expansion(double x) noexcept {
    if (!std::isfinite(x)) exact_ = false;
    else if (x != 0) c_[n_++] = x;
    v = x;
  }

  double v = 0;  ///< the value rounded to about an ulp (for values; signs come from sign3)

  friend Expansion operator+(const Expansion& a, const Expansion& b) noexcept {
    Expansion out;
    out.exact_ = a.exact_ && b.exact_;
    double h[2 * kCap];
    int n = a.n_;
    for (int i = 0; i < n; ++i) h[i] = a.c_[i];
    for (int j = 0; j < b.n_ && out.exact_; ++j) n = grow(h, n, b.c_[j], out.exact_);
    out.assign_compressed(h, n);
    return out;
  }
  friend Expansion operator-(Expansion a) noexcept {
    for (int i = 0; i < a.n_; ++i) a.c_[i] = -a.c_[i];
    a.v = -a.v;
    return a;
  }
  friend Expansion operator-(const Expansion& a, const Expansion& b) noexcept { return a + (-b); }
  friend Expansion operator*(const Expansion& a, const Expansion& b) noexcept {
    Expansion out;
    out.exact_ = a.exact_ && b.exact_;
    double sum[3 * kCap], part[2 * kCap];
    int n = 0;
    for (int j = 0; j < b.n_ && out.exact_; ++j) {
      const int m = scale(a.c_, a.n_, b.c_[j], part, out.exact_);
      for (int k = 0; k < m && out.exact_; ++k) n = grow(sum, n, part[k], out.exact_);
      n = compress(sum, n);
      if (n > kCap) out.exact_ = false;
    }
    out.assign_compressed(sum, n);
    return out;
  }

  /// -1, 0, +1: the exact sign; kUndecided when the arithmetic was not exact (see above).
  friend int sign3(const Expansion& x) noexcept {
    if (!x.exact_) return kUndecided;
    if (x.n_ == 0) return 0;
    return x.c_[x.n_ - 1] > 0 ? 1 : -1;
  }
  friend Expansion abs_of(const Expansion& x) noexcept { return sign3(x) < 0 ? -x : x; }

 private:
  double c_[kCap] = {};  ///< nonoverlapping, increasing magnitude, no zeros (exact sum = value)
  int n_ = 0;
  bool exact_ = true;

  static void two_sum(double a, double b, double& s, double& e) noexcept {
    s = a + b;
    const double bb = s - a;
    e = (a - (s - bb)) + (b - bb);
  }
  /// a b = p + e exactly when the product is well inside the normal range.
  static void two_prod(double a, double b, double& p, double& e, bool& ok) noexcept {
    p = a * b;
    e = std::fma(a, b, -p);
    const double m = std::abs(p);
    if (a != 0 && b != 0 && !(m >= 0x1p-960 && m <= 0x1p1000)) ok = false;
  }
  /// Grow-Expansion: h[0..n) + b into h (zero components dropped); returns the new length.
  static int grow(double* h, int n, double b, bool& ok) noexcept {
    double q = b;
    int k = 0;
    for (int i = 0; i < n; ++i) {
      double s, e;
      two_sum(q, h[i], s, e);
      q = s;
      if (e != 0) h[k++] = e;
    }
    if (q != 0) h[k++] = q;
    if (!std::isfinite(q)) ok = false;
    return k;
  }
  /// Scale-Expansion: e[0..n) b into h; returns the length (at most 2 n).
  static int scale(const double* e, int n, double b, double* h, bool& ok) noexcept {
    if (n == 0) return 0;
    int k = 0;
    double q, t;
    two_prod(e[0], b, q, t, ok);
    if (t != 0) h[k++] = t;
    for (int i = 1; i < n; ++i) {
      double p1, p0, s, hs;
      two_prod(e[i], b, p1, p0, ok);
      two_sum(q, p0, s, hs);
      if (hs != 0) h[k++] = hs;
      two_sum(p1, s, q, hs);
      if (hs != 0) h[k++] = hs;
    }
    if (q != 0) h[k++] = q;
    if (!std::isfinite(q)) ok = false;
    return k;
  }
  /// Compress: the same value in fewer, nonadjacent components (largest within an ulp of the
  /// sum); in place, returns the new length.
  static int compress(double* e, int n) noexcept {
    if (n == 0) return 0;
    int bottom = n - 1;
    double q = e[bottom];
    for (int i = n - 2; i >= 0; --i) {
      double s, t;
      two_sum(q, e[i], s, t);
      if (t != 0) {
        e[bottom--] = s;
        q = t;
      } else {
        q = s;
      }
    }
    int top = 0;
    for (int i = bottom + 1; i < n; ++i) {
      double s, t;
      two_sum(e[i], q, s, t);
      if (t != 0) e[top++] = t;
      q = s;
    }
    if (q != 0) e[top++] = q;
    return top;
  }
  void assign_compressed(double* h, int n) noexcept {
    n = compress(h, n);
    if (n > kCap) {
      exact_ = false;
      n = kCap;
    }
    n_ = n;
    for (int i = 0; i < n; ++i) c_[i] = h[i];
    v = n > 0 ? c_[n - 1] : 0.0;
  }
};

}  // namespace cpkit::rate::detail
