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
