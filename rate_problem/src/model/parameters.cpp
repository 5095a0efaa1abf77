#include "cpkit/rate_problem/model/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cpkit::rate {

std::string_view to_string(Criterion c) noexcept {
  switch (c) {
    case Criterion::kCoulomb:
      return "coulomb";
    case Criterion::kSoftening:
      return "softening";
  }
  return "unknown";
}

std::optional<Criterion> criterion_from_string(std::string_view s) noexcept {
  if (s == "coulomb" || s == "38") return Criterion::kCoulomb;
  if (s == "softening" || s == "35") return Criterion::kSoftening;
  return std::nullopt;
}

std::string ContactParameters::validate() const {
  std::ostringstream msg;
  const double values[] = {a11, a12, a22, mu, C_T, k_a, P_s};
  const char* names[] = {"a11", "a12", "a22", "mu", "C_T", "k_a", "P_s"};
  for (int i = 0; i < 7; ++i) {
    if (!std::isfinite(values[i])) {
      msg << names[i] << " = " << values[i] << " is not finite";
      return msg.str();
    }
  }
  // A symmetric positive definite: a11 > 0, a22 > 0 and det A > 0 (Sylvester). The determinant
  // is judged relative to a11 a22 so that a nearly singular A is reported, not divided by; and
  // on A scaled by a power of two (exact) to a largest entry in [1, 2), so that the verdict does
  // not depend on units (unscaled, a11 a22 overflows at 1e300 and underflows at 1e-300).
  const double amax = std::max({std::abs(a11), std::abs(a12), std::abs(a22)});
  const double f = amax > 0 ? std::ldexp(1.0, -std::ilogb(amax)) : 1.0;
  const double b11 = f * a11, b12 = f * a12, b22 = f * a22;
  if (!(b11 > 0) || !(b22 > 0) || !(b11 * b22 - b12 * b12 > 1e-14 * b11 * b22)) {
    msg << "A = [[" << a11 << ", " << a12 << "], [" << a12 << ", " << a22
        << "]] is not symmetric positive definite (need a11 > 0, a22 > 0, a11 a22 - a12^2 > 0; "
        << "det A = " << detA() << ")";
    return msg.str();
  }
  if (!(mu > 0)) {
    msg << "mu = " << mu << ": the friction coefficient must be > 0";
    return msg.str();
  }
  if (!(C_T >= 0)) {
    msg << "C_T = " << C_T << ": the tangential compliance must be >= 0";
    return msg.str();
  }
  if (!(k_a >= 0)) {
    msg << "k_a = " << k_a << ": the wear coefficient must be >= 0";
    return msg.str();
  }
  if (!(P_s > 0)) {
    msg << "P_s = " << P_s << ": the hardness must be > 0";
    return msg.str();
  }
  return {};
}

}  // namespace cpkit::rate
