#include "cpkit/rate_problem/model/parameters.hpp"

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
  // is judged relative to a11 a22 so that a nearly singular A is reported, not divided by.
  if (!(a11 > 0) || !(a22 > 0) || !(detA() > 1e-14 * a11 * a22)) {
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
