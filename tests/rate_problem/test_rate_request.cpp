// `cpkit rate`'s request in the library (requests/rate_request.hpp): the routes, the exit codes, the
// refusals and the text, without a subprocess. Values from hand solutions of the rate problem
// (docs/contact_model.md Sec. 1 and 3: dF - dP = A dw, the laws of each type) and the text of
// the docs' worked example.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/requests/rate_request.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/rate_text.hpp"

using namespace cpkit::rate;

namespace {

/// A = [[1, 2], [2, 5]] (det 1), mu = 1, state b, dF = (1, 1.2): the hand case of Fig. 5b.
RateRequest fig5b() {
  RateRequest r;
  r.state = "b";
  r.model.a11 = 1;
  r.model.a12 = 2;
  r.model.a22 = 5;
  r.model.mu = 1;
  r.dF = {1, 1.2};
  return r;
}

std::string refusal(const RateRequest& r) {
  try {
    run_rate_request(r);
  } catch (const cpkit::InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST_CASE("rate request: Fig. 5b by hand, three solutions, exit 0, the docs' text", "[rate][request]") {
  // By hand (C_T = 0, A^-1 = [[5, -2], [-2, 1]]): separation dP = 0, dw = A^-1 dF =
  // (2.6, -0.8); stick dw = 0, dP = dF = (1, 1.2) with |dP_T| <= mu dP_N; slip+ dP_T = dP_N = p,
  // dw = (l, 0): 1 - p = l, 1.2 - p = 2 l, so l = 0.2, p = 0.8.
  const RateOutcome out = run_rate_request(fig5b());
  CHECK(out.exit_code == cpkit::kExitOk);
  CHECK(out.notes.empty());
  REQUIRE(out.one_point);
  const RateSolutionSet& s = out.one_point->set;
  CHECK(s.complete);
  REQUIRE(s.count() == 3);
  std::set<std::string> types;
  for (const auto& p : s.solutions) {
    types.insert(std::string(to_string(p.type)));
    if (p.type == SolutionType::kSlipPlus) {
      CHECK(p.start.dP_T == Approx(0.8));
      CHECK(p.start.dP_N == Approx(0.8));
      CHECK(p.start.dw_Ti == Approx(0.2));
    }
    if (p.type == SolutionType::kSeparation) {
      CHECK(p.start.dw_T == Approx(2.6));
      CHECK(p.start.dw_N == Approx(-0.8));
    }
  }
  CHECK(types == std::set<std::string>{"separation", "stick", "slip+"});
  // docs/contact_model.md, "cpkit rate --state b --a11 1 --a12 2 --a22 5 --mu 1 --dF 1 1.2"
  CHECK(rate_outcome_text(out) ==
        "rate problem, state b, method enumerate\n"
        "count: 3   types: separation slip+ stick\n"
        "Lambda: 0   D_+: -1   D_-: 3   unique for all directions: no\n"
        "  separation point: dP_T=0 dP_N=0 dw_T=2.6 dw_N=-0.8 dw_Ti=2.6 dw_w=0\n"
        "  stick point: dP_T=1 dP_N=1.2 dw_T=0 dw_N=0 dw_Ti=0 dw_w=0\n"
        "  slip+ point: dP_T=0.8 dP_N=0.8 dw_T=0.2 dw_N=0 dw_Ti=0.2 dw_w=0\n");
  const auto j = rate_outcome_json(out, "v");
  CHECK(j["count"] == 3);
  CHECK_FALSE(j.contains("cpkit_version"));  // one point: only the program's "run" has it
}

TEST_CASE("rate request: a single solver finds one of the three, with the count for reference",
          "[rate][request]") {
  RateRequest r = fig5b();
  r.method = "lemke";
  const RateOutcome out = run_rate_request(r);
  CHECK(out.exit_code == cpkit::kExitOk);
  REQUIRE(out.one_point);
  REQUIRE(out.one_point->reference);
  CHECK(out.one_point->reference->count() == 3);
  CHECK_FALSE(out.one_point->set.complete);
  const std::string text = rate_outcome_text(out);
  CHECK(text.find("a solution (found by lemke") != std::string::npos);
  CHECK(text.find("complete enumeration (--method enumerate): 3 solution(s)\n") != std::string::npos);
}

TEST_CASE("rate request: no solution exits 1 (state d, Lambda < 0, L_+ > 0)", "[rate][request]") {
  // A = [[1, .5], [.5, 1]], mu = 3, s = +1, C_T = 0: Lambda = a11 - s mu a12 = -0.5 and
  // L_+ = dF_T - mu dF_N = 4 - 3 = 1 > 0: stick needs L_+ <= 0, slip needs L_+/Lambda > 0.
  RateRequest r;
  r.state = "d";
  r.model.a11 = 1;
  r.model.a12 = 0.5;
  r.model.a22 = 1;
  r.model.mu = 3;
  r.P_N = 1;
  r.dF = {4, 1};
  const RateOutcome out = run_rate_request(r);
  CHECK(out.exit_code == cpkit::kExitNoSolution);
  CHECK(out.one_point->set.count() == 0);
  CHECK(out.one_point->set.Lambda == Approx(-0.5));
  // a single solver finds nothing either, and says that the enumeration has none
  r.method = "lemke";
  std::vector<std::string> notes;
  const RateOutcome single = run_rate_request(r, [&](const std::string& n) { notes.push_back(n); });
  CHECK(single.exit_code == cpkit::kExitNoSolution);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("; the enumeration has 0 solution(s)") != std::string::npos);
}

TEST_CASE("rate request: a load exactly on a critical direction is decided exactly (issue 34)",
          "[rate][request]") {
  // dF = (a11, a12): N = a11 dF_N - a12 dF_T is 0 exactly (the separation / slip+ boundary of
  // issue 24 item 17), but formed from rounded products: until issue 34 the answer was "not
  // conclusive" (exit 5). By hand (C_T = 0): N = 0, so no separation (N < 0 needed) and
  // dP_N = N / D_s = 0; L_+ = a11 - mu a12 = D_+ > 0: slip+ with lambda = L_+ / D_+ = 1;
  // L_- < 0 < D_-: no slip-; L_+ > 0: no stick. One slip+ with dP = 0, dw_T^i = 1.
  RateRequest r = fig5b();
  r.model.a11 = 1.0142831963176735;
  r.model.a12 = 0.8450714454408795;
  r.model.a22 = 1.2075902949448927;
  r.model.mu = 1.038170126179592;
  r.dF = {1.0142831963176735, 0.8450714454408795};
  const RateOutcome out = run_rate_request(r);
  CHECK(out.exit_code == cpkit::kExitOk);
  CHECK(out.notes.empty());
  const RateSolutionSet& s = out.one_point->set;
  CHECK(s.complete);
  REQUIRE(s.count() == 1);
  CHECK(s.solutions[0].type == SolutionType::kSlipPlus);
  CHECK(s.solutions[0].start.dP_N == Approx(0).margin(1e-12));
  CHECK(s.solutions[0].start.dw_Ti == Approx(1).epsilon(1e-12));
}

TEST_CASE("rate request: refusals name the option", "[rate][request]") {
  RateRequest r = fig5b();
  r.sgn_PT = 1;
  CHECK(refusal(r) ==
        "--sgnPT has no effect in state b: only state d (sliding) has a sign of P_T");
  r = fig5b();
  r.dF.clear();  // no --dF
  CHECK(refusal(r) == "--dF is required (or give --system FILE)");
  r = fig5b();
  r.method = "simplex";
  CHECK(refusal(r) ==
        "--method must be enumerate, analytic, lemke, fb-newton or ipopt, got 'simplex'");
  r = fig5b();
  r.dF = {1};
  CHECK(refusal(r) == "--dF needs two values: DFT DFN");
  r = fig5b();
  r.state = "e";
  CHECK(refusal(r) == "--state must be a, b, c or d, got 'e'");
  r = fig5b();
  r.model.criterion = "36";
  CHECK(refusal(r) == "--criterion must be 38 or 35, got '36'");
  r = fig5b();
  r.model.a22 = 1;  // det A = 1 - 4 < 0
  CHECK(refusal(r).find("contact parameters") == 0);
  r = fig5b();
  r.facets = 8;
  CHECK(refusal(r) == "--facets applies to 3-D points (--system FILE with \"dim\": 3, "
                      "docs/contact_3d.md)");
  r = fig5b();
  r.system = "/nonexistent/system.json";
  CHECK(refusal(r) == "--state is a one-point option; with --system the state and parameters "
                      "come from the system file");
}

TEST_CASE("rate request: a material parameter that does not enter the state is noted", "[rate][request]") {
  RateRequest r = fig5b();
  r.model.k_a = 0.1;
  std::vector<std::string> notes;
  const RateOutcome out = run_rate_request(r, [&](const std::string& n) { notes.push_back(n); });
  CHECK(out.exit_code == cpkit::kExitOk);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].rfind("note: --k_a does not enter state b", 0) == 0);
}

TEST_CASE("rate request: two decoupled points are the product of their one-point sets",
          "[rate][request]") {
  // A = blockdiag([[1, 2], [2, 5]], [[2, 0], [0, 1]]): point 1 is Fig. 5b (3 solutions, above);
  // point 2 sticks (state c, C_T = 0: dw = 0, dP = dF = (0.5, 1), |0.5| < 1 * 1 inside the
  // cone): 3 x 1 solutions.
  const std::string path = write_file("cpkit_test_rate_request_2pt.json", R"({"name": "decoupled",
    "A": [[1, 2, 0, 0], [2, 5, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]],
    "points": [{"state": "b", "mu": 1}, {"state": "c", "mu": 1, "P_N": 1}],
    "dF": [1, 1.2, 0.5, 1]})");
  RateRequest r;
  r.system = path;
  const RateOutcome out = run_rate_request(r);
  CHECK(out.exit_code == cpkit::kExitOk);
  CHECK(out.route == RateOutcome::Route::kSystem);
  CHECK(out.n_points == 2);
  REQUIRE(out.system);
  REQUIRE(out.system->count() == 3);
  std::set<std::string> first;
  for (const auto& p : out.system->solutions) {
    first.insert(std::string(to_string(p.types[0])));
    CHECK(p.types[1] == SolutionType::kStick);
    CHECK(p.start.dP_T(1) == Approx(0.5));
    CHECK(p.start.dP_N(1) == Approx(1));
  }
  CHECK(first == std::set<std::string>{"separation", "stick", "slip+"});
  const auto j = rate_outcome_json(out, "test-version");
  CHECK(j["cpkit_version"] == "test-version");
  CHECK(j["n_points"] == 2);
  CHECK(j["input"]["dF"] == nlohmann::json({1, 1.2, 0.5, 1}));
  // a 2-D system refuses the 3-D options, and a load rate of the wrong length
  r.facets = 8;
  CHECK(refusal(r) == "--facets applies to 3-D points (\"dim\": 3 in the system file, "
                      "docs/contact_3d.md); " + path + " is a 2-D system");
  r.facets = 0;
  r.dF = {1, 2, 3};
  CHECK(refusal(r) == "--dF needs 2N = 4 numbers (T_1 N_1 T_2 N_2 ...) for the 2 points of " +
                          path + ", got 3");
  std::filesystem::remove(path);
}
