// The run of a `cpkit simulate` request, called directly (requests/simulate_request.hpp): the
// checks and their messages, the runs and their exit codes, the files written. Independent
// sources: hand calculations of the first steps (below), the messages and the caps stated in
// docs/simulation.md and docs/contact_3d.md, and condition (46) of the paper for the stop.
//
// Hand calculation used twice: A = I (a12 = 0 decouples normal and tangential), mu = 0.5,
// C_T = k_a = 0, from state b (P = 0, grazing), the load (F_T, F_N) rising as (0.5, 0.5) then
// (1, 1). Normal: no wear, so g = w_N = 0 and P_N = F_N. Step 1: stick would need P_T = 0.5 >
// mu P_N = 0.25, so slip+: P_T = 0.25, Dw_T = DF_T - DP_T = 0.25. Step 2: P_T = 0.5,
// Dw_T = 0.5 - 0.25 = 0.25. So w_T = slip = 0.5, dissipation P_T1 Dw_Ti summed = 0.0625 +
// 0.125 = 0.1875, stored energy a11 w_T^2 / 2 = 0.125, external work by the trapezoid rule
// 0.25 * 0.25 + 0.75 * 0.25 = 0.25, balance error |0.25 - 0.125 - 0.1875| / 0.25 = 0.25.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/requests/simulate_request.hpp"

using namespace cpkit::rate;
using Catch::Contains;
using Catch::Matchers::WithinAbs;
namespace fs = std::filesystem;

namespace {

/// A folder of this test process for its files, removed at exit.
fs::path scratch() {
  struct Folder {
    fs::path path = fs::temp_directory_path() /
                    ("cpkit_simulate_request_" + std::to_string(::getpid()));
    Folder() { fs::create_directories(path); }
    ~Folder() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const Folder d;
  return d.path;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p.string();
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// a11 = a22 = 1, a12 = 0, mu = 0.5: the model of the hand calculation.
SimulateRequest one_point() {
  SimulateRequest r;
  r.numbers.a11 = 1;
  r.numbers.a12 = 0;
  r.numbers.a22 = 1;
  r.numbers.mu = 0.5;
  return r;
}

/// The message of the InputError the request throws ("" when none).
std::string refusal(const SimulateRequest& r) {
  try {
    run_simulate_request(r);
  } catch (const cpkit::InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kPoint3d = CPKIT_SOURCE_DIR "/docs/examples/fretting_point_3d.json";

}  // namespace

TEST_CASE("simulate request: one point, two slip steps as by hand", "[simulate_request]") {
  SimulateRequest r = one_point();
  r.load = "ramp";
  r.numbers.F_T1 = 1;
  r.numbers.F_N1 = 1;
  r.numbers.steps = 2;
  r.csv = (scratch() / "ramp.csv").string();
  r.run = {{"echo", "given"}};
  const SimulateOutcome o = run_simulate_request(r);
  CHECK(o.exit_code == cpkit::kExitOk);
  const auto& j = o.summary;
  CHECK(j["outcome"] == "completed");
  CHECK(j["steps"] == 2);
  CHECK_THAT(j["final"]["P_T"].get<double>(), WithinAbs(0.5, 1e-12));
  CHECK_THAT(j["final"]["P_N"].get<double>(), WithinAbs(1.0, 1e-12));
  CHECK_THAT(j["final"]["w_T"].get<double>(), WithinAbs(0.5, 1e-12));
  CHECK_THAT(j["total_slip"].get<double>(), WithinAbs(0.5, 1e-12));
  CHECK(j["final_wear_depth"] == 0.0);
  CHECK_THAT(j["energy"]["dissipation"].get<double>(), WithinAbs(0.1875, 1e-12));
  CHECK_THAT(j["energy"]["stored"].get<double>(), WithinAbs(0.125, 1e-12));
  CHECK_THAT(j["energy"]["external_work"].get<double>(), WithinAbs(0.25, 1e-12));
  CHECK_THAT(j["energy"]["balance_error_rel"].get<double>(), WithinAbs(0.25, 1e-12));
  CHECK(j["branch_points"]["count"] == 0);
  CHECK(j["run"] == r.run);  // the program's echo, as given
  // The series (docs/simulation.md, "Time series"): the header, the start and both steps.
  CHECK(o.csv == r.csv);
  std::istringstream rows(slurp(o.csv));
  std::string line;
  std::getline(rows, line);
  CHECK(line.rfind("step,t,F_T,F_N,P_T,P_N,w_T,w_N,w_w,w_Ti,g,state,type", 0) == 0);
  int n = 0;
  while (std::getline(rows, line)) ++n;
  CHECK(n == 3);
  // The text: the docs' first line, the slip and the balance error.
  CHECK(o.text.rfind("simulate: completed after 2 steps\n", 0) == 0);
  CHECK_THAT(o.text, Contains("total slip 0.5\n"));
  CHECK_THAT(o.text, Contains("(relative error 0.25)"));
  CHECK(o.plot_script == "cpkit_plot_simulation.py");
}

TEST_CASE("simulate request: a normal load alone sticks, nothing is written without files",
          "[simulate_request]") {
  SimulateRequest r = one_point();
  r.load = "ramp";
  r.numbers.F_N1 = 1;
  r.numbers.steps = 4;
  const SimulateOutcome o = run_simulate_request(r);
  CHECK(o.exit_code == cpkit::kExitOk);
  CHECK(o.summary["final"]["P_N"] == 1.0);  // DP = DF: Dw = 0 in stick with no wear
  CHECK(o.summary["final"]["P_T"] == 0.0);
  CHECK(o.summary["total_slip"] == 0.0);
  CHECK(o.csv.empty());
  CHECK(o.summary_file.empty());
}

TEST_CASE("simulate request: criterion (35) stops at condition (46), exit 1",
          "[simulate_request]") {
  // docs/simulation.md: P_N <= 3 P_s mu / k_a = 3 * 1 * 0.5 / 0.3 = 5; the ramp's P_N = F_N
  // rises by 10 / 100 a step, so step 51 (P_N = 5.1) has no solution.
  SimulateRequest r = one_point();
  r.numbers.k_a = 0.3;
  r.numbers.F_N1 = 10;
  r.numbers.steps = 100;
  r.criterion = "35";
  r.load = "ramp";
  const SimulateOutcome o = run_simulate_request(r);
  CHECK(o.exit_code == cpkit::kExitNoSolution);
  CHECK(o.summary["outcome"] == "no_solution");
  CHECK(o.summary["steps"] == 50);
  CHECK(o.text.rfind("simulate: no_solution after 50 steps\n", 0) == 0);
}

TEST_CASE("simulate request: N decoupled points are the one-point hand calculation",
          "[simulate_request]") {
  // A = I (4 x 4): point 1 takes the slipping load, point 2 a normal load alone (stick).
  SimulateRequest r;
  r.system = write("two.json", R"({"name": "two", "A": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
      "points": [{"state": "b", "mu": 0.5, "C_T": 0, "k_a": 0, "P_s": 1},
                 {"state": "b", "mu": 0.5, "C_T": 0, "k_a": 0, "P_s": 1}]})");
  r.load_csv = write("two.csv", "0.5,0.5,0.5,0,0.5\n1,1,1,0,1\n");
  r.version = "v-test";
  const SimulateOutcome o = run_simulate_request(r);
  CHECK(o.exit_code == cpkit::kExitOk);
  const auto& j = o.summary;
  CHECK(j["n_points"] == 2);
  CHECK_THAT(j["final"]["P_T"][0].get<double>(), WithinAbs(0.5, 1e-12));
  CHECK_THAT(j["final"]["P_T"][1].get<double>(), WithinAbs(0.0, 1e-12));
  CHECK_THAT(j["final"]["P_N"][1].get<double>(), WithinAbs(1.0, 1e-12));
  CHECK_THAT(j["total_slip"][0].get<double>(), WithinAbs(0.5, 1e-12));
  CHECK(j["complete"] == true);
  CHECK(j["cpkit_version"] == "v-test");
  CHECK(!j.contains("run"));  // the program adds it to what it prints
  CHECK(o.text.rfind("simulate (2 points): completed after 2 steps\n", 0) == 0);
}

TEST_CASE("simulate request: one 3-D point runs lead + ramp + cycles x steps steps",
          "[simulate_request]") {
  SimulateRequest r;
  r.system = kPoint3d;
  r.orbit = {1, 1};
  r.lead_steps = 2;
  r.numbers.cycles = 1;
  r.numbers.steps_per_cycle = 8;
  r.numbers.ramp_steps = 2;
  const SimulateOutcome o = run_simulate_request(r);
  CHECK(o.exit_code == cpkit::kExitOk);
  CHECK(o.summary["dim"] == 3);
  CHECK(o.summary["steps"] == 2 + 2 + 1 * 8);  // docs/contact_3d.md: lead, ramp, orbit steps
  CHECK(o.summary["input"]["orbit"]["lead_steps"] == 2);
  CHECK(o.text.rfind("simulate (3-D point): completed after 12 steps\n", 0) == 0);
  CHECK(o.plot_script == "cpkit_plot_fretting_3d.py");
}

TEST_CASE("simulate request: refused requests name the option", "[simulate_request]") {
  SimulateRequest r = one_point();
  r.numbers.a11.reset();
  CHECK(refusal(r) == "a11 is required (--a11 or parameters.a11 in --config)");

  r = one_point();
  r.load = "ramp";
  r.numbers.F_N = 1;
  CHECK(refusal(r) == "--F_N has no effect here: it needs --load fretting (the load is ramp)");

  r = one_point();
  r.criterion = "36";
  CHECK(refusal(r) == "--criterion must be 38 or 35, got '36'");

  r = one_point();
  r.numbers.cycles = 1.5;
  CHECK(refusal(r) == "--cycles must be an integer in [-2147483648, 2147483647], got 1.5");

  r = one_point();
  r.numbers.k_M = 0.1;
  CHECK_THAT(refusal(r), Contains("is the Mroz-Stupkiewicz wear constant: it needs the wear law"));

  r = one_point();
  r.T_body = {300, 310};
  CHECK(refusal(r) == "--T-body has no effect here: it needs --heat (or heat.enabled)");

  r = one_point();
  r.orbit = {1, 1};
  CHECK(refusal(r) ==
        "--orbit needs a \"dim\": 3 system file (--system FILE; docs/contact_3d.md)");

  r = one_point();
  r.every = 5;  // no series to thin
  CHECK_THAT(refusal(r), Contains("has no effect without a time series"));

  // The step cap of docs/simulation.md: 10^9 ramp steps > 10^8.
  r = one_point();
  r.numbers.ramp_steps = 1e9;
  CHECK_THAT(refusal(r), Contains("kMaxSimulationSteps"));
}

TEST_CASE("simulate request: a 3-D point refuses the 2-D options and bad orbits",
          "[simulate_request]") {
  SimulateRequest r;
  r.system = kPoint3d;
  CHECK(refusal(r) == "a \"dim\": 3 simulation needs --orbit aX aY (the half-axes of the "
                      "tangential load orbit)");
  r.orbit = {1, 1};
  r.numbers.a11 = 1;
  CHECK_THAT(refusal(r), Contains("--a11 has no effect with a \"dim\": 3 system"));
  r.numbers = {};
  r.heat = true;
  CHECK_THAT(refusal(r), Contains("--heat has no effect with a \"dim\": 3 system"));
  r.heat = false;
  r.lead_steps = -1;
  CHECK(refusal(r) == "--lead-steps must be >= 0, got -1");
  r.lead_steps.reset();
  r.numbers.cycles = 0;
  CHECK(refusal(r) == "--cycles must be an integer in [1, 2147483647], got 0");
  r.numbers = {};
  r.numbers.k_M = 0.1;
  CHECK(refusal(r) == "--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
  // Two points: the 3-D simulation is for one.
  r.numbers = {};
  r.system = write("two3d.json", R"({"dim": 3, "A": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],
      [0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]],
      "points": [{"state": "b", "mu": 0.5}, {"state": "b", "mu": 0.5}]})");
  CHECK_THAT(refusal(r), Contains(": 2 points; the 3-D simulation"));
}

TEST_CASE("simulate request: outputs are checked before anything is written",
          "[simulate_request]") {
  SimulateRequest r = one_point();
  r.load = "ramp";
  r.numbers.F_N1 = 1;
  r.numbers.steps = 2;
  r.plot = (scratch() / "guarded").string();
  std::string seen_csv, seen_summary;
  const auto refuse = [&](const SimulateSettings& s) {
    seen_csv = s.csv.empty() ? s.plot + ".csv" : s.csv;
    seen_summary = s.summary;
    throw cpkit::InputError("refused by the program");
  };
  CHECK_THROWS_WITH(run_simulate_request(r, refuse), "refused by the program");
  CHECK(seen_csv == r.plot + ".csv");
  CHECK(seen_summary.empty());
  CHECK(!fs::exists(r.plot + ".csv"));  // nothing written
  // A refused request writes no file either (the check comes before the series is opened).
  r.numbers.mu = -1;
  CHECK_THAT(refusal(r), Contains("mu"));
  CHECK(!fs::exists(r.plot + ".csv"));
  CHECK(!fs::exists(r.plot + ".json"));
}
