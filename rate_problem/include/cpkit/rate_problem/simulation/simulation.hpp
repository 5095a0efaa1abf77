#pragma once
/// \file simulation.hpp
/// Quasi-static simulation of the one-point contact problem with friction, wear and heat
/// [Stromberg et al. 1996, Secs. 3-4; docs/simulation.md]: a load history is marched step by
/// step with the incremental problem (incremental_step.hpp), every step solved by complete
/// active-set enumeration (step_enumeration.hpp) and verified by its NCP residual.
///
/// - Several solutions: `branch_rule` decides (kClosest, the default: the solution closest to
///   the previous state in |DP_T| + |DP_N| + (det A / D0)|Dw_T^i|; kStop: stop there). Every
///   such step is a branch point (counted; the first `max_branch_records` are recorded).
/// - No solution (or a continuum, which no rule can choose from): the march stops and the
///   result says when, in which state and why. It never continues silently. Likewise when a
///   state or an energy is no longer finite (Outcome::kNumericalFailure).
/// - After a step the state is put exactly on its active constraints (g = 0 when P_N > 0,
///   P_T = s Y(P_N) after slip, P = 0 after separation) so that no drift accumulates.
/// - Thermodynamic checks every step: the mechanical dissipation (42)
///   D = P_T1 Dw_T^i + P_N1 Dw^w >= 0 (and the thermal part >= 0); the energy balance
///   W_ext = sum (F0 + F1)/2 . Dw = E(w, P_T) - E_0 + sum D with the stored energy
///   E = w.A w / 2 + C_T P_T^2 / 2 (trapezoidal work: exact for E; the end-of-step dissipation
///   makes the balance first-order accurate in the step), relative error reported.
#include <string>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation_result.hpp"

namespace cpkit::rate {

/// One row of the time series (the state after the step).
struct SimulationSample {
  long step = 0;
  double t = 0, F_T = 0, F_N = 0;
  double P_T = 0, P_N = 0, w_T = 0, w_N = 0, w_w = 0, w_Ti = 0, g = 0;
  StateLabel state = StateLabel::kB;   ///< contact state a-d after the step
  SolutionType type = SolutionType::kStick;  ///< the step's solution type
  int count = 1;                       ///< number of step solutions
  double dissipation = 0;              ///< mechanical dissipation (42) of the step
  double dissipation_total = 0, work_total = 0, stored = 0;
  double temperature = 0;              ///< interface temperature (T_initial when heat is off)
};

using SimulationOptions = SimulationOptionsOf<SimulationSample, ContactParameters>;
template <>
std::string SimulationOptions::validate() const;
using SimulationResult = SimulationResultOf<SimulationSample, double>;

/// Runs the simulation. Throws InputError for invalid options or history.
SimulationResult simulate(const LoadHistory& history, const SimulationOptions& options);
/// The same for a load produced point by point (fretting_source, ramp_source): memory
/// independent of the number of steps when options.on_sample is set (slip_per_cycle and
/// wear_per_cycle keep two numbers per cycle). A point that is not finite or whose t does not
/// increase throws InputError when it is reached.
SimulationResult simulate(const LoadSource& load, const SimulationOptions& options);

/// Contact state a-d of a configuration after a step (no validation).
StateLabel step_state_label(const ContactParameters& params, double P_T, double P_N,
                            double g) noexcept;

}  // namespace cpkit::rate
