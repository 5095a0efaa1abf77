#pragma once
// Internal: what the one-point march (simulation.cpp) and the N-point march
// (system_simulation.cpp) do the same way for every point at every step: the point placed on its
// active constraints, the step's dissipation and external work, and the load cycle a step
// belongs to; and the sentences every march (3-D fretting too) stops or completes with.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

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

}  // namespace cpkit::rate::detail
