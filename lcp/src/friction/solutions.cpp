// Several solutions of a frictional contact problem (solutions.hpp).
#include "cpkit/lcp/friction/solutions.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_helpers.hpp"

namespace cpkit::lcp::friction {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDistinct = 1e-6;

// 53-bit uniform in [0, 1): the same sequence on every platform (std::uniform_real_distribution
// is not specified bit for bit).
double uniform(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

struct Collector {
  const FrictionContactProblem& p;
  double r_ref;
  FrictionSolutionSet& set;
  int tried = 0, verified = 0;

  double distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    const double s = std::max({a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>(), r_ref});
    return s > 0 ? (a - b).lpNorm<Eigen::Infinity>() / s : 0.0;
  }
  /// Keeps a kSolved result that is not already listed; true when it was new.
  bool add(SolveResult r) {
    ++tried;
    if (r.status != Status::kSolved) return false;
    ++verified;
    for (const SolveResult& s : set.solutions)
      if (distance(s.z, r.z) <= kDistinct) return false;
    set.solutions.push_back(std::move(r));
    return true;
  }
};

}  // namespace

std::string FrictionSolutionsOptions::validate() const {
  if (const std::string e = common.validate(); !e.empty()) return e;
  if (starts < 1) return "starts must be >= 1, got " + std::to_string(starts);
  if (max_enumeration_contacts < 0) return "max_enumeration_contacts must be >= 0";
  return {};
}

FrictionSolutionSet friction_solutions(const FrictionContactProblem& p,
                                       const FrictionSolutionsOptions& o) {
  Stopwatch clock;
  helpers::check_problem(p);
  throw_if_invalid(o.validate(), "friction solutions options");
  const Eigen::Index nc = p.contacts(), n = 3 * nc;
  const FrictionUnits units = friction_units(p);
  const double r_ref = (units.q_inf > 0 && units.w_max > 0) ? units.q_inf / units.w_max : 1.0;
  FrictionSolutionSet set;
  Collector col{p, r_ref, set};

  CommonOptions local = o.common;
  auto remaining = [&] { return o.common.time_limit_s - clock.seconds(); };
  // 1. Every registered friction solver once (its own start), except chains.
  for (const SolverEntry& e : solvers().entries()) {
    if (!e.solve_fc || e.info.name == "auto") continue;
    if (remaining() <= 0) break;
    local.time_limit_s = remaining();
    SolveResult r = e.solve_fc(p, local);
    col.add(std::move(r));
  }
  // 2. Proximal point from seeded starts in the cones, of the data's own size r_ref:
  //    r_N uniform in [0, 2 r_ref], r_T uniform in the disc of radius mu r_N.
  std::mt19937_64 gen(o.seed);
  int runs = 0;
  for (int k = 0; k < o.starts; ++k) {
    if (remaining() <= 0) break;
    ProxOptions po;
    po.common = o.common;
    po.common.time_limit_s = remaining();
    po.r0.resize(n);
    for (Eigen::Index i = 0; i < nc; ++i) {
      const double rn = 2 * r_ref * uniform(gen);
      const double rad = p.mu[i] * rn * std::sqrt(uniform(gen)), th = 2 * kPi * uniform(gen);
      po.r0.segment<3>(3 * i) = Vec3(rn, rad * std::cos(th), rad * std::sin(th));
    }
    ++runs;
    col.add(solve_prox(p, po));
  }
  for (SolveResult& s : set.solutions) s.solver = s.solver.empty() ? "?" : s.solver;
  set.complete = false;
  set.message = "multistart: " + std::to_string(col.tried) + " solves (the registered friction "
                "solvers once, proximal point from " + std::to_string(runs) +
                " seeded starts, seed " + std::to_string(o.seed) + "), " +
                std::to_string(col.verified) + " verified, " +
                std::to_string(set.solutions.size()) +
                " distinct; complete: false (a solution no start led to is not found)";
  if (remaining() <= 0) set.message += "; the time limit stopped the search";
  return set;
}

}  // namespace cpkit::lcp::friction
