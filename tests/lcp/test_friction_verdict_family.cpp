// Seeded families of hostile frictional contact problems (issue 34: rank-deficient W, mixed
// scales, huge mu, rigid-mode global problems): no registered friction solver may return
// `solved` (or `solved_inaccurate`) for an r that an independent check refutes. The checks do
// not use cpkit's verdict:
// - rank-1 one-contact problems with NO solution, proved by the closed-form argument of
//   ../shared/problems/hostile-friction/F4-01 (any "solved" is false);
// - block-diagonal two-body problems: contact 2's part of every solution is the solution of its
//   own block, found by the brute force of friction_brute_force.hpp (states enumerated, slip
//   angle scanned);
// - huge mu (1e6..1e15) one-contact problems: the brute force again;
// - random rank-deficient W = J J^T: the Signorini-Coulomb law re-checked with u recomputed in
//   quadruple precision and judged in the data's units (||q||_inf), never in r's;
// - global problems with a rounded rank-deficient M: u = H^T v + w in quadruple precision,
//   no penetration beyond 1e-6 of max(|H^T||v| + |w|) where r_N > 0 (F4-02's check).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/global.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_brute_force.hpp"
#include "test_budget.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::SolveResult;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using Quad = __float128;
using cpkit::test::family_size;

FrictionContactProblem make(const MatrixXd& W, const VectorXd& q, const VectorXd& mu) {
  FrictionContactProblem p;
  p.W = W.sparseView();
  p.q = q;
  p.mu = mu;
  return p;
}

// Every registered friction solver on every `slow_every`-th problem; on the others the fast ones
// (auto and ipopt spend about a second on a problem without solution, the rest milliseconds:
// the suite's time budget).
std::vector<std::string> friction_solvers(int problem, int slow_every = 12) {
  std::vector<std::string> out;
  for (const std::string& name : cpkit::lcp::solvers().names(cpkit::ProblemKind::kFrictionContact))
    if (problem % slow_every == 0 || (name != "auto" && name != "ipopt")) out.push_back(name);
  return out;
}

cpkit::CommonOptions options() {
  cpkit::CommonOptions o;
  o.tol = 1e-10;
  o.time_limit_s = 5;
  return o;
}

bool accepted(const SolveResult& s) {
  return s.status == Status::kSolved || s.status == Status::kSolvedInaccurate;
}

// u = W r + q in quadruple precision: products of doubles are exact there, sums round at 2^-113.
std::vector<Quad> quad_velocity(const FrictionContactProblem& p, const VectorXd& r) {
  const MatrixXd W(p.W);
  std::vector<Quad> u(static_cast<std::size_t>(r.size()));
  for (Eigen::Index i = 0; i < W.rows(); ++i) {
    Quad s = p.q[i];
    for (Eigen::Index j = 0; j < W.cols(); ++j) s += static_cast<Quad>(W(i, j)) * r[j];
    u[static_cast<std::size_t>(i)] = s;
  }
  return u;
}

// The largest violation of the contact law by (r, u), with r judged in each contact's own size
// (at least rho = ||q||_inf / ||W||_max, the data's size of r: a separated contact's r_i is
// rounding noise) and u in the data's size sigma = ||q||_inf (never in r's): r in K_mu, u_N >= 0, r_N u_N = 0, and a
// sliding contact's r_T opposite to u_T on the cone's edge. Every comparison involving mu r_N
// allows mu 4 eps |r| (what double precision can say of r_N at all).
double law_violation(const FrictionContactProblem& p, const VectorXd& r, const std::vector<Quad>& u) {
  const double sigma = p.q.lpNorm<Eigen::Infinity>();
  const double rho = sigma / MatrixXd(p.W).cwiseAbs().maxCoeff();
  double worst = 0;
  for (Eigen::Index i = 0; i < p.mu.size(); ++i) {
    const double mu = p.mu[i], rn = r[3 * i];
    const double r_size = std::max(r.segment<3>(3 * i).norm(), rho);
    const double rt = r.segment<2>(3 * i + 1).norm();
    const double un = static_cast<double>(u[3 * i]) / sigma;
    const double ut1 = static_cast<double>(u[3 * i + 1]) / sigma;
    const double ut2 = static_cast<double>(u[3 * i + 2]) / sigma;
    const double ut = std::hypot(ut1, ut2);
    double v = std::max(0.0, -un);  // no penetration
    if (r_size > 0) {
      const double slack = 4e-16 * std::max(1.0, mu) * r_size;
      // In the cone: r_N >= 0 and Coulomb's bound |r_T| <= mu r_N, both in r's own size.
      v = std::max({v, -rn / r_size, (rt - mu * rn - slack) / r_size});
      // A normal force (read by the friction it allows): no normal motion.
      const bool force = std::max(1.0, mu) * rn > 1e-6 * r_size + slack;
      if (force) v = std::max(v, std::abs(un));
      if (ut > 1e-6) {  // sliding: r_T opposite to u_T, on the cone's edge
        if (rt > 0) {
          const double e1 = r[3 * i + 1] / rt + ut1 / ut, e2 = r[3 * i + 2] / rt + ut2 / ut;
          v = std::max(v, std::hypot(e1, e2) * rt / r_size);
        }
        v = std::max(v, (mu * rn - rt - slack) / r_size);
      }
    }
    worst = std::max(worst, v);
  }
  return worst;
}

// Dyadic numbers k / 2^e (exact in double, so that W = h h^T is exactly rank 1).
double dyadic(std::mt19937& rng, int lo, int hi, int e) {
  return std::ldexp(std::uniform_int_distribution<int>(lo, hi)(rng), -e);
}

}  // namespace

TEST_CASE("verdict family: rank-1 contacts without a solution are never solved",
          "[friction][verdict][family]") {
  // W = h h^T, h_N a power of two > 0, q_N < 0. u = q + s h with s = h . r. Separation needs
  // q_N >= 0 (no); stick needs q parallel to h (excluded); slip needs u_N = 0, s = -q_N / h_N
  // (exact), u_T = q_T + s h_T != 0 and r = r_N (1, -mu u_T/|u_T|) with h . r = s > 0, i.e.
  // r_N (h_N - mu h_T . u_T / |u_T|) = s: impossible when mu h_T . u_T >= h_N |u_T|, which is
  // required below with a 1 % margin (so rounding cannot decide it).
  std::mt19937 rng(2026);
  const int wanted = family_size(24, 6);
  int problems = 0, runs = 0;
  for (int trial = 0; problems < wanted && trial < 20000; ++trial) {
    const Eigen::Vector3d h(std::ldexp(1.0, std::uniform_int_distribution<int>(-2, 1)(rng)),
                            dyadic(rng, -16, 16, 3), dyadic(rng, -16, 16, 3));
    const Eigen::Vector3d q(-dyadic(rng, 1, 32, 3), dyadic(rng, -32, 32, 3), dyadic(rng, -32, 32, 3));
    const double mu = dyadic(rng, 1, 16, 3);
    if (h.cross(q).squaredNorm() == 0) continue;  // q parallel to h: a stick exists
    const double s = -q[0] / h[0];
    const Eigen::Vector2d uT = q.tail<2>() + s * h.tail<2>();
    if (uT.norm() == 0) continue;
    if (!(mu * h.tail<2>().dot(uT) >= 1.01 * h[0] * uT.norm())) continue;  // a slip may exist
    ++problems;
    const auto p = make(h * h.transpose(), q, VectorXd::Constant(1, mu));
    for (const std::string& name : friction_solvers(problems)) {
      const SolveResult res = cpkit::lcp::solvers().find(name)->solve_fc(p, options());
      CAPTURE(trial, name, h.transpose(), q.transpose(), mu, res.z.transpose(), res.message);
      CHECK_FALSE(accepted(res));
      ++runs;
    }
  }
  CHECK(problems == wanted);
  CHECK(runs >= wanted * 4);
}

TEST_CASE("verdict family: a small body beside a large one is judged in its own units",
          "[friction][verdict][family]") {
  // W = diag(W1, W2) (random SPD blocks), |q_1| ~ 1e4..1e8, |q_2| ~ 1e-2..1e-6: contact 2's part
  // of any solution solves W2 alone, whose solutions the brute force lists.
  std::mt19937 rng(34);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0, 1);
  const int trials = family_size(60, 15);
  int problems = 0, accepted_runs = 0, refused = 0;
  for (int trial = 0; trial < trials; ++trial) {
    MatrixXd W = MatrixXd::Zero(6, 6);
    for (int b = 0; b < 2; ++b) {
      Eigen::Matrix3d J;
      for (int i = 0; i < 9; ++i) J(i / 3, i % 3) = g(rng);
      W.block<3, 3>(3 * b, 3 * b) = J * J.transpose() + 0.1 * Eigen::Matrix3d::Identity();
    }
    VectorXd q(6);
    const double big = std::pow(10.0, 4 + 4 * U(rng)), small = std::pow(10.0, -2 - 4 * U(rng));
    for (int i = 0; i < 3; ++i) {
      q[i] = big * g(rng);
      q[3 + i] = small * g(rng);
    }
    q[0] = -std::abs(q[0]);
    const double mu = 0.1 + 0.8 * U(rng);
    const auto p = make(W, q, VectorXd::Constant(2, mu));
    const auto block2 = cpkit::test::brute_force_one_contact(W.block<3, 3>(3, 3), q.tail<3>(), mu);
    if (block2.size() != 1) continue;  // keep the problems whose contact 2 is unique
    ++problems;
    for (const std::string& name : friction_solvers(problems)) {
      const SolveResult res = cpkit::lcp::solvers().find(name)->solve_fc(p, options());
      if (!accepted(res)) {
        ++refused;
        continue;
      }
      ++accepted_runs;
      const Eigen::Vector3d r2 = res.z.tail<3>();
      const double size = std::max(block2[0].norm(), 1e-300);
      CAPTURE(trial, name, r2.transpose(), block2[0].transpose(), res.message);
      CHECK((r2 - block2[0]).norm() <= 1e-4 * size + 1e-4 * small);
    }
  }
  CHECK(problems >= 2 * trials / 3);
  CHECK(accepted_runs >= problems * 2);  // most solvers do solve these: the check is not empty
  INFO(refused);
}

TEST_CASE("verdict family: huge friction coefficients, one contact", "[friction][verdict][family]") {
  // mu = 1e6..1e15: an accepted r must lie in its cone (r_N >= 0, |r_T| <= mu r_N) and satisfy
  // the law re-checked in quadruple precision. Where the brute force's only solution is a stick
  // well inside the cone (|r_T| <= 0.9 mu r_N) or a separation, r must be it; a slip at such a
  // mu is not compared (r_N ~ |r_T| / mu is fixed by the data only to ~mu eps |r|: stick and slip
  // at the cone's edge cannot be told apart in double precision).
  std::mt19937 rng(13);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0, 1);
  const int trials = family_size(30, 8);
  int problems = 0, accepted_runs = 0, compared = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Eigen::Matrix3d J;
    for (int i = 0; i < 9; ++i) J(i / 3, i % 3) = g(rng);
    const Eigen::Matrix3d W = J * J.transpose() + 0.1 * Eigen::Matrix3d::Identity();
    Eigen::Vector3d q(-std::abs(g(rng)), 3 * g(rng), 3 * g(rng));
    const double mu = std::pow(10.0, 6 + 9 * U(rng));
    const auto truth = cpkit::test::brute_force_one_contact(W, q, mu);
    const bool clear = truth.size() == 1 && (truth[0].norm() == 0 ||
                                             truth[0].tail<2>().norm() <= 0.9 * mu * truth[0][0]);
    ++problems;
    const auto p = make(W, q, VectorXd::Constant(1, mu));
    for (const std::string& name : friction_solvers(problems)) {
      const SolveResult res = cpkit::lcp::solvers().find(name)->solve_fc(p, options());
      if (!accepted(res)) continue;
      ++accepted_runs;
      CAPTURE(trial, mu, name, res.z.transpose(), res.message);
      CHECK(res.z[0] >= 0);
      CHECK(res.z.tail<2>().norm() <= mu * res.z[0] * (1 + 1e-9));
      CHECK(law_violation(p, res.z, quad_velocity(p, res.z)) <= 1e-6);
      if (clear) {
        ++compared;
        CAPTURE(truth[0].transpose());
        CHECK((res.z - truth[0]).norm() <= 1e-6 * std::max(truth[0].norm(), q.norm()));
      }
    }
  }
  CHECK(problems == trials);
  CHECK(accepted_runs >= trials);
  CHECK(compared >= trials / 2);
}

TEST_CASE("verdict family: random rank-deficient W, the law re-checked in quadruple precision",
          "[friction][verdict][family]") {
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 1.0);
  const int trials = family_size(90, 24);
  int accepted_runs = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const int nc = 1 + trial % 3, m = 1 + trial % (3 * nc - 1);  // rank m < 3 nc
    MatrixXd J(3 * nc, m);
    for (int i = 0; i < J.size(); ++i) J(i % J.rows(), i / J.rows()) = g(rng);
    VectorXd q(3 * nc), mu(nc);
    for (int i = 0; i < 3 * nc; ++i) q[i] = g(rng);
    for (int i = 0; i < nc; ++i) mu[i] = U(rng);
    const auto p = make(J * J.transpose(), q, mu);
    for (const std::string& name : friction_solvers(trial)) {
      const SolveResult res = cpkit::lcp::solvers().find(name)->solve_fc(p, options());
      if (!accepted(res)) continue;
      ++accepted_runs;
      CAPTURE(trial, name, res.z.transpose(), res.message);
      CHECK(law_violation(p, res.z, quad_velocity(p, res.z)) <= 1e-6);
    }
  }
  CHECK(accepted_runs >= trials);
}

TEST_CASE("verdict family: global problems with a rigid mode never solved with penetration",
          "[friction][verdict][family]") {
  // M = B B^T with B of m - 1 or m - 2 columns (rounded: a free rigid mode), H, f, w random.
  std::mt19937 rng(98);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 0.3);
  int runs = 0;
  const int trials = family_size(40, 10);
  for (int trial = 0; trial < trials; ++trial) {
    const int nc = 2 + trial % 2, m = 5 + trial % 5, k = m - 1 - trial % 2;
    MatrixXd B(m, k), H(m, 3 * nc);
    for (int i = 0; i < B.size(); ++i) B(i % m, i / m) = g(rng);
    for (int i = 0; i < H.size(); ++i) H(i % m, i / m) = g(rng);
    cpkit::GlobalFrictionContactProblem gp;
    gp.M = MatrixXd(B * B.transpose()).sparseView();
    gp.H = H.sparseView();
    gp.f = VectorXd(m);
    gp.w = VectorXd(3 * nc);
    gp.mu = VectorXd(nc);
    for (int i = 0; i < m; ++i) gp.f[i] = g(rng);
    for (int i = 0; i < 3 * nc; ++i) gp.w[i] = g(rng);
    for (int i = 0; i < nc; ++i) gp.mu[i] = U(rng);
    // The condensed route (it refuses M when it sees the rigid mode) and, as `cpkit fc solve`
    // does for a singular M, the proximal route in the global variables.
    for (const std::string name : {"auto", "fb-soc", "nsgs", "prox", "proximal-route"}) {
      const bool proximal = name == "proximal-route";
      const auto out = proximal ? cpkit::lcp::friction::solve_global_proximal(gp, "auto", options())
                                : cpkit::lcp::friction::solve_global(gp, name, options());
      ++runs;
      if (!accepted(out.result)) continue;
      // u = H^T v + w in quadruple precision, judged in max(|H^T||v| + |w|).
      double sigma = 0;
      for (int c = 0; c < 3 * nc; ++c) {
        Quad u = gp.w[c];
        double size = std::abs(gp.w[c]);
        for (int j = 0; j < m; ++j) {
          u += static_cast<Quad>(H(j, c)) * out.v[j];
          size += std::abs(H(j, c) * out.v[j]);
        }
        sigma = std::max(sigma, size);
        (void)u;
      }
      for (int i = 0; i < nc; ++i) {
        Quad un = gp.w[3 * i];
        for (int j = 0; j < m; ++j) un += static_cast<Quad>(H(j, 3 * i)) * out.v[j];
        CAPTURE(trial, name, i, static_cast<double>(un), out.result.z.transpose());
        CHECK(static_cast<double>(un) >= -1e-6 * sigma);
        if (out.result.z[3 * i] > 1e-6 * out.result.z.lpNorm<Eigen::Infinity>())
          CHECK(std::abs(static_cast<double>(un)) <= 1e-6 * sigma);
      }
    }
  }
  CHECK(runs == 5 * trials);
}
