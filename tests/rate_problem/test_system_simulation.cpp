// The N-point simulation (system_simulation.hpp). Independent sources: the one-point
// simulation (N = 1), Archard's integral summed here from the streamed time series, the energy
// balance recomputed here, and the stick/slip pattern of the flat punch (edges first).
#include <catch2/catch.hpp>

#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/flat_punch.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"

using namespace cpkit::rate;

TEST_CASE("OnePointSystemSimulationEqualsTheOnePointSimulation", "[system_sim]") {
  SimulationOptions o;
  o.params.a11 = 2.0;
  o.params.a12 = 0.3;
  o.params.a22 = 1.5;
  o.params.mu = 0.5;
  o.params.C_T = 0.4;
  o.params.k_a = 0.01;
  FrettingCycle c;
  c.F_N = 1;
  c.amplitude = 1.2;
  c.cycles = 3;
  c.steps_per_cycle = 40;
  const SimulationResult ref = simulate(fretting_history(c), o);
  REQUIRE(ref.outcome == SimulationResult::Outcome::kCompleted);

  ContactSystem s;
  s.A.resize(2, 2);
  s.A << 2.0, 0.3, 0.3, 1.5;
  SystemPoint q;
  q.mu = 0.5;
  q.C_T = 0.4;
  q.k_a = 0.01;
  s.points.push_back(q);
  Eigen::VectorXd eT(2), eN(2);
  eT << 1, 0;
  eN << 0, 1;
  const auto r = simulate_system(s, system_fretting_source(c, eT, eN), {});
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  CHECK(r.steps == ref.steps);
  CHECK(r.final_state.w_w[0] == Approx(ref.wear_depth).epsilon(1e-9));
  CHECK(r.final_state.P_T[0] == Approx(ref.final_state.P_T).epsilon(1e-9).margin(1e-12));
  CHECK(r.final_state.P_N[0] == Approx(ref.final_state.P_N).epsilon(1e-9));
  CHECK(r.total_slip[0] == Approx(ref.total_slip).epsilon(1e-9));
  CHECK(r.external_work == Approx(ref.external_work).epsilon(1e-9));
  CHECK(r.energy_error == Approx(ref.energy_error).epsilon(1e-6).margin(1e-12));
  // Without on_sample the series is kept, as the one-point march keeps it: sample by sample.
  REQUIRE(r.series.size() == ref.series.size());
  REQUIRE(r.series.size() == static_cast<std::size_t>(ref.steps) + 1);
  for (std::size_t j = 0; j < r.series.size(); ++j) {
    INFO("sample " << j);
    CHECK(r.series[j].t == ref.series[j].t);
    CHECK(r.series[j].P_T[0] == Approx(ref.series[j].P_T).epsilon(1e-9).margin(1e-12));
    CHECK(r.series[j].w_w[0] == Approx(ref.series[j].w_w).epsilon(1e-9).margin(1e-15));
    CHECK(r.series[j].state[0] == ref.series[j].state);
  }
}

TEST_CASE("FlatPunchPartialSlipAndArchardWearPerPoint", "[system_sim]") {
  FlatPunch fp;
  fp.n_points = 5;
  fp.mu = 0.5;
  fp.k_a = 0.03;
  const ContactSystem s = flat_punch_system(fp);
  FrettingCycle c;
  c.F_N = 1;
  c.amplitude = 0.42;  // total |F_T| <= 0.84 mu F_N: the punch as a whole does not slide
  c.cycles = 2;  // two cycles show growth per cycle; each step enumerates 4^5 active sets
  c.steps_per_cycle = 24;
  c.ramp_steps = 4;
  WARN("tangential pattern " << s.pattern1->transpose());
  std::vector<SystemSimulationSample> series;
  SystemSimulationOptions o;
  o.on_sample = [&](const SystemSimulationSample& x) { series.push_back(x); };
  const auto r = simulate_system(s, system_fretting_source(c, *s.pattern1, *s.pattern2), o);
  INFO(r.message);
  REQUIRE(r.outcome == SimulationResult::Outcome::kCompleted);
  const int N = fp.n_points, mid = N / 2;
  // Partial slip: at the first load peak the edges slip, the middle sticks.
  const SystemSimulationSample& peak = series[static_cast<std::size_t>(c.ramp_steps + c.steps_per_cycle / 4)];
  CHECK(peak.type[0] == SolutionType::kSlipPlus);
  CHECK(peak.type[static_cast<std::size_t>(N - 1)] == SolutionType::kSlipPlus);
  CHECK(peak.type[static_cast<std::size_t>(mid)] == SolutionType::kStick);
  // Archard per point, summed here from the series: sum k P_N1 |Delta w_Ti|.
  const double k = fp.k_a / (3 * fp.P_s);
  for (int i = 0; i < N; ++i) {
    double archard = 0;
    for (std::size_t j = 1; j < series.size(); ++j)
      archard += k * series[j].P_N[i] * std::abs(series[j].w_Ti[i] - series[j - 1].w_Ti[i]);
    INFO("point " << i + 1);
    CHECK(r.final_state.w_w[i] == Approx(archard).epsilon(1e-9).margin(1e-15));
    CHECK(r.min_step_dissipation[i] >= 0);
  }
  // The wear profile: the edges wear, the stuck middle does not; it grows every cycle.
  CHECK(r.final_state.w_w[0] > 0);
  CHECK(r.final_state.w_w[N - 1] > 0);
  CHECK(r.final_state.w_w[mid] == 0);
  REQUIRE(r.wear_per_cycle.size() == static_cast<std::size_t>(c.cycles));
  for (const auto& w : r.wear_per_cycle) CHECK(w[0] > 0);
  // Energy balance recomputed here: W = E(w) + sum D (E0 = 0).
  const auto& f = r.final_state;
  const double E = 0.5 * f.w.dot(s.A * f.w);
  CHECK(std::abs(r.external_work - E - f.dissipation_total) <= 0.02 * r.work_abs);
  WARN("flat punch N = 5: steps " << r.steps << ", incomplete " << r.incomplete_steps
                                  << ", edge wear " << f.w_w[0] << ", energy error " << r.energy_error);
}

TEST_CASE("SystemSimulationBadInput", "[system_sim]") {
  FlatPunch fp;
  const ContactSystem s = flat_punch_system(fp);
  std::vector<SystemLoadPoint> pts = {{1.0, Eigen::VectorXd::Zero(3)}};
  CHECK_THROWS_WITH(simulate_system(s, system_history_source(pts), {}), Catch::Contains("need 10"));
  pts = {{1.0, Eigen::VectorXd::Zero(10)}, {0.5, Eigen::VectorXd::Zero(10)}};
  CHECK_THROWS_WITH(simulate_system(s, system_history_source(pts), {}), Catch::Contains("does not increase"));
  SystemSimulationOptions o;
  o.max_points = 3;
  CHECK_THROWS_WITH(simulate_system(s, system_history_source(pts), o), Catch::Contains("limit"));
  fp.n_points = 1;
  CHECK_THROWS_AS(flat_punch_system(fp), cpkit::InputError);
}
