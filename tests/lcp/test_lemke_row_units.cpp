// Lemke's method with the rows of the LCP in different units (issue 24): M -> D M, q -> D q for a
// positive diagonal D leaves the solution z unchanged. With the covering vector d = 1 a 40x40
// SPD problem with rows scaled by 10^-(i mod 17) ended in numerical_failure ("basis became
// singular"): row i's z0 rate was up to 1e16 times its own entries. The default covering vector
// now takes each row in its own units.
//
// Independent checks: the solution is verified from the data here (lcp_solution_check.hpp, a
// unit-free residual per row, not the library's), against the unscaled problem's z, and the
// SPD matrix makes the solution unique (so the two z must agree).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cpkit/lcp/lemke.hpp"
#include "lcp/lcp_solution_check.hpp"

using cpkit::Mat;
using cpkit::Status;
using cpkit::Vec;

TEST_CASE("Lemke: rows scaled by 10^-(i mod 17) solve to the unscaled z", "[lemke][units]") {
  const int n = 40;
  int failed_with_ones = 0;
  for (int seed = 0; seed < 8; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 rng(static_cast<unsigned long long>(seed));
    std::normal_distribution<double> N01(0.0, 1.0);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    Mat B(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) B(i, j) = N01(rng);
    const Mat M = B * B.transpose() / n + 0.1 * U(rng) * Mat::Identity(n, n);  // SPD
    Vec q(n);
    for (int i = 0; i < n; ++i) q(i) = N01(rng);
    Vec D(n);
    for (int i = 0; i < n; ++i) D(i) = std::pow(10.0, -(i % 17));
    const Mat Ms = D.asDiagonal() * M;
    const Vec qs = D.asDiagonal() * q;

    const cpkit::SolveResult plain = cpkit::lcp::solve_lemke(cpkit::LcpProblem(M, q));
    REQUIRE(plain.status == Status::kSolved);
    REQUIRE(lcp_test::is_solution_here(M, q, plain.z));
    const cpkit::SolveResult scaled = cpkit::lcp::solve_lemke(cpkit::LcpProblem(Ms, qs));
    CAPTURE(scaled.message);
    REQUIRE(scaled.status == Status::kSolved);
    // the scaled problem's solution, checked against its own data and the unscaled data
    CHECK(lcp_test::is_solution_here(Ms, qs, scaled.z));
    CHECK(lcp_test::is_solution_here(M, q, scaled.z));
    // unique solution (M SPD): the same z
    const double zmax = plain.z.cwiseAbs().maxCoeff();
    CHECK((scaled.z - plain.z).cwiseAbs().maxCoeff() <= 1e-9 * zmax);
    // the former default d = 1 on the scaled rows: the failure this test is about
    cpkit::lcp::LemkeOptions ones;
    ones.covering = Vec::Ones(n);
    const cpkit::SolveResult old = cpkit::lcp::solve_lemke(cpkit::LcpProblem(Ms, qs), ones);
    failed_with_ones += old.status != Status::kSolved;
  }
  INFO("d = 1 failed on " << failed_with_ones << " of 8");
  CHECK(failed_with_ones >= 1);
}
