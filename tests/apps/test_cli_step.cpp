// `cpkit step` and `cpkit simulate` end to end: runs the built binary (CPKIT_BINARY_DIR
// "/apps/cpkit"), checks the JSON fields, the exit codes (0 solution / completed, 1 none /
// stopped, 2 bad input with nothing on stdout) and the files `simulate` writes.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"
#include "peer_skip.hpp"

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

const std::string kLambdaNegative =
    "step --a11 1 --a12 0.9 --a22 1 --mu 2 --P_T0 2 --P_N0 1 --g0 0 ";

}  // namespace

TEST_CASE("CliStepAllJsonListsEverySolution", "[cli][step]") {
  // State d with Lambda = a11 - mu a12 = -0.8 < 0, L_+ = dF_T < 0: stick, slip+ (dP_N =
  // -a12 dF_T / Lambda = -0.01125, hand-derived from eqn (51)) and the jump to separation.
  const Run r = run_cli(kLambdaNegative + "--DF -0.01 0 --all --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 3);
  CHECK(j["types"] == nlohmann::json({"separation", "slip+", "stick"}));
  REQUIRE(j["solutions"].size() == 3);
  for (const auto& s : j["solutions"]) {
    CHECK(s["kind"] == "point");
    for (const char* k : {"DP_T", "DP_N", "Dw_T", "Dw_N", "Dw_Ti", "Dw_w", "P_T1", "P_N1", "g1"})
      CHECK(s["values"].contains(k));
    if (s["type"] == "slip+") CHECK(s["values"]["DP_N"].get<double>() == Approx(-0.01125));
    if (s["type"] == "separation") {
      CHECK(s["jump"] == true);
      CHECK(s["values"]["P_N1"].get<double>() == 0.0);
    }
  }
}

TEST_CASE("CliStepJumpWhereTheRateHasNone", "[cli][step]") {
  const Run r = run_cli(kLambdaNegative + "--DF 0.01 0 --all");
  CHECK(r.code == 0);
  CHECK(r.out.find("separation (point, jump)") != std::string::npos);
  CHECK(r.out.find("the rate problem has no solution") != std::string::npos);
}

TEST_CASE("CliStepOneSolutionByTheChain", "[cli][step]") {
  // From state b without wear, a11 > mu|a12|: the rate solution times the increment. Load
  // (2, 1): N = a11 dF_N - a12 dF_T = 0.4 > 0, slip+ with dP_N = N / (a11 - mu a12) = 0.4/0.85.
  const Run r = run_cli("step --a11 1 --a12 0.3 --a22 1 --mu 0.5 --P_T0 0 --P_N0 0 --g0 0 "
                      "--DF 2 1 --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["status"] == "solved");
  CHECK(j["type"] == "slip+");
  CHECK(j["values"]["DP_N"].get<double>() == Approx(0.4 / 0.85));
  CHECK(j["values"]["DP_T"].get<double>() == Approx(0.5 * 0.4 / 0.85));
}

TEST_CASE("CliStepSegmentIsOpenAtItsStickEnd", "[cli][step]") {
  // Issue 11, sec. 4 (hand calculation in tests/rate_problem/test_step_enumeration.cpp,
  // StickEndOfAStickSlipSegmentIsStick): a11 = a12 = mu = 1, a22 = 2, DF = (0.5, 0.5) from
  // state b. slip+ segment from zero-force slip (Dw_Ti = 0.5, closed) to the stick point
  // (DP = (0.5, 0.5), Dw_Ti = 0; open), and the stick point listed on its own.
  const Run r = run_cli("step --a11 1 --a12 1 --a22 2 --mu 1 --P_T0 0 --P_N0 0 --g0 0 "
                        "--DF 0.5 0.5 --all --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == "inf");
  REQUIRE(j["solutions"].size() == 2);
  const auto& stick = j["solutions"][0];
  CHECK(stick["type"] == "stick");
  CHECK(stick["kind"] == "point");
  CHECK(stick["values"]["DP_N"].get<double>() == Approx(0.5));
  CHECK(stick["values"]["DP_T"].get<double>() == Approx(0.5));
  const auto& seg = j["solutions"][1];
  CHECK(seg["type"] == "slip+");
  REQUIRE(seg["kind"] == "segment");
  for (const char* end : {"start", "end"}) {
    const bool at_stick = std::abs(seg[end]["Dw_Ti"].get<double>()) < 1e-12;
    CHECK(seg[std::string(end) + "_closed"] == !at_stick);
    CHECK(seg[end]["DP_N"].get<double>() == Approx(at_stick ? 0.5 : 0.0).margin(1e-12));
  }
  const Run t = run_cli("step --a11 1 --a12 1 --a22 2 --mu 1 --P_T0 0 --P_N0 0 --g0 0 "
                        "--DF 0.5 0.5 --all");
  CHECK(t.out.find("(open)") != std::string::npos);
}

TEST_CASE("CliStepExitCodes", "[cli][step]") {
  // Criterion (35) with mu/k = 5: no solution above P_N = 5.
  const Run none = run_cli("step --a11 1 --a12 0 --a22 1 --mu 0.5 --k_a 0.3 --criterion 35 "
                         "--P_T0 0 --P_N0 4.9 --g0 0 --DF 0 0.2 --all --json");
  CHECK(none.code == 1);
  CHECK(nlohmann::json::parse(none.out)["count"] == 0);
  for (const std::string bad :
       {"--P_T0 0 --P_N0 1 --g0 0.1 --DF 0 1", "--P_T0 0 --P_N0 -1 --g0 0 --DF 0 1",
        "--P_T0 1 --P_N0 1 --g0 0 --DF 0 1", "--P_T0 0 --P_N0 1 --g0 0 --DF 0 nan",
        "--P_T0 0 --P_N0 1 --g0 0 --DF 0", "--P_T0 0 --P_N0 1 --g0 0 --DF 0 1 --criterion 40"}) {
    const Run r = run_cli("step --a11 1 --a12 0 --a22 1 --mu 0.5 " + bad + " --all --json");
    CAPTURE(bad, r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
}

TEST_CASE("CliSimulateFromTheExampleConfig", "[cli][simulate]") {
  const fs::path dir = scratch_dir() / "sim";
  fs::create_directories(dir);
  const std::string cfg = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/fretting.json";
  const std::string csv = (dir / "run.csv").string(), sum = (dir / "run.json").string();
  const Run r = run_cli("simulate --config '" + cfg + "' --cycles 3 --csv '" + csv +
                      "' --summary '" + sum + "' --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["outcome"] == "completed");
  CHECK(j["steps"] == 10 + 3 * 100);
  CHECK(j["slip_per_cycle"].size() == 3);
  CHECK(j["final_wear_depth"].get<double>() > 0);
  CHECK(j["final_wear_depth"].get<double>() ==
        Approx(j["wear_integral"].get<double>()).epsilon(1e-12));
  CHECK(j["energy"]["balance_error_rel"].get<double>() < 1e-2);
  CHECK(j.contains("branch_points"));
  CHECK(j.contains("temperature"));
  // The CSV: header plus one row per step and the initial state.
  std::ifstream in(csv);
  std::string line;
  int rows = 0;
  std::getline(in, line);
  CHECK(line.rfind("step,t,F_T,F_N,P_T,P_N,w_T,w_N,w_w,w_Ti,g,state,type", 0) == 0);
  while (std::getline(in, line)) ++rows;
  CHECK(rows == 311);
  CHECK(fs::exists(sum));
  // Figures (the script is run with /usr/bin/python3; skipped without matplotlib).
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0) {
    const std::string prefix = (dir / "fig").string();
    const Run p = run_cli("simulate --config '" + cfg + "' --cycles 2 --csv '" + csv +
                        "' --summary '" + sum + "' --plot '" + prefix + "'");
    REQUIRE(p.code == 0);
    // simulate names every file it wrote, and nothing else goes to stderr.
    std::string expected;
    for (const std::string& w : {csv, sum})
      expected += "cpkit simulate: wrote " + w + "\n";
    for (const char* f : {"_loop", "_wear", "_state"})
      for (const char* ext : {".png", ".svg"})
        expected += "cpkit simulate: wrote " + prefix + f + ext + "\n";
    CHECK(p.err == expected);
    for (const char* f : {"_loop", "_wear", "_state"})
      for (const char* ext : {".png", ".svg"}) CHECK(fs::exists(prefix + f + ext));
  } else {
    CPKIT_SKIP_CHECK("matplotlib not available to /usr/bin/python3: figures not checked");
  }
}

TEST_CASE("CliSimulateStopsAndReportsAndRejectsBadInput", "[cli][simulate]") {
  const Run stop = run_cli("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --k_a 0.3 --criterion 35 "
                         "--load ramp --F_N1 10 --steps 100");
  CHECK(stop.code == 1);
  CHECK(stop.out.find("no solution") != std::string::npos);
  CHECK(stop.out.find("t = 0.51") != std::string::npos);
  const fs::path bad = scratch_dir() / "bad.json";
  std::ofstream(bad) << R"({"parameters": {"a11": 1, "a12": 0, "a22": 1, "mu": 0.5, "typo": 1}})";
  for (const std::string& args :
       {"simulate --config '" + bad.string() + "'", std::string("simulate --a11 1 --a12 0 --a22 1"),
        std::string("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --load csv"),
        std::string("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --cycles 0"),
        std::string("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --cycles 2.5"),
        std::string("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --heat --T-ref -3")}) {
    const Run r = run_cli(args);
    CAPTURE(args, r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
  }
}

TEST_CASE("CliStepSystemIsTheProductOfOnePointSteps", "[cli][step][system]") {
  // Two points that do not interact (block-diagonal A): point 1 is the Lambda < 0 case above
  // (3 solutions), point 2 a stick state with a unique solution. The N-point step must list
  // the 3 x 1 combinations, each point's values equal to the one-point `cpkit step --all`.
  const fs::path sys = scratch_dir() / "two_independent.json";
  {
    std::ofstream f(sys);
    f << R"({"name": "two independent points",
 "A": [[1, 0.9, 0, 0], [0.9, 1, 0, 0], [0, 0, 2, 0.3], [0, 0, 0.3, 1.5]],
 "points": [{"P_T": 2, "P_N": 1, "g": 0, "mu": 2},
            {"P_T": 0.1, "P_N": 1, "g": 0, "mu": 0.5}]})";
  }
  const Run r = run_cli("step --system '" + sys.string() + "' --DF -0.01 0 0.05 0.02 --all --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 3);
  CHECK(j["complete"] == true);
  CHECK(j["n_points"] == 2);
  CHECK(j["input"]["DF"].size() == 4);
  CHECK(j.contains("cpkit_version"));
  const auto one1 = nlohmann::json::parse(run_cli(kLambdaNegative + "--DF -0.01 0 --all --json").out);
  const auto one2 = nlohmann::json::parse(
      run_cli("step --a11 2 --a12 0.3 --a22 1.5 --mu 0.5 --P_T0 0.1 --P_N0 1 --g0 0 --DF 0.05 0.02 --all --json").out);
  REQUIRE(one2["count"] == 1);
  for (const auto& s : j["solutions"]) {
    CHECK(s["types"][1] == one2["solutions"][0]["type"]);
    CHECK(s["values"]["DP_T"][1].get<double>() ==
          Approx(one2["solutions"][0]["values"]["DP_T"].get<double>()).margin(1e-12));
    bool found = false;
    for (const auto& o : one1["solutions"])
      found = found || (o["type"] == s["types"][0] &&
                        std::abs(o["values"]["DP_N"].get<double>() - s["values"]["DP_N"][0].get<double>()) <= 1e-9 &&
                        std::abs(o["values"]["Dw_Ti"].get<double>() - s["values"]["Dw_Ti"][0].get<double>()) <= 1e-9);
    CHECK(found);
  }
}

TEST_CASE("CliStepSystemBadInput", "[cli][step][system]") {
  const std::string sys = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/three_point_punch.json";
  Run r = run_cli("step --system '" + sys + "' --DF 0.2 0.1 --all");
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("--dF needs 6 numbers") != std::string::npos);
  r = run_cli("step --system '" + sys + "' --DF 0 0 0 0 0 0 --all --mu 3");
  CHECK(r.code == 2);
  CHECK(r.err.find("--mu cannot be combined with --system") != std::string::npos);
  r = run_cli("step --system '" + sys + "' --DF 0 0 0 0 0 0");
  CHECK(r.code == 2);
  CHECK(r.err.find("--all") != std::string::npos);
  r = run_cli("step --system /nonexistent.json --DF 0 0 --all");
  CHECK(r.code == 2);
}

TEST_CASE("CliSimulateSystemOfIndependentPointsEqualsOneSimulationEach", "[cli][simulate][system]") {
  // Two points that do not interact, the fretting cycle through the patterns (1,0,1,0) and
  // (0,1,0,1): every point must wear as the one-point `cpkit simulate` of its own parameters.
  const fs::path dir = scratch_dir() / "sim_system";
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "system.json");
    f << R"({"A": [[2, 0.3, 0, 0], [0.3, 1.5, 0, 0], [0, 0, 2, 0.3], [0, 0, 0.3, 1.5]],
 "points": [{"state": "b", "mu": 0.5, "C_T": 0.4, "k_a": 0.01},
            {"state": "b", "mu": 0.5, "C_T": 0.4, "k_a": 0.02}],
 "patterns": [[1, 0, 1, 0], [0, 1, 0, 1]]})";
    std::ofstream c(dir / "config.json");
    c << R"({"system": "system.json",
 "load": {"type": "fretting", "F_N": 1, "amplitude": 1.2, "cycles": 3, "steps_per_cycle": 40}})";
  }
  const Run r = run_cli("simulate --config '" + (dir / "config.json").string() + "' --csv '" +
                        (dir / "run.csv").string() + "' --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["n_points"] == 2);
  CHECK(j["complete"] == true);  // m <= 2 everywhere
  const char* k_a[2] = {"0.01", "0.02"};
  for (int i = 0; i < 2; ++i) {
    const auto one = nlohmann::json::parse(
        run_cli(std::string("simulate --a11 2 --a12 0.3 --a22 1.5 --mu 0.5 --C_T 0.4 --k_a ") +
                k_a[i] + " --F_N 1 --amplitude 1.2 --cycles 3 --steps-per-cycle 40 --json")
            .out);
    CHECK(j["final_wear_depth"][i].get<double>() ==
          Approx(one["final_wear_depth"].get<double>()).epsilon(1e-9));
    CHECK(j["total_slip"][i].get<double>() == Approx(one["total_slip"].get<double>()).epsilon(1e-9));
  }
  // The streamed CSV: header + start + every step.
  const std::string csv = slurp(dir / "run.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 1 + j["steps"].get<long>());
  const Run bad = run_cli("simulate --config '" + (dir / "config.json").string() + "' --mu 0.3");
  CHECK(bad.code == 2);
  CHECK(bad.err.find("cannot be combined with a system") != std::string::npos);
}

TEST_CASE("CliStepInAnyUnitsAndAtTheEndsOfDoublesRange", "[cli][step][units]") {
  // Issue 24 item 3: A = 1e10 [[1, 0.3], [0.3, 1.2]], DF = (1, 0.5) from grazing: one slip+
  // (hand: P_N1 = 4/17, P_T1 = 2/17, Dw_T^i = 15/17 1e-10); no penetrating "separation".
  const Run r = run_cli("step --a11 1e10 --a12 3e9 --a22 1.2e10 --mu 0.5 --P_T0 0 --P_N0 0 "
                        "--g0 0 --DF 1 0.5 --all --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 1);
  CHECK(j["complete"] == true);
  CHECK(j["types"] == nlohmann::json({"slip+"}));
  CHECK(j["solutions"][0]["values"]["P_N1"].get<double>() == Approx(4.0 / 17).epsilon(1e-12));
  CHECK(j["solutions"][0]["values"]["Dw_Ti"].get<double>() ==
        Approx(15.0 / 17 * 1e-10).epsilon(1e-12));
  // cond(A) = 1e7: one slip- (exact rational solution: DP_N = 0.1802709301241728,
  // Dw_T^i = -1.583259173274164e-11, 43 % of Dw_T), never "stick".
  const Run c = run_cli("step --a11 127600897.60974222 --a12 34985746.76265956 "
                        "--a22 9592443.16983857 --mu 1.468801105377418 --C_T 7.96941781947783e-11 "
                        "--P_T0 0 --P_N0 0 --g0 0 --DF -0.2694949768340834 0.17897876001458093 "
                        "--all --json");
  INFO(c.err);
  REQUIRE(c.code == 0);
  const auto k = nlohmann::json::parse(c.out);
  CHECK(k["types"] == nlohmann::json({"slip-"}));
  CHECK(k["count"] == 1);
  CHECK(k["solutions"][0]["values"]["Dw_Ti"].get<double>() ==
        Approx(-1.583259173274164e-11).epsilon(1e-6));
  // Item 5: DF = (1.7e308, 1): the separation has Dw_T = 1.84e308 > DBL_MAX: refused, exit 2,
  // as `rate` and `simulate` do; DF = (1e308, 1): the separation, Dw_T = 1.2e308 / 1.11.
  const std::string unit = "--a11 1 --a12 0.3 --a22 1.2 --mu 0.5 ";
  for (const std::string& cmd :
       {"step " + unit + "--P_T0 0 --P_N0 0 --g0 0 --DF 1.7e308 1 --all",
        "step " + unit + "--P_T0 0 --P_N0 0 --g0 0 --DF 1.7e308 1",
        "rate --state b " + unit + "--dF 1.7e308 1",
        "simulate " + unit + "--load ramp --F_T1 1.7e308 --F_N1 1 --steps 1"}) {
    const Run b = run_cli(cmd);
    CAPTURE(cmd, b.out);
    CHECK(b.code == 2);
    CHECK(b.err.find("not representable") != std::string::npos);
  }
  const Run big = run_cli("step " + unit + "--P_T0 0 --P_N0 0 --g0 0 --DF 1e308 1 --all --json");
  INFO(big.err);
  REQUIRE(big.code == 0);
  const auto bj = nlohmann::json::parse(big.out);
  CHECK(bj["types"] == nlohmann::json({"separation"}));
  CHECK(bj["solutions"][0]["values"]["Dw_T"].get<double>() == Approx(1.2e308 / 1.11).epsilon(1e-13));
  // Subnormal loads: DF = (1e-320, 0.5e-320) is the (1, 0.5) problem scaled: one slip+.
  const Run sub = run_cli("step " + unit + "--P_T0 0 --P_N0 0 --g0 0 --DF 1e-320 5e-321 --all --json");
  INFO(sub.err);
  REQUIRE(sub.code == 0);
  CHECK(nlohmann::json::parse(sub.out)["types"] == nlohmann::json({"slip+"}));
  const Run rsub = run_cli("rate --state b " + unit + "--dF 1e-320 5e-321 --json");
  REQUIRE(rsub.code == 0);
  CHECK(nlohmann::json::parse(rsub.out)["types"] == nlohmann::json({"slip+"}));
}
