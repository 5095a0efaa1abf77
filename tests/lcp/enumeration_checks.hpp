#pragma once
// Test helper (not a test): checks shared by the enumeration tests.
#include <catch2/catch.hpp>

#include <cmath>

#include "cpkit/lcp/enumerate.hpp"
#include "lcp/enumerate_brute_force.hpp"

namespace enumeration_checks {

/// The enumerated set in the brute-force comparator's form.
inline brute::Found to_found(const cpkit::lcp::SolutionSet& s) {
  brute::Found f;
  for (const auto& e : s.solutions) {
    f.z.emplace_back(e.z.data(), e.z.data() + e.z.size());
    f.w.emplace_back(e.w.data(), e.w.data() + e.w.size());
  }
  for (const auto& p : s.pieces) {
    brute::Found::Piece pc;
    for (int i : p.support) pc.support |= 1u << i;
    pc.vertices = p.vertices;
    for (const auto& r : p.rays) pc.rays.emplace_back(r.data(), r.data() + r.size());
    f.pieces.push_back(pc);
  }
  f.infinite = s.infinite;
  return f;
}

/// Every listed solution, re-checked from the data with the unit-free componentwise test:
/// finite, z >= 0, w >= 0, z_i w_i = 0 and w = M z + q to 1e-8 W_i, W_i = |q_i| + (|M||z|)_i
/// (summed term by term, so an overflowing term is caught as non-finite).
inline void require_verified(const cpkit::lcp::SolutionSet& s, const cpkit::Mat& M,
                             const cpkit::Vec& q) {
  for (const auto& e : s.solutions) {
    REQUIRE(e.z.allFinite());
    REQUIRE(e.w.allFinite());
    REQUIRE(e.z.minCoeff() >= 0);
    REQUIRE(e.w.minCoeff() >= 0);
    for (int i = 0; i < int(q.size()); ++i) {
      double w = q(i), W = std::abs(q(i));
      for (int j = 0; j < int(q.size()); ++j) {
        w += M(i, j) * e.z(j);
        W += std::abs(M(i, j) * e.z(j));
      }
      REQUIRE(std::isfinite(w));
      REQUIRE(std::isfinite(W));
      REQUIRE(e.z(i) * e.w(i) == 0);
      REQUIRE(std::abs(w - e.w(i)) <= 1e-8 * W);
    }
  }
}

}  // namespace enumeration_checks
