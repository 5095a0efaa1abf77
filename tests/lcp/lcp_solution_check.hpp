#pragma once
// Test helper (not a test): an LCP solution checked in the test itself, from the data, not by
// the library's own residuals.
#include <algorithm>

#include "cpkit/core/problem.hpp"

namespace lcp_test {

/// z >= 0, w = M z + q >= 0 and min(z_i, w_i) = 0, each up to rel times the size of the terms
/// of row i, (|M| |z|)_i + |q_i| (unit-free: invariant under q -> a q and (M, q) -> b (M, q)).
inline bool is_solution_here(const cpkit::Mat& M, const cpkit::Vec& q, const cpkit::Vec& z,
                             double rel = 1e-9) {
  const cpkit::Vec w = M * z + q;
  const cpkit::Vec scale = M.cwiseAbs() * z.cwiseAbs() + q.cwiseAbs();
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const double t = rel * scale[i];
    if (z[i] < -t || w[i] < -t || std::min(z[i], w[i]) > t) return false;
  }
  return true;
}

}  // namespace lcp_test
