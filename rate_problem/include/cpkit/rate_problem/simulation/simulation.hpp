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
#include <functional>
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/heat.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

struct SimulationSample;

struct SimulationOptions {
  ContactParameters params;
  WearModel wear;
  HeatOptions heat;
  BranchRule branch_rule = BranchRule::kClosest;
  double tol = 1e-9;             ///< acceptance on the step NCP residual
  int record_every = 1;          ///< keep every n-th step in the series (0: none)
  int max_branch_records = 100;  ///< branch points recorded in detail
  /// When set, every recorded sample (the start state, every record_every-th step and the
  /// last step) is passed here as it is produced instead of being stored in
  /// SimulationResult::series: the run's memory is then independent of its number of steps.
  std::function<void(const SimulationSample&)> on_sample;
  std::string validate() const;
};

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

struct BranchPoint {
  long step = 0;
  double t = 0;
  int count = 0;
  unsigned types = 0;            ///< bit mask of the solution types
  SolutionType chosen = SolutionType::kStick;
};

/// How a simulation ended (every march: one 2-D point, N points, the 3-D fretting).
/// kContinuum: the step's solutions form a continuum (2-D, degenerate data); kAmbiguous: a
/// step that is not proved complete and the rule could not choose (3-D); kNumericalFailure: a
/// state or an energy left the range of double (data near 1e300): the run stops before that
/// step, never "completed" with inf/NaN in its results.
enum class SimulationOutcome {
  kCompleted, kNoSolution, kContinuum, kAmbiguous, kBranchStop, kNumericalFailure
};
/// "completed", "no_solution", "continuum", "ambiguous", "branch_stop", "numerical_failure".
std::string_view to_string(SimulationOutcome o) noexcept;

struct SimulationResult {
  using Outcome = SimulationOutcome;
  Outcome outcome = Outcome::kCompleted;
  std::string message;           ///< for a stop: time, state and why
  long steps = 0;                ///< steps completed
  std::vector<SimulationSample> series;  ///< empty when SimulationOptions::on_sample is set
  SimulationSample final_state;  ///< the last state reached
  long branch_steps = 0;         ///< steps with more than one solution
  std::vector<BranchPoint> branch_points;  ///< the first max_branch_records of them
  double wear_depth = 0;         ///< final w^w
  double wear_integral = 0;      ///< sum c_w P_N1 |Dw_T^i| (Archard: k_a/(3 P_s) int P_N |dw_T^i|)
  double total_slip = 0;         ///< sum |Dw_T^i|
  std::vector<double> slip_per_cycle, wear_per_cycle;  ///< when the history has a period
  double external_work = 0, stored_energy = 0, dissipation = 0;
  double work_abs = 0;           ///< sum |(F0 + F1)/2 . Dw| (the scale of the balance)
  double energy_error = 0;       ///< |W - (E - E0) - D| / max(work_abs, tiny)
  /// Most negative step dissipation D met, relative to its scale (|P_T1| + mu P_N1)|Dw_T^i| +
  /// P_N1 Dw^w; 0 when every step had D >= 0 (the expected result).
  double min_step_dissipation = 0;
  double thermal_dissipation = 0;
  double max_temperature = 0;
  double max_residual = 0;       ///< largest step NCP residual accepted
};

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
