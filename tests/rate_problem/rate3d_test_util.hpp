#pragma once
// Random 3-D stiffness matrices shared by the 3-D tests (rate, faceted, step, step solvers).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <random>

namespace cpkit::test {

/// A symmetric positive definite 3 x 3 stiffness on (T_X, T_Y, N) with a strong
/// tangential-normal coupling A_TN (where non-uniqueness lives): A_TT random SPD,
/// A_TN = coupling (u, u), and A_NN above the Schur-complement bound A_TN A_TT^-1 A_NT by a
/// margin in [0.0025, 0.05] (tight) or [0.1, 1.05] (not tight). Deterministic for the rng.
inline Eigen::Matrix3d coupled_spd(std::mt19937& rng, double coupling = 1, bool tight = true) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  Eigen::Matrix2d L;
  L << 0.5 + pos(rng), 0, u(rng), 0.5 + pos(rng);
  const Eigen::Matrix2d ATT = L * L.transpose();
  const Eigen::Vector2d ATN = coupling * Eigen::Vector2d(u(rng), u(rng));
  Eigen::Matrix3d A;
  A.topLeftCorner<2, 2>() = ATT;
  A.topRightCorner<2, 1>() = ATN;
  A.bottomLeftCorner<1, 2>() = ATN.transpose();
  const double margin = tight ? 0.05 * pos(rng) : 0.05 + pos(rng);
  A(2, 2) = ATN.dot(ATT.ldlt().solve(ATN)) + margin;
  return A;
}

}  // namespace cpkit::test
