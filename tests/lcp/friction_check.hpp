#pragma once
// Test helper (not a test): an independent check of a frictional contact solution, written
// without cpkit's cone code: u = W r + q recomputed here, then per contact the three conditions
// of De Saxce's form directly (r in K_mu, u_hat in K*_mu, r . u_hat = 0), each relative to the
// contact's own sizes. Returns the largest violation.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/status.hpp"

namespace cpkit::test {

inline double friction_violation(const Eigen::SparseMatrix<double>& W, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& mu, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = Eigen::MatrixXd(W) * r + q;  // dense product: a different route
  const double r_size = std::max(r.lpNorm<Eigen::Infinity>(), 1e-300);
  double worst = 0;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    const double rN = r[3 * i], rT = std::sqrt(r[3 * i + 1] * r[3 * i + 1] + r[3 * i + 2] * r[3 * i + 2]);
    const double uN = u[3 * i], uT = std::sqrt(u[3 * i + 1] * u[3 * i + 1] + u[3 * i + 2] * u[3 * i + 2]);
    const double m = mu[i];
    const double u_size = std::max({q.segment(3 * i, 3).norm(),
                                    Eigen::MatrixXd(W).middleRows(3 * i, 3).cwiseAbs().maxCoeff() * r_size, 1e-300});
    const double hatN = uN + m * uT;
    double v = std::max(0.0, -rN) / r_size;                        // r_N >= 0
    v = std::max(v, std::max(0.0, rT - m * rN) / r_size);          // |r_T| <= mu r_N
    v = std::max(v, std::max(0.0, -uN) / u_size);                  // u_hat in K*: u_N >= 0
    const double dot = rN * hatN + r[3 * i + 1] * u[3 * i + 1] + r[3 * i + 2] * u[3 * i + 2];
    v = std::max(v, std::abs(dot) / (r_size * u_size));            // r . u_hat = 0
    // Signorini on the normal: r_N u_N = 0
    v = std::max(v, std::abs(rN * uN) / (r_size * u_size));
    // Coulomb: when sliding (u_T != 0), r_T = -mu r_N u_T / |u_T|
    if (uT > 1e-6 * u_size)
      for (int j = 1; j < 3; ++j)
        v = std::max(v, std::abs(r[3 * i + j] + m * rN * u[3 * i + j] / uT) / r_size);
    worst = std::max(worst, v);
  }
  return worst;
}

/// W = H^T H as rigid bodies give (H: m dofs x 3 nc, m < 3 nc: rank-deficient), q = H^T v with
/// a random free velocity v; mu in [0.1, 0.8].
inline FrictionContactProblem rigid_like(std::mt19937& rng, int nc, int m) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 0.8);
  Eigen::MatrixXd H(m, 3 * nc);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < 3 * nc; ++j) H(i, j) = g(rng);
  Eigen::VectorXd v(m);
  for (int i = 0; i < m; ++i) v[i] = g(rng);
  FrictionContactProblem p;
  p.W = (H.transpose() * H).sparseView();
  p.q = H.transpose() * v;
  p.mu.resize(nc);
  for (int i = 0; i < nc; ++i) p.mu[i] = U(rng);
  return p;
}

/// 24 random problems (2..8 contacts, full rank every other one, normals shifted so that some
/// contacts press and others separate), solved by `solve` (tol 1e-10, 5000 iterations): every
/// answer called solved passes friction_violation; at least 3/4 are solved; none is called a
/// solution without being solved.
template <class Solve>
void check_random_rigid_problems(Solve solve) {
  std::mt19937 rng(7);
  int solved = 0, tried = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int nc = 2 + trial % 7;
    const int m = trial % 2 ? 3 * nc + 2 : std::max(2, 2 * nc);
    FrictionContactProblem p = rigid_like(rng, nc, m);
    for (int i = 0; i < nc; ++i) p.q[3 * i] = (i % 2 ? 0.5 : -1.0) * std::abs(p.q[3 * i]);
    const auto res = solve(p);
    ++tried;
    if (res.status == Status::kSolved) {
      ++solved;
      CHECK(friction_violation(p.W, p.q, p.mu, res.z) < 1e-7);
    } else {
      CHECK_FALSE(is_solution(res.status));
    }
  }
  INFO("solved " << solved << " of " << tried);
  CHECK(solved >= tried * 3 / 4);
}

/// Time limits from `from` to `to` seconds, each `factor` times the one before: a sweep that
/// ends a solve at each of its stages (the tests of a limit that runs out between two readings
/// of the clock, which must give a time limit, never a refusal of the limit as bad input).
inline std::vector<double> time_limit_sweep(double from, double to, double factor) {
  std::vector<double> limits;
  for (double t = from; t <= to; t *= factor) limits.push_back(t);
  return limits;
}

}  // namespace cpkit::test
