// FB semismooth Newton for second-order-cone complementarity (cone_complementarity_fb.hpp).
#include "cpkit/lcp/cone_complementarity_fb.hpp"

#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/finalize.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/damped_newton.hpp"
#include "cpkit/lcp/detail/fischer_burmeister.hpp"

namespace cpkit::lcp {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

using detail::pow2_below;

// Phi(z) and J = A + B M for the (scaled) problem; w is a buffer of size n.
struct Model {
  const SocProblem& p;
  VectorXd w;
  MatrixXd B;  // block-diagonal dPhi/dw, kept dense (J = A + B M in one product)
  void eval(const VectorXd& z, VectorXd& phi, MatrixXd& J) {
    w.noalias() = p.M * z;
    w += p.q;
    J.setZero();
    B.setZero();
    Eigen::Index k = 0;
    for (const int size : p.blocks) {
      if (size == 1) {
        double da, db;
        phi[k] = detail::fb_scalar(z[k], w[k], da, db);
        J(k, k) = da;
        B(k, k) = db;
      } else {
        Eigen::Vector3d ph;
        Eigen::Matrix3d Jx, Jy;
        detail::fb_soc(z.segment<3>(k), w.segment<3>(k), ph, Jx, Jy);
        phi.segment<3>(k) = ph;
        J.block<3, 3>(k, k) = Jx;
        B.block<3, 3>(k, k) = Jy;
      }
      k += size;
    }
    J.noalias() += B * p.M;
  }
};

const char* stop_text(DampedNewtonStop s) {
  switch (s) {
    case DampedNewtonStop::kDone: return "converged";
    case DampedNewtonStop::kIterationLimit: return "iteration limit reached";
    case DampedNewtonStop::kNonFinite: return "non-finite residual";
    case DampedNewtonStop::kStationary: return "stationary point of the merit function";
    case DampedNewtonStop::kLineSearchFailed: return "line search failed";
    case DampedNewtonStop::kNoProgress: return "the step no longer changes z";
  }
  return "";
}

}  // namespace

SolveResult solve_soc_fb(const SocProblem& p0, const SocFbOptions& o) {
  const Stopwatch clock;
  throw_if_invalid(p0.validate(), "cone problem" + (p0.name.empty() ? "" : " '" + p0.name + "'"));
  throw_if_invalid(o.common.validate(), "options");
  const Eigen::Index n = p0.size();
  if (o.z0.size() != 0 && (o.z0.size() != n || !o.z0.allFinite()))
    throw InputError("start z0 has " + std::to_string(o.z0.size()) + " entries or non-finite ones, expected " +
                     std::to_string(n) + " finite entries");
  // Exact power-of-two scaling: w = sw w', z = sz z', M' = M sz / sw, q' = q / sw.
  const double sw = pow2_below(n ? p0.q.lpNorm<Eigen::Infinity>() : 0.0);
  const double sm = pow2_below(n ? p0.M.cwiseAbs().maxCoeff() : 0.0), sz = sw / sm;
  SocProblem p = p0;
  p.M = p0.M * (1.0 / sm);
  p.q = p0.q * (1.0 / sw);
  Model model{p, VectorXd(n), MatrixXd::Zero(n, n)};
  VectorXd z = o.z0.size() ? VectorXd(o.z0 / sz) : VectorXd::Zero(n);
  VectorXd w(n);
  auto eval = [&model](const VectorXd& x, VectorXd& phi, MatrixXd& J) { model.eval(x, phi, J); };
  // The verdict is unit-free, so testing the scaled problem decides the original one.
  auto done = [&](const VectorXd& x, const VectorXd&) {
    w.noalias() = p.M * x;
    w += p.q;
    return soc_residuals(p, x, w).natural <= o.common.tol;
  };
  SolveResult res;
  res.solver = "fb-soc";
  DampedNewtonStats stats;
  const DampedNewtonStop stop =
      n ? damped_newton_counted<VectorXd, MatrixXd>(z, eval, done, o.common.max_iterations, res,
                                                    stats)
        : DampedNewtonStop::kDone;
  res.z = z * sz;
  res.jacobian_evals = res.function_evals;
  switch (stop) {
    case DampedNewtonStop::kDone: res.status = Status::kSolved; break;
    case DampedNewtonStop::kIterationLimit: res.status = Status::kIterationLimit; break;
    case DampedNewtonStop::kNonFinite: res.status = Status::kNumericalFailure; break;
    default: res.status = Status::kStalled; break;
  }
  if (stop != DampedNewtonStop::kDone)
    res.message = std::string("fb-soc: ") + stop_text(stop) + " after " +
                  std::to_string(stats.iterations) + " iterations";
  res = finalize(p0, std::move(res), o.common);
  res.seconds = clock.seconds();
  return res;
}

SolverEntry with_soc_fb(SolverEntry e) {
  e.solve_soc = [](const SocProblem& p, const CommonOptions& c) {
    SocFbOptions o;
    o.common = c;
    return solve_soc_fb(p, o);
  };
  e.info.description += "; cone problems (blocks v0 >= |v1|): dense LU, one damped Newton loop";
  return e;
}

}  // namespace cpkit::lcp
