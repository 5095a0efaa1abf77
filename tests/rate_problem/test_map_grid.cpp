// Parameter x direction and parameter x parameter maps: the critical line mu = a11/|a12| of
// state b and Lambda = 0 (eqn (51)) of state d where the closed forms put them, cell counts
// against the hand formulas, thread-count independence, CSV/JSON output.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"

using namespace cpkit::rate;

namespace {
constexpr double kPi = 3.14159265358979323846;

ContactParameters fig5() {
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 0.5;
  p.a22 = 1;
  p.C_T = 0.25;
  p.mu = 3;
  return p;
}
ContactState state_b() {
  ContactState s;
  s.label = StateLabel::kB;
  return s;
}
/// Lambda of eqn (51) for the state-d preset model (a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25,
/// s = +1), by hand.
double lambda_d(double mu, double kappa) {
  return 1 - 0.5 * mu + kappa * (0.5 - mu) - mu * kappa * 0.25 * 0.75;
}
}  // namespace

TEST_CASE("MuDirectionMapHasTheCriticalLineAtA11OverA12", "[map][grid]") {
  // Three solutions exactly for mu > a11/a12 = 2 and theta strictly between L+ = 0 and N = 0.
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 61};  // step 0.05, mu = 2 is row 30
  const int tn = 720;
  const ParamDirectionMap m = compute_param_direction_map(fig5(), state_b(), axis, tn);
  REQUIRE(m.cells() == 61 * tn);
  const double tN = std::atan(0.5);
  int64_t threes = 0;
  for (int i = 0; i < axis.n; ++i) {
    const double mu = axis.value(i);
    const double tL = std::atan((1 + mu * 0.125) / (mu * 1.25));  // L+ = 0 (dF_T > 0 branch)
    for (int j = 0; j < tn; ++j) {
      const double th = m.theta[j];
      const bool three = mu > 2 + 1e-9 && th > tL && th < tN;
      const int c = m.count[static_cast<std::size_t>(i) * tn + j];
      if (std::abs(th - tL) < 1e-9 || std::abs(th - tN) < 1e-9) continue;
      CAPTURE(mu, th);
      CHECK(c == (three ? 3 : 1));
      threes += three;
    }
  }
  CHECK(threes > 0);
  // The analytic critical value: D+ = a11 - mu a12 = 0 at mu = 2 (and D- has no zero here).
  REQUIRE(m.critical_values.size() == 1);
  CHECK(m.critical_values[0].name == "D+=0");
  CHECK(m.critical_values[0].x == Approx(2.0).margin(1e-12));
  // Critical-direction curves: every row has N = 0 at atan(0.5) and atan(0.5) + pi.
  int n_up = 0;
  for (const auto& c : m.critical_directions)
    if (std::abs(c.theta - tN) < 1e-12) ++n_up;
  CHECK(n_up == axis.n);
}

TEST_CASE("RatioAxisPutsTheCriticalLineAtOneOverMu", "[map][grid]") {
  const MapAxis axis{map_parameter("a12/a11"), -0.9, 0.9, 19};
  const ParamDirectionMap m = compute_param_direction_map(fig5(), state_b(), axis, 36);
  // D+ = a11 (1 - 3 r) = 0 at r = 1/3; D- = a11 (1 + 3 r) = 0 at r = -1/3.
  REQUIRE(m.critical_values.size() == 2);
  CHECK(m.critical_values[0].name == "D+=0");
  CHECK(m.critical_values[0].x == Approx(1.0 / 3).margin(1e-12));
  CHECK(m.critical_values[1].name == "D-=0");
  CHECK(m.critical_values[1].x == Approx(-1.0 / 3).margin(1e-12));
}

TEST_CASE("StateDMapHasLambdaZeroAtMu8Over7", "[map][grid]") {
  const auto preset = find_map_preset("state-d");
  REQUIRE(preset);
  const MapAxis axis{map_parameter("mu"), 0.2, 2.5, 47};
  const int tn = 180;
  const ParamDirectionMap m =
      compute_param_direction_map(preset->params, preset->state, axis, tn);
  REQUIRE(m.critical_values.size() == 1);
  CHECK(m.critical_values[0].name == "Lambda=0");
  CHECK(m.critical_values[0].x == Approx(8.0 / 7).margin(1e-12));
  for (int i = 0; i < axis.n; ++i) {
    const double mu = axis.value(i);
    bool has0 = false, has2 = false, only1 = true;
    for (int j = 0; j < tn; ++j) {
      const int c = m.count[static_cast<std::size_t>(i) * tn + j];
      has0 |= c == 0;
      has2 |= c == 2;
      only1 &= c == 1;
    }
    CAPTURE(mu);
    if (lambda_d(mu, 0.5) > 0) {
      CHECK(only1);
    } else {
      CHECK(has0);
      CHECK(has2);
    }
  }
}

TEST_CASE("ParamParamClassesFollowTheSignOfLambda", "[map][grid]") {
  const auto preset = find_map_preset("state-d-mu-kappa");
  REQUIRE(preset);
  const MapAxis a1{map_parameter("mu"), 0.1, 2.0, 21}, a2{map_parameter("kappa"), 0.0, 2.0, 17};
  const ParamParamMap m = compute_param_param_map(preset->params, preset->state, a1, a2);
  REQUIRE(m.cells() == 21 * 17);
  for (int i = 0; i < a1.n; ++i)
    for (int j = 0; j < a2.n; ++j) {
      const double L = lambda_d(a1.value(i), a2.value(j));
      if (std::abs(L) < 1e-9) continue;
      CAPTURE(a1.value(i), a2.value(j), L);
      const auto c = static_cast<UniquenessClass>(m.cls[static_cast<std::size_t>(i) * a2.n + j]);
      // Lambda < 0 (paper, after eqn (51)): two solutions for L_s < 0, none for L_s > 0.
      CHECK(c == (L > 0 ? UniquenessClass::kUniqueAll : UniquenessClass::kNoneAndSeveral));
    }
  // Critical-curve points satisfy Lambda = 0.
  REQUIRE(!m.critical_curve.empty());
  for (const auto& p : m.critical_curve) CHECK(std::abs(lambda_d(p.x, p.y)) < 1e-10);
  // State b over mu x a12/a11: unique iff a11 > mu |a12|, never without solution.
  const MapAxis b1{map_parameter("mu"), 0.2, 3.0, 15}, b2{map_parameter("a12/a11"), -0.9, 0.9, 13};
  const ParamParamMap mb = compute_param_param_map(fig5(), state_b(), b1, b2);
  for (int i = 0; i < b1.n; ++i)
    for (int j = 0; j < b2.n; ++j) {
      const double d = 1 - b1.value(i) * std::abs(b2.value(j));
      if (std::abs(d) < 1e-9) continue;
      const auto c = static_cast<UniquenessClass>(mb.cls[static_cast<std::size_t>(i) * b2.n + j]);
      CHECK(c == (d > 0 ? UniquenessClass::kUniqueAll : UniquenessClass::kNonUniqueSome));
    }
}

TEST_CASE("MapsAreIdenticalForAnyThreadCount", "[map][grid]") {
  const MapAxis axis{map_parameter("mu"), 0.1, 4.0, 97};
  MapOptions o1;
  o1.threads = 1;
  const ParamDirectionMap ref = compute_param_direction_map(fig5(), state_b(), axis, 101, o1);
  for (int t : {2, 3, 8}) {
    MapOptions o;
    o.threads = t;
    const ParamDirectionMap m = compute_param_direction_map(fig5(), state_b(), axis, 101, o);
    CAPTURE(t);
    CHECK(m.count == ref.count);
    CHECK(m.types == ref.types);
    REQUIRE(m.critical_directions.size() == ref.critical_directions.size());
    for (std::size_t k = 0; k < m.critical_directions.size(); ++k)
      CHECK(m.critical_directions[k].theta == ref.critical_directions[k].theta);
    std::ostringstream a, b;
    write_csv(m, a);
    write_csv(ref, b);
    CHECK(a.str() == b.str());
  }
  const auto preset = find_map_preset("state-d-mu-kappa");
  const MapAxis a1{map_parameter("mu"), 0.1, 2.0, 9}, a2{map_parameter("kappa"), 0.0, 2.0, 7};
  const ParamParamMap p1 = compute_param_param_map(preset->params, preset->state, a1, a2, o1);
  MapOptions o3;
  o3.threads = 3;
  const ParamParamMap p3 = compute_param_param_map(preset->params, preset->state, a1, a2, o3);
  CHECK(p1.cls == p3.cls);
  CHECK(p1.max_count == p3.max_count);
}

TEST_CASE("AnalyticCrossCheckReportsNoDisagreementOnFig5", "[map][grid]") {
  MapOptions o;
  o.method = RateMethod::kAnalytic;
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 31};
  const ParamDirectionMap m = compute_param_direction_map(fig5(), state_b(), axis, 90, o);
  CHECK(m.cross_checked);
  CHECK(m.disagreements == 0);
  REQUIRE(m.disagree.size() == m.count.size());
  const ParamDirectionMap e = compute_param_direction_map(fig5(), state_b(), axis, 90);
  CHECK(e.count == m.count);
  CHECK(e.types == m.types);
}

TEST_CASE("GridMapOutputsParse", "[map][grid][io]") {
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 4};
  const ParamDirectionMap m = compute_param_direction_map(fig5(), state_b(), axis, 8);
  std::ostringstream csv;
  write_csv(m, csv);
  std::istringstream in(csv.str());
  std::string line;
  std::getline(in, line);
  CHECK(line == "mu,theta,count,types");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') == 3);
  }
  CHECK(rows == 32);
  const auto j = nlohmann::json::parse(to_json(m).dump());
  CHECK(j["cells"] == 32);
  CHECK(j["axis"]["param"] == "mu");
  int64_t total = 0;
  for (const auto& [k, v] : j["counts"].items()) total += v.get<int64_t>();
  CHECK(total == 32);
  CHECK(j.contains("seconds"));
}

TEST_CASE("GridMapsRejectBadInput", "[map][grid]") {
  const ContactParameters p = fig5();
  const ContactState s = state_b();
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("mu"), 2, 1, 10}, 10),
                  cpkit::InputError);
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("mu"), 0.1, 1, 0}, 10),
                  cpkit::InputError);
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("mu"), 0.1, 1, 10}, 0),
                  cpkit::InputError);
  CHECK_THROWS_AS(
      compute_param_direction_map(p, s, {map_parameter("mu"), std::nan(""), 1, 10}, 10),
      cpkit::InputError);
  // mu <= 0 inside the range: an invalid model row.
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("mu"), -1, 1, 10}, 10),
                  cpkit::InputError);
  // kappa needs P_N > 0 (state b has P_N = 0).
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("kappa"), 0, 1, 10}, 10),
                  cpkit::InputError);
  MapOptions o;
  o.threads = -1;
  CHECK_THROWS_AS(compute_param_direction_map(p, s, {map_parameter("mu"), 0.1, 1, 10}, 10, o),
                  cpkit::InputError);
  CHECK_THROWS_AS(compute_param_param_map(p, s, {map_parameter("mu"), 0.1, 1, 3},
                                          {map_parameter("mu"), 0.1, 1, 3}),
                  cpkit::InputError);
  CHECK(map_parameter_from_string("a12/a11") == map_parameter("a12/a11"));
  CHECK(!map_parameter_from_string("nonsense"));
}
