// Every solution of the faceted problem by enumeration of its LCP (faceted.hpp).
#include <algorithm>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {

FacetedSolutionList faceted_solutions(const FrictionContactProblem& p, int k, double regularisation,
                                      double time_limit_s) {
  detail::check_problem(p);
  const Eigen::Index nc = p.contacts();
  if (nc * (k + 2) > kMaxEnumerationSize)
    throw InputError("faceted enumeration: n_c (k + 2) = " + std::to_string(nc * (k + 2)) +
                     " exceeds the enumeration's " + std::to_string(kMaxEnumerationSize) +
                     " unknowns");
  if (!(regularisation >= 0)) throw InputError("faceted enumeration: regularisation must be >= 0");
  FacetedSolutionList out;
  out.faceted = faceted_lcp(p, k);
  const FrictionUnits units = friction_units(p);
  const double eps = regularisation * detail::w_scale(p.W, units);
  for (Eigen::Index i = 0; i < nc; ++i)
    for (int j = 0; j <= k; ++j) out.faceted.lcp.M(i * (k + 2) + j, i * (k + 2) + j) += eps;
  EnumerationOptions eo;
  eo.time_limit_s = time_limit_s;
  const SolutionSet zs = enumerate_all(out.faceted.lcp, eo);
  out.extreme = zs.count();
  out.complete = zs.complete;
  out.infinite = zs.infinite;
  out.message = zs.message;
  const double r_ref = (units.q_inf > 0 && units.w_max > 0) ? units.q_inf / units.w_max : 1.0;
  for (const ExtremeSolution& x : zs.solutions) {
    const Eigen::VectorXd r = out.faceted.G * x.z;
    const bool seen = std::any_of(out.r.begin(), out.r.end(), [&](const Eigen::VectorXd& y) {
      const double s = std::max({r.lpNorm<Eigen::Infinity>(), y.lpNorm<Eigen::Infinity>(), r_ref});
      return (r - y).lpNorm<Eigen::Infinity>() <= 1e-6 * s;
    });
    if (!seen) out.r.push_back(r);
  }
  return out;
}

}  // namespace cpkit::lcp::friction
