// Quasi-static fretting simulation (simulation.hpp). Independent sources: the closed-form
// fretting loop of the decoupled problem (a12 = 0), Archard's law integrated here from the time
// series, energy sums recomputed here from the series, the backward-Euler heat balance summed
// here, and the paper's remark that (41) equals (37) with k_M = k_a / (3 P_s mu).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"

using namespace cpkit::rate;

namespace {

SimulationOptions decoupled(double k_a) {
  SimulationOptions o;
  o.params.a11 = 2.0;
  o.params.a12 = 0.0;
  o.params.a22 = 1.5;
  o.params.mu = 0.5;
  o.params.C_T = 0.4;
  o.params.k_a = k_a;
  o.params.P_s = 1.0;
  return o;
}

FrettingCycle cycle(double amplitude, int cycles = 8, int steps = 100) {
  FrettingCycle c;
  c.F_N = 1.0;
  c.amplitude = amplitude;
  c.cycles = cycles;
  c.steps_per_cycle = steps;
  c.ramp_steps = 10;
  return c;
}

}  // namespace

TEST_CASE("StickRegimeProducesNoWear", "[sim]") {
  // a12 = 0: stick holds while |F_T| < mu F_N (1 + a11 C_T) = 0.9.
  const SimulationOptions o = decoupled(0.03);
  const auto r = simulate(fretting_history(cycle(0.85)), o);
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  CHECK(r.wear_depth == 0);
  CHECK(r.total_slip == 0);
  CHECK(r.dissipation == 0);
  for (const auto& s : r.series) {
    CHECK((s.type == SolutionType::kStick || s.step == 0));
    CHECK(s.P_T == Approx(s.F_T / (1 + 2.0 * 0.4)).margin(1e-12));
  }
}

TEST_CASE("GrossSlipWearsAtTheArchardRate", "[sim]") {
  // a12 = 0, small wear: P_N ~ F_N. Between two load peaks of a steady cycle the irreversible
  // slip is 2 (F_a - mu P_N (1 + a11 C_T)) / a11, so per cycle
  //   slip = 4 (F_a - mu P_N (1 + a11 C_T)) / a11,  wear = k P_N slip  (Archard (37)).
  const double k_a = 3e-4, k = k_a / 3.0;
  const SimulationOptions o = decoupled(k_a);
  const double Fa = 1.3;
  const auto r = simulate(fretting_history(cycle(Fa, 6)), o);
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  REQUIRE(r.slip_per_cycle.size() == 6);
  for (std::size_t c = 1; c < 6; ++c) {
    // P_N during cycle c: F_N - a22 w^w (g = 0, a12 = 0); w^w is at most ~1e-3 here.
    const double PN = 1.0 - 1.5 * r.wear_depth;
    const double slip = 4 * (Fa - 0.5 * PN * (1 + 2.0 * 0.4)) / 2.0;
    CAPTURE(c);
    CHECK(r.slip_per_cycle[c] == Approx(slip).epsilon(2e-3));
    CHECK(r.wear_per_cycle[c] == Approx(k * PN * slip).epsilon(4e-3));
  }
  // Fretting loop: at the peaks P_T = +-mu P_N (gross slip).
  double maxPT = 0;
  for (const auto& s : r.series) maxPT = std::max(maxPT, std::abs(s.P_T));
  CHECK(maxPT == Approx(0.5).epsilon(2e-3));
}

TEST_CASE("TotalWearEqualsTheArchardIntegralOfTheRun", "[sim]") {
  // w^w(end) = k_a/(3 P_s) * integral of P_N |dw_T^i|, the integral summed here from the series
  // (end-of-step P_N, as the step evaluates the wear law). Coupled A, compliance, both criteria.
  for (auto crit : {Criterion::kCoulomb, Criterion::kSoftening}) {
    SimulationOptions o;
    o.params.a11 = 2.0;
    o.params.a12 = 0.3;
    o.params.a22 = 1.5;
    o.params.mu = 0.5;
    o.params.C_T = 0.2;
    o.params.k_a = 0.01;
    o.params.P_s = 0.5;
    o.params.criterion = crit;
    const auto r = simulate(fretting_history(cycle(1.2, 5)), o);
    REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
    double integral = 0;
    for (std::size_t i = 1; i < r.series.size(); ++i)
      integral += r.series[i].P_N * std::abs(r.series[i].w_Ti - r.series[i - 1].w_Ti);
    const double k = 0.01 / (3 * 0.5);
    CAPTURE(to_string(crit));
    REQUIRE(r.wear_depth > 0);
    CHECK(r.wear_depth == Approx(k * integral).epsilon(1e-9));
    CHECK(r.wear_integral == Approx(k * integral).epsilon(1e-9));
  }
}

TEST_CASE("DissipationIsNeverNegativeAndTheEnergyBalanceCloses", "[sim]") {
  SimulationOptions o;
  o.params.a11 = 2.0;
  o.params.a12 = 0.4;
  o.params.a22 = 1.5;
  o.params.mu = 0.5;
  o.params.C_T = 0.3;
  o.params.k_a = 0.01;
  o.params.P_s = 1.0;
  double prev_err = INFINITY;
  for (int steps : {50, 100, 200}) {
    const auto r = simulate(fretting_history(cycle(1.2, 4, steps)), o);
    REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
    // Recompute work, stored energy and dissipation from the series.
    double W = 0, Wabs = 0, D = 0;
    for (std::size_t i = 1; i < r.series.size(); ++i) {
      const auto& a = r.series[i - 1];
      const auto& b = r.series[i];
      const double dW = 0.5 * (a.F_T + b.F_T) * (b.w_T - a.w_T) + 0.5 * (a.F_N + b.F_N) * (b.w_N - a.w_N);
      W += dW;
      Wabs += std::abs(dW);
      const double Di = b.P_T * (b.w_Ti - a.w_Ti) + b.P_N * (b.w_w - a.w_w);
      CHECK(Di >= -1e-14);
      D += Di;
    }
    const auto& e = r.series.back();
    const double E = 0.5 * (2.0 * e.w_T * e.w_T + 2 * 0.4 * e.w_T * e.w_N + 1.5 * e.w_N * e.w_N) +
                     0.5 * 0.3 * e.P_T * e.P_T;
    const double err = std::abs(W - E - D) / Wabs;
    CAPTURE(steps, err, r.energy_error);
    CHECK(r.energy_error == Approx(err).epsilon(1e-6));
    CHECK(err < 2e-3);
    CHECK(err < prev_err);  // first order in the step
    prev_err = err;
    CHECK(r.min_step_dissipation >= 0);
    CHECK(r.dissipation == Approx(D).epsilon(1e-9));
  }
}

TEST_CASE("ALoadPathWithoutSolutionStopsWithAReport", "[sim]") {
  // Criterion (35) admits no P_N above mu/k (46): pressing a stuck point (a12 = 0, F_T = 0)
  // from 0 to 10 with mu/k = 5 must stop at the first load above 5 (F_N = 5.1 at t = 0.51).
  SimulationOptions o = decoupled(0.3);
  o.params.criterion = Criterion::kSoftening;
  LoadRamp ramp;
  ramp.F_N1 = 10;
  ramp.steps = 100;
  const auto r = simulate(ramp_history(ramp), o);
  CHECK(r.outcome == SimulationResult::Outcome::kNoSolution);
  CHECK(r.steps == 50);
  CHECK(r.final_state.P_N == Approx(5.0));
  CHECK(r.message.find("t = 0.51") != std::string::npos);
  CHECK(r.message.find("no solution") != std::string::npos);
  CHECK(r.message.find("P_N = 5") != std::string::npos);
}

TEST_CASE("BranchPointsAreRecordedAndRuleStopHaltsThere", "[sim]") {
  // mu a12 > a11 (Lambda = a11 - mu a12 < 0 at the sliding limit, model.md eqn (51)). Load
  // (0, 1), then F_T up to the sliding limit P_T = mu P_N = 2 and back. Stick steps below the
  // limit have three solutions. Hand check of step 2 (from P = (0, 1), dF = (1.5, 0), C_T = 0):
  // stick P_T1 = 1.5 < 2; slip+: g1 = -x - 0.9 xi = 0, P_T1 = 1.5 - xi = 2 P_N1 = 2 (1 - 0.9 xi)
  // gives xi = 0.625, P_N1 = 0.4375 > 0; separation: w = A^-1 F has w_N = (1 - 1.35)/0.19 < 0.
  // At F_T = 2.5 the only solution is the jump to separation.
  SimulationOptions o;
  o.params.a11 = 1.0;
  o.params.a12 = 0.9;
  o.params.a22 = 1.0;
  o.params.mu = 2.0;
  LoadHistory h;
  h.points = {{1, 0, 1}, {2, 1.5, 1}, {3, 2.0, 1}, {4, 1.9, 1}, {5, 2.5, 1}};
  const auto closest = simulate(h, o);
  REQUIRE(closest.outcome == SimulationResult::Outcome::kCompleted);
  CHECK(closest.branch_steps == 3);
  REQUIRE_FALSE(closest.branch_points.empty());
  CHECK(closest.branch_points.front().step == 2);
  CHECK(closest.branch_points.front().chosen == SolutionType::kStick);
  // The closest rule keeps sticking: P_T = F_T (C_T = 0, a12 dF_N = 0).
  CHECK(closest.series[4].P_T == Approx(1.9));
  CHECK(closest.series[5].type == SolutionType::kSeparation);
  CHECK(closest.series[5].P_N == 0);
  o.branch_rule = BranchRule::kStop;
  const auto stop = simulate(h, o);
  CHECK(stop.outcome == SimulationResult::Outcome::kBranchStop);
  CHECK(stop.steps == 1);
  CHECK(stop.message.find("3 solutions") != std::string::npos);
}

TEST_CASE("HeatFollowsTheBackwardEulerEnergyBalance", "[sim][heat]") {
  // No conduction: (C/T0) T1 (T1 - T) = D per step, so (C/T0) sum T1 (T1 - T) = D_total; and
  // (C/(2 T0)) (T_end^2 - T_init^2) = D_total up to the first-order sum of (C/2T0)(T1 - T)^2.
  SimulationOptions o = decoupled(0.01);
  o.heat.enabled = true;
  o.heat.heat_capacity = 0.05;
  o.heat.T_ref = 300;
  o.heat.T_initial = 300;
  const auto r = simulate(fretting_history(cycle(1.3, 3)), o);
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  double lhs = 0;
  for (std::size_t i = 1; i < r.series.size(); ++i)
    lhs += o.heat.heat_capacity / o.heat.T_ref * r.series[i].temperature *
           (r.series[i].temperature - r.series[i - 1].temperature);
  CHECK(lhs == Approx(r.dissipation).epsilon(1e-9));
  const double Tend = r.series.back().temperature;
  CHECK(Tend > 300);
  CHECK(o.heat.heat_capacity / (2 * o.heat.T_ref) * (Tend * Tend - 300 * 300) ==
        Approx(r.dissipation).epsilon(1e-3));
  // With conduction to bodies at 300 K and a long stick phase afterwards the interface cools
  // back towards 300 K, and the thermal dissipation of (42) is positive.
  o.heat.conductance[0] = 0.5;
  o.heat.conductance[1] = 0.5;
  o.heat.T_body[0] = 300;
  o.heat.T_body[1] = 300;
  LoadHistory h = fretting_history(cycle(1.3, 3));
  const double t_end = h.points.back().t;
  for (int i = 1; i <= 2000; ++i) h.points.push_back({t_end + 0.01 * i, 0.0, 1.0});
  const auto rc = simulate(h, o);
  REQUIRE(rc.outcome == SimulationResult::Outcome::kCompleted);
  CHECK(rc.max_temperature > 300);
  CHECK(rc.series.back().temperature == Approx(300).epsilon(1e-6));
  CHECK(rc.thermal_dissipation > 0);
}

TEST_CASE("MrozStupkiewiczWearEqualsArchardWithTheEquivalentConstant", "[sim]") {
  // Paper, after eqn (41): with |p_T| = mu p_N, (40) follows from (41) with
  // k_M = k_a / (3 p_s mu).
  SimulationOptions a = decoupled(0.006);
  SimulationOptions m = decoupled(0.0);
  m.wear.law = WearLaw::kMrozStupkiewicz;
  m.wear.k_M = 0.006 / (3 * 1.0 * 0.5);
  const auto ra = simulate(fretting_history(cycle(1.3, 3)), a);
  const auto rm = simulate(fretting_history(cycle(1.3, 3)), m);
  REQUIRE(ra.wear_depth > 0);
  CHECK(rm.wear_depth == Approx(ra.wear_depth).epsilon(1e-10));
}

TEST_CASE("LoadHistoriesParseAndRejectBadInput", "[sim][input]") {
  const LoadHistory h = parse_load_csv("t,F_T,F_N\n# comment\n0.5, 0, 1\n1.0, 0.2, 1\n");
  REQUIRE(h.points.size() == 2);
  CHECK(h.points[1].F_T == 0.2);
  CHECK_THROWS_AS(parse_load_csv("0.5,0,1\n0.5,0,1\n"), cpkit::InputError);   // t not increasing
  CHECK_THROWS_AS(parse_load_csv("0.5,0,1\n0.7,x,1\n"), cpkit::InputError);   // not a number
  CHECK_THROWS_AS(parse_load_csv("0.5,0\n"), cpkit::InputError);              // two columns
  CHECK_THROWS_AS(parse_load_csv("0.5,nan,1\n"), cpkit::InputError);
  CHECK_THROWS_AS(parse_load_csv(""), cpkit::InputError);
  CHECK_THROWS_AS(read_load_csv("/nonexistent/file.csv"), cpkit::InputError);
  // A leading unloaded point at t = 0 is the start; a loaded one at t <= 0 is bad input.
  const LoadHistory h0 = parse_load_csv("0,0,0\n1,0,1\n2,0.1,1\n");
  SimulationOptions o0;
  const auto r0 = simulate(h0, o0);
  CHECK(r0.steps == 2);
  CHECK(r0.series.back().step == 2);
  CHECK(r0.series.back().P_N == Approx(1.0));
  CHECK_THROWS_AS(simulate(parse_load_csv("0,0,1\n1,0,1\n"), o0), cpkit::InputError);
  FrettingCycle c;
  c.steps_per_cycle = 2;
  CHECK_THROWS_AS(fretting_history(c), cpkit::InputError);
  SimulationOptions o;
  o.heat.enabled = true;
  o.heat.T_ref = -1;
  CHECK_THROWS_AS(simulate(h, o), cpkit::InputError);
  o = SimulationOptions{};
  o.params.mu = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(simulate(h, o), cpkit::InputError);
  o = SimulationOptions{};
  o.wear.law = WearLaw::kMrozStupkiewicz;
  o.params.criterion = Criterion::kSoftening;
  CHECK_THROWS_AS(simulate(h, o), cpkit::InputError);
}

TEST_CASE("GeneratedLoadStreamsTheSameSeries", "[sim][stream]") {
  // The streamed run (load generated point by point, samples passed to a sink) must march the
  // same states as the stored run; the stored history is built by a loop written here.
  SimulationOptions o = decoupled(3e-3);
  const FrettingCycle c = cycle(1.2, 3, 40);
  LoadHistory h;
  const double dt = c.period / c.steps_per_cycle;
  for (int i = 1; i <= c.ramp_steps; ++i) h.points.push_back({i * dt, 0.0, c.F_N * i / c.ramp_steps});
  const double t_ramp = c.ramp_steps * dt;
  for (int k = 1; k <= c.cycles * c.steps_per_cycle; ++k)
    h.points.push_back({t_ramp + k * dt,
                        c.amplitude * std::sin(2 * M_PI * (k % c.steps_per_cycle) / c.steps_per_cycle),
                        c.F_N});
  h.period = c.period;
  h.cycle_start = t_ramp;
  const auto stored = simulate(h, o);
  std::vector<SimulationSample> streamed;
  o.record_every = 7;
  o.on_sample = [&](const SimulationSample& s) { streamed.push_back(s); };
  const auto r = simulate(fretting_source(c), o);
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  CHECK(r.series.empty());
  CHECK(r.steps == stored.steps);
  CHECK(r.wear_depth == Approx(stored.wear_depth).epsilon(1e-12));
  // Recorded: the start, every 7th step and the last step.
  REQUIRE(static_cast<long>(streamed.size()) == 1 + stored.steps / 7 + (stored.steps % 7 ? 1 : 0));
  for (const auto& s : streamed) {
    const auto& ref = stored.series[static_cast<std::size_t>(s.step)];
    CHECK(s.t == Approx(ref.t).epsilon(1e-12));
    CHECK(s.P_T == Approx(ref.P_T).epsilon(1e-9).margin(1e-12));
    CHECK(s.w_w == Approx(ref.w_w).epsilon(1e-9).margin(1e-15));
  }
}

TEST_CASE("GeneratedLoadPointsAreChecked", "[sim][stream]") {
  LoadSource src;
  src.size = 3;
  src.at = [](std::size_t i) { return LoadPoint{i == 2 ? 0.5 : 1.0 + static_cast<double>(i), 0.0, 1.0}; };
  CHECK_THROWS_AS(simulate(src, decoupled(0)), cpkit::InputError);
}
