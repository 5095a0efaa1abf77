// Nonsmooth Gauss-Seidel with exact one-contact steps (nsgs.hpp).
#include "cpkit/lcp/friction/nsgs.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {

SolveResult solve_nsgs(const FrictionContactProblem& p, const NsgsOptions& o) {
  const Stopwatch clock;
  detail::check_input(p, o.common, o.r0);
  const Eigen::Index nc = p.contacts(), n = 3 * nc;
  const int max_sweeps = o.common.max_iterations > 0 ? o.common.max_iterations : 2000;

  const std::vector<Mat3> blocks = detail::diagonal_blocks(p.W);
  double w_max = 0;
  for (Eigen::Index k = 0; k < p.W.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(p.W, k); it; ++it)
      w_max = std::max(w_max, std::abs(it.value()));
  // Proximal regularisation of (nearly) singular diagonal blocks (header comment).
  std::vector<double> rho(nc, 0.0);
  for (Eigen::Index i = 0; i < nc; ++i) {
    const Eigen::Vector3d sv = Eigen::JacobiSVD<Mat3>(blocks[i]).singularValues();
    if (!(sv[2] > 1e-10 * sv[0])) rho[i] = 1e-2 * std::max(blocks[i].cwiseAbs().maxCoeff(), w_max);
    if (rho[i] == 0 && sv[0] == 0) rho[i] = 1;  // W = 0: any positive scale
  }

  Eigen::VectorXd r = o.r0.size() ? o.r0 : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd u = p.W * r + p.q;
  const FrictionUnits units = friction_units(p);
  SolveResult res;
  res.solver = "nsgs";
  Eigen::VectorXd best = r;
  double best_res = friction_residuals(p, units, r, u).natural;
  Status stop = Status::kIterationLimit;
  int sweep = 0;
  if (best_res <= o.common.tol) stop = Status::kSolved;
  for (; sweep < max_sweeps && stop != Status::kSolved; ++sweep) {
    if (o.common.time_limit_s < 1e300 && clock.exceeded(o.common.time_limit_s)) {
      stop = Status::kTimeLimit;
      break;
    }
    for (Eigen::Index i = 0; i < nc; ++i) {
      const Vec3 ri = r.segment<3>(3 * i);
      const Vec3 b = u.segment<3>(3 * i) - blocks[i] * ri;
      Vec3 rn;
      if (rho[i] > 0)
        rn = one_contact_nearest(blocks[i] + rho[i] * Mat3::Identity(), b - rho[i] * ri, p.mu[i],
                                 ri);
      else
        rn = one_contact_nearest(blocks[i], b, p.mu[i], ri);
      const Vec3 d = rn - ri;
      if (d.isZero(0)) continue;
      for (int j = 0; j < 3; ++j)
        if (d[j] != 0)
          for (Eigen::SparseMatrix<double>::InnerIterator it(p.W, 3 * i + j); it; ++it)
            u[it.row()] += it.value() * d[j];
      r.segment<3>(3 * i) = rn;
    }
    u.noalias() = p.W * r;  // from the data: no drift in the test
    u += p.q;
    const double rs = friction_residuals(p, units, r, u).natural;
    if (o.common.record_trace) res.trace.push_back({sweep + 1, rs, 1.0, "sweep", -1, -1});
    if (rs < best_res) {
      best_res = rs;
      best = r;
    }
    if (rs <= o.common.tol) stop = Status::kSolved;
  }
  res.iterations = sweep;
  res.z = best;
  res.status = stop;
  if (stop != Status::kSolved)
    res.message = "nsgs: " + std::string(stop == Status::kTimeLimit ? "time limit" : "sweep limit") +
                  " reached after " + std::to_string(sweep) + " sweeps";
  res = finalize(p, std::move(res), o.common);
  res.seconds = clock.seconds();
  return res;
}

SolverEntry nsgs_entry() {
  SolverEntry e;
  e.info.name = "nsgs";
  e.info.description =
      "nonsmooth Gauss-Seidel over contacts with exact one-contact solutions (closed forms), "
      "proximal regularisation of singular blocks [Jean 1999; Acary-Bremond-Huber 2018]";
  e.info.dense = false;
  e.info.sparse = true;
  e.solve_fc = detail::with_common_options<NsgsOptions>(
      [](const FrictionContactProblem& p, const NsgsOptions& o) { return solve_nsgs(p, o); });
  return e;
}

}  // namespace cpkit::lcp::friction
