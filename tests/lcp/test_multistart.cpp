// Multistart search for additional NCP solutions: closed-form solution sets, never "complete".
#include <catch2/catch.hpp>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/multistart.hpp"

using cpkit::Mat;
using cpkit::Vec;
using namespace cpkit::lcp;

namespace {

/// NCP with exactly two solutions, (1, 0) and (3, 0):
///   F1 = -(x1 - 1)(x1 - 3),  F2 = x1 + x2.
/// x1 = 0 is impossible (F1(0) = -3 < 0), so x1 > 0 and F1 = 0: x1 in {1, 3}; then F2 > 0
/// forces x2 = 0.
cpkit::McpProblem two_solution_ncp() {
  return cpkit::make_ncp(
      2,
      [](const Vec& x, Vec& F) {
        F.resize(2);
        F << -(x(0) - 1) * (x(0) - 3), x(0) + x(1);
        return true;
      },
      [](const Vec& x, Mat& J) {
        J.resize(2, 2);
        J << -(2 * x(0) - 4), 0, 1, 1;
        return true;
      },
      "two_solutions");
}

/// mathiesen_modified (shared/problems/ncp.md): solutions {(t, 0, 0, 0) : 0 <= t <= 3}.
cpkit::McpProblem mathiesen_modified() {
  return cpkit::make_ncp(
      4,
      [](const Vec& x, Vec& F) {
        if (x(1) <= -1 || x(2) <= -1) return false;
        F.resize(4);
        F << -x(1) + x(2) + x(3), x(0) - (4.5 * x(2) + 2.7 * x(3)) / (x(1) + 1),
            5 - x(0) - (0.5 * x(2) + 0.3 * x(3)) / (x(2) + 1), 3 - x(0);
        return true;
      },
      [](const Vec& x, Mat& J) {
        if (x(1) <= -1 || x(2) <= -1) return false;
        const double a = x(1) + 1, b = x(2) + 1;
        J.setZero(4, 4);
        J.row(0) << 0, -1, 1, 1;
        J.row(1) << 1, (4.5 * x(2) + 2.7 * x(3)) / (a * a), -4.5 / a, -2.7 / a;
        J.row(2) << -1, 0, -(0.5 * b - (0.5 * x(2) + 0.3 * x(3))) / (b * b), -0.3 / b;
        J.row(3) << -1, 0, 0, 0;
        return true;
      },
      "mathiesen_modified");
}

bool contains(const MultistartResult& r, const Vec& x, double tol) {
  for (const auto& s : r.solutions)
    if ((s.x - x).lpNorm<Eigen::Infinity>() <= tol) return true;
  return false;
}

}  // namespace

TEST_CASE("multistart finds both solutions of a two-solution NCP", "[multistart]") {
  MultistartOptions o;
  o.starts = 10;
  o.seed = 7;
  const auto r = multistart_ncp(two_solution_ncp(), o);
  INFO(r.message);
  CHECK(r.solutions.size() == 2);
  CHECK(contains(r, Vec::Unit(2, 0), 1e-8));
  CHECK(contains(r, Vec::Unit(2, 0) * 3, 1e-8));
  CHECK(r.message.find("cannot prove") != std::string::npos);
}

TEST_CASE("multistart reaches both ends of mathiesen_modified's solution segment",
          "[multistart]") {
  MultistartOptions o;
  o.starts = 12;
  o.seed = 3;
  o.sample_lower = Vec::Constant(4, -2.0);  // references beyond both ends of the segment
  o.sample_upper = Vec::Constant(4, 5.0);
  const auto r = multistart_ncp(mathiesen_modified(), o);
  INFO(r.message);
  REQUIRE(!r.solutions.empty());
  // Every solution found lies on the segment {(t, 0, 0, 0) : 0 <= t <= 3} (closed form).
  for (const auto& s : r.solutions) {
    CAPTURE(s.x.transpose(), s.solver);
    CHECK(s.x.tail(3).lpNorm<Eigen::Infinity>() <= 1e-7);
    CHECK(s.x(0) >= -1e-9);
    CHECK(s.x(0) <= 3 + 1e-9);
  }
  CHECK(contains(r, Vec::Zero(4), 1e-6));
  CHECK(contains(r, Vec::Unit(4, 0) * 3, 1e-6));
}

TEST_CASE("multistart is deterministic for a seed and validates its options",
          "[multistart][input]") {
  MultistartOptions o;
  o.starts = 4;
  o.selection = false;
  const auto a = multistart_ncp(two_solution_ncp(), o);
  const auto b = multistart_ncp(two_solution_ncp(), o);
  REQUIRE(a.solutions.size() == b.solutions.size());
  for (std::size_t i = 0; i < a.solutions.size(); ++i) CHECK(a.solutions[i].x == b.solutions[i].x);
  o.starts = 0;
  CHECK_THROWS_AS(multistart_ncp(two_solution_ncp(), o), cpkit::InputError);
  o.starts = 3;
  o.sample_lower = Vec::Zero(3);
  o.sample_upper = Vec::Ones(3);
  CHECK_THROWS_AS(multistart_ncp(two_solution_ncp(), o), cpkit::InputError);
}
