// Semismooth Newton on the SOC Fischer-Burmeister reformulation (fb_soc.hpp).
#include "cpkit/lcp/friction/fb_soc.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/detail/fischer_burmeister.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
using Eigen::VectorXd;

using cpkit::lcp::detail::pow2_below;

struct Model {
  const FrictionContactProblem& p;  // the scaled problem
  std::vector<double> rho;          // Alart-Curnier's rho per contact; empty: the FB function
  // Phi at r (u = W r + q given); with `jac`, the blocks A_i = dPhi_i/dr_i, B_i = dPhi_i/du_i.
  void eval(const VectorXd& r, const VectorXd& u, VectorXd& phi, std::vector<Mat3>* A,
            std::vector<Mat3>* B) const {
    const Eigen::Index nc = p.contacts();
    for (Eigen::Index i = 0; i < nc; ++i) {
      const double mu = p.mu[i];
      const Vec3 ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
      if (!rho.empty()) {
        alart_curnier(i, ri, ui, phi, A, B);
        continue;
      }
      if (mu == 0) {
        double da, db;
        phi[3 * i] = lcp::detail::fb_scalar(ri[0], ui[0], da, db);
        phi[3 * i + 1] = ri[1];
        phi[3 * i + 2] = ri[2];
        if (A) {
          (*A)[i] = Vec3(da, 1, 1).asDiagonal();
          (*B)[i].setZero();
          (*B)[i](0, 0) = db;
        }
        continue;
      }
      const double nt = std::hypot(ui[1], ui[2]);
      const Vec3 x(mu * ri[0], ri[1], ri[2]);
      const Vec3 y(ui[0] + mu * nt, mu * ui[1], mu * ui[2]);
      Vec3 ph;
      Mat3 Jx, Jy;
      lcp::detail::fb_soc(x, y, ph, Jx, Jy);
      phi.segment<3>(3 * i) = ph;
      if (A) {
        (*A)[i] = Jx * Vec3(mu, 1, 1).asDiagonal();
        Mat3 Dy = Mat3::Zero();
        Dy(0, 0) = 1;
        if (nt > 0) {
          Dy(0, 1) = mu * ui[1] / nt;
          Dy(0, 2) = mu * ui[2] / nt;
        }
        Dy(1, 1) = Dy(2, 2) = mu;
        (*B)[i] = Jy * Dy;
      }
    }
  }
  void alart_curnier(Eigen::Index i, const Vec3& ri, const Vec3& ui, VectorXd& phi,
                     std::vector<Mat3>* A, std::vector<Mat3>* B) const;
};

// Alart-Curnier's Phi_i (fb_soc.hpp) and an element of its generalized Jacobian.
void Model::alart_curnier(Eigen::Index i, const Vec3& ri, const Vec3& ui, VectorXd& phi,
                          std::vector<Mat3>* A, std::vector<Mat3>* B) const {
  using Vec2 = Eigen::Vector2d;
  using Mat2 = Eigen::Matrix2d;
  const double mu = p.mu[i], rh = rho[static_cast<size_t>(i)];
  const double zn = ri[0] - rh * ui[0];
  Vec3 ph;
  Mat3 a = Mat3::Zero(), b = Mat3::Zero();
  if (zn > 0) {  // Phi_N = rho u_N
    ph[0] = rh * ui[0];
    b(0, 0) = rh;
  } else {  // Phi_N = r_N
    ph[0] = ri[0];
    a(0, 0) = 1;
  }
  const double radius = mu * std::max(0.0, zn);
  const Vec2 zt = ri.tail<2>() - rh * ui.tail<2>();
  const double nz = zt.norm();
  if (nz <= radius) {  // inside the disk: Phi_T = rho u_T
    ph.tail<2>() = rh * ui.tail<2>();
    b(1, 1) = b(2, 2) = rh;
  } else {  // on its edge: Phi_T = r_T - R z_T / |z_T|
    const Vec2 n = nz > 0 ? Vec2(zt / nz) : Vec2(1, 0);
    ph.tail<2>() = ri.tail<2>() - radius * n;
    const Mat2 dp = (nz > 0 ? radius / nz : 0.0) * (Mat2::Identity() - n * n.transpose());
    a.block<2, 2>(1, 1) = Mat2::Identity() - dp;
    b.block<2, 2>(1, 1) = rh * dp;
    if (zn > 0) {  // R = mu z_N
      a.block<2, 1>(1, 0) = -mu * n;
      b.block<2, 1>(1, 0) = mu * rh * n;
    }
  }
  phi.segment<3>(3 * i) = ph;
  if (A) {
    (*A)[static_cast<size_t>(i)] = a;
    (*B)[static_cast<size_t>(i)] = b;
  }
}

// Every entry of every block is stored, zeros included: the pattern of J = A + B W is then the
// same at every iterate and the LU's ordering is computed once per solve.
SpMat block_diagonal(const std::vector<Mat3>& blocks) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(blocks.size() * 9);
  for (size_t i = 0; i < blocks.size(); ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        t.emplace_back(static_cast<int>(3 * i) + a, static_cast<int>(3 * i) + b, blocks[i](a, b));
  const Eigen::Index n = static_cast<Eigen::Index>(3 * blocks.size());
  SpMat m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

// True when a and b (compressed) have the same sparsity pattern.
bool same_pattern(const SpMat& a, const SpMat& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

}  // namespace

SolveResult solve_fb_soc(const FrictionContactProblem& p0, const FbSocOptions& o) {
  const Stopwatch clock;
  detail::check_input(p0, o.common, o.r0);
  throw_if_invalid(o.full_step_below >= 0 && o.full_step_below <= 1
                       ? ""
                       : "full_step_below must be in [0, 1]",
                   "fb-soc options");
  const Eigen::Index nc = p0.contacts(), n = 3 * nc;
  const int max_it = o.common.max_iterations > 0 ? o.common.max_iterations : 200;

  // Exact power-of-two scaling: u = su u', r = sr r', W' = W sr / su, q' = q / su.
  double w_max = 0;
  for (Eigen::Index k = 0; k < p0.W.outerSize(); ++k)
    for (SpMat::InnerIterator it(p0.W, k); it; ++it) w_max = std::max(w_max, std::abs(it.value()));
  const double q_inf = p0.q.lpNorm<Eigen::Infinity>();
  const double su = pow2_below(q_inf), sw = pow2_below(w_max), sr = su / sw;
  FrictionContactProblem p = p0;
  p.W = p0.W * (1.0 / sw);  // sr / su = 1 / sw
  p.q = p0.q * (1.0 / su);
  Model model{p, {}};
  if (o.alart_curnier)
    for (const Mat3& d : detail::diagonal_blocks(p.W)) {
      const double w = d.diagonal().cwiseAbs().maxCoeff();
      model.rho.push_back(w > 0 ? 1 / w : 1.0);
    }
  const FrictionUnits units = friction_units(p);

  VectorXd r = o.r0.size() ? VectorXd(o.r0 / sr) : VectorXd::Zero(n);
  VectorXd u = p.W * r + p.q, phi(n), trial_r(n), trial_u(n), trial_phi(n);
  std::vector<Mat3> A(static_cast<size_t>(nc)), B(static_cast<size_t>(nc));
  model.eval(r, u, phi, &A, &B);
  double psi = 0.5 * phi.squaredNorm();
  VectorXd best = r;
  double best_res = friction_residuals(p, units, r, u).natural;

  SolveResult res;
  res.solver = "fb-soc";
  Status stop = best_res <= o.common.tol ? Status::kSolved : Status::kIterationLimit;
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  SpMat analysed_pattern;
  bool analysed = false;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  SpMat ldlt_pattern;
  bool ldlt_analysed = false;
  SpMat I(n, n);
  I.setIdentity();
  // Non-monotone Armijo reference for Newton steps: the largest Psi of the last `memory`
  // iterates [Grippo, Lampariello, Lucidi 1986].
  const int memory = std::max(1, o.nonmonotone_memory);
  // Stagnation: the best residual has not halved within kStagnation iterations (on the FCLIB
  // files a converging run halves it at least every ~30 iterations).
  constexpr int kStagnation = 50;
  double progress_res = best_res;
  int progress_it = 0;
  std::vector<double> history{psi};
  bool forced_last = false;  // the last step was a full step taken over the line search's
  int it = 0;
  for (; it < max_it && stop != Status::kSolved; ++it) {
    if (o.common.time_limit_s < 1e300 && clock.exceeded(o.common.time_limit_s)) {
      stop = Status::kTimeLimit;
      break;
    }
    SpMat J = block_diagonal(A) + block_diagonal(B) * p.W;
    J.makeCompressed();
    const VectorXd grad = J.transpose() * phi;
    VectorXd d;
    double jmax = 0;
    for (Eigen::Index k = 0; k < J.outerSize(); ++k)
      for (SpMat::InnerIterator jt(J, k); jt; ++jt) jmax = std::max(jmax, std::abs(jt.value()));
    // Newton direction, with a shift when J does not factorise.
    for (double shift : {0.0, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2}) {
      SpMat Js = shift == 0 ? J : SpMat(J + (shift * jmax) * I);
      Js.makeCompressed();
      if (!analysed || !same_pattern(Js, analysed_pattern)) {
        lu.analyzePattern(Js);  // COLAMD once per pattern (the pattern of J does not change)
        analysed_pattern = Js;
        analysed = true;
      }
      lu.factorize(Js);
      if (lu.info() != Eigen::Success) continue;
      d = lu.solve(-phi);
      if (lu.info() == Eigen::Success && d.allFinite()) break;
      d.resize(0);
    }
    // Line search along d from t0 down to t_min against the reference ref; 0 when it fails.
    auto search = [&](const VectorXd& dir, double t0, double t_min, double ref) {
      const double slope = grad.dot(dir);
      for (double tt = t0; tt >= t_min; tt *= 0.5) {
        trial_r = r + tt * dir;
        trial_u.noalias() = p.W * trial_r;
        trial_u += p.q;
        model.eval(trial_r, trial_u, trial_phi, nullptr, nullptr);
        const double tpsi = 0.5 * trial_phi.squaredNorm();
        ++res.function_evals;
        if (std::isfinite(tpsi) && tpsi <= ref + 1e-4 * tt * slope) return tt;
        ++res.line_search_steps;
      }
      return 0.0;
    };
    const double psi_ref = *std::max_element(history.begin(), history.end());
    std::string kind = "newton";
    double t = 0;
    // 1. Newton, against the non-monotone reference.
    if (d.size() == n && grad.dot(d) < 0) t = search(d, 1.0, 1e-14, psi_ref);
    // 1b. The full Newton step when the line search damped it below full_step_below (header):
    //     not twice in a row, and only to a finite point.
    const bool may_force = !forced_last;
    forced_last = false;
    if (d.size() == n && t < o.full_step_below && may_force) {
      trial_r = r + d;
      trial_u.noalias() = p.W * trial_r;
      trial_u += p.q;
      if (trial_r.allFinite() && trial_u.allFinite()) {
        t = 1;
        kind = "full";
        forced_last = true;
        ++res.function_evals;
      } else if (t > 0) {  // the damped step found above, again
        trial_r = r + t * d;
        trial_u.noalias() = p.W * trial_r;
        trial_u += p.q;
      }
    }
    // 2. Levenberg-Marquardt, (J^T J + lambda I) d = -J^T Phi with lambda = |Phi| (the scaled
    //    problem's units): a descent direction that stays bounded where J is singular
    //    (non-isolated solutions of rank-deficient W) [Fan, Yuan 2005].
    if (t == 0) {
      kind = "lm";
      const double lambda = std::max(phi.norm(), 1e-14);
      SpMat N = SpMat(J.transpose() * J) + lambda * I;
      N.makeCompressed();
      // AMD ordering once per pattern of J^T J + lambda I (J's pattern is fixed): only the
      // numbers are factorised again.
      if (!ldlt_analysed || !same_pattern(N, ldlt_pattern)) {
        ldlt.analyzePattern(N);
        ldlt_pattern = N;
        ldlt_analysed = true;
      }
      ldlt.factorize(N);
      if (ldlt.info() == Eigen::Success) {
        d = ldlt.solve(-grad);
        if (d.allFinite() && grad.dot(d) < 0) t = search(d, 1.0, 1e-14, psi);
      }
    }
    // 3. Steepest descent.
    if (t == 0) {
      kind = "gradient";
      ++res.gradient_steps;
      d = -grad;
      const VectorXd Jd = J * d;
      const double jd2 = Jd.squaredNorm();
      t = search(d, jd2 > 0 ? d.squaredNorm() / jd2 : 1.0, 1e-14, psi);
    }
    const bool accepted = t > 0;
    if (!accepted) {
      stop = Status::kStalled;
      res.message = "fb-soc: line search failed along the Newton, Levenberg-Marquardt and gradient directions";
      break;
    }
    r.swap(trial_r);
    u.swap(trial_u);
    model.eval(r, u, phi, &A, &B);
    ++res.jacobian_evals;
    psi = 0.5 * phi.squaredNorm();
    history.push_back(psi);
    if (static_cast<int>(history.size()) > memory) history.erase(history.begin());
    const double rs = friction_residuals(p, units, r, u).natural;
    if (o.common.record_trace) res.trace.push_back({it + 1, rs, t, kind, -1, -1});
    if (rs < best_res) {
      best_res = rs;
      best = r;
    }
    if (rs <= 0.5 * progress_res) {
      progress_res = rs;
      progress_it = it;
    }
    if (rs <= o.common.tol) {
      stop = Status::kSolved;
    } else if (it - progress_it >= kStagnation) {
      stop = Status::kStalled;
      res.message = "fb-soc: the residual did not halve in " + std::to_string(kStagnation) +
                    " iterations (stagnation)";
      ++it;
      break;
    }
  }
  res.iterations = it;
  res.z = best * sr;
  res.status = stop;
  if (stop == Status::kIterationLimit || stop == Status::kTimeLimit)
    res.message = "fb-soc: " +
                  std::string(stop == Status::kTimeLimit ? "time limit" : "iteration limit") +
                  " reached after " + std::to_string(it) + " iterations";
  res = finalize(p0, std::move(res), o.common);
  res.seconds = clock.seconds();
  return res;
}

SolverEntry fb_soc_entry() {
  SolverEntry e;
  e.info.name = "fb-soc";
  e.info.description =
      "semismooth Newton on the SOC Fischer-Burmeister reformulation, sparse LU, Armijo line "
      "search with gradient fallback [Fukushima-Luo-Tseng 2001; Acary-Bremond-Huber 2018]";
  e.info.dense = false;
  e.info.sparse = true;
  e.solve_fc = detail::with_common_options<FbSocOptions>(
      [](const FrictionContactProblem& p, const FbSocOptions& o) { return solve_fb_soc(p, o); });
  return e;
}

}  // namespace cpkit::lcp::friction
