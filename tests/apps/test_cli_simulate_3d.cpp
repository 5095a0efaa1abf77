// `cpkit simulate --system FILE` with a "dim": 3 file (apps/simulate_3d.cpp): fretting of one
// 3-D point under an elliptic load orbit. Runs the built binary; checks the JSON fields and the
// input echo, the streamed CSV (its wear increments sum to the summary's wear), the exit codes
// (2 for N > 1 points, 2-D-only options, bad values; nothing on stdout), and that the command
// line's total wear equals the library's (simulate_fretting_3d) for the same inputs.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace {

using cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;
using cpkit::test::slurp;

const std::string kExample = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/fretting_point_3d.json";
const std::string kBase = "simulate --system '" + kExample + "' --orbit 0.9 0.5 --cycles 3 "
                          "--steps-per-cycle 40 ";

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> v;
  std::stringstream ss(line);
  std::string x;
  while (std::getline(ss, x, ',')) v.push_back(x);
  return v;
}

}  // namespace

TEST_CASE("Simulate3dJsonEchoesInputsAndMatchesTheLibrary", "[cli][simulate3d]") {
  const CliRun r = run_cpkit(kBase + "--orbit-angle 0.3 --F_N 1.2 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["dim"] == 3);
  CHECK(j.contains("cpkit_version"));
  CHECK(j["run"].contains("cpkit_version"));
  CHECK(j["outcome"] == "completed");
  CHECK(j["input"]["orbit"]["a_X"] == 0.9);
  CHECK(j["input"]["orbit"]["a_Y"] == 0.5);
  CHECK(j["input"]["orbit"]["angle"] == 0.3);
  CHECK(j["input"]["orbit"]["F_N"] == 1.2);
  CHECK(j["input"]["orbit"]["cycles"] == 3);
  CHECK(j["input"]["orbit"]["lead_steps"] == 10);
  CHECK(j["input"]["point"]["alpha"] == nlohmann::json({0.6, 1.0}));
  CHECK(j["input"]["wear"]["law"] == "archard");
  for (const char* k : {"final", "final_wear_depth", "wear_integral", "total_slip", "total_lambda",
                        "slip_per_cycle", "wear_per_cycle", "wear_X_per_cycle",
                        "wear_Y_per_cycle", "dissipation", "min_step_dissipation_rel",
                        "branch_points", "incomplete_steps", "complete", "max_step_residual"})
    CHECK(j.contains(k));
  CHECK(j["wear_per_cycle"].size() == 3);
  CHECK(j["steps"] == 10 + 10 + 120);
  // The same run through the library.
  const auto sys = cpkit::rate::read_contact_system_3d(kExample);
  cpkit::rate::Fretting3dOptions o;
  o.params = sys.point_parameters(0);
  o.record_every = 0;
  cpkit::rate::EllipticOrbit b;
  b.F_N = 1.2;
  b.a_X = 0.9;
  b.a_Y = 0.5;
  b.angle = 0.3;
  b.cycles = 3;
  b.steps_per_cycle = 40;
  const auto lib = cpkit::rate::simulate_fretting_3d(b, o);
  const double w = j["final_wear_depth"].get<double>();
  CHECK(w > 1e-3);
  CHECK(std::abs(w - lib.wear_depth) <= 1e-12 * lib.wear_depth);
  CHECK(std::abs(j["wear_integral"].get<double>() - lib.wear_integral) <= 1e-12 * w);
}

TEST_CASE("Simulate3dCsvSummaryAndText", "[cli][simulate3d]") {
  const auto csv = scratch_dir() / "f3d.csv";
  const auto sum = scratch_dir() / "f3d.json";
  const CliRun r = run_cpkit(kBase + "--csv '" + csv.string() + "' --summary '" + sum.string() + "'");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("simulate (3-D point): completed after 140 steps") != std::string::npos);
  CHECK(r.out.find("last cycle: wear") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(sum));
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  const auto head = split(line);
  CHECK(head.front() == "step");
  CHECK(head.size() == 24);
  std::size_t iw = 0, idw = 0;
  for (std::size_t i = 0; i < head.size(); ++i) {
    if (head[i] == "w_w") iw = i;
    if (head[i] == "Dw_w") idw = i;
  }
  REQUIRE(iw > 0);
  REQUIRE(idw > 0);
  double sum_dw = 0, last_w = 0;
  int rows = 0;
  while (std::getline(in, line)) {
    const auto v = split(line);
    REQUIRE(v.size() == head.size());
    sum_dw += std::stod(v[idw]);
    last_w = std::stod(v[iw]);
    ++rows;
  }
  CHECK(rows == 141);  // start state + every step
  const double w = j["final_wear_depth"].get<double>();
  CHECK(std::abs(sum_dw - w) < 1e-9 * w);
  CHECK(std::abs(last_w - w) < 1e-9 * w);
  // --every thins the series; the summary is unchanged.
  const CliRun r2 = run_cpkit(kBase + "--every 10 --csv '" + csv.string() + "' --json");
  REQUIRE(r2.code == 0);
  std::ifstream in2(csv);
  int n2 = 0;
  while (std::getline(in2, line)) ++n2;
  CHECK(n2 == 1 + 1 + 14);
  CHECK(nlohmann::json::parse(r2.out)["final_wear_depth"] == j["final_wear_depth"]);
}

TEST_CASE("Simulate3dMrozWithKmMuEqualsArchard", "[cli][simulate3d]") {
  // The example's k = k_a / (3 P_s) = 0.01, mu = 0.5: k_M = 0.02. The file needs k_a = 0.
  const auto f = scratch_dir() / "mroz3d.json";
  std::ofstream(f) << R"({"dim": 3, "A": [[2.0, 0.2, 0.3], [0.2, 1.5, -0.1], [0.3, -0.1, 1.5]],
    "points": [{"state": "b", "mu": 0.5, "C_T": 0.2, "P_s": 1, "alpha": [0.6, 1.0]}]})";
  const CliRun m = run_cpkit("simulate --system '" + f.string() + "' --orbit 0.9 0.5 --cycles 3 "
                             "--steps-per-cycle 40 --wear-law mroz --k_M 0.02 --json");
  const CliRun a = run_cpkit(kBase + "--json");
  INFO(m.err);
  REQUIRE(m.code == 0);
  REQUIRE(a.code == 0);
  const double wm = nlohmann::json::parse(m.out)["final_wear_depth"].get<double>();
  const double wa = nlohmann::json::parse(a.out)["final_wear_depth"].get<double>();
  CHECK(std::abs(wm - wa) < 1e-9 * wa);
}

TEST_CASE("Simulate3dBadInputIsExit2", "[cli][simulate3d]") {
  const std::string two = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/two_point_system_3d.json";
  const std::vector<std::string> bad = {
      "simulate --system '" + two + "' --orbit 1 1",     // N > 1
      "simulate --system '" + kExample + "'",             // no orbit
      kBase + "--a11 2",                                  // 2-D-only options
      kBase + "--amplitude 0.3",
      kBase + "--mu 0.4",
      kBase + "--heat",
      kBase + "--load ramp",
      kBase + "--criterion 35",
      kBase + "--k_M 0.1",                                // k_M without mroz
      kBase + "--wear-law mroz --k_M 0.1",                // k_a in the file with mroz
      kBase + "--wear-law bogus",
      kBase + "--branch-rule sometimes",
      kBase + "--period 0",
      kBase + "--cycles 2.5",
      kBase + "--F_N -1",
      kBase + "--lead-steps -3",
      "simulate --system '" + kExample + "' --orbit nan 1",
      "simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --orbit 1 1",  // 3-D option in a 2-D run
      "simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --orbit-angle 1",
  };
  for (const auto& args : bad) {
    const CliRun r = run_cpkit(args);
    INFO(args << "\n" << r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
  // A point that does not start grazing.
  const auto f = scratch_dir() / "stick3d.json";
  std::ofstream(f) << R"({"dim": 3, "A": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    "points": [{"state": "c", "P_N": 1, "mu": 0.5}]})";
  const CliRun r = run_cpkit("simulate --system '" + f.string() + "' --orbit 1 1");
  CHECK(r.code == 2);
  CHECK(r.err.find("state b") != std::string::npos);
}
