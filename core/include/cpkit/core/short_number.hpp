#pragma once
/// \file short_number.hpp
/// A number with 3 significant digits, for messages ("residual 1.2e-09 > tol 1e-09"): enough to
/// read a size or compare with a tolerance, short enough for one line.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace cpkit {

namespace detail {

/// printf's "%.3g" of v into out (at least 16 chars), by integer arithmetic for 1e-20 <= |v| <
/// 1e22: |v| times an exact power of ten (one rounding) is the 3-digit mantissa, rounded to the
/// nearest integer as printf rounds the exact value, which it equals unless the scaled value is
/// within 1e-9 of a tie; 0 is "0" (or "-0"). False for a tie, non-finite or out-of-range v
/// (snprintf decides).
/// snprintf's conversion was most of a small solve's message (6 k instructions for three
/// numbers; this takes ~100 each). tests/core/test_short_number.cpp compares both.
inline bool short_number_fast(double v, char* out) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const double a = std::abs(v);
  if (a == 0) {  // an exact answer's residual: "0" (or "-0")
    std::memcpy(out, std::signbit(v) ? "-0" : "0", std::signbit(v) ? 3 : 2);
    return true;
  }
  if (!(a >= 1e-20 && a < 1e22)) return false;
  int x = static_cast<int>(std::floor(std::log10(a)));  // the decimal exponent, give or take 1
  auto scaled = [a](int e) {  // a / 10^(e - 2), exact powers: |e - 2| <= 22
    return e <= 2 ? a * kPow10[2 - e] : a / kPow10[e - 2];
  };
  double t = scaled(x);
  if (t < 100) t = scaled(--x);
  if (t >= 1000) t = scaled(++x);
  const double frac = t - std::floor(t);
  if (std::abs(frac - 0.5) <= 1e-9) return false;
  int m = static_cast<int>(t + 0.5);
  if (m == 1000) {  // 999.5 and up rounds into the next decade
    m = 100;
    ++x;
  }
  const char d[3] = {static_cast<char>('0' + m / 100), static_cast<char>('0' + m / 10 % 10),
                     static_cast<char>('0' + m % 10)};
  int digits = 3;  // significant digits once trailing zeros are dropped (%g drops them)
  while (digits > 1 && d[digits - 1] == '0') --digits;
  char* o = out;
  if (v < 0) *o++ = '-';
  if (x >= -4 && x < 3) {  // %f style, 2 - x decimals, trailing zeros dropped
    if (x >= 0) {
      for (int i = 0; i <= x; ++i) *o++ = d[i];
      if (digits > x + 1) *o++ = '.';
      for (int i = x + 1; i < digits; ++i) *o++ = d[i];
    } else {
      *o++ = '0';
      *o++ = '.';
      for (int i = 0; i < -x - 1; ++i) *o++ = '0';
      for (int i = 0; i < digits; ++i) *o++ = d[i];
    }
  } else {  // %e style: d.dd, trailing zeros dropped, an exponent of at least two digits
    *o++ = d[0];
    if (digits > 1) *o++ = '.';
    for (int i = 1; i < digits; ++i) *o++ = d[i];
    *o++ = 'e';
    *o++ = x < 0 ? '-' : '+';
    const int e = x < 0 ? -x : x;
    *o++ = static_cast<char>('0' + e / 10);
    *o++ = static_cast<char>('0' + e % 10);
  }
  *o = '\0';
  return true;
}

}  // namespace detail

/// printf's "%.3g" (what an ostream at precision 3 prints, without building a stream and its
/// locale: a one-contact solve formats a few of these, and the stream was a fifth of its cost).
inline std::string short_number(double v) {
  char buf[32];
  if (!detail::short_number_fast(v, buf)) std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace cpkit
