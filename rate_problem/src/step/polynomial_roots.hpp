#pragma once
// Real roots of the slip polynomials of the one-point step (private to rate_problem).

namespace cpkit::rate::detail {

/// Real roots of the cubic c[3] x^3 + ... + c[0] (c[3] != 0) in [lo, hi], by bracketing between
/// critical points (safeguarded Newton); sc[] bounds the magnitudes of the terms, so a value at
/// or under 1e-13 of that bound counts as a root. At most 4 roots (a root at a bracket end may
/// be listed once per bracket); returns their number.
int cubic_roots_in(const double c[4], const double sc[4], double lo, double hi,
                   double roots[4]) noexcept;

}  // namespace cpkit::rate::detail
