// The faceted state-b rate problem of a 3-D point (an LCP of size k + 2) against independent
// sources: the 2-D closed forms where the polygon holds the 2-D law exactly (isotropic, Y
// decoupled and unloaded, vertices at +-X), and the exact elliptic solution set
// (solve_rate_3d, a different algorithm), which the faceted counts approach as k grows.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>
#include <cmath>
#include <random>

#include "rate3d_test_util.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"

using namespace cpkit::rate;
namespace r2 = cpkit::rate;

using cpkit::test::coupled_spd;

namespace {
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("faceted 3-D, isotropic with Y decoupled and unloaded: the 2-D closed forms",
          "[rate3d][faceted]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  int non_unique = 0;
  for (int c = 0; c < 3000; ++c) {
    r2::ContactParameters p2;
    p2.a11 = 0.2 + 2 * pos(rng);
    p2.a22 = 0.2 + 2 * pos(rng);
    p2.a12 = 0.95 * u(rng) * std::sqrt(p2.a11 * p2.a22);
    p2.mu = 0.1 + 4 * pos(rng);
    p2.C_T = c % 3 == 0 ? 0 : pos(rng);
    const double th = kPi * u(rng);
    const r2::RateSolutionSet ref = r2::solve_rate_analytic(p2, {}, {std::cos(th), std::sin(th)});
    ContactParameters3d p3;
    p3.A << p2.a11, 0, p2.a12, 0, 0.3 + pos(rng), 0, p2.a12, 0, p2.a22;
    p3.mu = p2.mu;
    p3.C_T = p2.C_T;
    const int k = 4 + 2 * (c % 6);  // even: vertices at +-X
    const RateSolutionSet3d got = solve_rate_3d_faceted(p3, {std::cos(th), 0, std::sin(th)}, k);
    CAPTURE(c, k, p2.a11, p2.a12, p2.a22, p2.mu, p2.C_T, th, got.message);
    CHECK(got.complete);
    REQUIRE(got.count() == static_cast<int>(ref.solutions.size()));
    for (const auto& s : ref.solutions) {
      bool found = false;
      for (const auto& g : got.solutions)
        found = found || (std::abs(g.at.dP_N - s.start.dP_N) <= 1e-8 &&
                          std::abs(g.at.dP_T(0) - s.start.dP_T) <= 1e-8 &&
                          std::abs(g.at.dP_T(1)) <= 1e-8 &&
                          std::abs(g.at.dw_Ti(0) - s.start.dw_Ti) <= 1e-8 * (1 + 1 / p2.a11));
      CHECK(found);
    }
    non_unique += ref.solutions.size() > 1;
  }
  INFO(non_unique << " non-unique cases");
  CHECK(non_unique >= 5);
}

TEST_CASE("faceted 3-D: the counts approach the exact elliptic counts as k grows",
          "[rate3d][faceted]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  const std::vector<int> ks = {6, 12, 24, 64};
  std::vector<int> agree(ks.size(), 0);
  std::vector<double> max_angle_error(ks.size(), 0);
  int cases = 0, non_unique = 0;
  for (int c = 0; c < 400; ++c) {
    ContactParameters3d p;
    p.A = coupled_spd(rng, c % 2 ? 1.0 : 0.3, false);
    p.mu = 0.2 + 4 * pos(rng);
    p.C_T = c % 3 == 0 ? 0 : pos(rng);
    p.alpha = {0.4 + pos(rng), 0.4 + pos(rng)};
    const Eigen::Vector3d dF(u(rng), u(rng), u(rng));
    const RateSolutionSet3d exact = solve_rate_3d(p, {}, dF);
    if (!exact.complete) continue;  // a critical direction: no count to approach
    ++cases;
    non_unique += exact.count() > 1;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      const RateSolutionSet3d f = solve_rate_3d_faceted(p, dF, ks[i]);
      CAPTURE(c, ks[i], f.message);
      CHECK(f.complete);
      agree[i] += f.count() == exact.count();
      // the faceted slip directions approach the exact ones
      for (const auto& e : exact.solutions) {
        if (e.type != SolutionType::kSlip) continue;
        double best = 10;
        for (const auto& g : f.solutions)
          if (g.type == SolutionType::kSlip)
            best = std::min(best, std::abs(std::remainder(g.slip_angle - e.slip_angle, 2 * kPi)));
        max_angle_error[i] = std::max(max_angle_error[i], best);
      }
    }
  }
  INFO("agreement by k: " << agree[0] << " " << agree[1] << " " << agree[2] << " " << agree[3]
                          << " of " << cases);
  CHECK(cases >= 390);
  CHECK(non_unique >= 10);
  CHECK(agree[3] >= cases - 4);    // k = 64: all but critical-direction neighbours
  CHECK(agree[3] >= agree[0]);
  INFO("largest slip-angle error by k: " << max_angle_error[0] << " " << max_angle_error[1] << " "
                                          << max_angle_error[2] << " " << max_angle_error[3]);
  for (std::size_t i = 0; i < ks.size(); ++i) CHECK(max_angle_error[i] <= 2 * kPi / ks[i]);
  CHECK(max_angle_error[3] < max_angle_error[0]);
}

TEST_CASE("faceted 3-D: bad input", "[rate3d][faceted]") {
  ContactParameters3d p;
  CHECK_THROWS_AS(solve_rate_3d_faceted(p, {1, 0, 0}, 2), cpkit::InputError);
  CHECK_THROWS_AS(solve_rate_3d_faceted(p, {1, 0, 0}, kMaxFacets + 1), cpkit::InputError);
  CHECK_THROWS_AS(solve_rate_3d_faceted(p, {1, std::nan(""), 0}, 8), cpkit::InputError);
  p.mu = -1;
  CHECK_THROWS_AS(solve_rate_3d_faceted(p, {1, 0, 0}, 8), cpkit::InputError);
}
