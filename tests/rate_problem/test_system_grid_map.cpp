// The N-point parameter x direction map against independent answers: N = 1 against the one-point
// grid map (closed-form route), uncoupled points (coupling 0) against the product of one-point
// maps, thread-count independence, bad input.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
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
ParamDirectionMap one_point_map(const ContactSystem& S, int i, MapParameter p, double from,
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
    const ParamDirectionMap one = one_point_map(S, 0, MapParameter::kMu, from, to, 15, 90);
    REQUIRE(one.disagreements == 0);
    const SystemParamDirectionMap m = compute_system_param_direction_map(
        S, parse_system_map_parameter("mu", 1), from, to, 15, 90, 1);
    REQUIRE(m.unreliable == 0);
    REQUIRE(m.count.size() == one.count.size());
    for (std::size_t k = 0; k < m.count.size(); ++k) {
      INFO("trial " << trial << " cell " << k);
      REQUIRE(m.count[k] == one.count[k]);
      REQUIRE(mask_of(m.patterns[m.pattern[k]]) == one.types[k]);
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
    const SystemParamDirectionMap m = compute_system_param_direction_map(
        S, parse_system_map_parameter("coupling", 2), 0, 0, 1, 120, 2);
    REQUIRE(m.unreliable == 0);
    // Point i alone: its own 2x2 block; a one-point map along a12 fixed at its value.
    std::vector<ParamDirectionMap> one;
    for (int i = 0; i < 2; ++i) {
      const double a12 = S.A(2 * i, 2 * i + 1);
      one.push_back(one_point_map(S, i, MapParameter::kA12, a12, a12, 1, 120));
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
      const auto& got = m.patterns[m.pattern[j]];
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
  const auto a = compute_system_param_direction_map(S, p, 0.3, 3, 40, 200, 1);
  const auto b = compute_system_param_direction_map(S, p, 0.3, 3, 40, 200, 2);
  CHECK(a.count == b.count);
  CHECK(a.pattern == b.pattern);
  CHECK(a.patterns == b.patterns);
  CHECK(a.pattern_cells == b.pattern_cells);
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
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, parse_system_map_parameter("coupling", 2),
                                                       0, 2, 5, 10, 1),
                    Contains("coupling = 1.5"));  // 0.9 c < 1 fails first at c = 1.5
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, parse_system_map_parameter("mu", 2),
                                                       -1, 1, 5, 10, 1),
                    Contains("mu = -1"));
  CHECK_THROWS_WITH(compute_system_param_direction_map(S, parse_system_map_parameter("P_N", 2),
                                                       1, 2, 5, 10, 1),
                    Contains("no point"));
  CHECK_THROWS_AS(compute_system_param_direction_map(S, parse_system_map_parameter("mu", 2),
                                                     1, 2, 5, 0, 1),
                  cpkit::InputError);
}
