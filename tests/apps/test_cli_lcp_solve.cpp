// `cpkit lcp solve`: runs the built binary and checks exit codes (0 solved, 1 no solution,
// 2 bad input/usage), that --json prints one parseable object with the documented fields, and
// that bad input prints nothing on stdout.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using Run = cpkit::test::CliRun;
using cpkit::test::scratch_dir;
using cpkit::test::slurp;

Run run_cli(const std::string& args) { return cpkit::test::run_cpkit(args); }

std::string data(const std::string& name) {
  return std::string("'") + CPKIT_TEST_DATA_DIR + "/lcp/" + name + "'";
}

std::string write(const std::string& name, const std::string& text) {
  const auto path = scratch_dir() / name;
  std::ofstream(path) << text;
  return "'" + path.string() + "'";
}

}  // namespace

TEST_CASE("cli: solved problem, JSON output", "[cli]") {
  const auto r = run_cli("lcp solve " + data("deudeu.json") + " --json");
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "solved");
  // M is positive definite (a P-matrix): the default's tiny route answers with the one
  // solution, no pivots; --solver lemke takes Lemke's three.
  CHECK(j.at("solver") == "enumeration");
  CHECK(j.at("iterations") == 0);
  REQUIRE(j.at("z").size() == 2);
  // Unique solution (4/3, 7/3), w = 0 (file note, hand check: M = [[2,1],[1,2]], q = (-5,-6)).
  CHECK(j["z"][0].get<double>() == Approx(4.0 / 3.0).epsilon(1e-14));
  CHECK(j["z"][1].get<double>() == Approx(7.0 / 3.0).epsilon(1e-14));
  CHECK(j.at("w").size() == 2);
  CHECK(j.at("residual").get<double>() <= 1e-10);
  CHECK_FALSE(j.contains("certificate"));
  CHECK(r.err.empty());
  // Lemke on the same problem: z0 enters, then z2 and z1 replace it (three pivots).
  const auto l = run_cli("lcp solve " + data("deudeu.json") + " --solver lemke --json");
  REQUIRE(l.code == 0);
  CHECK(nlohmann::json::parse(l.out).at("iterations") == 3);
}

TEST_CASE("cli: DART's Lemke_12D contact LCP is solved, not cycle_detected (issue 24)",
          "[cli][lemke]") {
  // Reproducer of issue 24, item 7: `lcp solve FILE --solver lemke` ended in cycle_detected.
  // Exact rational lexicographic Lemke (tests/data/lemke/exact_lemke.py) takes 8 pivots, the z0
  // pivot included; Siconos' lexicolemke 7 without it. The z is checked from the data here.
  const std::string file = std::string(CPKIT_TEST_DATA_DIR) + "/lemke/engine_dart_lemke_12d.json";
  const auto r = run_cli("lcp solve '" + file + "' --solver lemke --json");
  CAPTURE(r.out, r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "solved");
  CHECK(j.at("iterations") == 8);
  std::ifstream in(file);
  const auto doc = nlohmann::json::parse(in);
  REQUIRE(j.at("z").size() == 12);
  for (size_t i = 0; i < 12; ++i) {
    double w = doc["q"][i].get<double>(), scale = std::abs(w);
    for (size_t k = 0; k < 12; ++k) {
      w += doc["M"][i][k].get<double>() * j["z"][k].get<double>();
      scale += std::abs(doc["M"][i][k].get<double>() * j["z"][k].get<double>());
    }
    const double z = j["z"][i].get<double>();
    CHECK(z >= -1e-9 * scale);
    CHECK(w >= -1e-9 * scale);
    CHECK(std::min(z, w) <= 1e-9 * scale);
  }
}

TEST_CASE("cli: infeasible problem exits 1 with a certificate", "[cli]") {
  const auto r = run_cli("lcp solve " + data("infeasible_copositive_plus.json") + " --json");
  REQUIRE(r.code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "infeasible");
  REQUIRE(j.contains("certificate"));
  // y proportional to (1, 1): M^T y = 0, q^T y < 0 (the file's stated certificate).
  CHECK(j["certificate"]["y"][0].get<double>() == Approx(j["certificate"]["y"][1].get<double>()));
  CHECK(j["certificate"]["q_dot_y"].get<double>() < 0);
}

TEST_CASE("cli: ray termination and pivot limit exit 1, with what to try", "[cli]") {
  auto r = run_cli("lcp solve " + data("battle_of_the_sexes.json") + " --solver lemke --json");
  CHECK(r.code == 1);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "ray_termination");
  // A ray without a certificate proves nothing (the file has 3 solutions): the hint says so
  // and names the ways on, never "infeasible".
  const std::string hint = j.at("hint").get<std::string>();
  CHECK(hint.find("proves nothing") != std::string::npos);
  CHECK(hint.find("--solver auto") != std::string::npos);
  CHECK(hint.find("cpkit lcp enumerate") != std::string::npos);
  CHECK_FALSE(j.contains("certificate"));
  r = run_cli("lcp solve " + data("battle_of_the_sexes.json") + " --solver lemke");
  CHECK(r.code == 1);
  CHECK(r.out.find("hint:       Lemke's secondary ray proves nothing") != std::string::npos);
  r = run_cli("lcp solve " + data("murty_exp_6.json") + " --solver lemke --json --max-iter 10");
  CHECK(r.code == 1);
  j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "iteration_limit");
  CHECK(j.at("iterations") == 10);
  CHECK(j.at("hint").get<std::string>().find("--max-iter") != std::string::npos);
  // A proof (a certificate) needs no hint.
  r = run_cli("lcp solve " + data("infeasible_copositive_plus.json") + " --json");
  CHECK(r.code == 1);
  CHECK_FALSE(nlohmann::json::parse(r.out).contains("hint"));
}

TEST_CASE("cli: the default solver is auto, as Python's cpkit.solve (issue 37)", "[cli]") {
  // The README's example: Lemke alone ends on a secondary ray; the default solves it. The
  // answer must be one of the three equilibria the file lists (bimatrix_examples, by hand:
  // two pure, one mixed), each checked here against z >= 0, w = Mz + q >= 0, z.w = 0 too.
  const auto r = run_cli("lcp solve " + data("battle_of_the_sexes.json") + " --json");
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "solved");
  CHECK_FALSE(j.contains("hint"));
  CHECK(j.at("run").at("options").at("solver") == "auto");
  const double M[4][4] = {{0, 0, 1, 3}, {0, 0, 4, 2}, {2, 4, 0, 0}, {3, 1, 0, 0}};
  const double sols[3][4] = {{0.5, 0, 1, 0}, {0, 1, 0, 0.5}, {0.3, 0.1, 0.1, 0.3}};
  int matches = 0;
  for (const auto& s : sols) {
    bool same = true;
    for (int i = 0; i < 4; ++i) same &= std::abs(j["z"][i].get<double>() - s[i]) < 1e-9;
    matches += same;
  }
  CHECK(matches == 1);
  for (int i = 0; i < 4; ++i) {
    double w = -1;
    for (int k = 0; k < 4; ++k) w += M[i][k] * j["z"][k].get<double>();
    CHECK(w >= -1e-9);
    CHECK(std::min(w, j["z"][i].get<double>()) <= 1e-9);
  }
  // --help states the default.
  const auto h = run_cli("lcp solve --help");
  CHECK(h.out.find("default auto") != std::string::npos);
}

TEST_CASE("cli: text report, trace, .dat input", "[cli]") {
  auto r = run_cli("lcp solve " + data("murty_exp_6.json") + " --solver lemke");
  REQUIRE(r.code == 0);
  CHECK(r.out.find("status:     solved") != std::string::npos);
  CHECK(r.out.find("iterations: 64") != std::string::npos);
  r = run_cli("lcp solve " + data("deudeu.json") + " --trace --json");
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out).at("trace").size() == 3);
  // Siconos .dat (n, dense storage 0, sizes), column-major: M = [[2, 1], [0, 3]] is stored as
  // columns (2, 0), (1, 3). q = (-2, -3): z2 = 1 (w2 = 0), w1 = 2 z1 + 1 - 2 = 0 -> z1 = 1/2.
  r = run_cli("lcp solve " + write("p.dat", "2\n0\n2\n2\n2\t2\n2 0\n1 3\n-2 -3\n") + " --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["z"][0].get<double>() == Approx(0.5));
  CHECK(j["z"][1].get<double>() == Approx(1.0));
}

TEST_CASE("cli: options --tol and --time-limit are passed on", "[cli]") {
  auto r = run_cli("lcp solve " + data("deudeu.json") + " --json --tol 1e-3 --time-limit 10");
  CHECK(r.code == 0);
  r = run_cli("lcp solve " + data("deudeu.json") + " --tol -1");
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("tol") != std::string::npos);
  r = run_cli("lcp solve " + data("deudeu.json") + " --time-limit 0");
  CHECK(r.code == 2);
  CHECK(r.out.empty());
}

TEST_CASE("cli: bad input and usage exit 2 with nothing on stdout", "[cli]") {
  const std::string cases[] = {
      "lcp solve /nonexistent/file.json",
      "lcp solve " + write("bad.json", R"({"M": [[1, 2]], "q": [1, 2]})"),
      "lcp solve " + write("nan.json", R"({"M": [[1]], "q": ["x"]})"),
      "lcp solve " + write("bad.dat", "2\n1 2\n3 oops\n5 6\n"),
      "lcp solve " + write("p.txt", "1"),
      "lcp solve " + data("deudeu.json") + " --solver no-such-solver",
      "lcp solve " + data("deudeu.json") + " --no-such-option",
      "lcp solve " + data("deudeu.json") + " --max-iter -3",
      "lcp solve",
      "lcp",
  };
  for (const auto& args : cases) {
    CAPTURE(args);
    const auto r = run_cli(args);
    CAPTURE(r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
  // Messages name the problem.
  CHECK(run_cli("lcp solve " + data("deudeu.json") + " --solver nope").err.find("valid: lemke") !=
        std::string::npos);
  CHECK(run_cli("lcp solve " + write("bad2.dat", "2\n0\n2\n2\n2\t2\n1 2\n3 oops\n5 6\n"))
            .err.find(":7:") != std::string::npos);
  CHECK(run_cli("lcp solve " + write("bad2.json", R"({"M": [[1, 2], [3]], "q": [1, 2]})"))
            .err.find("M row 1") != std::string::npos);
}
