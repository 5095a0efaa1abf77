// The one table of map parameters (maps/map_parameter_table.hpp) against the three parsers and
// appliers it governs: every name the table gives a kind of map is accepted by that kind's
// parser (and names itself back), every other name is refused naming it; NAME@i; P_s of
// N-point maps set as the file would set it (the softening limit |P_T| = mu P_N - k P_N^2,
// k = k_a / (3 P_s), by hand).
#include <catch2/catch.hpp>

#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"

using namespace cpkit::rate;

TEST_CASE("MapParameterTableGovernsTheThreeParsers", "[map][params]") {
  int one = 0, n_points = 0, three_d = 0;
  for (const auto& row : map_parameter_table()) {
    const std::string name = row.name;
    CAPTURE(name);
    // One point: the row found by its name is the row, and applies to a one-point model.
    const auto p1 = map_parameter_from_string(name);
    CHECK(p1.has_value() == bool(row.dimensions & kMapOnePoint));
    CHECK(bool(row.set_one_point) == bool(row.dimensions & kMapOnePoint));
    if (p1) {
      CHECK(p1->row == &row);
      CHECK(p1->name() == name);
      ++one;
    }
    // N points.
    if (row.dimensions & kMapNPoints) {
      CHECK(parse_system_map_parameter(name, 2).name() == name);
      ++n_points;
    } else {
      CHECK_THROWS_WITH(parse_system_map_parameter(name, 2),
                        Catch::Contains("'" + name + "'") && Catch::Contains("does not apply"));
    }
    // 3-D.
    if (row.dimensions & kMap3d) {
      CHECK(cpkit::rate::parse_map_3d_parameter(name, 2).name() == name);
      ++three_d;
    } else {
      CHECK_THROWS_WITH(cpkit::rate::parse_map_3d_parameter(name, 2),
                        Catch::Contains("'" + name + "'") && Catch::Contains("does not apply"));
    }
  }
  // The rows per kind: one point 10, N points 6 (P_s included), 3-D 6.
  CHECK(one == 10);
  CHECK(n_points == 6);
  CHECK(three_d == 6);
}

TEST_CASE("MapParameterNamesAreCheckedWithTheirPoint", "[map][params]") {
  CHECK_THROWS_WITH(check_map_parameter("nonsense", kMapOnePoint, 1, "--param"),
                    Catch::StartsWith("--param: unknown map parameter 'nonsense'") &&
                        Catch::Contains("kappa"));
  CHECK_THROWS_WITH(check_map_parameter("coupling", kMapOnePoint, 1),
                    Catch::Contains("applies to N-point maps"));
  CHECK_THROWS_WITH(check_map_parameter("mu@1", kMapOnePoint, 1),
                    Catch::Contains("no point number"));
  CHECK_THROWS_WITH(check_map_parameter("coupling@1", kMapNPoints, 2),
                    Catch::Contains("not to one point"));
  CHECK_THROWS_WITH(check_map_parameter("P_s@3", kMapNPoints, 2),
                    Catch::Contains("1..2"));
  CHECK_THROWS_WITH(check_map_parameter("P_s@x", kMapNPoints, 2), Catch::Contains("1..2"));
  CHECK_THROWS_WITH(check_map_parameter("P_N", kMap3d, 1), Catch::Contains("does not apply"));
  const MapParameterRef r = check_map_parameter("P_s@2", kMapNPoints, 2);
  CHECK(std::string(r.row->name) == "P_s");
  CHECK(r.point == 2);
  CHECK(parse_system_map_parameter("P_s@2", 2).name() == "P_s@2");
}

TEST_CASE("OnePointRowsApplyThemselvesToTheModel", "[map][params]") {
  // The older spellings name the same rows; names of other kinds and NAME@i are not one-point.
  CHECK(map_parameter_from_string("ratio")->name() == "a12/a11");
  CHECK(map_parameter_from_string("a12_a11")->name() == "a12/a11");
  CHECK(map_parameter_from_string("CT")->name() == "C_T");
  CHECK(map_parameter_from_string("C_t")->name() == "C_T");
  CHECK(map_parameter_from_string("ka")->name() == "k_a");
  CHECK(map_parameter_from_string("Ps")->name() == "P_s");
  CHECK(map_parameter_from_string("PN")->name() == "P_N");
  CHECK(!map_parameter_from_string("coupling"));
  CHECK(!map_parameter_from_string("alpha_X"));
  CHECK(!map_parameter_from_string("mu@1"));
  CHECK_THROWS_AS(map_parameter("nonsense"), cpkit::InputError);

  // By hand: a12/a11 = 0.25 with a11 = 2 gives a12 = 0.5; kappa = 0.5 with P_s = 2, P_N = 3
  // gives k_a = 3 P_s kappa / P_N = 1; P_N sets the state's normal force.
  ContactParameters p;
  p.a11 = 2;
  p.P_s = 2;
  ContactState st;
  st.P_N = 3;
  apply_map_parameter(map_parameter("a12/a11"), 0.25, p, st);
  CHECK(p.a12 == 0.5);
  CHECK(p.a11 == 2);
  apply_map_parameter(map_parameter("kappa"), 0.5, p, st);
  CHECK(p.k_a == 1);
  apply_map_parameter(map_parameter("P_N"), 7, p, st);
  CHECK(st.P_N == 7);
  apply_map_parameter(map_parameter("mu"), 0.75, p, st);
  CHECK(p.mu == 0.75);
  // kappa needs P_N > 0; a row of another kind of map does not apply to one point.
  st.P_N = 0;
  CHECK_THROWS_WITH(apply_map_parameter(map_parameter("kappa"), 0.5, p, st),
                    Catch::Contains("needs P_N > 0"));
  CHECK_THROWS_WITH(apply_map_parameter(map_parameter("coupling"), 0.5, p, st),
                    Catch::Contains("does not apply to one-point maps"));
}

TEST_CASE("PsOfAnNPointMapSetsTheHardnessAndTheSlidingLimit", "[map][params]") {
  // Point 2 slides (state d, P_N = 2) under the softening criterion (35): |P_T| = mu P_N - k P_N^2.
  const ContactSystem base = parse_contact_system(
      R"({"A": [[2, 0.1, 0, 0], [0.1, 2, 0, 0], [0, 0, 2, 0.1], [0, 0, 0.1, 2]],
          "criterion": "softening",
          "points": [{"state": "b", "mu": 0.5, "k_a": 0.3, "P_s": 1},
                     {"state": "d", "mu": 0.5, "k_a": 0.3, "P_s": 1, "P_N": 2, "sgnPT": 1}]})");
  const ContactSystem s = apply_system_map_parameter(base, parse_system_map_parameter("P_s@2", 2), 4);
  CHECK(s.points[0].P_s == 1);
  CHECK(s.points[1].P_s == 4);
  // k = 0.3 / (3 * 4) = 0.025: P_T = 0.5 * 2 - 0.025 * 4 = 0.9 (hand calculation).
  CHECK(s.points[1].P_T == Approx(0.9).epsilon(1e-14));
  const ContactSystem all = apply_system_map_parameter(base, parse_system_map_parameter("P_s", 2), 2);
  CHECK(all.points[0].P_s == 2);
  CHECK(all.points[1].P_s == 2);
  CHECK_THROWS_AS(apply_system_map_parameter(base, parse_system_map_parameter("P_s", 2), 0),
                  cpkit::InputError);
}

TEST_CASE("EveryRowOfSystemsSetsItsOwnQuantity", "[map][params]") {
  // The rows apply themselves (set_point, set_point_3d): each must set the point field its name
  // says, of point 2 only with @2, and nothing else (fields read back by name, by hand).
  const ContactSystem base = parse_contact_system(
      R"({"A": [[2, 0.1, 0, 0], [0.1, 2, 0, 0], [0, 0, 2, 0.1], [0, 0, 0.1, 2]],
          "points": [{"state": "c", "mu": 0.5, "P_N": 1}, {"state": "c", "mu": 0.5, "P_N": 1}]})");
  auto field_2d = [](const SystemPoint& p, const std::string& name) {
    return name == "mu" ? p.mu : name == "C_T" ? p.C_T : name == "k_a" ? p.k_a
         : name == "P_s" ? p.P_s : name == "P_N" ? p.P_N : -1.0;
  };
  auto field_3d = [](const SystemPoint3d& p, const std::string& name) {
    return name == "mu" ? p.mu : name == "C_T" ? p.C_T : name == "k_a" ? p.k_a
         : name == "P_s" ? p.P_s : name == "alpha_X" ? p.alpha(0) : name == "alpha_Y" ? p.alpha(1)
         : -1.0;
  };
  ContactSystem3d base3;
  base3.A = Eigen::MatrixXd::Identity(6, 6);
  base3.points.resize(2);
  int decided_2d = 0, decided_3d = 0;
  for (const auto& row : map_parameter_table()) {
    const std::string name = row.name;
    CAPTURE(name);
    if ((row.dimensions & kMapNPoints) && row.per_point) {
      const ContactSystem s =
          apply_system_map_parameter(base, parse_system_map_parameter(name + "@2", 2), 0.375);
      CHECK(field_2d(s.points[1], name) == 0.375);
      CHECK(field_2d(s.points[0], name) == field_2d(base.points[0], name));
      ++decided_2d;
    }
    if (row.dimensions & kMap3d) {
      ContactSystem3d s = base3;
      apply_map_3d_parameter(parse_map_3d_parameter(name + "@2", 2), 0.375, s);
      CHECK(field_3d(s.points[1], name) == 0.375);
      CHECK(field_3d(s.points[0], name) == field_3d(base3.points[0], name));
      ++decided_3d;
    }
  }
  CHECK(decided_2d == 5);  // mu, C_T, k_a, P_s, P_N
  CHECK(decided_3d == 6);  // mu, C_T, k_a, P_s, alpha_X, alpha_Y
  // coupling has no point: it scales the blocks between points (A(c) = D + c (A - D)).
  ContactSystem coupled = base;
  coupled.A(0, 2) = coupled.A(2, 0) = 0.25;
  const ContactSystem c =
      apply_system_map_parameter(coupled, parse_system_map_parameter("coupling", 2), 0.5);
  CHECK(c.A(0, 2) == 0.125);
  CHECK(c.A(2, 0) == 0.125);
  CHECK(c.A(1, 0) == 0.1);  // a point's own block is kept
  // P_N is refused for a point in state a or b, naming it.
  const ContactSystem ab = parse_contact_system(
      R"({"A": [[2, 0.1], [0.1, 2]], "points": [{"state": "b", "mu": 0.5}]})");
  CHECK_THROWS_WITH(
      apply_system_map_parameter(ab, parse_system_map_parameter("P_N@1", 1), 1),
      Catch::Contains("point 1 is in state b (P_N applies to points in state c or d)"));
  CHECK_THROWS_WITH(apply_system_map_parameter(ab, parse_system_map_parameter("P_N", 1), 1),
                    "map parameter P_N: no point of the system is in state c or d");
}
