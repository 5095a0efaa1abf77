#include "cpkit/rate_problem/model/contact_state.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

std::string_view to_string(StateLabel s) noexcept {
  switch (s) {
    case StateLabel::kA:
      return "a";
    case StateLabel::kB:
      return "b";
    case StateLabel::kC:
      return "c";
    case StateLabel::kD:
      return "d";
  }
  return "unknown";
}

std::optional<StateLabel> state_from_string(std::string_view s) noexcept {
  if (s == "a" || s == "open") return StateLabel::kA;
  if (s == "b" || s == "grazing") return StateLabel::kB;
  if (s == "c" || s == "stick") return StateLabel::kC;
  if (s == "d" || s == "sliding") return StateLabel::kD;
  return std::nullopt;
}

std::string ContactState::validate(const ContactParameters& params) const {
  std::ostringstream msg;
  if (!std::isfinite(P_N)) {
    msg << "P_N = " << P_N << " is not finite";
    return msg.str();
  }
  const bool in_contact = label == StateLabel::kC || label == StateLabel::kD;
  if (!in_contact) {
    if (P_N != 0) {
      msg << "state " << to_string(label) << " has P = 0 [Stromberg et al. 1996, Sec. 4.2], got P_N = "
          << P_N;
      return msg.str();
    }
    if (sgn_PT < -1 || sgn_PT > 1) {
      msg << "sgn P_T = " << sgn_PT << " must be -1, 0 or +1";
      return msg.str();
    }
    return {};
  }
  if (!(P_N > 0)) {
    msg << "state " << to_string(label) << " needs P_N > 0, got P_N = " << P_N;
    return msg.str();
  }
  if (label == StateLabel::kD && sgn_PT != 1 && sgn_PT != -1) {
    msg << "state d needs sgn P_T = +1 or -1 (the sliding direction), got " << sgn_PT;
    return msg.str();
  }
  if (label == StateLabel::kC && (sgn_PT < -1 || sgn_PT > 1)) {
    msg << "sgn P_T = " << sgn_PT << " must be -1, 0 or +1";
    return msg.str();
  }
  if (params.criterion == Criterion::kSoftening && params.k_a > 0) {
    // (46): the softened cone |P_T| <= mu P_N - k P_N^2 needs k P_N <= mu. At equality the cone
    // is the single point P_T = 0 and neither state c nor a sliding direction exists.
    const double bound = 3.0 * params.P_s * params.mu / params.k_a;
    // within a relative 1e-12 of the bound counts as at the bound (rounding of k = k_a/(3 P_s))
    if (!(params.kappa(P_N) < params.mu * (1.0 - 1e-12))) {
      msg << "P_N = " << P_N << " violates the bound (46) of the softening criterion (35): need "
          << "P_N < 3 P_s mu / k_a = " << bound
          << " (at the bound the friction cone degenerates to P_T = 0)";
      return msg.str();
    }
  }
  return {};
}

ContactState classify(const ContactConfiguration& c, const ContactParameters& p, double tol) {
  throw_if_invalid(p.validate(), "contact parameters");
  const double vals[] = {c.w_N, c.w_w, c.w_T, c.P_N, c.P_T};
  const char* names[] = {"w_N", "w^w", "w_T", "P_N", "P_T"};
  for (int i = 0; i < 5; ++i) {
    if (!std::isfinite(vals[i])) {
      throw InputError(std::string("contact configuration: ") + names[i] + " is not finite");
    }
  }
  if (!(tol >= 0) || !std::isfinite(tol)) throw InputError("classify: tol must be finite and >= 0");
  const double force_zero = tol * (1.0 + std::max(std::abs(c.P_N), std::abs(c.P_T)));
  const double gap_zero = tol * (1.0 + std::max(std::abs(c.w_N), std::abs(c.w_w)));
  const double gap = c.w_N - c.w_w;  // (48): w_N - w^w <= 0
  std::ostringstream msg;
  if (c.P_N < -force_zero) {
    msg << "contact configuration: P_N = " << c.P_N << " < 0 (tension is inadmissible, eqn (48))";
    throw InputError(msg.str());
  }
  if (gap > gap_zero) {
    msg << "contact configuration: w_N - w^w = " << gap << " > 0 (penetration, eqn (48))";
    throw InputError(msg.str());
  }
  ContactState s;
  if (std::abs(c.P_N) <= force_zero) {
    if (std::abs(c.P_T) > force_zero) {
      msg << "contact configuration: P_T = " << c.P_T << " with P_N = 0 violates |P_T| <= mu P_N";
      throw InputError(msg.str());
    }
    s.label = gap < -gap_zero ? StateLabel::kA : StateLabel::kB;
    s.P_N = 0;
    s.sgn_PT = 0;
    return s;
  }
  if (std::abs(gap) > gap_zero) {
    msg << "contact configuration: P_N = " << c.P_N << " > 0 with an open gap w_N - w^w = " << gap
        << " violates P_N (w_N - w^w) = 0 (eqn (48))";
    throw InputError(msg.str());
  }
  double limit = p.mu * c.P_N;  // (38)
  if (p.criterion == Criterion::kSoftening) {
    limit -= p.k() * c.P_N * c.P_N;  // (35): mu P_N - k P_N^2
  }
  s.P_N = c.P_N;
  s.sgn_PT = c.P_T > 0 ? 1 : (c.P_T < 0 ? -1 : 0);
  const double excess = std::abs(c.P_T) - limit;
  if (excess > force_zero) {
    msg << "contact configuration: |P_T| = " << std::abs(c.P_T) << " exceeds the friction limit "
        << limit << " (" << (p.criterion == Criterion::kCoulomb ? "eqn (38)" : "eqn (35)") << ")";
    throw InputError(msg.str());
  }
  s.label = excess >= -force_zero ? StateLabel::kD : StateLabel::kC;
  if (s.label == StateLabel::kD && s.sgn_PT == 0) {
    throw InputError("contact configuration: sliding limit with P_T = 0 (the cone has collapsed; "
                     "see the bound (46))");
  }
  throw_if_invalid(s.validate(p), "contact configuration");
  return s;
}

}  // namespace cpkit::rate
