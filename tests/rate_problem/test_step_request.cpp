// Tests of what `cpkit step` was asked (requests/step_request.hpp) and of its text
// (report/step_text.hpp), without the program. Every expected value comes from an independent
// source: hand calculations (in the comments) of steps whose answer is a closed form (a stick
// step is DP = DF; an open 3-D step is DP = 0, Dw = A^-1 DF; a softening step beyond condition
// (46) has no solution), the worked example of docs/simulation.md ("cpkit step") with its
// documented text, a solution set known to be infinite (docs/simulation.md's segment, embedded in
// 3-D), and the messages the command documents and its CLI tests expect.
#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/step_text.hpp"
#include "cpkit/rate_problem/requests/step_request.hpp"

namespace {

using namespace cpkit::rate;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

/// One 2-D point: A = [[a11, a12], [a12, a22]], mu, start (P_T0, P_N0, g0), load (DFT, DFN):
/// every required option given.
StepRequest point(double a11, double a12, double a22, double mu, double P_T0, double P_N0,
                  double g0, double DFT, double DFN) {
  StepRequest r;
  r.model.a11 = a11;
  r.model.a12 = a12;
  r.model.a22 = a22;
  r.model.mu = mu;
  r.P_T0 = P_T0;
  r.P_N0 = P_N0;
  r.g0 = g0;
  r.DF = {DFT, DFN};
  return r;
}

/// A request on a system file given as text (read once, as the program does).
StepRequest with_file(const std::string& text, std::vector<double> DF) {
  StepRequest r;
  r.system = "sys.json";
  r.file = parse_system_file(text, "sys.json");
  r.DF = std::move(DF);
  return r;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(b)); }

// A = diag(2, 2, 4) per point, open (state a): with --g0 -1 and DF = (0.2, -0.4, 0.4) the gap
// stays open, g1 = -1 + 0.4 / 4 = -0.9 < 0, so the step is DP = 0, Dw = A^-1 DF =
// (0.1, -0.2, 0.1); a contact solution would need DP_N = DF_N - 4 = -3.6 < -P_N0 = 0.
const char* kOpen3d =
    R"({"name": "open", "dim": 3, "A": [[2, 0, 0], [0, 2, 0], [0, 0, 4]],
        "points": [{"mu": 0.5, "state": "a"}]})";
const char* kTwoOpen3d =
    R"({"name": "two", "dim": 3,
        "A": [[2, 0, 0, 0, 0, 0], [0, 2, 0, 0, 0, 0], [0, 0, 4, 0, 0, 0],
              [0, 0, 0, 2, 0, 0], [0, 0, 0, 0, 2, 0], [0, 0, 0, 0, 0, 4]],
        "points": [{"mu": 0.5, "state": "a"}, {"mu": 0.5, "state": "a"}]})";

void check_open_values(const Step3dValues& v) {
  CHECK(v.P_T1.norm() == 0.0);
  CHECK(v.P_N1 == 0.0);
  CHECK(near(v.Dw_T(0), 0.1));
  CHECK(near(v.Dw_T(1), -0.2));
  CHECK(near(v.Dw_N, 0.1));
  CHECK(near(v.g1, -0.9));
}

}  // namespace

TEST_CASE("step request, one 2-D point: a stick step is DP = DF (hand calculation)", "[step]") {
  // A = I, mu = 1, from (P_T, P_N) = (0, 1) in contact, DF = (0.1, 0.1). Stick (Dw = 0) gives
  // DP = DF: P1 = (0.1, 1.1), inside the cone. Separation needs P_N1 = 0, so Dw_N = 1.1 and
  // g1 = 1.1 > 0: no. Slip+ needs P_T1 = 1.1 and Dw_T = 0.1 - 1.1 < 0 against its sign; slip-
  // needs P_T1 = -1.1 and Dw_T = 1.2 > 0: no. So exactly one solution.
  StepRequest r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.all = true;
  const StepOutcome all = run_step_request(r);
  CHECK(all.route == StepRoute::kPointAll);
  CHECK(all.exit_code == cpkit::kExitOk);
  REQUIRE(all.set.count() == 1);
  CHECK(all.set.complete);
  const StepSolution& s = all.set.solutions[0];
  CHECK(s.type == SolutionType::kStick);
  CHECK(near(s.start.P_T1, 0.1));
  CHECK(near(s.start.P_N1, 1.1));
  CHECK(std::abs(s.start.g1) <= 1e-15);
  CHECK(std::abs(s.start.Dw_T) <= 1e-15);

  r.all = false;  // the chain: the active-set link, out of the one solution the enumeration has
  const StepOutcome one = run_step_request(r);
  CHECK(one.route == StepRoute::kPointChain);
  CHECK(one.exit_code == cpkit::kExitOk);
  CHECK(one.one.solver == "active-set");
  CHECK(one.one.solution.type == SolutionType::kStick);
  CHECK(near(one.one.solution.values.P_T1, 0.1));
  CHECK(near(one.one.solution.values.P_N1, 1.1));
  REQUIRE(one.has_enumeration);
  CHECK(one.set.count() == 1);
  CHECK_THAT(step_text(one), Contains("\n1 of 1 solution\n"));
}

TEST_CASE("step request, one 2-D point: the worked example of docs/simulation.md", "[step]") {
  // State d, Lambda = a11 - mu a12 = -0.8 < 0: stick, slip+ (DP_N = -a12 dF_T / Lambda =
  // -0.01125, eqn (51)) and the jump to separation; the documented text, line by line.
  StepRequest r = point(1, 0.9, 1, 2, 2, 1, 0, -0.01, 0);
  r.all = true;
  const StepOutcome all = run_step_request(r);
  CHECK(all.exit_code == cpkit::kExitOk);
  CHECK(step_text(all) ==
        "step: 3 solution(s), 2 continuous (rate-consistent)\n"
        "  separation (point, jump): DP_T=-2 DP_N=-1 Dw_T=5.736842105 Dw_N=-4.163157895 "
        "Dw_Ti=5.736842105 Dw_w=0 | P_T1=0 P_N1=0 g1=-4.163157895\n"
        "  stick (point): DP_T=-0.01 DP_N=0 Dw_T=0 Dw_N=0 Dw_Ti=0 Dw_w=0 | P_T1=1.99 P_N1=1 g1=0\n"
        "  slip+ (point): DP_T=-0.0225 DP_N=-0.01125 Dw_T=0.0125 Dw_N=0 Dw_Ti=0.0125 Dw_w=0 | "
        "P_T1=1.9775 P_N1=0.98875 g1=0\n");
  // Without --all: the stick solution (closest to the start), "1 of 3 solutions; --all lists
  // them" in the text, solutions_found 3 in the JSON (docs/simulation.md).
  r.all = false;
  const StepOutcome one = run_step_request(r);
  CHECK(one.exit_code == cpkit::kExitOk);
  CHECK(one.one.solution.type == SolutionType::kStick);
  CHECK_THAT(step_text(one), Contains("1 of 3 solutions; --all lists them\n"));
  const nlohmann::json j = step_outcome_json(one, "test");
  CHECK(j["solutions_found"] == 3);
  CHECK(j["listed"] == 1);
  CHECK(j["enumeration_complete"] == true);
  CHECK(!j.contains("cpkit_version"));  // the one-point objects carry it in the program's "run"
}

TEST_CASE("step request, one 2-D point beyond condition (46): no solution, exit 1", "[step]") {
  // Criterion (35), A = I, mu = 1, k = k_a / (3 P_s) = 1: |P_T| <= Y(P_N) = P_N (1 - P_N) needs
  // P_N1 <= 1. From (0, 0.5) in contact with DF = (0, 1): stick gives P_N1 = 1.5 > 1; separation
  // gives Dw_N = 1 + 0.5 > 0 = g1 > 0; slip has Dw_T = -P_T1 (A = I, C_T = 0), against the sign
  // of P_T1 unless P_T1 = 0 = Y, i.e. P_N1 in {0, 1}, where g1 = 0 needs P_N1 = 1.5. None.
  StepRequest r = point(1, 0, 1, 1, 0, 0.5, 0, 0, 1);
  r.model.k_a = 3;
  r.model.criterion = "35";
  r.all = true;
  const StepOutcome out = run_step_request(r);
  CHECK(out.exit_code == cpkit::kExitNoSolution);
  CHECK(out.set.count() == 0);
  CHECK(out.set.complete);
}

TEST_CASE("step request, 3-D open point: the step is the open solution", "[step][step3d]") {
  StepRequest r = with_file(kOpen3d, {0.2, -0.4, 0.4});
  r.g0 = -1;
  r.all = true;
  const StepOutcome out = run_step_request(r);
  CHECK(out.route == StepRoute::kPoint3d);
  CHECK(out.exit_code == cpkit::kExitOk);
  REQUIRE(out.step_3d.set.count() == 1);
  CHECK(out.step_3d.set.complete);
  CHECK(out.step_3d.set.solutions[0].type == SolutionType::kOpen);
  check_open_values(out.step_3d.set.solutions[0].values);
  CHECK_THAT(step_text(out), StartsWith("step, 3-D point open (state a), exact\ncount: 1\n  open: "));
  const nlohmann::json j = step_outcome_json(out, "v");
  CHECK(j["cpkit_version"] == "v");
  CHECK(j["input"]["state"] == "a");
  CHECK(j["input"]["g0"] == -1.0);
  CHECK(!j["input"].contains("n_points"));
  CHECK(j["count"] == 1);

  // --multistart: local solvers never prove completeness, but the open solution is found.
  r.all = false;
  r.multistart = 3;
  const StepOutcome ms = run_step_request(r);
  CHECK(ms.exit_code == cpkit::kExitOk);
  CHECK_FALSE(ms.step_3d.set.complete);
  REQUIRE(ms.step_3d.set.count() >= 1);
  check_open_values(ms.step_3d.set.solutions[0].values);
}

TEST_CASE("step request, two coupled open 3-D points: each point's open step", "[step][step3d]") {
  // Block-diagonal A: each point is the open point above.
  StepRequest r = with_file(kTwoOpen3d, {0.2, -0.4, 0.4, 0.2, -0.4, 0.4});
  r.g0 = -1;
  const StepOutcome out = run_step_request(r);
  CHECK(out.route == StepRoute::kSystem3d);
  CHECK(out.exit_code == cpkit::kExitOk);
  CHECK(out.step_3d.solver == "fb-soc");
  REQUIRE(out.step_3d.system_set.count() == 1);
  for (const auto& p : out.step_3d.system_set.solutions[0].points) check_open_values(p.values);
  const nlohmann::json j = step_outcome_json(out, "v");
  CHECK(j["input"]["n_points"] == 2);
  CHECK(j["input"]["state"] == nlohmann::json({"a", "a"}));
  CHECK(j["input"]["g0"] == nlohmann::json({-1.0, -1.0}));
  CHECK(j["input"]["chain"] == nlohmann::json({"fb-soc"}));
  CHECK(j["status"] == "solved");
  CHECK_THAT(step_text(out), StartsWith("step, 2 coupled 3-D points two (states aa), FB-SOC Newton: "
                                        "solved in "));
}

TEST_CASE("step request, 3-D point with a continuum of solutions: not proved complete, exit 5",
          "[step][step3d]") {
  // docs/simulation.md: from state b with a11 = a12 = mu = 1, a22 = 2, DF = (0.5, 0.5) the 2-D
  // step has the stick point DP = DF and a slip+ segment: infinitely many solutions. The same
  // point in 3-D with an unloaded, decoupled Y direction has that continuum too, so no finite
  // count can be complete; the stick point P1 = (0.5, 0, 0.5) is a solution (Dw = 0).
  StepRequest r = with_file(R"({"name": "seg", "dim": 3, "A": [[1, 0, 1], [0, 3, 0], [1, 0, 2]],
                                "points": [{"mu": 1, "state": "b"}]})",
                            {0.5, 0, 0.5});
  r.all = true;
  const StepOutcome out = run_step_request(r);
  CHECK(out.exit_code == cpkit::kExitInconclusive);
  CHECK_FALSE(out.step_3d.set.complete);
  REQUIRE(out.errors.size() == 1);
  CHECK_THAT(out.errors[0], StartsWith("not proved complete: "));
  bool stick = false;
  for (const auto& s : out.step_3d.set.solutions)
    stick = stick || (s.type == SolutionType::kStick && near(s.values.P_T1(0), 0.5) &&
                      std::abs(s.values.P_T1(1)) <= 1e-15 && near(s.values.P_N1, 0.5));
  CHECK(stick);
}

TEST_CASE("step request: refused requests name the problem", "[step]") {
  const std::string two_d = R"({"A": [[1, 0], [0, 1]], "points": [{"mu": 1, "state": "b"}]})";
  const std::string b3 = R"({"name": "b", "dim": 3, "A": [[2, 0, 0], [0, 2, 0], [0, 0, 4]],
                             "points": [{"mu": 0.5, "state": "b", "k_a": 0.1}]})";
  const std::string two_b3 =
      R"({"name": "two", "dim": 3,
          "A": [[2, 0, 0, 0, 0, 0], [0, 2, 0, 0, 0, 0], [0, 0, 4, 0, 0, 0],
                [0, 0, 0, 2, 0, 0], [0, 0, 0, 0, 2, 0], [0, 0, 0, 0, 0, 4]],
          "points": [{"mu": 0.5, "state": "b"}, {"mu": 0.5, "state": "b"}]})";
  StepRequest r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.k_M = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
  r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.g0.reset();  // no --g0
  CHECK_THROWS_WITH(run_step_request(r), "--g0 is required (or --system FILE for N points)");
  r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.DF.push_back(0);
  CHECK_THROWS_WITH(run_step_request(r), "--dF needs two values: DFT DFN");
  r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.facets = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--facets applies to a \"dim\": 3 --system file (one 3-D point)");
  r = point(1, 0, 1, 1, 0, 1, 0, 0.1, 0.1);
  r.chain = "active-set,nope";
  CHECK_THROWS_WITH(run_step_request(r), StartsWith("--chain: unknown solver 'nope' (valid: "));

  CHECK_THROWS_WITH(run_step_request(with_file(two_d, {0, 1})),
                    "--system needs --all (the N-point step reports every solution)");
  r = with_file(two_d, {0, 1});
  r.model.a11 = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--a11 cannot be combined with --system (the system file gives every "
                    "point's parameters and state)");
  r = with_file(two_d, {0, 1, 2});
  r.all = true;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--dF needs 2 numbers (DF_T, DF_N per point, 1 points), got 3");

  CHECK_THROWS_WITH(run_step_request(with_file(kOpen3d, {0, 0, 1})),
                    "the point is in state a (open): give its gap with --g0 G, G < 0");
  r = with_file(b3, {0, 0, 1});
  r.g0 = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--g0 applies to a state-a (open) point; the point is in state b (in "
                    "contact, g0 = 0)");
  r = with_file(b3, {0, 0, 1});
  r.wear_law = "mroz";
  r.k_M = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "sys.json: the point's k_a (Archard) has no effect with --wear-law mroz: "
                    "remove it from the file or use --wear-law archard");
  r = with_file(kOpen3d, {0, 0});
  r.g0 = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--dF needs 3 numbers for a 3-D point (DF_TX DF_TY DF_N), got 2");
  r = with_file(kOpen3d, {0, 0, 1});
  r.model.a11 = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--a11 cannot be combined with a \"dim\": 3 --system file (the file gives "
                    "the point's parameters and state)");

  r = with_file(two_b3, {0, 0, 1, 0, 0, 1});
  r.all = true;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--all is not available for 2 coupled 3-D points: there is no complete "
                    "enumeration of the coupled 3-D step (only one point, N = 1, is enumerated "
                    "exactly); use --chain fb-soc (default) or --multistart N");
  r = with_file(two_b3, {0, 0, 1, 0, 0, 1});
  r.g0 = 0;
  CHECK_THROWS_WITH(run_step_request(r),
                    "--g0 applies to state-a (open) points; no point of this file is in state a");
  CHECK_THROWS_WITH(run_step_request(with_file(kTwoOpen3d, {0, 0, 1, 0, 0, 1})),
                    "point 1 is in state a (open): give the gap of the open points with --g0 G, "
                    "G < 0");
  CHECK_THROWS_WITH(run_step_request(with_file(two_b3, {0, 0, 1})),
                    "--dF needs 3N = 6 numbers for 2 3-D points (DF_TX DF_TY DF_N per point), "
                    "got 3");
  r = with_file(two_b3, {0, 0, 1, 0, 0, 1});
  r.chain = "exact";
  CHECK_THROWS_WITH(run_step_request(r),
                    "--chain 'exact': for 2 coupled 3-D points the only link is fb-soc (exact "
                    "and ipopt are one-point solvers)");
}
