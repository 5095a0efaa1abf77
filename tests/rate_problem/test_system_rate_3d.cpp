// The faceted rate problem of N coupled 3-D points against independent sources:
// - N = 1: the one-point routes (faceted for state b, exact for c and d: different code);
// - block-diagonal A: the product of the one-point sets;
// - isotropic points whose Y directions are decoupled and unloaded, with an even number of
//   facets (vertices at +-X, where the polygon holds the 2-D law exactly): the 2-D N-point
//   solver (rate::solve_rate_problem, the enumeration of the 2-D rate LCP);
// - the time limit (issue 24, item 11): eight grazing points used to run without bound; one
//   deadline for the whole solve ends it with complete = false (the stated answer).
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <tuple>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

using namespace cpkit::rate;
namespace r2 = cpkit::rate;

namespace {
constexpr double kPi = 3.14159265358979323846;

Eigen::MatrixXd random_spd(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd L(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) L(i, j) = u(rng);
  return L * L.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
}

SystemPoint3d random_point(std::mt19937& rng, char state) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  SystemPoint3d p;
  p.mu = 0.2 + 3 * pos(rng);
  p.C_T = pos(rng);
  p.k_a = pos(rng);
  p.alpha = {0.4 + pos(rng), 0.4 + pos(rng)};
  p.state.state = state;
  if (state == 'c' || state == 'd') {
    p.state.P_N = 0.2 + pos(rng);
    const double th = kPi * u(rng);
    p.state.P_T = (state == 'c' ? 0.5 : 1.0) * p.mu * p.state.P_N *
                  (p.alpha.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th)));
  }
  return p;
}

/// One-point solution set of point i alone (faceted in b, exact in c/d).
RateSolutionSet3d one_point(const ContactSystem3d& s, int i, const Eigen::Vector3d& dF, int k) {
  if (s.points[i].state.state == 'b') return solve_rate_3d_faceted(s.point_parameters(i), dF, k);
  return solve_rate_3d(s.point_parameters(i), s.points[i].state, dF);
}
}  // namespace

TEST_CASE("N-point 3-D, N = 1: the one-point routes", "[rate3d][system]") {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int c = 0; c < 300; ++c) {
    ContactSystem3d s;
    s.A = random_spd(rng, 3);
    s.points = {random_point(rng, "bcd"[c % 3])};
    const Eigen::Vector3d dF(u(rng), u(rng), u(rng));
    const int k = 6 + c % 10;
    const SystemRateSet3d got = solve_system_rate_3d_faceted(s, dF, k);
    const RateSolutionSet3d want = one_point(s, 0, dF, k);
    CAPTURE(c, s.points[0].state.state, got.message);
    REQUIRE(got.complete == want.complete);
    REQUIRE(got.count() == want.count());
    for (const auto& w : want.solutions) {
      bool found = false;
      for (const auto& g : got.solutions)
        found = found || (g.types[0] == w.type && std::abs(g.rates[0].dP_N - w.at.dP_N) < 1e-9 &&
                          (g.rates[0].dP_T - w.at.dP_T).cwiseAbs().maxCoeff() < 1e-9 &&
                          (g.rates[0].dw_Ti - w.at.dw_Ti).cwiseAbs().maxCoeff() < 1e-8);
      CHECK(found);
    }
  }
}

TEST_CASE("N-point 3-D, block-diagonal A: the product of the one-point sets", "[rate3d][system]") {
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(-1, 1);
  int several = 0;
  for (int c = 0; c < 200; ++c) {
    ContactSystem3d s;
    s.A = Eigen::MatrixXd::Zero(6, 6);
    s.A.topLeftCorner(3, 3) = random_spd(rng, 3);
    s.A.bottomRightCorner(3, 3) = random_spd(rng, 3);
    s.points = {random_point(rng, "bbd"[c % 3]), random_point(rng, "bdc"[c % 3])};
    Eigen::VectorXd dF(6);
    for (int i = 0; i < 6; ++i) dF(i) = u(rng);
    const int k = 8;
    const SystemRateSet3d got = solve_system_rate_3d_faceted(s, dF, k);
    const RateSolutionSet3d one = one_point(s, 0, dF.head<3>(), k), two = one_point(s, 1, dF.tail<3>(), k);
    CAPTURE(c, got.message);
    REQUIRE(got.complete);
    CHECK(got.count() == one.count() * two.count());
    several += got.count() > 1;
  }
  CHECK(several > 5);
}

TEST_CASE("N-point 3-D, decoupled Y and loads in the X-N planes: the 2-D N-point solver",
          "[rate3d][system]") {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  int compared = 0, several = 0;
  for (int c = 0; c < 300; ++c) {
    const int n = 2 + c % 2;
    const Eigen::MatrixXd A2 = random_spd(rng, 2 * n);
    r2::ContactSystem s2;
    s2.A = A2;
    ContactSystem3d s3;
    s3.A = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        s3.A(3 * i, 3 * j) = A2(2 * i, 2 * j);          // T-T
        s3.A(3 * i, 3 * j + 2) = A2(2 * i, 2 * j + 1);  // T-N
        s3.A(3 * i + 2, 3 * j) = A2(2 * i + 1, 2 * j);
        s3.A(3 * i + 2, 3 * j + 2) = A2(2 * i + 1, 2 * j + 1);
      }
    for (int i = 0; i < n; ++i) s3.A(3 * i + 1, 3 * i + 1) = 0.5 + pos(rng);  // Y: decoupled
    Eigen::VectorXd dF2(2 * n), dF3 = Eigen::VectorXd::Zero(3 * n);
    for (int i = 0; i < n; ++i) {
      const char st = "bbd"[(c + i) % 3];
      r2::SystemPoint q;
      q.mu = 0.3 + 3 * pos(rng);
      q.C_T = pos(rng);
      q.k_a = pos(rng);
      q.state.label = st == 'b' ? r2::StateLabel::kB : r2::StateLabel::kD;
      if (st == 'd') {
        q.state.P_N = 0.2 + pos(rng);
        q.state.sgn_PT = u(rng) < 0 ? -1 : 1;
        q.P_N = q.state.P_N;
        q.P_T = q.state.sgn_PT * q.mu * q.P_N;
      }
      s2.points.push_back(q);
      SystemPoint3d p;
      p.mu = q.mu;
      p.C_T = q.C_T;
      p.k_a = q.k_a;
      p.state.state = st;
      if (st == 'd') p.state.P_N = q.P_N, p.state.P_T = {q.P_T, 0};
      s3.points.push_back(p);
      dF2(2 * i) = dF3(3 * i) = u(rng);
      dF2(2 * i + 1) = dF3(3 * i + 2) = u(rng);
    }
    const r2::SystemRateSolutionSet want = r2::solve_rate_problem(s2, dF2);
    if (!want.complete || want.infinite) continue;  // degenerate: nothing to compare
    const SystemRateSet3d got = solve_system_rate_3d_faceted(s3, dF3, 8);
    CAPTURE(c, n, got.message);
    REQUIRE(got.complete);
    REQUIRE(got.count() == want.count());
    for (const auto& w : want.solutions) {
      bool found = false;
      for (const auto& g : got.solutions) {
        bool same = true;
        for (int i = 0; i < n; ++i)
          same = same && std::abs(g.rates[i].dP_N - w.start.dP_N(i)) < 1e-8 &&
                 std::abs(g.rates[i].dP_T(0) - w.start.dP_T(i)) < 1e-8 &&
                 std::abs(g.rates[i].dP_T(1)) < 1e-10;
        found = found || same;
      }
      CHECK(found);
    }
    ++compared;
    several += want.count() > 1;
  }
  CHECK(compared >= 280);
  CHECK(several >= 10);
}

TEST_CASE("N-point 3-D: bad input", "[rate3d][system]") {
  ContactSystem3d s;
  s.A = Eigen::MatrixXd::Identity(3, 3);
  s.points = {SystemPoint3d{}};
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, Eigen::VectorXd::Zero(2), 8), cpkit::InputError);
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, Eigen::VectorXd::Ones(3), 2), cpkit::InputError);
  s.points.assign(11, SystemPoint3d{});
  s.A = Eigen::MatrixXd::Identity(33, 33);
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, Eigen::VectorXd::Ones(33), 4), cpkit::InputError);
  s.points.assign(3, SystemPoint3d{});
  s.A = Eigen::MatrixXd::Identity(9, 9);
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, Eigen::VectorXd::Ones(9), 32), cpkit::InputError);  // 96 > 64
}

namespace {
/// Eight grazing points in a chain (issue 24, item 11): 2^8 separation cases, the first an LCP
/// of size 8 K; `cpkit rate --facets 4` on such a system never ended. A is diagonally dominant
/// (SPD by Gershgorin).
ContactSystem3d eight_grazing_points() {
  const int n = 8;
  ContactSystem3d s;
  s.name = "eight grazing points";
  s.A = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    s.A.block<3, 3>(3 * i, 3 * i) << 1.0, 0.0, 0.3, 0.0, 1.0, 0.2, 0.3, 0.2, 1.5;
    if (i + 1 < n)
      for (const auto& [r, c, v] : {std::tuple{0, 0, 0.1}, std::tuple{2, 2, 0.2},
                                    std::tuple{0, 2, 0.05}, std::tuple{2, 0, 0.05},
                                    std::tuple{1, 1, 0.1}})
        s.A(3 * i + r, 3 * (i + 1) + c) = s.A(3 * (i + 1) + c, 3 * i + r) = v;
    SystemPoint3d p;
    p.mu = 3;
    p.C_T = 0.25;
    p.state.state = 'b';
    s.points.push_back(p);
  }
  Eigen::VectorXd dF(3 * n);
  for (int i = 0; i < n; ++i) dF.segment<3>(3 * i) << 1.0, 0.5, i % 2 ? -0.2 : 0.3;
  s.dF = dF;
  return s;
}
}  // namespace

TEST_CASE("N-point 3-D: one time limit for the whole solve (issue 24, item 11)",
          "[rate3d][system]") {
  const ContactSystem3d s = eight_grazing_points();
  const auto t0 = std::chrono::steady_clock::now();
  const SystemRateSet3d got = solve_system_rate_3d_faceted(s, *s.dF, 4, 0.5);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(got.timed_out);
  CHECK_FALSE(got.complete);
  CHECK(got.message.find("time limit of 0.5 s reached") != std::string::npos);
  CHECK(seconds < 10);  // about 0.5 s; the bound allows a slow (sanitizer) build
  // a limit must be positive (NaN too is refused); an infinite one is no limit
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, *s.dF, 4, 0.0), cpkit::InputError);
  CHECK_THROWS_AS(solve_system_rate_3d_faceted(s, *s.dF, 4, std::nan("")), cpkit::InputError);
}
