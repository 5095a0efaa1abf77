// The N-point direction map against independent answers: N = 1 against the one-point direction
// map, dense sampling of the rate problem against the sectors, block-diagonal A against the
// product of one-point counts, bad input; the LCP size counted from the states before any
// other work (issue 24, item 12).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

#include "system_test_util.hpp"
#include "test_budget.hpp"

using namespace cpkit::rate;
using cpkit::test::family_size;

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

using cpkit::test::random_label;
using cpkit::test::random_point;
using cpkit::test::random_spd;

/// One-point RateSummary types bitmask of an N = 1 tuple list.
unsigned type_mask(const SystemRateSummary& s) {
  unsigned m = 0;
  for (int i = 0; i < s.n_tuples; ++i) m |= 1u << static_cast<unsigned>(s.tuples[static_cast<std::size_t>(i)]);
  return m;
}

/// The sector containing theta (reduced to the map's range), or nullptr on a boundary.
const SystemDirectionSector* sector_at(const SystemDirectionMap& map, double theta) {
  for (const auto& s : map.sectors)
    for (double t : {theta, theta + kTwoPi})
      if (t > s.theta_from && t < s.theta_to) return &s;
  return nullptr;
}

double angle_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), kTwoPi);
  return std::min(d, kTwoPi - d);
}

}  // namespace

TEST_CASE("system direction map: N = 1 equals the one-point direction map", "[rate][maps][system]") {
  std::mt19937 rng(7);
  int compared = 0, with_critical = 0;
  for (int trial = 0; trial < 400; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, random_label(rng))};
    S.A = random_spd(rng, 2);
    if (!S.validate().empty()) continue;
    const DirectionMap one = compute_direction_map(S.point_parameters(0), S.points[0].state);
    const SystemDirectionMap sys = compute_system_direction_map(S);
    CAPTURE(trial, S.A, to_string(S.points[0].state.label), S.points[0].mu, S.points[0].C_T,
            S.points[0].k_a);
    REQUIRE(sys.critical.size() == one.critical.size());
    REQUIRE(sys.sectors.size() == one.sectors.size());
    for (std::size_t i = 0; i < one.critical.size(); ++i) {
      CHECK(angle_distance(sys.critical[i].theta, one.critical[i].theta) < 1e-8);
      CHECK(sys.critical[i].summary.count == one.critical[i].summary.count);
      CHECK(type_mask(sys.critical[i].summary) == one.critical[i].summary.types);
    }
    for (std::size_t i = 0; i < one.sectors.size(); ++i) {
      CHECK(sys.sectors[i].summary.count == one.sectors[i].summary.count);
      CHECK(type_mask(sys.sectors[i].summary) == one.sectors[i].summary.types);
    }
    ++compared;
    with_critical += one.critical.empty() ? 0 : 1;
  }
  CHECK(compared > 300);
  CHECK(with_critical > 100);
}

TEST_CASE("system direction map: dense sampling agrees with the sectors", "[rate][maps][system]") {
  std::mt19937 rng(21);
  std::normal_distribution<double> G(0, 1);
  const int n = family_size(60, 32);
  int maps = 0, counts_seen_nonunique = 0;
  for (int trial = 0; trial < n; ++trial) {
    const int N = 2 + trial % 2;
    ContactSystem S;
    for (int i = 0; i < N; ++i) S.points.push_back(random_point(rng, random_label(rng)));
    S.A = random_spd(rng, 2 * N);
    Eigen::VectorXd e1(2 * N), e2(2 * N);
    for (int i = 0; i < 2 * N; ++i) { e1(i) = G(rng); e2(i) = G(rng); }
    S.pattern1 = e1;
    S.pattern2 = e2;
    if (!S.validate().empty()) continue;
    const SystemDirectionMap map = compute_system_direction_map(S);  // all cores
    const SystemRatePrecomputed pre = precompute_system_rate(S);
    CAPTURE(trial, S.A, e1, e2, map.critical.size());
    {  // one thread: the same map, bit for bit
      MapOptions one;
      one.threads = 1;
      const SystemDirectionMap m1 = compute_system_direction_map(S, one);
      REQUIRE(m1.sectors.size() == map.sectors.size());
      REQUIRE(m1.critical.size() == map.critical.size());
      for (std::size_t k = 0; k < m1.sectors.size(); ++k) {
        CHECK(m1.sectors[k].theta_from == map.sectors[k].theta_from);
        CHECK(same_solution_set(m1.sectors[k].summary, map.sectors[k].summary));
      }
      for (std::size_t k = 0; k < m1.critical.size(); ++k)
        CHECK(m1.critical[k].theta == map.critical[k].theta);
      CHECK(m1.evaluations == map.evaluations);
    }
    constexpr int kSamples = 1500;
    const SystemDirectionSector* prev = nullptr;
    SystemRateSummary prev_s;
    double prev_t = 0;
    for (int k = 0; k < kSamples; ++k) {
      const double t = (k + 0.37) * kTwoPi / kSamples;
      bool near_critical = false;
      for (const auto& c : map.critical) near_critical = near_critical || angle_distance(c.theta, t) < 1e-7;
      const SystemRateSummary s = summarize_rate_problem(pre, std::cos(t) * e1 + std::sin(t) * e2);
      if (!near_critical && s.reliable) {
        const SystemDirectionSector* sec = sector_at(map, t);
        REQUIRE(sec != nullptr);
        CAPTURE(t, sec->theta_from, sec->theta_to);
        CHECK(same_solution_set(s, sec->summary));
        if (s.count > 1 || s.count < 0) ++counts_seen_nonunique;
        (void)prev;
        prev = sec;
      }
      if (k > 0 && !same_solution_set(s, prev_s)) {  // a change brackets a critical direction
        bool bracketed = false;
        for (const auto& c : map.critical)
          for (double ct : {c.theta, c.theta + kTwoPi})
            bracketed = bracketed || (ct >= prev_t - 1e-9 && ct <= t + 1e-9);
        CHECK(bracketed);
      }
      prev_s = s;
      prev_t = t;
    }
    ++maps;
  }
  CHECK(maps > 2 * n / 3);
  CHECK(counts_seen_nonunique > 0);
}

TEST_CASE("system direction map: block-diagonal A multiplies the one-point counts", "[rate][maps][system]") {
  std::mt19937 rng(5);
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, random_label(rng)), random_point(rng, random_label(rng))};
    S.A = Eigen::MatrixXd::Zero(4, 4);
    S.A.block(0, 0, 2, 2) = random_spd(rng, 2);
    S.A.block(2, 2, 2, 2) = random_spd(rng, 2);
    if (!S.validate().empty()) continue;
    const SystemDirectionMap map = compute_system_direction_map(S);  // default patterns
    for (const auto& sec : map.sectors) {
      const double t = 0.5 * (sec.theta_from + sec.theta_to);
      const LoadRate l{std::cos(t), std::sin(t)};
      const int c0 = summarize_rate_problem(S.point_parameters(0), S.points[0].state, l).count;
      const int c1 = summarize_rate_problem(S.point_parameters(1), S.points[1].state, l).count;
      const int expected = (c0 == 0 || c1 == 0) ? 0 : ((c0 < 0 || c1 < 0) ? -1 : c0 * c1);
      CAPTURE(trial, t, c0, c1);
      CHECK(sec.summary.count == expected);
      ++checked;
    }
    // a one-point critical direction is critical for the pair unless the other point has no
    // solution around it (then the pair has none on either side)
    for (int i = 0; i < 2; ++i) {
      const DirectionMap one = compute_direction_map(S.point_parameters(i), S.points[static_cast<std::size_t>(i)].state);
      const int o = 1 - i;
      for (const auto& c : one.critical) {
        bool other_solvable = true;
        for (double d : {-1e-6, 0.0, 1e-6}) {
          const LoadRate l{std::cos(c.theta + d), std::sin(c.theta + d)};
          other_solvable = other_solvable &&
              summarize_rate_problem(S.point_parameters(o), S.points[static_cast<std::size_t>(o)].state, l).count != 0;
        }
        if (!other_solvable) continue;
        bool found = false;
        for (const auto& d : map.critical) found = found || angle_distance(c.theta, d.theta) < 1e-8;
        CHECK(found);
      }
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("system direction map: bad input", "[rate][maps][system]") {
  ContactSystem S;
  SystemPoint p;
  p.state.label = StateLabel::kB;
  S.points = {p, p};
  S.A = Eigen::MatrixXd::Identity(4, 4);
  Eigen::VectorXd e(4);
  e << 1, 0, 1, 0;
  S.pattern1 = e;
  S.pattern2 = 2 * e;
  CHECK_THROWS_WITH(compute_system_direction_map(S), Catch::Contains("parallel"));
  S.pattern2 = Eigen::VectorXd::Zero(4);
  CHECK_THROWS_AS(compute_system_direction_map(S), cpkit::InputError);
  S.pattern1.reset();
  S.pattern2.reset();
  MapOptions o;
  o.method = RateMethod::kAnalytic;
  CHECK_THROWS_WITH(compute_system_direction_map(S, o), Catch::Contains("enumeration"));
  S.A(0, 1) = 5;  // not symmetric
  CHECK_THROWS_AS(compute_system_direction_map(S), cpkit::InputError);
  // six points in state b: LCP of size 18 > kMaxSystemMapLcp
  ContactSystem big;
  big.points.assign(6, p);
  big.A = Eigen::MatrixXd::Identity(12, 12);
  CHECK_THROWS_WITH(compute_system_direction_map(big), Catch::Contains("at most"));
}

TEST_CASE("system maps: the LCP size is counted from the states, before any other work "
          "(issue 24, item 12)", "[rate][maps][system]") {
  // 3 per point in state b, 1 per point in state d, 0 in a and c (counted by hand).
  ContactSystem S;
  for (StateLabel l : {StateLabel::kA, StateLabel::kB, StateLabel::kC, StateLabel::kD,
                       StateLabel::kB, StateLabel::kD}) {
    SystemPoint p;
    p.state.label = l;
    S.points.push_back(p);
  }
  CHECK(system_map_lcp_size(S) == 3 + 1 + 3 + 1);
  CHECK_NOTHROW(check_system_map_lcp_size(S, "a map"));
  // 1000 points in state b: refused by the count alone. A is left empty (not 2000 x 2000): the
  // refusal must come before validate() (an O(N^3) Cholesky) and the precomputation, which
  // would also refuse this system for its size, so their message would show up instead.
  ContactSystem big;
  SystemPoint b;
  b.state.label = StateLabel::kB;
  big.points.assign(1000, b);
  CHECK(system_map_lcp_size(big) == 3000);
  CHECK_THROWS_WITH(check_system_map_lcp_size(big, "a map"), Catch::Contains("has size 3000"));
  CHECK_THROWS_WITH(compute_system_direction_map(big), Catch::Contains("has size 3000"));
  SystemMapAxis axis;
  axis.param = parse_system_map_parameter("mu", 1000);
  axis.from = 1;
  axis.to = 2;
  axis.n = 2;
  CHECK_THROWS_WITH(compute_system_param_direction_map(big, axis, 4),
                    Catch::Contains("has size 3000"));
  CHECK_THROWS_WITH(estimate_system_param_direction_map(big, axis, 4, MapOptions{}),
                    Catch::Contains("has size 3000"));
}

TEST_CASE("system rate problem on critical directions: degenerate LCPs keep their solutions",
          "[rate][maps][system]") {
  // On a direction where a point's stick-trial slip rate vanishes, q has exact zeros in the
  // rows of its (l+, l-) pair, whose columns are exact negatives of each other: a degenerate LCP
  // (found by a parameter x parameter map: the tree search pruned on rounding noise 1e-17 and
  // reported "no solution", complete, where a solution exists). Independent check: a
  // floating-point brute force over all complementary bases; whenever it finds a solution the
  // enumeration must report at least one.
  std::mt19937 rng(808);
  int checked = 0, with_solution = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int N = 2;
    ContactSystem S;
    for (int i = 0; i < N; ++i)
      S.points.push_back(random_point(rng, trial % 3 == 2 ? random_label(rng) : StateLabel::kB));
    S.A = random_spd(rng, 2 * N);
    if (!S.validate().empty()) continue;
    const SystemRatePrecomputed pre = precompute_system_rate(S);
    if (pre.m == 0) continue;
    Eigen::MatrixXd E(2 * N, 2);
    E.setZero();
    for (int i = 0; i < N; ++i) {
      E(2 * i, 0) = 1;
      E(2 * i + 1, 1) = 1;
    }
    const Eigen::MatrixXd QE = pre.Q * E;
    for (int r = 0; r < pre.m; ++r) {
      const double t0 = std::atan2(-QE(r, 0), QE(r, 1));  // q_r(theta) = 0
      for (double th : {t0, t0 + M_PI}) {
        const Eigen::VectorXd dF = E.col(0) * std::cos(th) + E.col(1) * std::sin(th);
        // q as the rate problem forms it: entries that are rounding noise of their terms are 0
        Eigen::VectorXd q = pre.Q * dF;
        const Eigen::VectorXd terms = pre.G.cwiseAbs() * (pre.Pf.cwiseAbs() * dF.cwiseAbs());
        for (int k = 0; k < pre.m; ++k)
          if (std::abs(q(k)) <= 1e-10 * terms(k)) q(k) = 0;
        bool exists = false;
        for (unsigned B = 0; B < (1u << pre.m) && !exists; ++B) {
          Eigen::MatrixXd Bm(pre.m, pre.m);
          for (int i = 0; i < pre.m; ++i)
            Bm.col(i) = ((B >> i) & 1u) ? Eigen::VectorXd(-pre.M.col(i))
                                        : Eigen::VectorXd(Eigen::VectorXd::Unit(pre.m, i));
          Eigen::FullPivLU<Eigen::MatrixXd> lu(Bm);
          if (!lu.isInvertible()) continue;
          const Eigen::VectorXd x = lu.solve(q);
          exists = x.minCoeff() >= -1e-9 * (1 + x.cwiseAbs().maxCoeff());
        }
        const SystemRateSummary s = summarize_rate_problem(pre, dF);
        INFO("trial " << trial << " row " << r << " theta " << th);
        if (exists) REQUIRE(s.count != 0);
        ++checked;
        with_solution += exists;
      }
    }
  }
  CHECK(checked > 500);
  CHECK(with_solution > 100);
}
