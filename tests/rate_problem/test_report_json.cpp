// The JSON of rate and step results (report/json.hpp, report/json_3d.hpp), called
// directly. Independent sources: the grazing example of docs/contact_model.md Sec. 5 (state b,
// A = [[1, 2], [2, 5]], mu = 1, dF = (1, 1.2): separation, stick and slip+), solved here by hand
// with A^-1 = [[5, -2], [-2, 1]] (det A = 1); its degenerate segment (mu = 0.5, dF = (1, 2));
// and solution sets written field by field here, whose JSON must carry exactly those numbers.
#include <catch2/catch.hpp>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"
#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/simulation_csv.hpp"
#include "cpkit/rate_problem/report/simulation_json.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"

using namespace cpkit::rate;
using nlohmann::json;

namespace {

ContactParameters grazing_params(double mu) {
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 2;
  p.a22 = 5;
  p.mu = mu;
  return p;
}

/// The solution of `type` in a "solutions" array (null when absent).
json find_type(const json& sols, const std::string& type) {
  for (const auto& e : sols)
    if (e.at("type") == type) return e;
  return nullptr;
}

/// Checks the six rates of a JSON object against hand values.
void check_rates(const json& r, std::vector<double> want) {
  const char* names[] = {"dP_T", "dP_N", "dw_T", "dw_N", "dw_Ti", "dw_w"};
  REQUIRE(r.size() == 6);
  for (int k = 0; k < 6; ++k) {
    CAPTURE(names[k]);
    CHECK(r.at(names[k]).get<double>() == Approx(want[k]).margin(1e-12));
  }
}

}  // namespace

TEST_CASE("rate JSON: the grazing example, every solution by hand", "[report]") {
  const RateSolutionSet s =
      solve_rate_problem(grazing_params(1), {StateLabel::kB, 0, 1}, {1, 1.2});
  const json j = rate_set_json(s);
  CHECK(j.at("complete") == true);
  CHECK(j.at("count") == 3);
  CHECK_FALSE(j.contains("found"));
  CHECK_FALSE(j.contains("enumerated_count"));
  CHECK(j.at("types") == json({"separation", "slip+", "stick"}));  // sorted names
  // D_s = a11 - s mu a12: D_+ = 1 - 2 = -1, D_- = 1 + 2 = 3; unique iff a11 > mu |a12| (1 > 2).
  CHECK(j.at("D_plus").get<double>() == Approx(-1));
  CHECK(j.at("D_minus").get<double>() == Approx(3));
  CHECK(j.at("Lambda").get<double>() == 0);
  CHECK(j.at("unique_for_all_directions") == false);
  const json& sols = j.at("solutions");
  REQUIRE(sols.size() == 3);
  for (const auto& e : sols) CHECK(e.at("kind") == "point");
  // separation: dP = 0, dw = A^-1 dF = (5 - 2.4, -2 + 1.2) = (2.6, -0.8), dw_T^i = dw_T.
  check_rates(find_type(sols, "separation").at("rates"), {0, 0, 2.6, -0.8, 2.6, 0});
  // stick: dw = 0, dP = dF.
  check_rates(find_type(sols, "stick").at("rates"), {1, 1.2, 0, 0, 0, 0});
  // slip+: dP_T = dP_N = p, dw = (w, 0): 1 - p = w, 1.2 - p = 2 w -> w = 0.2, p = 0.8.
  check_rates(find_type(sols, "slip+").at("rates"), {0.8, 0.8, 0.2, 0, 0.2, 0});
}

TEST_CASE("rate JSON: a segment, and a single solver's answer is not a count", "[report]") {
  // a11 = mu |a12| = 1: the slip+ segment from the stick point dP = dF = (1, 2) (open) to
  // zero-force slip dP = 0, dw = A^-1 dF = (5 - 4, -2 + 2) = (1, 0) (closed).
  const RateSolutionSet s =
      solve_rate_problem(grazing_params(0.5), {StateLabel::kB, 0, 1}, {1, 2});
  const json j = rate_set_json(s);
  CHECK(j.at("count") == "inf");
  const json seg = find_type(j.at("solutions"), "slip+");
  REQUIRE(seg.is_object());
  CHECK(seg.at("kind") == "segment");
  CHECK_FALSE(seg.contains("rates"));
  CHECK(seg.at("start_closed") == false);
  CHECK(seg.at("end_closed") == true);
  check_rates(seg.at("start"), {1, 2, 0, 0, 0, 0});
  check_rates(seg.at("end"), {0, 0, 1, 0, 1, 0});
  check_rates(find_type(j.at("solutions"), "stick").at("rates"), {1, 2, 0, 0, 0, 0});

  // A single solver's set, written here: found (not count), enumerated_count from the reference.
  RateSolutionSet one;
  one.complete = false;
  RateSolution p;
  p.type = SolutionType::kStick;
  p.start = {1, 1.2, 0, 0, 0, 0};
  one.solutions.push_back(p);
  RateSolutionSet reference;
  reference.solutions.resize(3);
  const json k = rate_set_json(one, &reference);
  CHECK(k.at("complete") == false);
  CHECK_FALSE(k.contains("count"));
  CHECK(k.at("found") == 1);
  CHECK(k.at("enumerated_count") == 3);
  CHECK(k.at("solutions")[0].at("rates").at("dP_N") == 1.2);
}

TEST_CASE("rate JSON: N points, one array per field", "[report]") {
  SystemRateSolutionSet s;
  s.complete = false;
  s.message = "why";
  SystemRateSolution p;
  p.types = {SolutionType::kSeparation, SolutionType::kStick};
  p.kind = RateSolution::Kind::kRay;
  const auto two = [](double a, double b) { return Eigen::VectorXd((Eigen::VectorXd(2) << a, b).finished()); };
  p.start = {two(0, 1), two(0, 2), two(3, 0), two(-1, 0), two(3, 0), two(0, 0)};
  p.start_closed = false;
  p.direction = {two(0, 1), two(0, 0), two(0, 0), two(0, 0), two(0, 0), two(0, 0)};
  s.solutions.push_back(p);
  const json j = system_rate_set_json(s);
  CHECK(j.at("complete") == false);
  CHECK(j.at("found") == 1);
  CHECK(j.at("message") == "why");
  const json& e = j.at("solutions")[0];
  CHECK(e.at("types") == json({"separation", "stick"}));
  CHECK(e.at("kind") == "ray");
  CHECK(e.at("start_closed") == false);
  CHECK(e.at("start").at("dP_N") == json({0.0, 2.0}));
  CHECK(e.at("start").at("dw_N") == json({-1.0, 0.0}));
  CHECK(e.at("direction").at("dP_T") == json({0.0, 1.0}));
  CHECK_FALSE(e.contains("end"));
}

TEST_CASE("step JSON: the grazing step, by hand", "[report]") {
  // From P = 0, g = 0 without wear the step's equations are the rate problem's: the same three
  // solutions (docs/contact_model.md), with P1 = DP and g1 = g0 + Dw_N - Dw_w = Dw_N.
  StepProblem p;
  p.params = grazing_params(1);
  p.state = {0, 0, 0};
  p.load = {1, 1.2};
  const json j = step_set_json(enumerate_step(p));
  CHECK(j.at("count") == 3);
  CHECK(j.at("complete") == true);
  CHECK_FALSE(j.contains("message"));
  CHECK(j.at("types") == json({"separation", "slip+", "stick"}));
  const json sep = find_type(j.at("solutions"), "separation");
  REQUIRE(sep.is_object());
  const json& v = sep.at("values");
  REQUIRE(v.size() == 9);
  CHECK(v.at("DP_T").get<double>() == Approx(0).margin(1e-12));
  CHECK(v.at("Dw_T").get<double>() == Approx(2.6));
  CHECK(v.at("Dw_N").get<double>() == Approx(-0.8));
  CHECK(v.at("g1").get<double>() == Approx(-0.8));
  CHECK(v.at("P_N1").get<double>() == Approx(0).margin(1e-12));
  const json slip = find_type(j.at("solutions"), "slip+").at("values");
  CHECK(slip.at("DP_T").get<double>() == Approx(0.8));
  CHECK(slip.at("P_N1").get<double>() == Approx(0.8));
  CHECK(slip.at("Dw_Ti").get<double>() == Approx(0.2));
  for (const auto& e : j.at("solutions")) {
    CHECK(e.contains("jump"));
    CHECK(e.at("residual").get<double>() < 1e-10);
  }

  // One chain's answer: one of the three, with the enumeration it was picked from.
  const StepSolveResult r = solve_step(p);
  const StepSolutionSet all = enumerate_step(p);
  const json k = step_result_json(r, &all);
  CHECK(k.at("status") == "solved");
  CHECK(k.at("solutions_found") == 3);
  CHECK(k.at("listed") == 1);
  CHECK(k.at("enumeration_complete") == true);
  const std::string type = k.at("type");
  const json want = find_type(j.at("solutions"), type);
  REQUIRE(want.is_object());
  CHECK(k.at("values").at("P_T1").get<double>() ==
        Approx(want.at("values").at("P_T1").get<double>()).margin(1e-9));
  CHECK(k.at("attempts").is_array());
  CHECK_FALSE(k.at("attempts").empty());
  CHECK(step_result_json(r).contains("solutions_found") == false);
}

TEST_CASE("step JSON: N points, one array per field", "[report]") {
  SystemStepSolutionSet s;
  s.complete = true;
  SystemStepSolution sol;
  sol.types = {SolutionType::kStick, SolutionType::kSlipMinus};
  StepValues a, b;
  a.DP_T = 1;
  a.P_N1 = 2;
  b.DP_T = -3;
  b.g1 = -0.5;
  sol.values = {a, b};
  sol.residual = 1e-15;
  s.solutions.push_back(sol);
  s.notes = {"n1"};
  const json j = system_step_set_json(s);
  CHECK(j.at("count") == 1);
  CHECK(j.at("complete") == true);
  CHECK(j.at("notes") == json({"n1"}));
  const json& e = j.at("solutions")[0];
  CHECK(e.at("types") == json({"stick", "slip-"}));
  CHECK(e.at("values").size() == 9);
  CHECK(e.at("values").at("DP_T") == json({1.0, -3.0}));
  CHECK(e.at("values").at("P_N1") == json({2.0, 0.0}));
  CHECK(e.at("values").at("g1") == json({0.0, -0.5}));
  CHECK(e.at("residual") == 1e-15);
}

TEST_CASE("3-D JSON: pairs, slip directions by hand", "[report][3d]") {
  using namespace cpkit::rate;
  Rates3d slip, stick;
  slip.dP_T = {1, -2};
  slip.dP_N = 0.5;
  slip.dw_Ti = {3, 4};  // |(3, 4)| = 5: direction (0.6, 0.8), angle atan2(4, 3)
  stick.dP_N = 7;
  const json r = rates_3d_json({slip, stick});
  CHECK(r.at("dP_T") == json({{1.0, -2.0}, {0.0, 0.0}}));
  CHECK(r.at("dP_N") == json({0.5, 7.0}));
  CHECK(r.at("dw_Ti")[0] == json({3.0, 4.0}));
  json e;
  add_slip_json(e, {SolutionType::kSlip, SolutionType::kStick}, {slip, stick});
  CHECK(e.at("slip_direction")[0][0].get<double>() == Approx(0.6));
  CHECK(e.at("slip_direction")[0][1].get<double>() == Approx(0.8));
  CHECK(e.at("slip_direction")[1].is_null());
  CHECK(e.at("slip_angle")[0].get<double>() == Approx(0.9272952180016122));
  json none;
  add_slip_json(none, {SolutionType::kStick}, {stick});
  CHECK_FALSE(none.contains("slip_direction"));  // no point slips: no field

  Step3dSolution s;
  s.type = SolutionType::kSlip;
  s.values.P_T1 = {0.3, -0.4};
  s.values.DP_T = {1, 2};
  s.values.DP_N = 3;
  s.values.Dw_T = {4, 5};
  s.values.Dw_N = 6;
  s.values.g1 = -0.25;
  s.slip_direction = {0, -1};
  s.slip_angle = -1.5707963267948966;
  const json j = step_3d_solution_json(s);
  CHECK(j.at("type") == "slip");
  CHECK(j.at("P_T1") == json({0.3, -0.4}));
  CHECK(j.at("DP") == json({1.0, 2.0, 3.0}));
  CHECK(j.at("Dw") == json({4.0, 5.0, 6.0}));
  CHECK(j.at("g1") == -0.25);
  CHECK(j.at("slip_direction") == json({0.0, -1.0}));
  s.type = SolutionType::kStick;
  CHECK(step_3d_solution_json(s).at("slip_angle").is_null());
}

TEST_CASE("step JSON: the N-point input echo", "[report]") {
  ContactSystem sys;
  sys.name = "two";
  sys.A = (Eigen::MatrixXd(4, 4) << 2, 0.5, 0, 0, 0.5, 3, 0, 0, 0, 0, 4, 1, 0, 0, 1, 5).finished();
  sys.points.resize(2);
  sys.points[1].mu = 0.3;
  sys.points[1].P_N = 2;
  sys.points[1].g = 0;
  const json j = contact_system_json(sys);
  CHECK(j.at("name") == "two");
  CHECK(j.at("A").size() == 4);
  CHECK(j.at("A")[0] == json({2.0, 0.5, 0.0, 0.0}));
  CHECK(j.at("A")[3] == json({0.0, 0.0, 1.0, 5.0}));  // row 4 as written above
  CHECK(j.at("points").size() == 2);
  CHECK(j.at("points")[1].at("mu") == 0.3);
  CHECK(j.at("points")[1].at("P_N") == 2.0);
  CHECK(j.at("points")[1].size() == 7);  // mu, C_T, k_a, P_s, P_T, P_N, g
}

TEST_CASE("checked rate: the grazing example through every route, against the hand solutions",
          "[report][routes]") {
  // The three hand solutions of the grazing example (first test case): separation, stick, slip+.
  const std::vector<std::pair<std::string, Rates>> hand = {
      {"separation", {0, 0, 2.6, -0.8, 2.6, 0}}, {"stick", {1, 1.2, 0, 0, 0, 0}},
      {"slip+", {0.8, 0.8, 0.2, 0, 0.2, 0}}};
  const ContactState st{StateLabel::kB, 0, 1};
  for (RateMethod m : {RateMethod::kEnumerate, RateMethod::kAnalytic}) {
    CAPTURE(to_string(m));
    const CheckedRateSolution c = solve_rate_problem_checked(grazing_params(1), st, {1, 1.2}, m);
    CHECK(c.problem.empty());
    CHECK_FALSE(c.inconclusive);
    CHECK_FALSE(c.reference.has_value());  // the second route is internal: nothing to report
    CHECK(c.set.count() == 3);
  }
  std::vector<RateMethod> single = {RateMethod::kLemke};
  if (cpkit::lcp::solvers().find("fb-newton") != nullptr) single.push_back(RateMethod::kFbNewton);
  for (RateMethod m : single) {
    CAPTURE(to_string(m));
    const CheckedRateSolution c = solve_rate_problem_checked(grazing_params(1), st, {1, 1.2}, m);
    REQUIRE(c.reference.has_value());
    CHECK(c.reference->count() == 3);
    CHECK(c.problem.empty());
    REQUIRE(c.set.solutions.size() == 1);
    // the solver's point is one of the hand solutions, of the same type
    const RateSolution& x = c.set.solutions.front();
    int matches = 0;
    for (const auto& [type, r] : hand) {
      const bool same = std::abs(x.start.dP_T - r.dP_T) < 1e-6 &&
                        std::abs(x.start.dP_N - r.dP_N) < 1e-6 &&
                        std::abs(x.start.dw_T - r.dw_T) < 1e-6 &&
                        std::abs(x.start.dw_N - r.dw_N) < 1e-6;
      if (same) {
        ++matches;
        CHECK(std::string(to_string(x.type)) == type);
      }
    }
    CHECK(matches == 1);
  }
}

TEST_CASE("3-D system route: stick points by hand, their JSON, and what is refused",
          "[report][3d]") {
  // Points in state c (P_T inside the ellipse, P_N > 0): the rate problem has the one solution
  // stick, dP = dF, dw = 0 (no slip, no separation: dw_N = 0 in contact).
  ContactSystem3d sys;
  sys.A = Eigen::MatrixXd::Identity(3, 3) * 2;
  sys.points.resize(1);
  sys.points[0].state.state = 'c';
  sys.points[0].state.P_N = 1;
  const SystemRateRoute3d one = solve_system_rate_3d(sys, Eigen::Vector3d(1, 2, 3), 0);
  REQUIRE(one.complete);
  REQUIRE(one.count() == 1);
  const json j = system_rate_3d_json(one);
  CHECK(j.at("route") == "exact");
  CHECK(j.at("complete") == true);
  CHECK(j.at("count") == 1);
  CHECK_FALSE(j.contains("found"));
  CHECK_FALSE(j.contains("time_limit_reached"));
  const json& e = j.at("solutions")[0];
  CHECK(e.at("types") == json({"stick"}));
  CHECK(e.at("kind") == "point");
  CHECK(e.at("values").at("dP_T")[0][0].get<double>() == Approx(1));
  CHECK(e.at("values").at("dP_T")[0][1].get<double>() == Approx(2));
  CHECK(e.at("values").at("dP_N")[0].get<double>() == Approx(3));
  CHECK(e.at("values").at("dw_N")[0].get<double>() == Approx(0).margin(1e-12));
  CHECK_FALSE(e.contains("slip_angle"));  // nothing slips

  // Two decoupled stick points: the faceted N-point route, the product of the one-point sets.
  ContactSystem3d two = sys;
  two.A = Eigen::MatrixXd::Identity(6, 6) * 2;
  two.points.push_back(sys.points[0]);
  Eigen::VectorXd dF(6);
  dF << 1, 2, 3, -1, 0.5, 4;
  const SystemRateRoute3d both = solve_system_rate_3d(two, dF, 8);
  REQUIRE(both.count() == 1);
  const json k = system_rate_3d_json(both);
  CHECK(k.at("route") == "faceted");
  CHECK(k.at("solutions")[0].at("types") == json({"stick", "stick"}));
  CHECK(k.at("solutions")[0].at("values").at("dP_N")[1].get<double>() == Approx(4));
  CHECK(k.at("solutions")[0].at("values").at("dP_T")[1][0].get<double>() == Approx(-1));

  // Coupled points need facets; one point not grazing has no faceted problem.
  CHECK_THROWS_AS(solve_system_rate_3d(two, dF, 0), cpkit::InputError);
  CHECK_THROWS_AS(solve_system_rate_3d(sys, Eigen::Vector3d(1, 2, 3), 8), cpkit::InputError);
}

TEST_CASE("3-D step JSON: attempts, a set and a coupled set, field by field", "[report][3d]") {
  // Attempts written here: the JSON carries exactly these values; a non-finite residual is null.
  cpkit::Attempt ok{"fb-soc", cpkit::Status::kSolved, 1e-14, 0.5, "", 7};
  cpkit::Attempt bad{"ipopt", cpkit::Status::kNumericalFailure,
                     std::numeric_limits<double>::quiet_NaN(), 0.25, "diverged", 3};
  const json at = attempts_json({ok, bad});
  REQUIRE(at.size() == 2);
  CHECK(at[0].at("solver") == "fb-soc");
  CHECK(at[0].at("solved") == true);
  CHECK(at[0].at("residual") == 1e-14);
  CHECK(at[0].at("iterations") == 7);
  CHECK(at[0].at("seconds") == 0.5);
  CHECK(at[1].at("solved") == false);
  CHECK(at[1].at("residual").is_null());
  CHECK(at[1].at("message") == "diverged");

  Step3dSolution stick;
  stick.type = SolutionType::kStick;
  stick.values.P_N1 = 2;
  Step3dSolutionSet set;
  set.solutions = {stick, stick};
  const json all = step_3d_set_json(set);
  CHECK(all.at("complete") == true);
  CHECK(all.at("count") == 2);
  CHECK_FALSE(all.contains("found"));
  CHECK_FALSE(all.contains("message"));
  CHECK(all.at("solutions")[1].at("P_N1") == 2.0);
  set.complete = false;
  set.message = "two roots too close";
  const json part = step_3d_set_json(set);
  CHECK(part.at("found") == 2);
  CHECK_FALSE(part.contains("count"));
  CHECK(part.at("message") == "two roots too close");
  const json chain = step_3d_set_json(set, false);  // a chain's answer: no count, no complete
  CHECK_FALSE(chain.contains("complete"));
  CHECK_FALSE(chain.contains("found"));
  CHECK(chain.at("solutions").size() == 2);

  SystemStep3dSolutionSet coupled;
  coupled.solutions.push_back({{stick, stick}, 3e-13});
  const json c = system_step_3d_set_json(coupled);
  CHECK(c.at("complete") == false);  // never a count for coupled 3-D points
  CHECK(c.at("found") == 1);
  CHECK(c.at("solutions")[0].at("residual") == 3e-13);
  CHECK(c.at("solutions")[0].at("points").size() == 2);
  CHECK(c.at("solutions")[0].at("points")[0].at("type") == "stick");
}

TEST_CASE("simulation summaries: N points and 3-D fretting, field by field", "[report][simulation]") {
  // An N-point result written here (two points): the JSON carries exactly these numbers.
  ContactSystem sys;
  sys.name = "pair";
  sys.points.resize(2);
  SimulateSettings s;
  s.system = "pair.json";
  s.load_type = "csv";
  s.load_csv = "load.csv";
  SystemSimulationResult r;
  r.inconclusive = true;  // stopped without a proof: "inconclusive", whatever the outcome
  r.outcome = SimulationResult::Outcome::kNoSolution;
  r.steps = 12;
  r.incomplete_steps = 1;
  r.final_state.w_w = Eigen::Vector2d(0.5, 0.25);
  r.wear_integral = Eigen::Vector2d(1, 2);
  r.wear_per_cycle = {Eigen::Vector2d(3, 4)};
  const json j = system_simulation_summary_json(r, s, sys);
  CHECK(j.at("input").at("system") == "pair.json");
  CHECK(j.at("input").at("file") == "load.csv");
  CHECK_FALSE(j.at("input").contains("fretting"));
  CHECK(j.at("outcome") == "inconclusive");
  CHECK(j.at("n_points") == 2);
  CHECK(j.at("final_wear_depth") == json({0.5, 0.25}));
  CHECK(j.at("wear_integral") == json({1.0, 2.0}));
  CHECK(j.at("wear_per_cycle") == json({{3.0, 4.0}}));
  CHECK(j.at("complete") == false);  // one step not proved complete
  CHECK_FALSE(j.contains("temperature"));  // heat off

  // 3-D fretting: the lead-in defaults to steps_per_cycle / 4 = 40 / 4 = 10 steps; an ambiguous
  // stop is never complete, even with every step proved complete.
  EllipticOrbit orbit;
  orbit.a_X = 0.3;
  orbit.a_Y = -0.2;
  orbit.steps_per_cycle = 40;
  Fretting3dOptions o;
  o.params.A = Eigen::Matrix3d::Identity() * 2;
  o.params.alpha = {1, 0.5};
  o.wear.law = WearLaw::kMrozStupkiewicz;
  o.wear.k_M = 0.01;
  Fretting3dResult f;
  f.outcome = Fretting3dResult::Outcome::kAmbiguous;
  f.wear_per_cycle = {0.125};
  const json k = fretting_3d_summary_json(f, orbit, o, "point.json", "one");
  CHECK(k.at("dim") == 3);
  CHECK(k.at("input").at("orbit").at("lead_steps") == 10);
  CHECK(k.at("input").at("orbit").at("a_Y") == -0.2);
  CHECK(k.at("input").at("point").at("A")[1] == json({0.0, 2.0, 0.0}));
  CHECK(k.at("input").at("point").at("alpha") == json({1.0, 0.5}));
  CHECK(k.at("input").at("wear").at("law") == "mroz-stupkiewicz");  // wear.hpp's name
  CHECK(k.at("input").at("wear").at("k_M") == 0.01);
  CHECK(k.at("incomplete_steps") == 0);
  CHECK(k.at("complete") == false);
  CHECK(k.at("wear_per_cycle") == json({0.125}));
  f.outcome = Fretting3dResult::Outcome::kCompleted;
  CHECK(fretting_3d_summary_json(f, orbit, o, "point.json", "one").at("complete") == true);
}

TEST_CASE("simulation CSV: headers and rows written here by hand", "[report][simulation]") {
  CHECK(simulation_csv_header() ==
        "step,t,F_T,F_N,P_T,P_N,w_T,w_N,w_w,w_Ti,g,state,type,count,dissipation,"
        "dissipation_total,work_total,stored,temperature\n");
  SimulationSample s;
  s.step = 3;
  s.t = 0.5;
  s.F_T = 1;
  s.F_N = 2;
  s.P_T = -0.25;
  s.P_N = 2;
  s.state = StateLabel::kD;
  s.type = SolutionType::kSlipMinus;
  s.count = 1;
  s.temperature = 20;
  std::ostringstream one;
  write_simulation_csv_row(one, s);
  CHECK(one.str() == "3,0.5,1,2,-0.25,2,0,0,0,0,0,d,slip-,1,0,0,0,0,20\n");

  CHECK(system_simulation_csv_header(2) ==
        "step,t,F_T_1,F_N_1,P_T_1,P_N_1,w_T_1,w_N_1,w_w_1,w_Ti_1,g_1,state_1,type_1,"
        "temperature_1,F_T_2,F_N_2,P_T_2,P_N_2,w_T_2,w_N_2,w_w_2,w_Ti_2,g_2,state_2,type_2,"
        "temperature_2,count,complete,dissipation_total,work_total,stored\n");
  SystemSimulationSample x;
  x.step = 1;
  x.t = 2;
  x.F = Eigen::Vector4d(1, 2, 3, 4);
  x.w = Eigen::Vector4d(0, -1, 0, -2);
  x.P_T = Eigen::Vector2d(0.5, 0.75);
  x.P_N = Eigen::Vector2d(2, 4);
  x.w_w = Eigen::Vector2d::Zero();
  x.w_Ti = Eigen::Vector2d::Zero();
  x.g = Eigen::Vector2d(0, -0.5);
  x.temperature = Eigen::Vector2d(20, 21);
  x.state = {StateLabel::kC, StateLabel::kA};
  x.type = {SolutionType::kStick, SolutionType::kSeparation};
  x.count = 2;
  x.complete = false;
  std::ostringstream two;
  write_system_simulation_csv_row(two, x);
  CHECK(two.str() == "1,2,1,2,0.5,2,0,-1,0,0,0,c,stick,20,3,4,0.75,4,0,-2,0,0,-0.5,a,separation,"
                     "21,2,0,0,0,0\n");

  CHECK(fretting_3d_csv_header() ==
        "step,t,F_TX,F_TY,F_N,P_TX,P_TY,P_N,g,w_TX,w_TY,w_N,w_TiX,w_TiY,Dw_TiX,Dw_TiY,lambda,"
        "Dw_w,w_w,type,count,complete,dissipation,cycle\n");
  Fretting3dSample f;
  f.step = 7;
  f.F_T = {0.5, -0.5};
  f.F_N = 1;
  f.type = SolutionType::kSlip;
  f.count = 1;
  f.complete = true;
  f.cycle = 2;
  std::ostringstream three;
  write_fretting_3d_csv_row(three, f);
  CHECK(three.str() == "7,0,0.5,-0.5,1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,slip,1,1,0,2\n");
}
