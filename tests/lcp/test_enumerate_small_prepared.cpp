// Tests of the prepared-matrix path (enumerate_small_prepared.hpp): for many matrices and many
// right-hand sides per matrix, SmallPreparedLcp::enumerate must give exactly the solution set of
// enumerate_small (field by field), and on integer data both must equal the independent exact
// brute force of enumerate_brute_force.hpp (rational arithmetic).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/enumerate_small_prepared.hpp"
#include "lcp/enumerate_brute_force.hpp"
#include "lcp/enumerate_small_found.hpp"

namespace {

using cpkit::lcp::SmallPreparedLcp;
using cpkit::lcp::SmallSolutionSet;

bool close(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
}

template <int N>
void require_same(const SmallSolutionSet<N>& a, const SmallSolutionSet<N>& b) {
  REQUIRE(a.num_points == b.num_points);
  REQUIRE(a.num_pieces == b.num_pieces);
  REQUIRE(a.infinite == b.infinite);
  REQUIRE(a.ambiguous == b.ambiguous);
  REQUIRE(a.dropped == b.dropped);
  for (int p = 0; p < a.num_points; ++p) {
    REQUIRE(a.support[p] == b.support[p]);
    for (int j = 0; j < N; ++j) {
      REQUIRE(close(a.z[p](j), b.z[p](j)));
      REQUIRE(close(a.w[p](j), b.w[p](j)));
    }
  }
  for (int k = 0; k < a.num_pieces; ++k) {
    const auto& pa = a.pieces[k];
    const auto& pb = b.pieces[k];
    REQUIRE(pa.support == pb.support);
    REQUIRE(pa.vertex_mask == pb.vertex_mask);
    REQUIRE(pa.num_rays == pb.num_rays);
    for (int r = 0; r < pa.num_rays; ++r)
      for (int j = 0; j < N; ++j) REQUIRE(close(pa.rays[r](j), pb.rays[r](j)));
  }
}

/// Random integer matrices (many zero entries: singular principal blocks are frequent), many
/// integer q per matrix; prepared == per-call, and (for every `brute_every`-th q) == brute force.
template <int N>
void integer_sweep(unsigned seed, int matrices, int qs, int range, double zero_prob,
                   int brute_every, long long& singular_seen) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> val(-range, range);
  std::uniform_real_distribution<double> u(0, 1);
  SmallSolutionSet<N> a, b;
  for (int t = 0; t < matrices; ++t) {
    std::vector<std::vector<int>> Mi(N, std::vector<int>(N));
    Eigen::Matrix<double, N, N> M;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        Mi[i][j] = u(rng) < zero_prob ? 0 : val(rng);
        M(i, j) = Mi[i][j];
      }
    const SmallPreparedLcp<N> prep(M);
    for (int s = 0; s < qs; ++s) {
      std::vector<int> qi(N);
      Eigen::Matrix<double, N, 1> q;
      for (int i = 0; i < N; ++i) {
        qi[i] = u(rng) < zero_prob ? 0 : val(rng);
        q(i) = qi[i];
      }
      CAPTURE(M, q.transpose());
      cpkit::lcp::enumerate_small<N>(M, q, a);
      prep.enumerate(q, b);
      require_same<N>(a, b);
      singular_seen += b.infinite;
      if (s % brute_every == 0 && b.ambiguous == 0 && b.dropped == 0) brute::check(Mi, qi, to_found<N>(b));
    }
  }
}

/// The state-b rate LCP of the one-point problem (docs/model.md, Sec. 2).
void rate_lcp(double a11, double a12, double a22, double CT, double mu, double dFT, double dFN,
              Eigen::Matrix3d& M, Eigen::Vector3d& q) {
  const double detA = a11 * a22 - a12 * a12, D0 = a22 + CT * detA;
  const double S = (1 + a11 * CT) * dFN - a12 * CT * dFT;
  M << 1 + a11 * CT, a12, -a12, mu * D0 - a12, detA, -detA, mu * D0 + a12, -detA, detA;
  const double t = a22 * dFT - a12 * dFN;
  q << -S, -t, t;
}

}  // namespace

TEST_CASE("SmallPreparedLcp: random integer LCPs n = 1..4 equal enumerate_small and the brute force",
          "[enumerate_small_prepared]") {
  long long inf = 0;
  integer_sweep<1>(11, 20, 20, 3, 0.3, 1, inf);
  integer_sweep<2>(12, 150, 30, 3, 0.3, 3, inf);
  integer_sweep<3>(13, 150, 30, 2, 0.35, 5, inf);
  integer_sweep<4>(14, 60, 20, 2, 0.4, 10, inf);
  CHECK(inf > 50);  // the sweep does reach infinite solution sets (singular pieces)
}

TEST_CASE("SmallPreparedLcp: rate LCPs over random parameters equal enumerate_small",
          "[enumerate_small_prepared][rate]") {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0, 1);
  SmallSolutionSet<3> a, b;
  int degenerate = 0, infinite = 0;
  for (int t = 0; t < 300; ++t) {
    // A symmetric positive definite, C_T >= 0, mu > 0; every third set exactly on a11 = mu|a12|
    const double a12 = (u(rng) - 0.5) * 4, mu = 0.05 + u(rng);
    const double a11 = t % 3 == 0 ? mu * std::abs(a12) : 0.1 + 3 * u(rng);
    const double a22 = (a12 * a12 + 0.1) / a11 + 3 * u(rng), CT = t % 5 == 0 ? 0 : u(rng);
    Eigen::Matrix3d M;
    Eigen::Vector3d q;
    rate_lcp(a11, a12, a22, CT, mu, 1, 0, M, q);
    const SmallPreparedLcp<3> prep(M);
    for (int k = 0; k < 64; ++k) {
      const double th = 2 * M_PI * k / 64.0;
      // k % 8 == 0 and some directions hit N = a11 dFN - a12 dFT = 0 (the segment) exactly
      double dFT = std::cos(th), dFN = std::sin(th);
      if (k % 16 == 3) { dFT = a11; dFN = a12; }
      rate_lcp(a11, a12, a22, CT, mu, dFT, dFN, M, q);
      CAPTURE(a11, a12, a22, CT, mu, dFT, dFN);
      cpkit::lcp::enumerate_small<3>(M, q, a);
      prep.enumerate(q, b);
      require_same<3>(a, b);
      degenerate += t % 3 == 0;
      infinite += b.infinite;
    }
  }
  CHECK(degenerate > 0);
  CHECK(infinite > 0);  // every rate LCP has the ray (0, 1, 1): pieces are listed
}

TEST_CASE("SmallPreparedLcp: another tol falls back to enumerate_small; bad input throws",
          "[enumerate_small_prepared]") {
  Eigen::Matrix2d M;
  M << 1, -1, -1, 1;
  const SmallPreparedLcp<2> prep(M);
  Eigen::Vector2d q(-1, 1);
  SmallSolutionSet<2> a, b;
  cpkit::lcp::enumerate_small<2>(M, q, a, 1e-9);
  prep.enumerate(q, b, 1e-9);
  require_same<2>(a, b);
  REQUIRE(b.infinite);  // z = (1 + t, t), t >= 0: a ray
  Eigen::Matrix2d bad = M;
  bad(0, 1) = NAN;
  CHECK_THROWS_AS(SmallPreparedLcp<2>(bad), cpkit::InputError);
  CHECK_THROWS_AS(SmallPreparedLcp<2>(M, 0.0), cpkit::InputError);
  CHECK_THROWS_AS(prep.enumerate(Eigen::Vector2d(INFINITY, 0), b), cpkit::InputError);
  CHECK_THROWS_AS(prep.enumerate(q, b, 1.0), cpkit::InputError);
}
