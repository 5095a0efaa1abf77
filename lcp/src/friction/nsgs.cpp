// Nonsmooth Gauss-Seidel with exact one-contact steps (nsgs.hpp).
#include "cpkit/lcp/friction/nsgs.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/friction/one_contact_newton.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {
namespace {

// Contact i's local problem u = A x + b (A = W_ii + rho I), fixed for the whole solve.
struct LocalBlock {
  Mat3 A;
  Mat3 A_inv;               // meaningful when `invertible`
  double rho = 0;           // proximal term (0: none)
  bool invertible = false;  // A well conditioned (smallest singular value > 1e-8 largest)
};

// The step of contact i, b = u_i - W_ii r_i: a solution of the local problem from ri on
// (one_contact_newton.hpp: ri's own state first, as Siconos' NSGS starts its local Newton at
// r_i; at convergence the step tends to 0, so it is the closest solution unless another one is
// as close). What that does not solve (singular blocks, Newton not settling) takes every closed
// form and the solution closest to ri (one_contact_nearest).
Vec3 local_step(const LocalBlock& L, Vec3 b, double mu, const Vec3& ri) {
  if (L.rho > 0) b -= L.rho * ri;
  Vec3 x;
  if (one_contact_newton(L.A, L.invertible ? &L.A_inv : nullptr, b, mu, ri, x)) return x;
  return one_contact_nearest(L.A, b, mu, ri);
}

// True when W_ii is so well conditioned that the SVD's tests below would find it neither
// singular (sigma_min > 1e-10 sigma_max) nor short of an inverse (sigma_min > 1e-8 sigma_max);
// `inverse` receives W_ii^-1 (by cofactors, as the SVD's route computes it). For a 3 x 3 matrix
// each 2-norm is within sqrt(3) of the 1-norm, so sigma_max / sigma_min <= 3 ||A||_1 ||A^-1||_1,
// and a bound of 1e7 leaves a factor 10 for the rounding of A^-1. The SVD (2.4 k instructions,
// a tenth of a one-contact solve) runs only where this does not decide.
bool well_conditioned(const Mat3& A, Mat3& inverse) {
  inverse = A.inverse();
  const double kappa_1 = A.cwiseAbs().colwise().sum().maxCoeff() *
                         inverse.cwiseAbs().colwise().sum().maxCoeff();
  return 3 * kappa_1 <= 1e7;  // false for NaN / Inf (a singular A)
}

// How many sweeps may pass without the full verdict (its cost is several sweeps' worth).
constexpr int kMaxUnchecked = 20;

}  // namespace

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
  std::vector<LocalBlock> local(static_cast<size_t>(nc));
  for (Eigen::Index i = 0; i < nc; ++i) {
    LocalBlock& L = local[static_cast<size_t>(i)];
    const Mat3& Wii = blocks[static_cast<size_t>(i)];
    if (well_conditioned(Wii, L.A_inv)) {  // what the SVD below would decide, without it
      L.A = Wii;
      L.invertible = true;
      continue;
    }
    const Eigen::Vector3d sv = Eigen::JacobiSVD<Mat3>(Wii).singularValues();
    if (!(sv[2] > 1e-10 * sv[0])) L.rho = 1e-2 * std::max(Wii.cwiseAbs().maxCoeff(), w_max);
    if (L.rho == 0 && sv[0] == 0) L.rho = 1;  // W = 0: any positive scale
    L.A = Wii + L.rho * Mat3::Identity();
    const Eigen::Vector3d sa = L.rho > 0 ? Eigen::JacobiSVD<Mat3>(L.A).singularValues() : sv;
    L.invertible = sa[2] > 1e-8 * sa[0];
    if (L.invertible) L.A_inv = L.A.inverse();
  }

  Eigen::VectorXd r = o.r0.size() ? o.r0 : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd u = p.W * r + p.q;
  const FrictionUnits units = friction_units(p);
  SolveResult res;
  res.solver = "nsgs";
  Eigen::VectorXd best = r;
  // From r = 0 with some q_N < 0 (a contact pressed), r = 0 is refused by the verdict
  // (friction_verdict.hpp: normal_i is 1 there, to rounding; tol < 0.5): its number, needed
  // only when no sweep does better, is computed then.
  bool zero_pressed = false;
  for (Eigen::Index i = 0; i < nc && o.r0.size() == 0 && o.common.tol < 0.5; ++i)
    zero_pressed = zero_pressed || p.q[3 * i] < 0;
  double best_res = zero_pressed ? std::numeric_limits<double>::infinity()
                                 : friction_residuals(p, units, r, u).natural;
  const double r_ref = units.q_inf > 0 && units.w_max > 0 ? units.q_inf / units.w_max : 0.0;
  Status stop = Status::kIterationLimit;
  int sweep = 0;
  if (best_res <= o.common.tol) stop = Status::kSolved;
  // The full verdict (friction_residuals) costs more than a sweep, so between checks a light
  // measure decides when to look: the largest change of r in the sweep relative to r's size
  // (Siconos' NSGS does the same with ||dr|| / ||r||). `ratio` (verdict / light measure at the
  // last check) predicts the verdict; it is checked when the prediction reaches tol, after
  // kMaxUnchecked sweeps at most, at the last sweep, and at every sweep when a trace is wanted.
  double ratio = 0;
  int unchecked = 0;
  for (; sweep < max_sweeps && stop != Status::kSolved; ++sweep) {
    if (o.common.time_limit_s < 1e300 && clock.exceeded(o.common.time_limit_s)) {
      stop = Status::kTimeLimit;
      break;
    }
    double change = 0;
    for (Eigen::Index i = 0; i < nc; ++i) {
      const LocalBlock& L = local[static_cast<size_t>(i)];
      const Vec3 ri = r.segment<3>(3 * i);
      const Vec3 b = u.segment<3>(3 * i) - blocks[static_cast<size_t>(i)] * ri;
      const Vec3 rn = local_step(L, b, p.mu[i], ri);
      const Vec3 d = rn - ri;
      if (d.isZero(0)) continue;
      for (int j = 0; j < 3; ++j)
        if (d[j] != 0)
          for (Eigen::SparseMatrix<double>::InnerIterator it(p.W, 3 * i + j); it; ++it)
            u[it.row()] += it.value() * d[j];
      r.segment<3>(3 * i) = rn;
      change = std::max(change, d.cwiseAbs().maxCoeff());
    }
    const double light = change / std::max(r.lpNorm<Eigen::Infinity>(), r_ref);
    ++unchecked;
    const bool check = o.common.record_trace || unchecked >= kMaxUnchecked ||
                       sweep + 1 == max_sweeps || !std::isfinite(light) ||
                       !(ratio * light > o.common.tol);
    if (!check) continue;
    unchecked = 0;
    u.noalias() = p.W * r;  // from the data: no drift in the test
    u += p.q;
    const double rs = friction_residuals(p, units, r, u).natural;
    if (light > 0 && std::isfinite(rs)) ratio = rs / light;
    if (o.common.record_trace) res.trace.push_back({sweep + 1, rs, 1.0, "sweep", -1, -1});
    if (rs < best_res) {
      best_res = rs;
      best = r;
    }
    if (rs <= o.common.tol) stop = Status::kSolved;
  }
  if (zero_pressed && stop != Status::kSolved) {  // r = 0 when it is still the best (ties: r = 0)
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    if (!(friction_residuals(p, units, zero, p.q).natural > best_res)) best = zero;
  }
  res.iterations = sweep;
  res.z = best;
  res.status = stop;
  if (stop != Status::kSolved)
    res.message = "nsgs: " + std::string(stop == Status::kTimeLimit ? "time limit" : "sweep limit") +
                  " reached after " + std::to_string(sweep) + " sweeps";
  res = finalize(p, units, std::move(res), o.common);
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
