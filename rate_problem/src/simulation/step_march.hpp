#pragma once
// Internal: the one loop of every march (one 2-D point, simulation.cpp; N points,
// system_simulation.cpp; one 3-D point under an orbit, fretting_3d.cpp), and what the 2-D
// marches do the same way for every point at every step: the point placed on its active
// constraints, the step's dissipation and external work, and the load cycle a step belongs to.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation_result.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"

namespace cpkit::rate::detail {

/// A point's forces and gap after a step, placed exactly on its active constraints.
struct PlacedPoint {
  double P_T = 0, P_N = 0, g = 0;
};

/// Separated or open (or P_N1 <= 0): P = 0, g = min(g1, 0). In contact: g = 0 and P_T on the
/// friction limit Y = mu P_N1 - kc P_N1^2 when slipping (kc: criterion (35)'s softening, else
/// 0), else P_T1 clamped into [-Y, Y].
inline PlacedPoint place_on_constraints(const StepValues& v, SolutionType type, double mu,
                                        double kc) noexcept {
  PlacedPoint p{v.P_T1, v.P_N1, v.g1};
  if (p.P_N <= 0 || type == SolutionType::kSeparation || type == SolutionType::kOpen) {
    p.P_N = 0;
    p.P_T = 0;
    p.g = std::min(v.g1, 0.0);
  } else {
    p.g = 0;
    const double Y = mu * p.P_N - kc * p.P_N * p.P_N;
    if (type == SolutionType::kSlipPlus) p.P_T = Y;
    if (type == SolutionType::kSlipMinus) p.P_T = -Y;
    p.P_T = std::clamp(p.P_T, -Y, Y);
  }
  return p;
}

/// The step's dissipation (42): D = P_T1 Dw_T^i + P_N1 Dw^w.
inline double step_dissipation(const StepValues& v) noexcept {
  return v.P_T1 * v.Dw_Ti + v.P_N1 * v.Dw_w;
}

/// The dissipation relative to its own scale (negative only through rounding or a
/// non-dissipative law; a run reports the most negative).
inline double relative_dissipation(const StepValues& v, double mu) noexcept {
  const double D_scale =
      (std::abs(v.P_T1) + mu * std::abs(v.P_N1)) * std::abs(v.Dw_Ti) + std::abs(v.P_N1 * v.Dw_w);
  return step_dissipation(v) / std::max(D_scale, 1e-300);
}

/// The work of the load, from (F_T0, F_N0) to (F_T1, F_N1), over the step (trapezoidal rule).
inline double step_work(double F_T0, double F_N0, double F_T1, double F_N1,
                        const StepValues& v) noexcept {
  return 0.5 * (F_T0 + F_T1) * v.Dw_T + 0.5 * (F_N0 + F_N1) * v.Dw_N;
}

/// The cycle (0-based) of a cyclic load whose time span holds the midpoint of the step from
/// t_prev to t; false when the load has no period or the step lies before the first cycle.
inline bool step_cycle(double period, double cycle_start, double t_prev, double t,
                       std::size_t& cycle) noexcept {
  if (!(period > 0) || !(t > cycle_start)) return false;
  const double tc = 0.5 * (t_prev + t) - cycle_start;
  if (tc < 0) return false;
  cycle = static_cast<std::size_t>(std::floor(tc / period));
  return true;
}

/// The sentence every march stops with: "stopped before t = <at>: <why>Last state: <last>".
/// The parts are the march's own words (the CLI prints them byte for byte): `at` the load point
/// (its time; one point and 3-D add the load), `why` ending with its own separator, `last` the
/// march's description of the state it stopped in.
inline std::string stop_message(const std::string& at, const std::string& why,
                                const std::string& last) {
  return "stopped before t = " + at + ": " + why + "Last state: " + last;
}

/// Why a march with the branch rule 'stop' stops at a step with `count` > 1 solutions.
inline std::string branch_stop_why(std::size_t count) {
  return "the step has " + std::to_string(count) + " solutions and the branch rule is 'stop'. ";
}

/// The message of a march that completed its `steps` steps in the state described by `last`.
inline std::string completed_message(long steps, const std::string& last) {
  return "completed " + std::to_string(steps) + " steps; final " + last;
}

/// Why a march stops at a step: the outcome and the march's own words (ending with their
/// separator).
struct MarchStop {
  SimulationOutcome outcome;
  std::string why;
};

/// The one loop of every march over a load source. `March` is the march kind: its types
/// (Point, Sample, Step: the solved step, Result, Options) and its words and steps:
/// - `Sample start(const Point& first, double& t_prev, std::size_t& k0)`: the start state, the
///   start time and the first load point to march to;
/// - `void check(const Point&, std::size_t k, double t_prev)`: throws InputError for a bad point;
/// - `std::optional<MarchStop> solve(const Sample&, const Point&, Step&, Result&)`: every
///   solution of the step to the point (or a stop);
/// - `std::size_t count(const Step&)`; `MarchStop no_solution(const Step&, Result&)`;
///   `std::optional<MarchStop> ambiguous(const Step&)`: several solutions no rule may choose
///   from; `std::size_t choose(const Step&, const Point&, Result&)`: the branch rule 'closest';
///   `kCountsStoppedBranch`: a step the rule 'stop' stops at counts as a branch step;
/// - `std::optional<MarchStop> advance(const Sample& cur, const Point&, const Step&, std::size_t
///   chosen, double t_prev, Result&, Sample& next)`: the state after the step and the running
///   sums (a stop when a value would not be finite);
/// - `std::string at(const Point&, SimulationOutcome)`, `std::string describe(const Sample&)`:
///   the load and the state in the sentences of a stop (the CLI prints them byte for byte);
/// - `void finish(Result&)`: the totals, once `final_state` and `message` are set.
template <class March>
void run_march(March& m, const LoadSourceOf<typename March::Point>& load,
               const typename March::Options& opt, typename March::Result& res) {
  using Sample = typename March::Sample;
  const bool streaming = static_cast<bool>(opt.on_sample);
  auto record = [&](const Sample& s) {
    if (streaming) opt.on_sample(s);
    else res.series.push_back(s);
  };
  double t_prev = 0;
  std::size_t k0 = 0;
  Sample cur = m.start(load.at(0), t_prev, k0);
  if (opt.record_every > 0) record(cur);
  typename March::Step step;
  for (std::size_t k = k0; k < load.size; ++k) {
    const typename March::Point lp = load.at(k);
    m.check(lp, k, t_prev);
    auto stop = [&](const MarchStop& s) {
      res.outcome = s.outcome;
      res.message = stop_message(m.at(lp, s.outcome), s.why, m.describe(cur));
    };
    if (const auto s = m.solve(cur, lp, step, res)) {
      stop(*s);
      break;
    }
    const std::size_t count = m.count(step);
    if (count == 0) {
      stop(m.no_solution(step, res));
      break;
    }
    std::size_t chosen = 0;
    if (count > 1) {
      if (const auto s = m.ambiguous(step)) {
        stop(*s);
        break;
      }
      chosen = m.choose(step, lp, res);
      if (March::kCountsStoppedBranch) ++res.branch_steps;
      if (opt.branch_rule == BranchRule::kStop) {
        stop({SimulationOutcome::kBranchStop, branch_stop_why(count)});
        break;
      }
      if (!March::kCountsStoppedBranch) ++res.branch_steps;
    }
    Sample next = cur;
    if (const auto s = m.advance(cur, lp, step, chosen, t_prev, res, next)) {
      stop(*s);
      break;
    }
    next.step = res.steps + 1;
    next.t = lp.t;
    next.count = static_cast<int>(count);
    t_prev = lp.t;
    cur = std::move(next);
    ++res.steps;
    if (opt.record_every > 0 && (res.steps % opt.record_every == 0 || k + 1 == load.size))
      record(cur);
  }
  res.final_state = cur;
  if (res.outcome == SimulationOutcome::kCompleted)
    res.message = completed_message(res.steps, m.describe(cur));
  m.finish(res);
}

}  // namespace cpkit::rate::detail
