#include "small_contact.hpp"

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::capi {

bool solve_one_contact_unique(const FrictionContactProblem& p, const SolverEntry& entry,
                              const CommonOptions& o, SolveResult& r) {
  static const SolverEntry* const nsgs = lcp::solvers().find("nsgs");
  static const SolverEntry* const automatic = lcp::solvers().find("auto");
  if (p.contacts() != 1 || (&entry != nsgs && &entry != automatic)) return false;
  const Mat3 W = p.W;  // 3 x 3
  const lcp::friction::OneContactSolutions all =
      lcp::friction::one_contact_solutions(W, p.q.head<3>(), p.mu[0]);
  if (all.count != 1) return false;
  // The claim, with the scratch result's other fields cleared (their storage is kept).
  r.z = all.r[0];
  r.status = Status::kSolved;
  r.solver = "one-contact";
  r.iterations = r.function_evals = r.jacobian_evals = r.line_search_steps = r.gradient_steps = 0;
  r.seconds = 0;
  r.certificate.reset();
  r.ray.reset();
  r.basis.clear();
  r.trace.clear();
  r.attempts.clear();
  r.message.clear();
  r = finalize(p, std::move(r), o);
  return is_solution(r.status);
}

}  // namespace cpkit::capi
