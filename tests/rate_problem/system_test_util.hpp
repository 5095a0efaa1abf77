#pragma once
// Random N-point systems for the tests of tests/rate_problem (seeded: deterministic).
#include <Eigen/Dense>
#include <random>

#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::test {

/// A random point (state, parameters); degenerate ones on purpose now and then (C_T = 0,
/// k_a = 0).
inline rate::SystemPoint random_point(std::mt19937& rng, rate::StateLabel label) {
  using rate::StateLabel;
  std::uniform_real_distribution<double> U(0, 1);
  rate::SystemPoint p;
  p.mu = 0.1 + 3 * U(rng);
  p.C_T = U(rng) < 0.3 ? 0.0 : U(rng);
  p.k_a = U(rng) < 0.3 ? 0.0 : U(rng);
  p.P_s = 0.5 + U(rng);
  p.state.label = label;
  if (label == StateLabel::kC || label == StateLabel::kD) p.state.P_N = 0.2 + 2 * U(rng);
  if (label == StateLabel::kD) p.state.sgn_PT = U(rng) < 0.5 ? 1 : -1;
  p.P_N = p.state.P_N;
  p.P_T = label == StateLabel::kD ? p.state.sgn_PT * p.mu * p.P_N : 0.0;
  if (label == StateLabel::kA) p.g = -1;
  return p;
}

/// A random symmetric positive definite n x n matrix (smallest eigenvalue >= 0.2).
inline Eigen::MatrixXd random_spd(std::mt19937& rng, int n) {
  std::normal_distribution<double> G(0, 1);
  Eigen::MatrixXd B(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) B(i, j) = G(rng);
  return B * B.transpose() + 0.2 * Eigen::MatrixXd::Identity(n, n);
}

inline rate::StateLabel random_label(std::mt19937& rng) {
  return static_cast<rate::StateLabel>(std::uniform_int_distribution<int>(0, 3)(rng));
}

}  // namespace cpkit::test
