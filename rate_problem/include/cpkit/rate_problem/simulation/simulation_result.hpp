#pragma once
/// \file simulation_result.hpp
/// What every quasi-static march shares (docs/simulation.md): how it ended, its options and its
/// result, as one template over the march's sample (the state after a step) and its per-point
/// quantity (double for one point, Eigen::VectorXd with one entry per point of a system). The
/// three marches are its instances: SimulationResult (one 2-D point, simulation.hpp),
/// SystemSimulationResult (N 2-D points, system_simulation.hpp), Fretting3dResult (one 3-D point
/// under an orbit, fretting_3d.hpp); the same for the options. A field a march does not fill
/// keeps its default; each field says which marches fill it.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/heat.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/model/wear.hpp"

namespace cpkit::rate {

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

/// A step with several solutions (one 2-D point records the first max_branch_records).
struct BranchPoint {
  long step = 0;
  double t = 0;
  int count = 0;
  unsigned types = 0;            ///< bit mask of the solution types
  SolutionType chosen = SolutionType::kStick;
};

/// The options of a march over samples `Sample` of a point with parameters `Params` (N points:
/// `Params` is unused, the system holds every point's parameters).
template <class Sample, class Params>
struct SimulationOptionsOf {
  Params params;         ///< one point: its parameters (2-D or 3-D)
  WearModel wear;        ///< one point: the wear law (3-D: Archard (40) or Mroz (41) with k_M)
  HeatOptions heat;      ///< 2-D: the interface temperature (off by default)
  BranchRule branch_rule = BranchRule::kClosest;
  double tol = 1e-9;     ///< 2-D: acceptance on the step's (unit-free for N points) NCP residual
  int record_every = 1;  ///< keep every n-th step (0: none); plus the start and the last step
  int max_branch_records = 100;  ///< one 2-D point: branch points recorded in detail
  int max_points = 8;            ///< N points: enumeration limit (system_step.hpp)
  /// 3-D: a step whose enumeration finds no solution (not proved complete: a near-double root
  /// of the slip condition, met in nearly symmetric problems with little wear) is tried by a
  /// local Newton method on the slip equations from the start state's slip direction; a root
  /// verified by step_3d_residual <= 1e-9 is taken and counted in `local_steps` and
  /// `incomplete_steps` (false: such a step stops the run).
  bool local_fallback = true;
  /// When set, every recorded sample (the start state, every record_every-th step and the
  /// last step) is passed here as it is produced instead of being stored in the result's
  /// `series`: the run's memory is then independent of its number of steps.
  std::function<void(const Sample&)> on_sample;
  /// Empty when usable; else names the first bad field (defined for each march).
  std::string validate() const;
};

/// The result of a march over samples `Sample`, with per-point sums of type `PerPoint`.
template <class Sample, class PerPoint>
struct SimulationResultOf {
  using Outcome = SimulationOutcome;
  Outcome outcome = Outcome::kCompleted;  ///< 3-D: never kContinuum
  bool inconclusive = false;  ///< N points: stopped at a step with no solution found, no proof
  std::string message;        ///< for a stop: time, state and why
  long steps = 0;             ///< steps completed
  std::vector<Sample> series;  ///< the recorded samples; empty when on_sample is set
  Sample final_state;          ///< the last state reached
  long branch_steps = 0;       ///< steps with more than one solution (the rule chose)
  std::vector<BranchPoint> branch_points;  ///< one 2-D point: the first max_branch_records
  long incomplete_steps = 0;  ///< N points, 3-D: steps whose enumeration was not proved complete
  long local_steps = 0;       ///< 3-D: of them, solved by the local fallback (local_fallback)
  /// 3-D: of the local steps, those whose enumeration had claimed "complete, no solution" (a
  /// defect of the enumeration: the verified root contradicts it); the first one's data.
  long enumeration_missed = 0;
  std::string first_missed;
  double wear_depth = 0;      ///< one point: final w^w
  /// The wear law summed along the run from the end-of-step values: 2-D sum c_w P_N1 |Dw_T^i|
  /// (c_w the law's coefficient; N points: per point, Archard k_i); 3-D Archard (40)
  /// sum k P_N1 |D Dw_T^i|, Mroz (41) sum k_M P_T1 . Dw_T^i.
  PerPoint wear_integral{};
  PerPoint total_slip{};            ///< sum |Dw_T^i| (3-D: Euclidean length of the slip path)
  double total_lambda = 0;          ///< 3-D: sum |D Dw_T^i|
  PerPoint dissipation{};           ///< sum of the steps' dissipation (42)
  /// Most negative step dissipation D met, relative to its scale; 0 when every step had D >= 0
  /// (the expected result).
  PerPoint min_step_dissipation{};
  double thermal_dissipation = 0;   ///< one 2-D point, heat on
  PerPoint max_temperature{};       ///< 2-D
  /// Per cycle of a periodic load: slip length (one point), wear, and (3-D) the wear split by
  /// slip direction, wear_X = sum c_w P_N1 (alpha_X Dw_TiX)^2 / |D Dw_T^i|.
  std::vector<double> slip_per_cycle;
  std::vector<PerPoint> wear_per_cycle;
  std::vector<double> wear_X_per_cycle, wear_Y_per_cycle;
  /// 2-D: W = sum (F0 + F1)/2 . Dw, the stored energy E and the scale sum |(F0 + F1)/2 . Dw|.
  double external_work = 0, stored_energy = 0, work_abs = 0;
  double energy_error = 0;  ///< 2-D: |W - (E - E0) - sum D| / max(work_abs, tiny)
  double max_residual = 0;  ///< largest step residual accepted
};

}  // namespace cpkit::rate
