// Nonsmooth Gauss-Seidel with exact one-contact steps (nsgs.hpp).
#include "cpkit/lcp/friction/nsgs.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {
namespace {

// one_contact.hpp's acceptance of a local solution.
constexpr double kLocalTol = 1e-9;

// Contact i's local problem u = A x + b (A = W_ii + rho I), fixed for the whole solve.
struct LocalBlock {
  Mat3 A;
  Mat3 A_inv;               // meaningful when `invertible`
  double rho = 0;           // proximal term (0: none)
  bool invertible = false;  // A well conditioned (smallest singular value > 1e-8 largest)
};

// Slip from the direction phi0 on: r = r_N e(phi), e = (1, -mu cos phi, -mu sin phi), u_N = 0,
// u_T parallel to d = (cos phi, sin phi) (one_contact.hpp's slip equations). Newton's method on
// the direction equation g(phi) = v_1 sin phi - v_2 cos phi = 0, v_j = (A e)_N b_j - b_N (A e)_j
// (u_T times (A e)_N). Returns false when Newton does not settle or the answer is no solution.
bool slip_from(const Mat3& A, const Vec3& b, double mu, double phi0, Vec3& r) {
  // v_j(phi) = P_j + Q_j cos phi + R_j sin phi.
  double P[3], Q[3], R[3];
  for (int j = 1; j < 3; ++j) {
    P[j] = -b[0] * A(j, 0) + b[j] * A(0, 0);
    Q[j] = -b[0] * (-mu * A(j, 1)) + b[j] * (-mu * A(0, 1));
    R[j] = -b[0] * (-mu * A(j, 2)) + b[j] * (-mu * A(0, 2));
  }
  double phi = phi0;
  bool settled = false;
  for (int it = 0; it < 12 && !settled; ++it) {
    const double c = std::cos(phi), s = std::sin(phi);
    const double v1 = P[1] + Q[1] * c + R[1] * s, v2 = P[2] + Q[2] * c + R[2] * s;
    const double dv1 = -Q[1] * s + R[1] * c, dv2 = -Q[2] * s + R[2] * c;
    const double g = v1 * s - v2 * c, dg = dv1 * s + v1 * c - dv2 * c + v2 * s;
    if (!(std::abs(dg) > 0)) return false;
    const double step = g / dg;
    if (!std::isfinite(step) || std::abs(step) > 0.5) return false;
    phi -= step;
    settled = std::abs(step) <= 1e-14 * std::max(1.0, std::abs(phi));
  }
  if (!settled) return false;
  const Vec3 e(1, -mu * std::cos(phi), -mu * std::sin(phi));
  const double we = A.row(0).dot(e);
  if (!(we != 0)) return false;
  r = (-b[0] / we) * e;
  return r[0] > 0 && one_contact_residual(A, b, mu, r) <= kLocalTol;
}

// The step of contact i: the local solution closest to ri (one_contact.hpp), b = u_i - W_ii r_i.
// Where the contact stays in its state, the answer is found where the contact already is,
// without the closed forms of every solution:
// - ri = 0 and b_N >= 0: separation, r = 0, a solution at distance 0 from ri;
// - ri strictly inside K_mu and the stick solution x = -A^-1 b in K_mu: the contact sticks on;
// - ri on the boundary of K_mu (slip) and Newton's method on the slip equations from ri's
//   direction finds a solution (local residual <= one_contact's 1e-9): the contact slips on.
// These follow ri's branch of solutions (at convergence the step tends to 0, so it is the closest
// solution unless another one is as close). Everything else (changes of state, singular blocks)
// takes every closed form and the closest solution (one_contact_nearest).
Vec3 local_step(const LocalBlock& L, Vec3 b, double mu, const Vec3& ri) {
  if (L.rho > 0) b -= L.rho * ri;
  if (ri.isZero(0) && b[0] >= 0) return Vec3::Zero();
  if (ri[0] > 0 && mu > 0) {
    const double rt = std::hypot(ri[1], ri[2]);
    if (L.invertible && rt < mu * ri[0]) {
      const Vec3 x = -(L.A_inv * b);
      if (x[0] > 0 && std::hypot(x[1], x[2]) <= mu * x[0]) return x;
    } else if (rt > 0 && rt >= (1 - 1e-9) * mu * ri[0]) {
      Vec3 x;
      if (slip_from(L.A, b, mu, std::atan2(-ri[2], -ri[1]), x)) return x;
    }
  }
  return one_contact_nearest(L.A, b, mu, ri);
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
  double best_res = friction_residuals(p, units, r, u).natural;
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
