// Several solutions of a frictional contact problem (solutions.hpp).
#include "cpkit/lcp/friction/solutions.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_common.hpp"
#include "../uniform01.hpp"

namespace cpkit::lcp::friction {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDistinct = 1e-6;
// The enumeration route's faceting: complete enumeration costs up to 2^(n_c (k + 2)) bases, so
// the pyramid is coarse: 4 facets up to 3 contacts, 3 facets (a triangle, facet error 50 %)
// beyond. Measured (Rover1039, 4 contacts): 4 facets did not finish in 10 s, 3 facets 0.7 s;
// Rover3865 (5 contacts) does not finish with 3 either (8 facets: not even the 4-contact box
// in 60 s). The faceted solutions are only starting points of the polish on the true cone.
inline int enumeration_facets(Eigen::Index nc) { return nc <= 3 ? 4 : 3; }
constexpr double kEnumerationSeconds = 5;
constexpr Eigen::Index kIpoptContacts = 10;
constexpr double kEnumerationRegularisation = 1e-8;

using lcp::detail::uniform01;

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

// The families of solutions.hpp: group by u, then the affine hull of each group's r by SVD.
std::vector<SolutionFamily> families_of(const std::vector<SolveResult>& list, double q_inf,
                                        double r_ref) {
  std::vector<SolutionFamily> out;
  std::vector<bool> taken(list.size(), false);
  for (std::size_t a = 0; a < list.size(); ++a) {
    if (taken[a]) continue;
    SolutionFamily f;
    f.members.push_back(static_cast<int>(a));
    const Eigen::VectorXd& ua = list[a].w;
    for (std::size_t b = a + 1; b < list.size(); ++b) {
      const Eigen::VectorXd& ub = list[b].w;
      const double size = std::max({ua.lpNorm<Eigen::Infinity>(), ub.lpNorm<Eigen::Infinity>(), q_inf});
      if (!taken[b] && (ua - ub).lpNorm<Eigen::Infinity>() <= kDistinct * size) {
        taken[b] = true;
        f.members.push_back(static_cast<int>(b));
      }
    }
    const Eigen::VectorXd& r0 = list[a].z;
    Eigen::MatrixXd D(r0.size(), static_cast<Eigen::Index>(f.members.size()) - 1);
    double size = r_ref;
    for (std::size_t k = 1; k < f.members.size(); ++k) {
      const Eigen::VectorXd& rk = list[static_cast<std::size_t>(f.members[k])].z;
      D.col(static_cast<Eigen::Index>(k) - 1) = rk - r0;
      size = std::max({size, rk.lpNorm<Eigen::Infinity>(), r0.lpNorm<Eigen::Infinity>()});
    }
    f.basis.resize(r0.size(), 0);
    if (D.cols() > 0) {
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(D, Eigen::ComputeThinU);
      Eigen::Index rank = 0;
      while (rank < svd.singularValues().size() && svd.singularValues()[rank] > kDistinct * size)
        ++rank;
      f.basis = svd.matrixU().leftCols(rank);
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

std::string FrictionSolutionsOptions::validate() const {
  if (const std::string e = common.validate(); !e.empty()) return e;
  if (starts < 1 || starts > kMaxStarts)
    return "starts must be in [1, " + std::to_string(kMaxStarts) + "], got " + std::to_string(starts);
  if (max_enumeration_contacts < 0) return "max_enumeration_contacts must be >= 0";
  return {};
}

FrictionSolutionSet friction_solutions(const FrictionContactProblem& p,
                                       const FrictionSolutionsOptions& o) {
  Stopwatch clock;
  detail::check_problem(p);
  throw_if_invalid(o.validate(), "friction solutions options");
  const Eigen::Index nc = p.contacts(), n = 3 * nc;
  const FrictionUnits units = friction_units(p);
  const double r_ref = (units.q_inf > 0 && units.w_max > 0) ? units.q_inf / units.w_max : 1.0;
  FrictionSolutionSet set;
  Collector col{p, r_ref, set};

  CommonOptions local = o.common;
  auto remaining = [&] { return o.common.time_limit_s - clock.seconds(); };
  std::string faceted_note;
  // 0. Small problems: every solution of the (regularised) faceted problem, each polished on
  //    the true cone.
  const int k = enumeration_facets(nc);
  if (nc >= 1 && nc <= o.max_enumeration_contacts && nc * (k + 2) <= kMaxEnumerationSize) {
    const FacetedSolutionList fs =
        faceted_solutions(p, k, kEnumerationRegularisation,
                          std::min(kEnumerationSeconds, std::max(0.0, remaining() / 2)));
    for (const Eigen::VectorXd& r : fs.r) {
      if (remaining() <= 0) break;
      SolveResult claim;
      claim.solver = "faceted-enumeration";
      claim.z = r;
      SolveResult exact = finalize(p, claim, o.common);
      if (exact.status == Status::kSolved) {
        exact.message = "a faceted solution that is exact on the true cone";
        col.add(std::move(exact));
        continue;
      }
      CommonOptions pc = o.common;
      pc.time_limit_s = remaining();
      SolveResult s = polish_on_true_cone(p, r, pc);
      s.solver = "faceted-enumeration+polish";
      s.message = "polished from a faceted solution; " + s.message;
      col.add(std::move(s));
    }
    faceted_note =
        "faceted problem (" + std::to_string(k) + " facets, facet error " +
        short_number(100 * fs.faceted.facet_error) + " %, regularised by " +
        short_number(kEnumerationRegularisation) +
        " w_scale on the force diagonal; LCP of " + std::to_string(fs.faceted.lcp.size()) +
        " unknowns): " + std::to_string(fs.extreme) + " extreme LCP solutions, " +
        std::to_string(fs.r.size()) + " distinct r, enumeration " +
        (fs.complete ? "complete for the faceted problem" : "NOT complete (" + fs.message + ")") +
        (!fs.infinite       ? ""
         : fs.r.size() > 1 ? ", with continua (listed by their vertices)"
                           : ", infinitely many LCP solutions (in the facet multipliers) giving "
                             "the same r") +
        "; " +
        std::to_string(col.verified) +
        " of them verified on the true cone (exact or polished); "
        "complete for the faceted problem is not complete for the true cone; ";
  } else if (nc > o.max_enumeration_contacts) {
    faceted_note = std::to_string(nc) + " contacts > max_enumeration_contacts = " +
                   std::to_string(o.max_enumeration_contacts) + ": no enumeration; ";
  }
  // 1. Every registered friction solver once (its own start), except chains; each gets at
  //    most a fair share of the remaining time (the seeded phase counting as one more), so
  //    that one slow solver (NSGS on a rank-deficient stack) cannot starve the others.
  std::vector<const SolverEntry*> first;
  std::set<std::string> failed_first;
  for (const SolverEntry& e : solvers().entries()) {
    if (!e.solve_fc || e.info.name == "auto") continue;
    // Ipopt's dense MPCC is the slow fallback (52 contacts: no answer in 20 s): small only.
    if (e.info.name == "ipopt" && nc > kIpoptContacts) continue;
    first.push_back(&e);
  }
  for (std::size_t j = 0; j < first.size(); ++j) {
    if (remaining() <= 0) break;
    local.time_limit_s = remaining() / static_cast<double>(first.size() - j + 1);
    SolveResult r = first[j]->solve_fc(p, local);
    if (r.status != Status::kSolved) failed_first.insert(first[j]->info.name);
    col.add(std::move(r));
  }
  // A solver that failed from its own start on this problem is not run from the seeds (NSGS
  // on a rank-deficient stack would spend its 2000 sweeps at every start).
  const bool seed_nsgs = !failed_first.count("nsgs"), seed_fb = !failed_first.count("fb-soc");
  // 2. NSGS, fb-soc and proximal point from seeded starts in the cones, of the data's own size
  // r_ref:
  //    r_N uniform in [0, 2 r_ref], r_T uniform in the disc of radius mu r_N. NSGS stays near
  //    its start (each contact takes its solution nearest the current r_i); PROX's large early
  //    proximal steps reach farther.
  std::mt19937_64 gen(o.seed);
  int runs = 0;
  for (int start = 0; start < o.starts; ++start) {
    if (remaining() <= 0) break;
    ProxOptions po;
    po.common = o.common;
    po.common.time_limit_s = remaining();
    po.r0.resize(n);
    for (Eigen::Index i = 0; i < nc; ++i) {
      const double rn = 2 * r_ref * uniform01(gen);
      const double rad = p.mu[i] * rn * std::sqrt(uniform01(gen)), th = 2 * kPi * uniform01(gen);
      po.r0.segment<3>(3 * i) = Vec3(rn, rad * std::cos(th), rad * std::sin(th));
    }
    ++runs;
    if (seed_nsgs) {
      NsgsOptions no;
      no.common = po.common;
      no.r0 = po.r0;
      col.add(solve_nsgs(p, no));
      if (remaining() <= 0) break;
    }
    if (seed_fb) {
      FbSocOptions fo;
      fo.common = po.common;
      fo.common.time_limit_s = remaining();
      fo.r0 = po.r0;
      col.add(solve_fb_soc(p, fo));
      if (remaining() <= 0) break;
    }
    po.common.time_limit_s = remaining();
    col.add(solve_prox(p, po));
  }
  for (SolveResult& s : set.solutions) s.solver = s.solver.empty() ? "?" : s.solver;
  set.families = families_of(set.solutions, units.q_inf, r_ref);
  set.complete = false;
  set.message =
      faceted_note + "multistart: " + std::to_string(col.tried) +
      " solves (the registered friction "
      "solvers once (ipopt only up to " +
      std::to_string(kIpoptContacts) + " contacts), nsgs, fb-soc and prox from " +
      std::to_string(runs) + " seeded starts, seed " + std::to_string(o.seed) +
      (seed_nsgs && seed_fb ? std::string()
                            : std::string("; not from the seeds: ") + (seed_nsgs ? "" : "nsgs ") +
                                  (seed_fb ? "" : "fb-soc ") + "(failed from their own start)") +
      "), " + std::to_string(col.verified) + " verified, " + std::to_string(set.solutions.size()) +
      " distinct; complete: false (a solution no start led to is not found)";
  if (remaining() <= 0) set.message += "; the time limit stopped the search";
  set.message += "; " + std::to_string(set.solutions.size()) + " distinct r with " +
                 std::to_string(set.families.size()) + " distinct u";
  for (const SolutionFamily& f : set.families) {
    if (f.dimension() == 0) continue;
    set.message += "; solutions";
    for (int m : f.members) set.message += " " + std::to_string(m + 1);
    set.message += " share u: one continuum, r in a convex set of dimension >= " +
                   std::to_string(f.dimension()) + " (every convex combination of them solves)";
  }
  return set;
}

}  // namespace cpkit::lcp::friction
