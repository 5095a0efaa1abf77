// `cpkit rate --system FILE`: JSON layout, values from a hand case, exit codes on bad input.
#include <catch2/catch.hpp>
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
