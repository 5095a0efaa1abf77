#include "small_contact.hpp"

#include <cmath>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/friction/one_contact_newton.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::capi {
namespace {

/// The decoupled isotropic contact's unique solution (small_contact.hpp) into r; false when W
/// is not of that form.
bool decoupled_isotropic_solution(const Mat3& W, const Vec3& q, double mu, Vec3& r) {
  const double a = W(0, 0), c = W(1, 1);
  if (!(a > 0 && c > 0 && W(2, 2) == c && W(0, 1) == 0 && W(0, 2) == 0 && W(1, 0) == 0 &&
        W(2, 0) == 0 && W(1, 2) == 0 && W(2, 1) == 0))
    return false;
  if (!(q[0] < 0)) {  // r_N > 0 would need u_N = a r_N + q_N = 0: separation
    r.setZero();
    return true;
  }
  const double r_n = -q[0] / a, radius = mu * r_n;
  const double t1 = -q[1] / c, t2 = -q[2] / c, t = std::hypot(t1, t2);
  r[0] = r_n;
  if (t <= radius) {  // stick: u = 0
    r[1] = t1;
    r[2] = t2;
  } else {  // slip: on the disc's edge, opposite to the sliding velocity
    r[1] = t1 * (radius / t);
    r[2] = t2 * (radius / t);
  }
  return true;
}

}  // namespace

bool one_contact_route(int contacts, const SolverEntry& entry) {
  static const SolverEntry* const nsgs = lcp::solvers().find("nsgs");
  static const SolverEntry* const automatic = lcp::solvers().find("auto");
  return contacts == 1 && (&entry == nsgs || &entry == automatic);
}

bool solve_one_contact_fast(const OneContact& contact, const Vec3& q, double mu, double tol,
                            Vec3& r, Vec3& u, double& unit_free) {
  // A candidate is the answer when the verdict accepts it.
  auto accept = [&](const Vec3& candidate) {
    Vec3 u_candidate;
    const double v =
        one_contact_unit_free(contact.W, contact.stored, q, mu, candidate, u_candidate);
    if (!(v <= tol)) return false;
    r = candidate;
    u = u_candidate;
    unit_free = v;
    return true;
  };
  Vec3 candidate;
  if (decoupled_isotropic_solution(contact.W, q, mu, candidate)) return accept(candidate);
  if (lcp::friction::one_contact_newton(contact.W, nullptr, q, mu, Vec3::Zero(), candidate) &&
      accept(candidate))
    return true;
  // Not found or not verified: every solution in closed form.
  const lcp::friction::OneContactSolutions all =
      lcp::friction::one_contact_solutions(contact.W, q, mu);
  return all.count == 1 && accept(all.r[0]);  // the general route decides (and explains) the rest
}

bool solve_one_contact_unique(const FrictionContactProblem& p, const SolverEntry& entry,
                              const CommonOptions& o, SolveResult& r) {
  if (!one_contact_route(static_cast<int>(p.contacts()), entry)) return false;
  const Mat3 W = p.W;  // 3 x 3
  const lcp::friction::OneContactSolutions all =
      lcp::friction::one_contact_solutions(W, p.q.head<3>(), p.mu[0]);
  if (all.count != 1) return false;
  r.z = all.r[0];
  reuse_as_claim(r, Status::kSolved, "one-contact");  // the scratch result's storage kept
  r = finalize(p, std::move(r), o);
  return is_solution(r.status);
}

}  // namespace cpkit::capi
