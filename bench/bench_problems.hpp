#pragma once
// Problem generators shared by the benchmarks, so that benchmarks that compare on "the same
// problems" really draw the same ones.
#include <random>
#include <string>

#include "cpkit/core/problem.hpp"

namespace cpkit::bench {

/// Random dense P-matrix LCP: B, S, q uniform in [-1, 1], M = B B^T / n + I + S - S^T
/// (symmetric part positive definite, hence a P-matrix with a unique solution). bench_lemke and
/// bench_fb_newton draw from one std::mt19937 seeded 2026 in order through their sizes.
inline LcpProblem random_p_lcp(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat B(n, n), S(n, n);
  Vec q(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) B(i, j) = u(rng), S(i, j) = u(rng);
    q[i] = u(rng);
  }
  return LcpProblem(B * B.transpose() / n + Mat::Identity(n, n) + S - S.transpose(), q,
                    "random_p_" + std::to_string(n));
}

}  // namespace cpkit::bench

namespace cpkit::bench {

/// Fully degenerate LCP M = I, q = -1 (solution z = 1): every ratio of every pivot ties.
inline LcpProblem identity_lcp(int n) {
  return LcpProblem(Mat::Identity(n, n), -Vec::Ones(n), "identity_" + std::to_string(n));
}

/// M = I with q drawn from {-2, -1, 0, 1} (many equal entries: ties at every pivot);
/// solution z = max(-q, 0).
inline LcpProblem identity_ties_lcp(int n, std::mt19937& rng) {
  std::uniform_int_distribution<int> u(-2, 1);
  Vec q(n);
  for (int i = 0; i < n; ++i) q[i] = u(rng);
  return LcpProblem(Mat::Identity(n, n), q, "identity_ties_" + std::to_string(n));
}

/// Contact LCPs of a physics engine (Stewart-Trinkle / Anitescu-Potra, polyhedral friction
/// cone with 4 directions), the C++ counterpart of tests/data/lemke/contact_lcp.py: `bodies`
/// independent rigid bodies resting on the ground with 2 contacts each (12 unknowns per body:
/// 2 normal impulses, 8 friction impulses, 2 sliding multipliers; M block diagonal), unit-size
/// masses and lever arms (M ~ 1) and velocities of size 1e-10 (q ~ 1e-10, lambda rows q = 0).
/// Contact points on a half-unit grid and vertical normals make it degenerate.
inline LcpProblem contact_lcp(int bodies, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> grid(-2, 2);
  const int nb = 12;
  Mat M = Mat::Zero(nb * bodies, nb * bodies);
  Vec q = Vec::Zero(nb * bodies);
  auto cross = [](const Eigen::Vector3d& r, const Eigen::Vector3d& d) { return r.cross(d); };
  for (int b = 0; b < bodies; ++b) {
    const double mass = 1.0 + 0.5 * u(rng);
    const Eigen::Vector3d inertia(0.55 + 0.45 * u(rng), 0.55 + 0.45 * u(rng),
                                  0.55 + 0.45 * u(rng));
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
    A.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / mass;
    A.bottomRightCorner<3, 3>() = inertia.cwiseInverse().asDiagonal();
    Eigen::Matrix<double, 6, 2> N;
    Eigen::Matrix<double, 6, 8> D;
    for (int c = 0; c < 2; ++c) {
      const Eigen::Vector3d n(0, 0, 1), t1(1, 0, 0), t2(0, 1, 0);
      const Eigen::Vector3d r(grid(rng) / 2.0, grid(rng) / 2.0, -0.5);
      N.col(c) << n, cross(r, n);
      const Eigen::Vector3d dirs[4] = {t1, t2, -t1, -t2};
      for (int k = 0; k < 4; ++k) D.col(4 * c + k) << dirs[k], cross(r, dirs[k]);
    }
    Eigen::Matrix<double, 8, 2> E = Eigen::Matrix<double, 8, 2>::Zero();
    E.block<4, 1>(0, 0).setOnes();
    E.block<4, 1>(4, 1).setOnes();
    const double mu = 0.5;
    Mat Mb = Mat::Zero(nb, nb);
    Mb.block(0, 0, 2, 2) = N.transpose() * A * N;
    Mb.block(0, 2, 2, 8) = N.transpose() * A * D;
    Mb.block(2, 0, 8, 2) = D.transpose() * A * N;
    Mb.block(2, 2, 8, 8) = D.transpose() * A * D;
    Mb.block(2, 10, 8, 2) = E;
    Mb.block(10, 0, 2, 2) = mu * Mat::Identity(2, 2);
    Mb.block(10, 2, 2, 8) = -E.transpose();
    Eigen::Matrix<double, 6, 1> v;
    for (int i = 0; i < 6; ++i) v[i] = (u(rng) < -0.2) ? 0.0 : 1e-10 * u(rng);
    v[2] = -1e-10 * (1.5 + 0.5 * u(rng));
    Vec qb = Vec::Zero(nb);
    qb.head(2) = N.transpose() * v;
    qb.segment(2, 8) = D.transpose() * v;
    M.block(nb * b, nb * b, nb, nb) = Mb;
    q.segment(nb * b, nb) = qb;
  }
  return LcpProblem(M, q, "contact_" + std::to_string(bodies) + "_bodies");
}

}  // namespace cpkit::bench
