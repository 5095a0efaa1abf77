// The N-point system file (docs/file_formats.md, "System file"): the examples read back with the
// values written in them, and every inconsistency is an InputError naming the field and point.
#include <catch2/catch.hpp>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

using namespace cpkit::rate;

namespace {

const std::string kA2 = R"("A": [[2, 0.5, 0.1, 0], [0.5, 2, 0, 0.1], [0.1, 0, 2, 0.3], [0, 0.1, 0.3, 2]])";

std::string two_points(const std::string& p1, const std::string& p2, const std::string& extra = "") {
  return "{" + kA2 + R"(, "points": [)" + p1 + ", " + p2 + "]" + extra + "}";
}

/// parse must throw an InputError whose message contains every needle.
void bad(const std::string& text, std::initializer_list<const char*> needles) {
  CAPTURE(text);
  try {
    parse_contact_system(text, "sys.json");
    FAIL("no error");
  } catch (const cpkit::InputError& e) {
    const std::string m = e.what();
    CAPTURE(m);
    CHECK(m.find("sys.json") != std::string::npos);
    for (const char* n : needles) CHECK(m.find(n) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("system examples read back", "[rate][system]") {
  const ContactSystem two = read_contact_system(CPKIT_TEST_DATA_DIR "/systems/two_point_system.json");
  REQUIRE(two.n_points() == 2);
  CHECK(two.name == "two-point coupled contact");
  CHECK(two.points[0].state.label == StateLabel::kB);
  CHECK(two.points[1].state.label == StateLabel::kD);
  CHECK(two.points[1].state.P_N == 2);
  CHECK(two.points[1].state.sgn_PT == 1);
  CHECK(two.points[1].P_T == 6);  // sgnPT mu P_N, Coulomb
  CHECK(two.points[1].values_given == false);
  REQUIRE(two.dF.has_value());
  CHECK((*two.dF)(1) == -1.0);
  REQUIRE(two.pattern2.has_value());
  CHECK((*two.pattern2)(3) == 1.0);
  const ContactParameters p2 = two.point_parameters(1);
  CHECK(p2.a11 == 1.0);
  CHECK(p2.a12 == 0.3);
  CHECK(p2.a22 == 1.0);
  CHECK(p2.mu == 3);
  CHECK(p2.C_T == 0.25);

  const ContactSystem punch = read_contact_system(CPKIT_TEST_DATA_DIR "/systems/three_point_punch.json");
  REQUIRE(punch.n_points() == 3);
  // classified from the values: |P_T| = mu P_N at the edges, below it in the middle
  CHECK(punch.points[0].state.label == StateLabel::kD);
  CHECK(punch.points[0].state.sgn_PT == 1);
  CHECK(punch.points[1].state.label == StateLabel::kC);
  CHECK(punch.points[2].state.label == StateLabel::kD);
  CHECK(punch.points[2].state.sgn_PT == -1);
  CHECK(punch.points[1].values_given);
  CHECK(punch.validate().empty());
}

TEST_CASE("system file: values and labels", "[rate][system]") {
  const auto s = parse_contact_system(
      two_points(R"({"state": "a", "g": -0.5})", R"({"P_T": 0, "P_N": 0, "g": 0})"));
  CHECK(s.points[0].state.label == StateLabel::kA);
  CHECK(s.points[0].g == -0.5);
  CHECK(s.points[1].state.label == StateLabel::kB);
  // label and values both given, consistent
  const auto t = parse_contact_system(two_points(
      R"({"state": "d", "mu": 0.5, "P_N": 2, "sgnPT": -1, "P_T": -1, "g": 0})",
      R"({"state": "c", "P_N": 1, "P_T": 0.1})", R"(, "criterion": "coulomb")"));
  CHECK(t.points[0].values_given);
  CHECK(t.points[0].P_T == -1);
  CHECK(t.points[1].state.label == StateLabel::kC);
}

TEST_CASE("system file: bad input names the field and point", "[rate][system]") {
  const std::string ok = R"({"state": "b"})";
  bad("[1, 2]", {"JSON object"});
  bad("{\"A\": ", {"not valid JSON"});
  bad(two_points(ok, ok, R"(, "extra": 1)"), {"unknown key", "extra"});
  bad(two_points(ok, R"({"state": "b", "muu": 1})"), {"point 2", "unknown key", "muu"});
  bad("{" + kA2 + "}", {"points"});
  bad(R"({"points": [{"state": "b"}]})", {"A"});
  bad(R"({"A": [[1, 0], [0, 1]], "points": [{"state": "b"}, {"state": "b"}]})", {"A has 2 rows", "4"});
  bad(R"({"A": [[1, 0], [0]], "points": [{"state": "b"}]})", {"A[1]"});
  bad(R"({"A": [[1, 0.5], [0.4, 1]], "points": [{"state": "b"}]})", {"not symmetric"});
  bad(R"({"A": [[1, 2], [2, 1]], "points": [{"state": "b"}]})", {"positive definite"});
  bad(R"({"A": [[1, 1], [1, 1]], "points": [{"state": "b"}]})", {"A"});
  bad(R"({"A": [[1, "x"], [0, 1]], "points": [{"state": "b"}]})", {"A[0][1]", "number"});
  bad(R"({"A": [[1, 1e999], [0, 1]], "points": [{"state": "b"}]})", {"1e999"});
  bad(two_points(ok, R"({"state": "b", "P_N": 1})"), {"point 2", "P_N"});
  bad(two_points(R"({"state": "d", "P_N": 1, "sgnPT": 1, "P_T": 0.2})", ok), {"point 1", "state d", "P_T"});
  bad(two_points(R"({"state": "d", "P_N": 1})", ok), {"point 1", "sgnPT"});
  bad(two_points(R"({"state": "d", "P_N": 1, "sgnPT": 0})", ok), {"point 1", "sgnPT"});
  bad(two_points(ok, R"({"state": "c"})"), {"point 2", "P_N"});
  bad(two_points(ok, R"({"state": "c", "P_N": -1})"), {"point 2", "P_N"});
  bad(two_points(ok, R"({"state": "c", "P_N": 1, "P_T": 0.5})"), {"point 2", "state c", "|P_T|"});
  bad(two_points(ok, R"({"state": "e"})"), {"point 2", "state"});
  bad(two_points(ok, R"({"state": "a"})"), {"point 2", "g < 0"});
  bad(two_points(ok, R"({"state": "b", "g": -1})"), {"point 2", "g"});
  bad(two_points(ok, R"({"mu": 0.5})"), {"point 2", "state"});
  bad(two_points(ok, R"({"P_T": 1, "P_N": 1, "g": 0})"), {"point 2", "friction limit"});
  bad(two_points(ok, R"({"P_T": 0, "P_N": -1, "g": 0})"), {"point 2", "P_N"});
  bad(two_points(ok, R"({"P_T": 0, "P_N": 1, "g": -1})"), {"point 2", "gap"});
  bad(two_points(ok, R"({"state": "b", "mu": 0})"), {"point 2", "mu"});
  bad(two_points(ok, R"({"state": "b", "C_T": -1})"), {"point 2", "C_T"});
  bad(two_points(ok, ok, R"(, "dF": [1, 2, 3])"), {"dF", "4"});
  bad(two_points(ok, ok, R"(, "patterns": [[1, 0, 0, 0]])"), {"patterns"});
  bad(two_points(ok, ok, R"(, "patterns": [[1, 0, 0, 0], [0, 1, 0]])"), {"patterns[1]"});
  bad(two_points(ok, ok, R"(, "criterion": "tresca")"), {"criterion"});
  CHECK_THROWS_AS(read_contact_system("/nonexistent/sys.json"), cpkit::InputError);
}

TEST_CASE("ContactSystem::validate on a constructed system", "[rate][system]") {
  ContactSystem s;
  CHECK(!s.validate().empty());  // no points
  s.points.resize(2);
  s.A = Eigen::MatrixXd::Identity(4, 4);
  CHECK(s.validate().empty());  // defaults: state b, P = 0
  s.A(0, 3) = 0.5;
  CHECK(s.validate().find("symmetric") != std::string::npos);
  s.A(3, 0) = 0.5;
  CHECK(s.validate().empty());
  s.points[1].state.label = StateLabel::kD;
  CHECK(s.validate().find("point 2") != std::string::npos);
  CHECK_THROWS_AS(s.point_parameters(2), std::out_of_range);
}

TEST_CASE("system file: directories and devices are refused", "[rate][system]") {
  CHECK_THROWS_AS(read_contact_system("/dev/zero"), cpkit::InputError);
  CHECK_THROWS_AS(read_contact_system("/tmp"), cpkit::InputError);
}
