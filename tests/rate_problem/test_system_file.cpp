// The N-point system file (docs/file_formats.md, "System file"): the examples read back with the
// values written in them, and every inconsistency is an InputError naming the field and point.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"

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

TEST_CASE("ContactSystem3d::validate and point_parameters: the 2-D checks in 3-D", "[rate][system]") {
  // ContactSystemOf<3> shares validate() and point_parameters() with the 2-D system; the
  // expectations are read off the data by hand.
  ContactSystem3d s;
  CHECK(s.validate() == "points: the system needs at least one point");
  s.points.resize(2);
  s.A = Eigen::MatrixXd::Identity(4, 4);
  CHECK(s.validate() == "A is 4 x 4, need 3N x 3N = 6 x 6 for the 2 points");
  s.A = 2 * Eigen::MatrixXd::Identity(6, 6);
  s.A(1, 5) = s.A(5, 1) = 0.25;  // point 1's T_Y couples to point 2's N
  CHECK(s.validate().empty());   // defaults: state b, P = 0, alpha = (1, 1)
  s.A(5, 1) = 0.5;
  CHECK(s.validate().find("A is not symmetric: A[1][5] = 0.25 but A[5][1] = 0.5") == 0);
  s.A(5, 1) = 0.25;
  // point 2's own block is rows/columns 3..5: the coupling entry (1, 5) is not in it
  s.points[1].mu = 0.75;
  s.points[1].alpha = Eigen::Vector2d(2, 0.5);
  const ContactParameters3d p = s.point_parameters(1);
  CHECK(p.A == 2 * Eigen::Matrix3d::Identity());
  CHECK(p.mu == 0.75);
  CHECK(p.alpha == Eigen::Vector2d(2, 0.5));
  CHECK(s.point_parameters(0).A(1, 2) == 0);
  CHECK_THROWS_AS(s.point_parameters(2), std::out_of_range);
  s.points[1].mu = 0;
  CHECK(s.validate().rfind("point 2: mu must be finite and > 0", 0) == 0);
  s.points[1].mu = 0.75;
  s.points[0].state.state = 'c';  // stick needs P_N > 0
  CHECK(s.validate().rfind("point 1: state c needs P_N > 0", 0) == 0);
  s.points[0].state.state = 'b';
  s.dF = Eigen::VectorXd::Zero(4);
  CHECK(s.validate() == "dF has 4 entries, need 3N = 6");
  s.dF = Eigen::VectorXd::Zero(6);
  CHECK(s.validate().empty());
  s.criterion = Criterion::kSoftening;  // 3-D points follow Coulomb (38) only
  CHECK(!s.validate().empty());
}

TEST_CASE("system file: directories and devices are refused", "[rate][system]") {
  CHECK_THROWS_AS(read_contact_system("/dev/zero"), cpkit::InputError);
  CHECK_THROWS_AS(read_contact_system("/tmp"), cpkit::InputError);
}

// ---- issue 24: items 13-16 (one read, one JSON parser, exact symmetrisation, scale-free SPD) ----

namespace {

/// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const cpkit::InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kOne3d = R"("points": [{"state": "b", "mu": 2}])";

}  // namespace

TEST_CASE("system file: an A asymmetric within the tolerance is accepted and made exactly "
          "symmetric (A = 0.5 A + 0.5 A^T aliased in Eigen)", "[rate][system]") {
  // A(0,1) - A(1,0) = 2e-11, relative 1e-11 of max|A| = 2: within the documented 1e-10. The
  // symmetrised entry is the mean, 0.5 + 1e-11 (by hand; exact to rounding).
  const std::string A2 = "[[2, 0.50000000002, 0.1, 0], [0.5, 2, 0, 0.1], [0.1, 0, 2, 0.3], "
                         "[0, 0.1, 0.3, 2]]";
  const ContactSystem s = parse_contact_system(
      "{\"A\": " + A2 + R"(, "points": [{"state": "b"}, {"state": "b"}]})");
  CHECK(s.A(0, 1) == s.A(1, 0));  // exactly: the aliased version left them 1e-11 apart
  CHECK(s.A(0, 1) == Approx(0.5 + 1e-11).epsilon(1e-15));
  CHECK(s.A == s.A.transpose());
  // The next check that reads A (the N-point step, symmetric to 1e-12) accepts it.
  SystemStepProblem step;
  step.system = s;
  step.DF = Eigen::VectorXd::Zero(4);
  CHECK(step.validate().empty());

  // The same for "dim": 3: A(0,2) = 1 + 1e-10 against A(2,0) = 1 (relative 5e-11 of 2).
  const auto s3 = cpkit::rate::parse_contact_system_3d(
      R"({"dim": 3, "A": [[2, 0, 1.0000000001], [0, 1, 0.5], [1, 0.5, 2]], )" + kOne3d + "}");
  CHECK(s3.A(0, 2) == s3.A(2, 0));
  CHECK(s3.A(0, 2) == Approx(1 + 5e-11).epsilon(1e-15));
  cpkit::rate::SystemStep3dProblem step3;
  step3.system = s3;
  step3.states.resize(1);
  step3.DF = Eigen::Vector3d(0, 0, 1);
  CHECK(step3.validate().empty());
  // Beyond the tolerance: refused, 2-D and 3-D.
  CHECK(error_of([&] {
          parse_contact_system(R"({"A": [[2, 0.5000001], [0.5, 2]], "points": [{"state": "b"}]})");
        }).find("not symmetric") != std::string::npos);
  CHECK(error_of([&] {
          cpkit::rate::parse_contact_system_3d(
              R"({"dim": 3, "A": [[2, 0, 1.00001], [0, 1, 0.5], [1, 0.5, 2]], )" + kOne3d + "}");
        }).find("not symmetric") != std::string::npos);
}

TEST_CASE("system file: an SPD A is accepted in any units, 1e-300 to 1e300 (scale-free "
          "Cholesky)", "[rate][system]") {
  // [[2, 0.5], [0.5, 2]] has eigenvalues 1.5 and 2.5: SPD whatever the positive factor.
  for (const char* f : {"1e-300", "1e-200", "1", "1e200", "1e300"}) {
    CAPTURE(f);
    const std::string c = f;
    const std::string a2 = "[[2" + c.substr(1) + ", 0.5" + c.substr(1) + "], [0.5" + c.substr(1) +
                           ", 2" + c.substr(1) + "]]";
    CHECK_NOTHROW(parse_contact_system("{\"A\": " + a2 + R"(, "points": [{"state": "b"}]})"));
    // 3-D: [[2,0,1],[0,1,0.5],[1,0.5,2]] (leading minors 2, 2, 2.5: SPD)
    const std::string k = c.substr(1);  // "e-300", ..., "" for 1
    const std::string a3 = "[[2" + k + ", 0, 1" + k + "], [0, 1" + k + ", 0.5" + k + "], [1" + k +
                           ", 0.5" + k + ", 2" + k + "]]";
    CHECK_NOTHROW(cpkit::rate::parse_contact_system_3d(R"({"dim": 3, "A": )" + a3 + ", " +
                                                         kOne3d + "}"));
    // indefinite in every unit: [[1, 2], [2, 1]] (eigenvalues 3 and -1)
    const std::string bad2 = "[[1" + k + ", 2" + k + "], [2" + k + ", 1" + k + "]]";
    CHECK(error_of([&] {
            parse_contact_system("{\"A\": " + bad2 + R"(, "points": [{"state": "b"}]})");
          }).find("not positive definite") != std::string::npos);
  }
}

TEST_CASE("system file: 1e-400 and 1e400 are refused, 2-D and 3-D (no silent 0)", "[rate][system]") {
  const std::string m2 = error_of([] {
    parse_contact_system(R"({"A": [[1, 1e-400], [1e-400, 1]], "points": [{"state": "b"}]})", "s.json");
  });
  CHECK(m2.find("s.json:1: '1e-400' is below the smallest double") != std::string::npos);
  const std::string m3 = error_of([] {
    cpkit::rate::parse_contact_system_3d(
        "{\"dim\": 3, \"A\": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],\n \"points\": [{\"state\": "
        "\"b\", \"mu\": 1e-400}]}", "s3.json");
  });
  CHECK(m3.find("s3.json:2: '1e-400' is below the smallest double") != std::string::npos);
  CHECK(error_of([] {
          parse_contact_system(R"({"A": [[1e400, 0], [0, 1]], "points": [{"state": "b"}]})");
        }).find("outside the range of double") != std::string::npos);
  CHECK(error_of([] {
          parse_contact_system(R"({"A": [[1, 0], [0, 1]], "points": [{"state": "b"}], "A": 1})");
        }).find("duplicate field \"A\"") != std::string::npos);
}

TEST_CASE("system file: 10^6 nested brackets are refused with a message, 2-D and 3-D",
          "[rate][system]") {
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  for (const std::string& text :
       {deep, "{\"A\": " + deep + ", \"points\": []}", "{\"dim\": 3, \"A\": " + deep + "}",
        "{\"dim\": 3, \"A\": [[1]], \"points\": [{\"state\": \"b\", \"mu\": " + deep + "}]}"}) {
    const std::string m2 = error_of([&] { parse_contact_system(text, "deep.json"); });
    CHECK(m2.find("deep.json:1: nesting deeper than 64 levels") != std::string::npos);
    const std::string m3 = error_of([&] { cpkit::rate::parse_contact_system_3d(text, "deep.json"); });
    CHECK(m3.find("deep.json:1: nesting deeper than 64 levels") != std::string::npos);
  }
  // A wide value (10^5 numbers where one is expected) is shown in 40 characters.
  std::string wide = "[";
  for (int i = 0; i < 100'000; ++i) wide += (i ? ",1" : "1");
  wide += "]";
  const std::string m = error_of([&] {
    parse_contact_system(R"({"A": [[1, 0], [0, 1]], "points": [{"state": "b", "mu": )" + wide + "}]}");
  });
  CAPTURE(m);
  // the first 37 bytes of the dump ('[' and 18 times "1,") and "..."
  std::string shown = "[";
  for (int i = 0; i < 18; ++i) shown += "1,";
  CHECK(m.find("point 1: mu must be a number, got " + shown + "...") !=
        std::string::npos);
  CHECK(m.size() < 200);
}

TEST_CASE("system file: read once, dimension from the document, errors surface", "[rate][system]") {
  // A FIFO (what `--system <(cat F)` gives) can be read only once: read_system_file reads it
  // once, and the dimension comes from the parsed document.
  const std::string fifo =
      (std::filesystem::temp_directory_path() / ("cpkit_sys_fifo_" + std::to_string(::getpid()))).string();
  std::remove(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string text = R"({"dim": 3, "A": [[2, 0, 1], [0, 1, 0.5], [1, 0.5, 2]], )" + kOne3d + "}";
  std::thread writer([&] { std::ofstream(fifo) << text; });
  const SystemFile f = read_system_file(fifo);
  writer.join();
  std::remove(fifo.c_str());
  CHECK(f.dim == 3);
  CHECK(f.source == fifo);
  const auto s3 = cpkit::rate::parse_contact_system_3d(f);
  CHECK(s3.A(2, 2) == 2);
  // dim absent is 2; a 2-D reader refuses a dim-3 document and the 3-D reader a 2-D one.
  CHECK(parse_system_file(R"({"A": [[1]]})").dim == 2);
  CHECK(error_of([&] { parse_contact_system(f); }).find("dim 3") != std::string::npos);
  CHECK(error_of([] {
          cpkit::rate::parse_contact_system_3d(R"({"A": [[1, 0], [0, 1]], "points": [{"state": "b"}]})");
        }).find("dim must be 3") != std::string::npos);
  // A broken file of either dimension is an error naming the problem, never "not 3-D".
  CHECK(error_of([] { parse_system_file(R"({"dim": 3, "A": )", "b.json"); })
            .find("b.json:1: not valid JSON") != std::string::npos);
  CHECK(error_of([] { parse_system_file(R"({"dim": 4})", "b.json"); })
            .find("b.json: dim must be 2 (2-D points) or 3 (3-D points), got 4") != std::string::npos);
  CHECK(error_of([] { parse_system_file(R"({"dim": "3"})", "b.json"); })
            .find("dim must be 2") != std::string::npos);
  CHECK(error_of([] { parse_system_file("[1]", "b.json"); })
            .find("b.json: the system file must be a JSON object") != std::string::npos);
  CHECK(error_of([] { read_system_file("/nonexistent/s.json"); })
            .find("cannot open system file /nonexistent/s.json") != std::string::npos);
}

TEST_CASE("system file: the fuzz regressions of issue 24 give their stated answers", "[rate][system]") {
  // tests/fuzz/regressions/system_file/ (replayed by ctest fuzz.system_file); "" = accepted.
  const std::string dir = CPKIT_SOURCE_DIR "/tests/fuzz/regressions/system_file/";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"nesting_20000_2d.json", "nesting_20000_2d.json:1: nesting deeper than 64 levels"},
      {"nesting_20000_3d.json", "nesting_20000_3d.json:1: nesting deeper than 64 levels"},
      {"underflow_2d.json", "underflow_2d.json:1: '1e-400' is below the smallest double"},
      {"underflow_3d.json", "underflow_3d.json:2: '1e-400' is below the smallest double"},
      {"duplicate_dim.json", "duplicate field \"dim\""},
      {"dim_string.json", "dim must be 2 (2-D points) or 3 (3-D points), got \"3\""},
      {"asymmetric_within_tolerance.json", ""},
      {"spd_1e300_2d.json", ""},
      {"spd_1e-300_3d.json", ""}};
  for (const auto& [name, expected] : cases) {
    CAPTURE(name);
    const std::string m = error_of([&, n = name] {
      const SystemFile f = read_system_file(dir + n);
      if (f.dim == 3) cpkit::rate::parse_contact_system_3d(f);
      else parse_contact_system(f);
    });
    if (expected.empty()) CHECK(m.empty());
    else CHECK(m.find(expected) != std::string::npos);
  }
}
