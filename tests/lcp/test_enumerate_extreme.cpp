// Regression tests of issue 11 for the enumeration on hostile and extreme input: solutions that
// double precision cannot represent are never listed (they are counted in `unrepresentable` and
// leave complete = false), tiny entries next to huge ones are judged by the unit-free
// componentwise rule, every listed solution is finite and re-checked here from the data, and
// the time limit holds in every phase (hang guards with a generous bound, not timings).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/enumerate_small_prepared.hpp"
#include "lcp/enumeration_checks.hpp"

using cpkit::lcp::enumerate_all;
using cpkit::lcp::EnumerationOptions;
using cpkit::lcp::SolutionSet;

namespace {

using enumeration_checks::require_verified;
using enumeration_checks::to_found;

SolutionSet run(const cpkit::Mat& M, const cpkit::Vec& q, const EnumerationOptions& opt = {}) {
  const SolutionSet s = enumerate_all(cpkit::LcpProblem(M, q), opt);
  require_verified(s, M, q);
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Entries +-10^k, k uniform in [-300, 300] (seeded).
void extreme(int n, unsigned seed, cpkit::Mat& M, cpkit::Vec& q) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> k(-300, 300), sg(0, 1);
  M.resize(n, n);
  q.resize(n);
  for (int i = 0; i < n; ++i) {
    q(i) = (sg(rng) ? 1 : -1) * std::pow(10.0, k(rng));
    for (int j = 0; j < n; ++j) M(i, j) = (sg(rng) ? 1 : -1) * std::pow(10.0, k(rng));
  }
}

}  // namespace

TEST_CASE("enumerate_all: a solution beyond double's range is reported, never listed wrong",
          "[enumerate][extreme]") {
  // M = [[1e-320]], q = [-1]: the only solution is z = 1e320 (not representable); it used to be
  // listed as z = 0 with w = 0 (w is -1 there).
  cpkit::Mat M(1, 1);
  cpkit::Vec q(1);
  M << 1e-320;
  q << -1;
  SolutionSet s = run(M, q);
  CHECK(s.solutions.empty());
  CHECK(s.unrepresentable >= 1);
  CHECK_FALSE(s.complete);
  CHECK(s.message.find("not representable") != std::string::npos);
  // the same with [[1e-200]], q = [-1e200] (z = 1e400)
  M << 1e-200;
  q << -1e200;
  s = run(M, q);
  CHECK(s.solutions.empty());
  CHECK(s.unrepresentable >= 1);
  CHECK_FALSE(s.complete);
  // as a block of a larger problem (the general engine): z = (1e320, 1) not representable,
  // and no other solution exists (w_1 = z_1 - 1 with w_0 = 1e-320 z_0 - 1)
  cpkit::Mat M5 = cpkit::Mat::Identity(5, 5);
  M5(0, 0) = 1e-320;
  cpkit::Vec q5 = -cpkit::Vec::Ones(5);
  s = run(M5, q5);
  CHECK(s.solutions.empty());
  CHECK(s.unrepresentable >= 1);
  CHECK_FALSE(s.complete);
  // with q = [+1] the answer z = 0 is exact and complete
  M << 1e-320;
  q << 1;
  s = run(M, q);
  REQUIRE(s.solutions.size() == 1);
  CHECK(s.solutions[0].z(0) == 0);
  CHECK(s.solutions[0].w(0) == 1);
  CHECK(s.complete);
  CHECK(s.unrepresentable == 0);
}

TEST_CASE("enumerate_small: non-representable candidates are counted, not listed", "[enumerate_small][extreme]") {
  Eigen::Matrix<double, 1, 1> M, q;
  M << 1e-320;
  q << -1;
  cpkit::lcp::SmallSolutionSet<1> out;
  cpkit::lcp::enumerate_small<1>(M, q, out);
  CHECK(out.num_points == 0);
  CHECK(out.unrepresentable == 1);
  CHECK(out.dropped >= 1);  // callers that check `dropped` see an incomplete list
  const cpkit::lcp::SmallPreparedLcp<1> prep(M);
  prep.enumerate(q, out);
  CHECK(out.num_points == 0);
  CHECK(out.unrepresentable == 1);
}

TEST_CASE("enumerate_all: a tiny entry next to a huge one (diag(1e200, 1))", "[enumerate][extreme]") {
  // diag(1e200, 1), q = (1, -1): the only solution is z = (0, 1), w = (1, 0); w = (0, 0) used to
  // be listed (the basic solution of S = {0, 1}, z_0 = -1e-200, was rounded to z_0 = 0).
  for (double big : {1e11, 1e200}) {
    CAPTURE(big);
    cpkit::Mat M = cpkit::Mat::Zero(2, 2);
    M(0, 0) = big;
    M(1, 1) = 1;
    cpkit::Vec q(2);
    q << 1, -1;
    SolutionSet s = run(M, q);
    REQUIRE(s.solutions.size() == 1);
    CHECK(s.solutions[0].z == Eigen::Vector2d(0, 1));
    CHECK(s.solutions[0].w == Eigen::Vector2d(1, 0));
    CHECK(s.complete);
    CHECK(s.ambiguous == 0);
    // q = (-1, -1): z = (1 / big, 1), w = (0, 0); the tiny z_0 matters and is kept
    q << -1, -1;
    s = run(M, q);
    REQUIRE(s.solutions.size() == 1);
    CHECK(s.solutions[0].z(0) == Approx(1 / big).epsilon(1e-14));
    CHECK(s.solutions[0].z(1) == Approx(1).epsilon(1e-14));
    CHECK(s.solutions[0].w == Eigen::Vector2d(0, 0));
    CHECK(s.complete);
    // the same structure inside a 6 x 6 problem (general engine): identity elsewhere, q = 1
    cpkit::Mat M6 = cpkit::Mat::Identity(6, 6);
    M6(0, 0) = big;
    cpkit::Vec q6 = cpkit::Vec::Ones(6);
    q6(0) = 1;
    q6(1) = -1;
    s = run(M6, q6);
    REQUIRE(s.solutions.size() == 1);
    CHECK(s.solutions[0].z(0) == 0);
    CHECK(s.solutions[0].z(1) == 1);
    CHECK(s.solutions[0].w(0) == 1);
    CHECK(s.complete);
  }
}

TEST_CASE("enumerate_all: subnormal-filled 12 x 12 matrices list only finite, verified points",
          "[enumerate][extreme]") {
  // entries of order 1e-310 (subnormal): the same problem with M scaled by 2^1000 (exactly) has
  // the solutions z 2^-1000. With q of order 1e-310 too they are representable and the answers
  // agree; with q of order 1, z is of order 1e310: not representable, never listed, and the
  // enumeration says it is incomplete. Nothing non-finite is ever listed.
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  int total_beyond = 0;
  for (int rep = 0; rep < 6; ++rep) {
    const int n = 12;
    cpkit::Mat M(n, n);
    cpkit::Vec q(n);
    for (int i = 0; i < n; ++i) {
      q(i) = u(rng) * (rep % 2 ? 1.0 : 1e-310);
      for (int j = 0; j < n; ++j) M(i, j) = u(rng) * 1e-310;
    }
    CAPTURE(rep);
    const SolutionSet s = run(M, q);
    const cpkit::Mat Mb = std::ldexp(1.0, 1000) * M;
    const SolutionSet b = run(Mb, q);
    REQUIRE(b.complete);
    int beyond = 0;  // solutions of (M, q) beyond DBL_MAX
    for (const auto& e : b.solutions) beyond += !std::isfinite(std::ldexp(e.z.cwiseAbs().maxCoeff(), 1000));
    if (rep % 2 == 0) CHECK(beyond == 0);
    total_beyond += beyond;
    CHECK(s.complete == (beyond == 0));
    if (beyond > 0) CHECK(s.unrepresentable > 0);
    REQUIRE(s.solutions.size() == b.solutions.size() - beyond);
    size_t p = 0;
    for (const auto& e : b.solutions) {
      if (!std::isfinite(std::ldexp(e.z.cwiseAbs().maxCoeff(), 1000))) continue;
      for (int j = 0; j < n; ++j) CHECK(std::ldexp(e.z(j), 1000) == s.solutions[p].z(j));
      ++p;
    }
  }
  CHECK(total_beyond > 0);  // the family does exercise non-representable solutions
}

TEST_CASE("enumerate_all: extreme 16 x 16 entries (10^k, |k| <= 300) return promptly", "[enumerate][extreme][time]") {
  cpkit::Mat M;
  cpkit::Vec q;
  for (unsigned seed : {1u, 2u, 3u}) {
    extreme(16, seed, M, q);
    EnumerationOptions opt;
    opt.time_limit_s = 1;
    const auto t0 = std::chrono::steady_clock::now();
    const SolutionSet s = run(M, q, opt);  // every listed point verified from the data
    const double dt = seconds_since(t0);
    CAPTURE(seed, dt, s.message, s.unrepresentable, s.solutions.size());
    CHECK(dt < 10 * opt.time_limit_s);  // a hang guard, not a timing
    if (!s.complete) CHECK_FALSE(s.message.empty());
  }
}

TEST_CASE("enumerate_all: the time limit holds in every phase", "[enumerate][time]") {
  SECTION("singular pieces (M = 0, q = 0: every leaf is a high-dimensional piece)") {
    const int n = 16;
    EnumerationOptions opt;
    opt.time_limit_s = 0.3;
    opt.max_piece_dim = 8;
    const auto t0 = std::chrono::steady_clock::now();
    const SolutionSet s = run(cpkit::Mat::Zero(n, n), cpkit::Vec::Zero(n), opt);
    const double dt = seconds_since(t0);
    CAPTURE(dt, s.nodes);
    CHECK(dt < 10 * opt.time_limit_s);
    CHECK_FALSE(s.complete);
    CHECK(s.message.find("time limit") != std::string::npos);
  }
  SECTION("the search (a P-matrix that defeats pruning: M = I, q = 0, n = 24)") {
    // every index is degenerate (w_i = z_i = 0): nothing can be pruned for sure
    const int n = 24;
    EnumerationOptions opt;
    opt.time_limit_s = 0.3;
    const auto t0 = std::chrono::steady_clock::now();
    const SolutionSet s = run(cpkit::Mat::Identity(n, n), cpkit::Vec::Zero(n), opt);
    const double dt = seconds_since(t0);
    CAPTURE(dt, s.nodes, s.complete);
    CHECK(dt < 10 * opt.time_limit_s);
    if (!s.complete) CHECK(s.message.find("time limit") != std::string::npos);
    REQUIRE(s.solutions.size() >= 1);  // z = 0 is the solution
    CHECK(s.solutions[0].z.isZero(0));
  }
  SECTION("a finite default") {
    CHECK(EnumerationOptions{}.time_limit_s == 60);
  }
}
