// `cpkit rate --system FILE`: JSON layout, values from a hand case, exit codes on bad input.
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace {

std::string write_system(const std::string& name, const std::string& text) {
  const auto p = cpkit::test::scratch_dir() / name;
  std::ofstream(p) << text;
  return "'" + p.string() + "'";
}

// Point 1: the hand case of Fig. 5b (A = [[1,2],[2,5]], mu = 1, state b, dF = (1, 1.2): three
// solutions, slip+ with dP = (0.8, 0.8), dw_T^i = 0.2); point 2: state c with identity block,
// uncoupled: stick, dw = 0, dP = dF = (0.5, 1).
const char* kSystem = R"({"name": "hand", "A": [[1, 2, 0, 0], [2, 5, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
 "points": [{"state": "b", "mu": 1}, {"state": "c", "mu": 1, "P_N": 1}],
 "dF": [1, 1.2, 0.5, 1]})";

}  // namespace

TEST_CASE("cpkit rate --system: a product of a hand case and a stick point", "[cli][rate][system]") {
  const std::string f = write_system("hand.json", kSystem);
  const auto r = cpkit::test::run_cpkit("rate --system " + f + " --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 3);
  CHECK(j["n_points"] == 2);
  CHECK(j["input"]["dF"].size() == 4);
  CHECK(j.contains("cpkit_version"));
  bool found = false;
  for (const auto& s : j["solutions"]) {
    CHECK(s["kind"] == "point");
    CHECK(s["types"][1] == "stick");
    if (s["types"][0] == "slip+") {
      found = true;
      CHECK(s["values"]["dP_T"][0].get<double>() == Approx(0.8));
      CHECK(s["values"]["dP_N"][0].get<double>() == Approx(0.8));
      CHECK(s["values"]["dw_Ti"][0].get<double>() == Approx(0.2));
      CHECK(s["values"]["dP_T"][1].get<double>() == Approx(0.5));
      CHECK(s["values"]["dP_N"][1].get<double>() == Approx(1.0));
    }
  }
  CHECK(found);
  // --dF overrides the file's; lemke gives one solution inside the set
  const auto l = cpkit::test::run_cpkit("rate --system " + f + " --dF 1 1.2 0.5 1 --method lemke --json");
  INFO(l.err);
  CHECK(l.code == 0);
  CHECK(nlohmann::json::parse(l.out)["complete"] == false);
}

TEST_CASE("cpkit rate --system: bad input exits 2 naming the problem", "[cli][rate][system]") {
  const std::string f = write_system("hand2.json", kSystem);
  auto r = cpkit::test::run_cpkit("rate --system " + f + " --dF 1 2 3");
  CHECK(r.code == 2);
  CHECK(r.err.find("--dF") != std::string::npos);
  r = cpkit::test::run_cpkit("rate --system " + f + " --method analytic");
  CHECK(r.code == 2);
  CHECK(r.err.find("--method") != std::string::npos);
  r = cpkit::test::run_cpkit("rate --system " + f + " --state b");
  CHECK(r.code == 2);
  const std::string bad = write_system("bad.json", R"({"A": [[1, 0], [0, 1]], "points": [{"state": "d", "P_N": 1}]})");
  r = cpkit::test::run_cpkit("rate --system " + bad);
  CHECK(r.code == 2);
  CHECK(r.err.find("point 1") != std::string::npos);
  CHECK(r.err.find("sgnPT") != std::string::npos);
  CHECK(r.out.empty());
}

TEST_CASE("cpkit rate/step/simulate --system: loads near 1e308 rescaled or refused alike",
          "[cli][rate][step][system]") {
  // Issue 24, item 5: `step --system coupled_grazing_points.json --DF 1e308 1 0.1 1 --all`
  // answered "0 solution(s) (complete)" where `rate` said "not representable". The load is
  // 1e308 (1, ~0, ~0, ~0): both grazing points separate (dP = 0, dw = A^-1 dF has dw_N < 0,
  // checked in test_system_rate.cpp); rate and step (P = 0, g = 0, no wear: the rate problem
  // times 1) must both say so.
  const std::string f = "'" + std::string(CPKIT_SOURCE_DIR) + "/docs/examples/coupled_grazing_points.json'";
  auto r = cpkit::test::run_cpkit("rate --system " + f + " --dF 1e308 1 0.1 1 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  CHECK(j["count"] == 1);
  CHECK(j["solutions"][0]["types"] == nlohmann::json({"separation", "separation"}));
  r = cpkit::test::run_cpkit("step --system " + f + " --DF 1e308 1 0.1 1 --all --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  CHECK(j["count"] == 1);
  CHECK(j["solutions"][0]["types"] == nlohmann::json({"separation", "separation"}));
  CHECK(j["solutions"][0]["values"]["P_N1"][0] == 0.0);
  // The same system 1000 x softer: dw = 1e311 A^-1 e1 is beyond double: refused by both (2),
  // and a simulation reaching that step stops there (numerical_failure, 1), never "0 solutions".
  const std::string soft = write_system("soft.json", R"({"A": [[0.00203, 0.00025, -0.00123, 0.00158],
       [0.00025, 0.00376, 0.00123, 0.00026], [-0.00123, 0.00123, 0.00212, -0.00099],
       [0.00158, 0.00026, -0.00099, 0.00205]],
       "points": [{"state": "b", "mu": 7.71}, {"state": "b", "mu": 2.03}]})");
  r = cpkit::test::run_cpkit("rate --system " + soft + " --dF 1e308 0 0 0");
  CHECK(r.code == 2);
  CHECK(r.err.find("not representable") != std::string::npos);
  r = cpkit::test::run_cpkit("step --system " + soft + " --DF 1e308 0 0 0 --all");
  CHECK(r.code == 2);
  CHECK(r.err.find("not representable") != std::string::npos);
  const auto csv = cpkit::test::scratch_dir() / "big_load.csv";
  std::ofstream(csv) << "t,F_T1,F_N1,F_T2,F_N2\n1,1e308,0,0,0\n";
  r = cpkit::test::run_cpkit("simulate --system " + soft + " --load csv --load-csv '" + csv.string() + "' --json");
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(nlohmann::json::parse(r.out)["outcome"] == "numerical_failure");
  CHECK(r.out.find("not representable") != std::string::npos);
}

TEST_CASE("cpkit rate --system: a 1000-point enumeration is refused right after reading "
          "(issue 24, item 12)", "[cli][rate][system]") {
  // 1000 grazing points (state b), A = 2 I: the rate LCP has 3 * 1000 = 3000 variables (hand
  // count), beyond the enumeration's 64. It used to run the N^3 precomputation for minutes.
  const int N = 1000;
  std::string a = "[", pts = "[", dF = "[";
  for (int i = 0; i < 2 * N; ++i) {
    a += std::string(i ? "," : "") + "[";
    for (int j = 0; j < 2 * N; ++j) a += std::string(j ? "," : "") + (i == j ? "2" : "0");
    a += "]";
    dF += std::string(i ? "," : "") + (i % 2 ? "1" : "0.1");
  }
  for (int i = 0; i < N; ++i) pts += std::string(i ? "," : "") + R"({"state": "b", "mu": 0.5})";
  const std::string f = write_system("thousand.json", R"({"A": )" + a + "], \"points\": " + pts +
                                                          "], \"dF\": " + dF + "]}");
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = cpkit::test::run_cpkit("rate --system " + f);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.find("the rate LCP has size 3000") != std::string::npos);
  CHECK(r.err.find("at most 64") != std::string::npos);
  CHECK(s < 60);  // bound for a sanitizer build; reading the 8 MB file is most of it
}
