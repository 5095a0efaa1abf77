// The N-point grid maps against independent answers: N = 1 against the one-point grid maps
// (closed-form route), uncoupled points (coupling 0) against the product of one-point maps,
// param-param cells against dense sampling of directions, streaming and thread-count
// independence, bad input.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

#include "system_test_util.hpp"

using namespace cpkit::rate;
using cpkit::test::random_label;
using cpkit::test::random_point;
using cpkit::test::random_spd;

namespace {

/// The one-point map of point i of an uncoupled system, on the same axis and directions (with
/// the default patterns, point i sees dF_i = (cos theta, sin theta)).
ParamDirectionMap one_point_map(const ContactSystem& S, int i, MapParameterRef p, double from,
                                double to, int n, int theta_n) {
  const SystemPoint& pt = S.points[static_cast<std::size_t>(i)];
  MapAxis axis;
  axis.param = p;
  axis.from = from;
  axis.to = to;
  axis.n = n;
  MapOptions o;
  o.threads = 1;
  o.method = RateMethod::kAnalytic;  // closed forms, cross-checked against the enumeration
  ContactParameters par = S.point_parameters(i);
  return compute_param_direction_map(par, pt.state, axis, theta_n, o);
}

SystemMapAxis sys_axis(const std::string& name, int n_points, double from, double to, int n) {
  SystemMapAxis a;
  a.param = parse_system_map_parameter(name, n_points);
  a.from = from;
  a.to = to;
  a.n = n;
  return a;
}

MapOptions threads(int t) {
  MapOptions o;
  o.threads = t;
  return o;
}

/// Type set of one point in an N = 1 pattern, as the one-point bitmask.
unsigned mask_of(const std::vector<TypeTuple>& tuples) {
  unsigned m = 0;
  for (TypeTuple t : tuples) m |= 1u << t;
  return m;
}

}  // namespace

TEST_CASE("N = 1: the system map equals the one-point map cell by cell", "[map][system]") {
  std::mt19937 rng(31);
  int multi = 0;
  for (int trial = 0; trial < 12; ++trial) {
    ContactSystem S;
    S.points.push_back(random_point(rng, trial % 2 ? StateLabel::kB : StateLabel::kD));
    S.A = random_spd(rng, 2);
    const double from = 0.2, to = 4;
    const ParamDirectionMap one = one_point_map(S, 0, map_parameter("mu"), from, to, 15, 90);
    REQUIRE(one.disagreements == 0);
    const SystemParamDirectionMap m = compute_system_param_direction_map(S, sys_axis("mu", 1, from, to, 15), 90, threads(1));
    REQUIRE(m.unreliable == 0);
    REQUIRE(m.count.size() == one.count.size());
    for (std::size_t k = 0; k < m.count.size(); ++k) {
      INFO("trial " << trial << " cell " << k);
      REQUIRE(m.count[k] == one.count[k]);
      REQUIRE(mask_of(m.table.patterns[m.pattern[k]]) == one.types[k]);
      multi += one.count[k] > 1 || one.count[k] < 0;
    }
  }
  CHECK(multi > 0);  // the comparison met non-unique cells
}

TEST_CASE("coupling 0: counts and patterns are products of one-point maps", "[map][system]") {
  std::mt19937 rng(5);
  int multi = 0;
  for (int trial = 0; trial < 8; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, trial % 2 ? StateLabel::kB : random_label(rng)),
                random_point(rng, StateLabel::kB)};
    S.A = random_spd(rng, 4);  // coupled; the map's coupling axis removes the coupling at 0
    const SystemParamDirectionMap m = compute_system_param_direction_map(S, sys_axis("coupling", 2, 0, 0, 1), 120, threads(2));
    REQUIRE(m.unreliable == 0);
    // Point i alone: its own 2x2 block; a one-point map along a12 fixed at its value.
    std::vector<ParamDirectionMap> one;
    for (int i = 0; i < 2; ++i) {
      const double a12 = S.A(2 * i, 2 * i + 1);
      one.push_back(one_point_map(S, i, map_parameter("a12"), a12, a12, 1, 120));
    }
    for (int j = 0; j < 120; ++j) {
      const int c1 = one[0].count[j], c2 = one[1].count[j];
      const int expect = (c1 == 0 || c2 == 0) ? 0 : (c1 < 0 || c2 < 0) ? -1 : c1 * c2;
      INFO("trial " << trial << " direction " << j);
      REQUIRE(m.count[j] == expect);
      // tuples: every pair of one-point types present (point 1 is the lowest base-5 digit)
      std::set<TypeTuple> pairs;
      for (unsigned t1 = 0; t1 < 5; ++t1)
        for (unsigned t2 = 0; t2 < 5; ++t2)
          if ((one[0].types[j] >> t1 & 1u) && (one[1].types[j] >> t2 & 1u)) pairs.insert(t1 + 5 * t2);
      const auto& got = m.table.patterns[m.pattern[j]];
      if (expect != 0) REQUIRE(std::set<TypeTuple>(got.begin(), got.end()) == pairs);
      multi += expect > 1 || expect < 0;
    }
  }
  CHECK(multi > 0);
}

TEST_CASE("the system map does not depend on the thread count", "[map][system]") {
  std::mt19937 rng(9);
  ContactSystem S;
  S.points = {random_point(rng, StateLabel::kB), random_point(rng, StateLabel::kD)};
  S.A = random_spd(rng, 4);
  const auto p = parse_system_map_parameter("mu@2", 2);
  const auto a = compute_system_param_direction_map(S, sys_axis("mu@2", 2, 0.3, 3, 40), 200, threads(1));
  const auto b = compute_system_param_direction_map(S, sys_axis("mu@2", 2, 0.3, 3, 40), 200, threads(2));
  CHECK(a.count == b.count);
  CHECK(a.pattern == b.pattern);
  CHECK(a.table.patterns == b.table.patterns);
  CHECK(a.table.cells == b.table.cells);
  // the per-point parameter changed only point 2: mu of point 1 is the file's in every row
  const ContactSystem row = apply_system_map_parameter(S, p, 2.5);
  CHECK(row.points[0].mu == S.points[0].mu);
  CHECK(row.points[1].mu == 2.5);
  CHECK(row.points[1].P_T == row.points[1].state.sgn_PT * 2.5 * row.points[1].P_N);
}

TEST_CASE("system map parameters: bad input is an error naming it", "[map][system]") {
  std::mt19937 rng(2);
  ContactSystem S;
  S.points = {random_point(rng, StateLabel::kB), random_point(rng, StateLabel::kB)};
  S.A = Eigen::MatrixXd::Identity(4, 4);
  S.A(0, 2) = S.A(2, 0) = 0.9;
  S.A(1, 3) = S.A(3, 1) = 0.9;
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(parse_system_map_parameter("mu@0", 2), Contains("1..2"));
  CHECK_THROWS_WITH(parse_system_map_parameter("mu@3", 2), Contains("1..2"));
  CHECK_THROWS_WITH(parse_system_map_parameter("mu@x", 2), Contains("1..2"));
  CHECK_THROWS_WITH(parse_system_map_parameter("a11", 2), Contains("coupling"));
  CHECK_THROWS_WITH(parse_system_map_parameter("coupling@1", 2), Contains("whole system"));
  // A(c) has off-diagonal 0.9 c: positive definite only for c < 1/0.9; rows c = 0, 0.5, .., 2
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, sys_axis("coupling", 2, 0, 2, 5), 10, threads(1)),
                    Contains("coupling = 1.5"));  // 0.9 c < 1 fails first at c = 1.5
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, sys_axis("mu", 2, -1, 1, 5), 10, threads(1)),
                    Contains("mu = -1"));
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, sys_axis("P_N", 2, 1, 2, 5), 10, threads(1)),
                    Contains("no point"));
  CHECK_THROWS_AS(compute_system_param_direction_map(S, sys_axis("mu", 2, 1, 2, 5), 0, threads(1)),
                  cpkit::InputError);
}

TEST_CASE("N = 1: the system param-param map equals the one-point param-param map",
          "[map][system]") {
  // The one-point map classifies each cell from its closed-form direction map (cross-checked
  // against enumeration); the system map from the N-point exact direction map.
  std::mt19937 rng(77);
  std::set<int> classes;
  for (int trial = 0; trial < 6; ++trial) {
    ContactSystem S;
    S.points.push_back(random_point(rng, trial % 3 ? StateLabel::kB : StateLabel::kD));
    S.A = random_spd(rng, 2);
    MapAxis a1, a2;
    a1.param = map_parameter("mu");
    a1.from = 0.1;
    a1.to = 4;
    a1.n = 9;
    a2.param = map_parameter("C_T");
    a2.from = 0;
    a2.to = 2;
    a2.n = 5;
    MapOptions o;
    o.threads = 1;
    o.method = RateMethod::kAnalytic;
    const ParamParamMap one =
        compute_param_param_map(S.point_parameters(0), S.points[0].state, a1, a2, o);
    REQUIRE(one.disagreements == 0);
    const SystemParamParamMap m = compute_system_param_param_map(
        S, sys_axis("mu", 1, 0.1, 4, 9), sys_axis("C_T", 1, 0, 2, 5), threads(2));
    REQUIRE(m.unreliable == 0);
    REQUIRE(m.inconsistent_sectors == 0);
    REQUIRE(m.cls.size() == one.cls.size());
    for (std::size_t k = 0; k < m.cls.size(); ++k) {
      INFO("trial " << trial << " cell " << k);
      REQUIRE(m.cls[k] == one.cls[k]);
      REQUIRE(m.min_count[k] == one.min_count[k]);
      REQUIRE(m.max_count[k] == one.max_count[k]);
      REQUIRE(mask_of(m.table.patterns[m.pattern[k]]) == one.types[k]);
      classes.insert(m.cls[k]);
    }
  }
  CHECK(classes.size() >= 2);  // the comparison met more than one class
}

TEST_CASE("param-param cells of 2-point systems contain what dense sampling of directions sees",
          "[map][system]") {
  // Every sampled direction's count and tuples must be within the cell's [min, max] and its
  // union pattern; a sampled direction without solution needs a class that says so.
  std::mt19937 rng(123);
  int non_unique = 0;
  for (int trial = 0; trial < 4; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, StateLabel::kB), random_point(rng, random_label(rng))};
    S.A = random_spd(rng, 4);
    const SystemMapAxis a1 = sys_axis("mu", 2, 0.2, 3, 4), a2 = sys_axis("coupling", 2, 0, 1, 3);
    const SystemParamParamMap m = compute_system_param_param_map(S, a1, a2, threads(2));
    REQUIRE(m.unreliable == 0);
    Eigen::VectorXd e1, e2;
    system_map_patterns(S, e1, e2);
    for (int i = 0; i < a1.n; ++i)
      for (int j = 0; j < a2.n; ++j) {
        const ContactSystem cell = apply_system_map_parameter(
            apply_system_map_parameter(S, a1.param, a1.value(i)), a2.param, a2.value(j));
        const SystemRatePrecomputed pre = precompute_system_rate(cell);
        const std::size_t k = static_cast<std::size_t>(i * a2.n + j);
        const auto& pattern = m.table.patterns[m.pattern[k]];
        const auto rank = [](int c) { return c < 0 ? 1000 : c; };
        for (int t = 0; t < 720; ++t) {
          const double th = (t + 0.37) * 2 * M_PI / 720;
          const SystemRateSummary s = summarize_rate_problem(pre, std::cos(th) * e1 + std::sin(th) * e2);
          INFO("trial " << trial << " cell " << i << "," << j << " theta " << th);
          REQUIRE(rank(s.count) >= rank(m.min_count[k]));
          REQUIRE(rank(s.count) <= rank(m.max_count[k]));
          for (int q = 0; q < s.n_tuples; ++q)
            REQUIRE(std::find(pattern.begin(), pattern.end(), s.tuples[q]) != pattern.end());
          if (s.count == 0)
            REQUIRE((m.cls[k] == 2 || m.cls[k] == 3));
        }
        non_unique += m.cls[k] == 1 || m.cls[k] == 3;
      }
  }
  CHECK(non_unique > 0);
}

TEST_CASE("system grid maps: streamed blocks equal the map kept in memory, for any thread count",
          "[map][system]") {
  std::mt19937 rng(4);
  ContactSystem S;
  S.points = {random_point(rng, StateLabel::kB), random_point(rng, StateLabel::kD)};
  S.A = random_spd(rng, 4);
  const SystemMapAxis ax = sys_axis("mu", 2, 0.3, 3, 30);
  const auto kept = compute_system_param_direction_map(S, ax, 50, threads(1));
  std::vector<int8_t> count;
  std::vector<uint16_t> pattern;
  int next_row = 0;
  const auto streamed = compute_system_param_direction_map(
      S, ax, 50, threads(2), {}, [&](const SystemParamDirectionRows& r) {
        REQUIRE(r.row_begin == next_row);  // in row order
        next_row = r.row_end;
        const std::size_t cells = static_cast<std::size_t>(r.row_end - r.row_begin) * 50;
        count.insert(count.end(), r.count, r.count + cells);
        pattern.insert(pattern.end(), r.pattern, r.pattern + cells);
      });
  CHECK(streamed.count.empty());
  CHECK(count == kept.count);
  CHECK(pattern == kept.pattern);
  CHECK(streamed.table.patterns == kept.table.patterns);
  CHECK(streamed.table.cells == kept.table.cells);

  const SystemMapAxis b1 = sys_axis("mu@1", 2, 0.3, 3, 6), b2 = sys_axis("k_a", 2, 0, 1, 4);
  const auto pp1 = compute_system_param_param_map(S, b1, b2, threads(1));
  const auto pp2 = compute_system_param_param_map(S, b1, b2, threads(2));
  CHECK(pp1.cls == pp2.cls);
  CHECK(pp1.min_count == pp2.min_count);
  CHECK(pp1.max_count == pp2.max_count);
  CHECK(pp1.pattern == pp2.pattern);
  CHECK(pp1.table.patterns == pp2.table.patterns);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(compute_system_param_param_map(S, b1, sys_axis("mu@1", 2, 0, 1, 3)),
                    Contains("same parameter"));
  // an estimate samples real cells and scales with the grid
  const auto e = estimate_system_param_direction_map(S, ax, 50, threads(1));
  CHECK(e.sampled > 0);
  CHECK(e.cells == 1500);
  CHECK(e.seconds > 0);
}
