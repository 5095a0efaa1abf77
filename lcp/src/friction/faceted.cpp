// The faceted LCP of a frictional contact problem and Lemke's method on it (faceted.hpp).
#include "cpkit/lcp/friction/faceted.hpp"

#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

FacetedLcp faceted_lcp(const FrictionContactProblem& p, int k) {
  detail::check_problem(p);
  if (k < 3 || k > 64) throw InputError("facets must be in [3, 64], got " + std::to_string(k));
  const Eigen::Index nc = p.contacts(), m = k + 2, N = nc * m;
  FacetedLcp f;
  f.facets = k;
  f.facet_error = 1 - std::cos(kPi / k);
  f.G = Eigen::MatrixXd::Zero(3 * nc, N);
  for (Eigen::Index i = 0; i < nc; ++i) {
    f.G(3 * i, i * m) = 1;
    for (int j = 0; j < k; ++j) {
      const double th = 2 * kPi * j / k;
      f.G(3 * i + 1, i * m + 1 + j) = std::cos(th);
      f.G(3 * i + 2, i * m + 1 + j) = std::sin(th);
    }
  }
  // G^T W G by blocks of W's stored entries (W sparse, G block diagonal with 3 x m blocks).
  Eigen::MatrixXd WG = Eigen::MatrixXd::Zero(3 * nc, N);
  for (Eigen::Index c = 0; c < p.W.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(p.W, c); it; ++it)
      WG.row(it.row()).segment(c / 3 * m, m) += it.value() * f.G.row(c).segment(c / 3 * m, m);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(N, N);
  for (Eigen::Index i = 0; i < nc; ++i)
    M.middleRows(i * m, m) = f.G.block(3 * i, i * m, 3, m).transpose() * WG.middleRows(3 * i, 3);
  for (Eigen::Index i = 0; i < nc; ++i) {
    const Eigen::Index o = i * m, l = o + k + 1;
    for (int j = 0; j < k; ++j) {
      M(o + 1 + j, l) = 1;   // w_beta_j += lambda
      M(l, o + 1 + j) = -1;  // w_lambda -= beta_j
    }
    M(l, o) = p.mu[i];  // w_lambda = mu r_N - ...
  }
  f.lcp.M = std::move(M);
  f.lcp.q = f.G.transpose() * p.q;
  f.lcp.name = p.name.empty() ? "faceted" : p.name + " (faceted, " + std::to_string(k) + " facets)";
  return f;
}

std::string FacetedLemkeOptions::validate() const {
  if (const std::string e = common.validate(); !e.empty()) return e;
  if (facets < 3 || facets > 64) return "facets must be in [3, 64], got " + std::to_string(facets);
  if (covering.size() && !(covering.minCoeff() > 0 && covering.allFinite()))
    return "covering vector must be positive and finite";
  return {};
}

SolveResult solve_faceted_lemke(const FrictionContactProblem& p, const FacetedLemkeOptions& o) {
  Stopwatch clock;
  detail::check_problem(p);
  throw_if_invalid(o.validate(), "faceted Lemke options");
  const Eigen::Index nc = p.contacts();
  if (nc > kFacetedMaxContacts) {
    SolveResult out;
    out.solver = "lemke";
    out.status = Status::kUnsupported;
    out.message = "Lemke on the faceted cone takes at most " + std::to_string(kFacetedMaxContacts) +
                  " contacts (a dense LCP of n_c (k + 2) unknowns); this problem has " +
                  std::to_string(nc) + ": use nsgs, fb-soc or prox";
    return out;
  }
  const FacetedLcp f = faceted_lcp(p, o.facets);
  LemkeOptions lo;
  lo.common = o.common;
  lo.common.record_trace = false;
  if (o.covering.size()) {
    if (o.covering.size() != f.lcp.size())
      throw InputError("faceted Lemke options: covering vector has " +
                       std::to_string(o.covering.size()) + " entries, expected " +
                       std::to_string(f.lcp.size()));
    lo.covering = o.covering;
  }
  const SolveResult lcp = solve_lemke(f.lcp, lo);
  const std::string facets = std::to_string(o.facets) + " facets, facet error 1 - cos(pi/" +
                             std::to_string(o.facets) +
                             ") = " + short_number(100 * f.facet_error) + " %";
  SolveResult claim;
  claim.solver = "lemke";
  claim.iterations = lcp.iterations;
  if (!is_solution(lcp.status)) {
    claim.status = lcp.status;
    claim.message = "Lemke on the faceted cone (" + facets + ") ended with " +
                    std::string(to_string(lcp.status)) + ": " + lcp.message;
    if (lcp.status == Status::kInfeasible) {
      // Lemke's certificate proves the FACETED problem infeasible; K_k is inside K_mu, so this
      // says nothing certain about the true cone: reported, never granted as kInfeasible.
      claim.status = Status::kStalled;
      claim.message +=
          "; the faceted problem has no solution (certificate checked for the "
          "faceted LCP), which proves nothing for the true cone";
      claim.seconds = clock.seconds();
      return claim;
    }
    claim.z = lcp.z.size() == f.lcp.size() ? Eigen::VectorXd(f.G * lcp.z) : Eigen::VectorXd();
    SolveResult res = claim.z.size() ? finalize(p, claim, o.common) : claim;
    if (is_solution(res.status)) res.message += "; the true verdict accepts this r";
    res.seconds = clock.seconds();
    return res;
  }
  claim.z = f.G * lcp.z;
  claim.status = Status::kNotRun;  // not claimed: the faceted answer is only a candidate
  SolveResult faceted = finalize(p, claim, o.common);
  if (faceted.status == Status::kNotRun) faceted.status = Status::kStalled;
  const FrictionErrors fe = friction_errors(p, faceted.z);
  faceted.message = "the faceted answer (" + facets + ", " + std::to_string(lcp.iterations) +
                    " pivots) on the true cone: unit-free error " +
                    short_number(fe.unit_free) + ", relative_q " +
                    short_number(fe.relative_q);
  if (faceted.status == Status::kSolved || !o.polish) {
    if (!is_solution(faceted.status))
      faceted.message += "; not a solution of the true problem (polish off)";
    faceted.seconds = clock.seconds();
    return faceted;
  }
  CommonOptions pc = o.common;
  pc.time_limit_s = o.common.time_limit_s - clock.seconds();  // read once: a solver refuses <= 0
  if (!(pc.time_limit_s > 0)) {
    faceted.message += "; not polished: time limit reached";
    faceted.seconds = clock.seconds();
    return faceted;
  }
  SolveResult polished = polish_on_true_cone(p, faceted.z, pc);
  const std::string head = faceted.message;
  SolveResult& best =
      (is_solution(polished.status) || polished.residuals.natural < faceted.residuals.natural)
          ? polished
          : faceted;
  best.solver = "lemke";
  best.iterations = lcp.iterations + (&best == &polished ? polished.iterations : 0);
  best.message = head + "; polished on the true cone from it (polish_on_true_cone): " +
                 std::string(to_string(polished.status)) + ", unit-free error " +
                 short_number(polished.residuals.natural) +
                 (&best == &polished ? " (returned: the polished r)"
                                     : " (returned: the faceted r, the polish did no better)");
  best.seconds = clock.seconds();
  return best;
}

SolveResult polish_on_true_cone(const FrictionContactProblem& p, const Eigen::VectorXd& r0,
                                const CommonOptions& c) {
  Stopwatch clock;
  // Gauss-Seidel prox first: each contact takes its exact solution nearest the current r_i, so
  // it stays near r0 (fb-soc's line search may land on another solution: it did on the
  // 3-solution contact of the tests); bounded (40 x 50 sweeps) because it is slow on
  // rank-deficient W, where fb-soc then takes over.
  ProxOptions po;
  po.common = c;
  po.common.max_iterations = 40;
  po.max_sweeps = 50;
  po.r0 = r0;
  po.sigma = 1e-3;
  po.inner = ProxInner::kGaussSeidel;
  SolveResult a = solve_prox(p, po);
  a.solver = "polish";
  if (a.status == Status::kSolved) return a;
  FbSocOptions fo;
  fo.common = c;
  fo.common.time_limit_s = c.time_limit_s - clock.seconds();  // read once: fb-soc refuses <= 0
  if (!(fo.common.time_limit_s > 0)) return a;
  fo.r0 = r0;
  SolveResult b = solve_fb_soc(p, fo);
  b.solver = "polish";
  if (b.status == Status::kSolved) return b;
  return b.residuals.natural < a.residuals.natural ? b : a;
}

SolverEntry with_faceted_lemke(SolverEntry e) {
  e.info.description += "; friction problems: on the faceted cone (8 facets), polished by prox";
  e.solve_fc = detail::with_common_options<FacetedLemkeOptions>(
      [](const FrictionContactProblem& p, const FacetedLemkeOptions& o) { return solve_faceted_lemke(p, o); });
  return e;
}

}  // namespace cpkit::lcp::friction
