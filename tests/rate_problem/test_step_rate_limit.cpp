// Small increments: the continuous (non-jump) step solutions divided by the increment converge
// to the rate solutions of the rate module's analytic route (the paper's closed forms,
// implemented independently of the step code), for both criteria, with wear, from states b, c
// and d (Lambda of both signs).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"

using namespace cpkit::rate;

TEST_CASE("ContinuousStepSolutionsConvergeToTheRateSolutions", "[step][rate]") {
  std::mt19937 gen(21);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 1e-6;
  int compared = 0, multi = 0, none = 0;
  for (int it = 0; it < 300; ++it) {
    ContactParameters a;
    a.a11 = 1.2 + u(gen);
    a.a22 = 1.2 + u(gen);
    a.a12 = 0.9 * u(gen) * std::sqrt(a.a11 * a.a22);
    a.mu = 1.5 + u(gen);
    a.C_T = it % 2 ? 0.0 : 0.5 + 0.4 * u(gen);
    a.k_a = it % 3 == 0 ? 0.0 : 0.3 + 0.2 * u(gen);
    a.P_s = 1.0;
    a.criterion = it % 4 == 0 ? Criterion::kSoftening : Criterion::kCoulomb;
    if (!a.validate().empty() || a.detA() < 0.05) continue;
    ContactState st;
    const int kind = it % 3;  // 0: b, 1: c, 2: d
    st.label = kind == 0 ? StateLabel::kB : kind == 1 ? StateLabel::kC : StateLabel::kD;
    st.P_N = kind == 0 ? 0.0 : 0.6 + 0.3 * u(gen);
    st.sgn_PT = u(gen) > 0 ? 1 : -1;
    if (!st.validate(a).empty()) continue;
    StepProblem p;
    p.params = a;
    p.state.P_N0 = st.P_N;
    const double Y = a.mu * st.P_N - (a.criterion == Criterion::kSoftening ? a.k() : 0.0) * st.P_N * st.P_N;
    p.state.P_T0 = kind == 2 ? st.sgn_PT * Y : kind == 1 ? 0.4 * st.sgn_PT * Y : 0.0;
    const double th = 2 * M_PI * u(gen);
    const LoadRate dF{std::cos(th), std::sin(th)};
    p.load = {h * dF.dF_T, h * dF.dF_N};
    const RateSolutionSet rate = solve_rate_problem(a, st, dF, RateMethod::kAnalytic);
    if (rate.infinite) continue;
    const StepSolutionSet step = enumerate_step(p);
    REQUIRE_FALSE(step.infinite);
    CAPTURE(it, kind, a.a11, a.a12, a.a22, a.mu, a.C_T, a.k_a, to_string(a.criterion), st.P_N,
            st.sgn_PT, th);
    REQUIRE(step.continuous_count == rate.count());
    for (const auto& s : step.solutions) {
      if (s.jump) continue;
      bool matched = false;
      for (const auto& r : rate.solutions) {
        const Rates& q = r.start;
        const double err = std::max({std::abs(s.start.DP_T / h - q.dP_T),
                                     std::abs(s.start.DP_N / h - q.dP_N),
                                     std::abs(s.start.Dw_T / h - q.dw_T),
                                     std::abs(s.start.Dw_N / h - q.dw_N),
                                     std::abs(s.start.Dw_Ti / h - q.dw_Ti),
                                     std::abs(s.start.Dw_w / h - q.dw_w)});
        const double scale = 1 + std::max({std::abs(q.dP_T), std::abs(q.dP_N), std::abs(q.dw_T),
                                           std::abs(q.dw_N)});
        if (err <= 1e-4 * scale && r.type == s.type) matched = true;
      }
      CHECK(matched);
    }
    ++compared;
    if (rate.count() > 1) ++multi;
    if (rate.count() == 0) ++none;
  }
  CHECK(compared > 150);
  CHECK(multi > 0);
  CHECK(none > 0);
}
