// Proximal point method for frictional contact (prox.hpp).
#include "cpkit/lcp/friction/prox.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {

std::string ProxOptions::validate(Eigen::Index n) const {
  if (const std::string e = common.validate(); !e.empty()) return e;
  if (r0.size() != 0 && r0.size() != n)
    return "r0 has " + std::to_string(r0.size()) + " entries, expected " + std::to_string(n);
  if (r0.size() && !r0.allFinite()) return "r0 must be finite";
  if (!(sigma > 0) || !std::isfinite(sigma)) return "sigma must be positive and finite";
  if (!(nu >= 0) || !std::isfinite(nu)) return "nu must be >= 0 and finite";
  if (!(alpha0 >= 0) || !std::isfinite(alpha0)) return "alpha0 must be >= 0 and finite";
  if (!(shrink >= 1) || !std::isfinite(shrink)) return "shrink must be >= 1 and finite";
  if (!(shrink_after_failure >= 1) || !std::isfinite(shrink_after_failure))
    return "shrink_after_failure must be >= 1 and finite";
  if (max_sweeps < 0) return "max_sweeps must be >= 0";
  if (newton_after_failure < 0) return "newton_after_failure must be >= 0";
  if (!(full_step_below >= 0 && full_step_below <= 1)) return "full_step_below must be in [0, 1]";
  return {};
}

SolveResult solve_prox(const FrictionContactProblem& p, const ProxOptions& o) {
  Stopwatch clock;
  detail::check_problem(p);
  const Eigen::Index nc = p.contacts(), n = 3 * nc;
  throw_if_invalid(o.validate(n), "prox options");
  const FrictionUnits units = friction_units(p);
  const std::vector<Mat3> D = detail::diagonal_blocks(p.W);
  const double w_scale = detail::w_scale(p.W, units);
  const double r_ref = (units.q_inf > 0 && units.w_max > 0) ? units.q_inf / units.w_max : 0.0;
  const int max_outer = o.common.max_iterations > 0 ? o.common.max_iterations : 500;
  const int max_sweeps = o.max_sweeps > 0 ? o.max_sweeps : 200;

  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  Eigen::VectorXd r = o.r0.size() ? o.r0 : Eigen::VectorXd::Zero(n);
  // Start inside the cones: the iteration keeps r there.
  for (Eigen::Index i = 0; i < nc; ++i)
    r.segment<3>(3 * i) = project_on_cone(r.segment<3>(3 * i), p.mu[i]);
  Eigen::VectorXd u = p.W * r + p.q;
  double e = friction_residuals(p, units, r, u).natural;
  Eigen::VectorXd best = r;
  double best_e = e;
  Eigen::VectorXd rk(n);
  SolveResult out;
  out.solver = "prox";
  bool failed = false;
  double alpha = 0;
  int inner_failures = 0;
  double shrink = o.shrink;
  Status stop = Status::kIterationLimit;
  for (int k = 0; k < max_outer; ++k) {
    if (best_e <= o.common.tol) {
      stop = Status::kSolved;
      break;
    }
    if (clock.exceeded(o.common.time_limit_s)) {
      stop = Status::kTimeLimit;
      break;
    }
    const double ec = std::isfinite(e) ? std::min(e, 1.0) : 1.0;
    // PROX's sigma e^nu, but never above the start alpha0 nor above alpha_{k-1} / shrink after
    // a converged inner solve: alpha = sigma e^nu alone fell with e only and took 20-35 outer
    // iterations on the FCLIB files (4-7 with this rule).
    const double prox_rule = o.sigma * std::pow(ec, o.nu) * w_scale;
    if (failed)
      alpha *= 10;
    else if (k == 0)
      alpha = o.alpha0 > 0 ? std::min(o.alpha0 * w_scale, prox_rule) : prox_rule;
    else
      alpha = std::min(prox_rule, alpha / shrink);
    alpha = std::clamp(alpha, 1e-10 * w_scale, 1e10 * w_scale);  // floor and cap in W's units
    if (failed) shrink = std::min(o.shrink, o.shrink_after_failure);  // from now on (prox.hpp)
    rk = r;
    u = p.W * r + p.q;  // fresh each outer step: no drift of the incremental updates
    const double inner_tol = std::max(ec / 10, o.common.tol / 10);
    bool converged = false;
    if (o.inner != ProxInner::kGaussSeidel) {
      // The time left, taken once: read again after the check above it could be <= 0, which
      // fb-soc refuses as bad input (RockPile_tob1 with the FB inner solve at 40 s, h64).
      const double left = o.common.time_limit_s - clock.seconds();
      if (!(left > 0)) {
        stop = Status::kTimeLimit;
        break;
      }
      // The regularised problem (W + alpha I, q - alpha r_k) by semismooth Newton from r_k.
      FrictionContactProblem reg;
      reg.W = p.W + alpha * identity;
      reg.q = p.q - alpha * rk;
      reg.mu = p.mu;
      FbSocOptions fo;
      fo.common = o.common;
      // To the outer tol: the regularised problem's unit-free verdict is relative to its own
      // q - alpha r_k, which a large alpha inflates (a loose tolerance there accepted r_k
      // itself on FrictionContact3D_RR_1c, and the iteration stood still); Newton makes the
      // extra digits cheap.
      fo.common.tol = o.common.tol;
      fo.common.time_limit_s = left;
      fo.common.record_trace = false;
      // Once an inner solve has failed, each is cut short (prox.hpp): a failure costs its cap,
      // not fb-soc's 50-step stagnation stop.
      if (inner_failures > 0 && o.newton_after_failure > 0)
        fo.common.max_iterations = o.newton_after_failure;
      fo.r0 = rk;
      fo.alart_curnier = o.inner == ProxInner::kAlartCurnier;
      fo.full_step_below = o.full_step_below;
      const SolveResult in = solve_fb_soc(reg, fo);
      out.function_evals += in.iterations;
      if (in.z.size() == n && in.z.allFinite()) r = in.z;
      converged = in.status == Status::kSolved;
    }
    for (int s = 0; o.inner == ProxInner::kGaussSeidel && s < max_sweeps; ++s) {
      ++out.function_evals;
      double change = 0;
      for (Eigen::Index i = 0; i < nc; ++i) {
        const Vec3 ri = r.segment<3>(3 * i), rki = rk.segment<3>(3 * i);
        const Vec3 ui = u.segment<3>(3 * i);
        // Contact i's problem of the regularised system, solved exactly (one_contact.hpp):
        // u'_i = (W_ii + alpha I) x + b, b = u_i - W_ii r_i - alpha rk_i.
        const Vec3 b = ui - D[i] * ri - alpha * rki;
        const Vec3 x = one_contact_nearest(D[i] + alpha * Mat3::Identity(), b, p.mu[i], ri);
        const Vec3 dr = x - ri;
        if (dr.cwiseAbs().maxCoeff() > 0) {
          r.segment<3>(3 * i) = x;
          detail::add_columns(p.W, 3 * i, dr, u);
          change = std::max(change, dr.lpNorm<Eigen::Infinity>());
        }
      }
      const double size = std::max(r.lpNorm<Eigen::Infinity>(), r_ref);
      if (!std::isfinite(change)) break;
      if (change <= inner_tol * size) {
        converged = true;
        break;
      }
      if (clock.exceeded(o.common.time_limit_s)) break;
    }
    ++out.iterations;
    if (!r.allFinite()) {
      r = best;
      failed = true;
      ++inner_failures;
      continue;
    }
    u = p.W * r + p.q;
    e = friction_residuals(p, units, r, u).natural;
    if (e < best_e) {
      best_e = e;
      best = r;
    }
    failed = !converged;
    if (failed) ++inner_failures;
    if (o.common.record_trace) {
      TraceEntry t;
      t.iteration = out.iterations;
      t.residual = e;
      t.step = alpha;
      t.kind = converged ? "prox" : "prox-inner-failed";
      out.trace.push_back(t);
    }
  }
  if (best_e <= o.common.tol) stop = Status::kSolved;
  out.z = best;
  out.status = stop == Status::kSolved ? Status::kSolved : stop;
  out.message = "proximal point: " + std::to_string(out.iterations) + " outer iterations, " +
                std::to_string(out.function_evals) +
                (o.inner == ProxInner::kGaussSeidel ? " Gauss-Seidel sweeps, "
                 : o.inner == ProxInner::kFbSoc     ? " inner Newton iterations (fb-soc), "
                                                    : " inner Newton iterations (Alart-Curnier), ") +
                std::to_string(inner_failures) + " inner solves not converged, last alpha " +
                short_number(alpha / w_scale) + " w_scale";
  out.seconds = clock.seconds();
  SolveResult res = finalize(p, units, std::move(out), o.common);
  res.seconds = clock.seconds();
  return res;
}

SolverEntry prox_entry() {
  SolverEntry e;
  e.info.name = "prox";
  e.info.description =
      "proximal point method (semismooth Newton inner solves on Alart-Curnier's function, PROX's "
      "alpha rule with a geometric decrease) for friction problems [Acary-Bremond-Huber 2018]";
  e.info.dense = false;
  e.info.sparse = false;
  e.solve_fc = detail::with_common_options<ProxOptions>(
      [](const FrictionContactProblem& p, const ProxOptions& o) { return solve_prox(p, o); });
  return e;
}

}  // namespace cpkit::lcp::friction
