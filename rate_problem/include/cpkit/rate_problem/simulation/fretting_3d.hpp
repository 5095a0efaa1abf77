#pragma once
/// \file fretting_3d.hpp
/// Quasi-static fretting of one three-dimensional contact point under an elliptic tangential
/// load orbit, with the elliptic friction law (39) and anisotropic Archard wear (40) or the
/// Mroz-Stupkiewicz law (41) [Stromberg, Johansson & Klarbring 1996; docs/contact_3d.md,
/// "Fretting with an elliptic load orbit"].
///
/// The load is marched step by step with the implicit 3-D step (step_3d.hpp); every step is
/// solved by enumerate_step_3d (every solution, exactly) and:
/// - one solution: taken (a step whose enumeration is not proved complete is counted in
///   `incomplete_steps`); none found: a local Newton method on the
///   slip equations (Fretting3dOptions::local_fallback), its root verified and counted
///   (also when the enumeration claimed to be complete: counted as `enumeration_missed`);
/// - several solutions, proved complete: the branch rule decides (rate::BranchRule::kClosest,
///   the default: smallest |DP_T| + |DP_N| + |K Dw_T^i| with K = (I + C_T S)^-1 S, S the
///   tangential stiffness with the normal DOF held, A_TT - A_TN A_NT / A_NN: every term a
///   force, as the 2-D rule; kStop: stop there);
/// - several solutions and not proved complete (ambiguous), or none: the march stops and the
///   result says when, in which state and why (never silently).
/// After a step the state is put exactly on its active constraints (g = 0 when P_N > 0, the
/// traction on the friction ellipse ||P_T|| = mu P_N after slip, P = 0 after separation), as
/// the 2-D simulation does, so that no drift accumulates.
///
/// Units: any consistent set (forces, lengths; A force/length, C_T length/force, k and k_M
/// 1/force). Angles in radians.
#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "cpkit/rate_problem/model/parameters_3d.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation_result.hpp"

namespace cpkit::rate {

/// One load point (t, F_TX, F_TY, F_N).
struct LoadPoint3d {
  double t = 0;
  Eigen::Vector2d F_T{0, 0};
  double F_N = 0;
};

/// The elliptic load orbit. Three phases, each step of length dt = period / steps_per_cycle:
///  1. normal ramp: F_N rises linearly to F_N in `ramp_steps` steps, F_T = 0;
///  2. lead-in: F_T rises linearly from 0 to the orbit's start R(angle) (a_X, 0) in
///     `lead_steps` steps (0: no lead-in; the first orbit step then starts from F_T = 0);
///  3. `cycles` cycles of the orbit F_T(t) = R(angle) (a_X cos(2 pi s/period),
///     a_Y sin(2 pi s/period)), s = t - cycle_start(), F_N constant, `steps_per_cycle` steps
///     per cycle (a_Y < 0: clockwise; a_Y = 0: a straight back-and-forth line).
/// R(angle) is the rotation by `angle` (rad) in the (X, Y) plane.
struct EllipticOrbit {
  double F_N = 1;
  double a_X = 0.5, a_Y = 0.5;
  double angle = 0;
  double period = 1;
  int cycles = 10;
  int steps_per_cycle = 100;
  int ramp_steps = 10;
  int lead_steps = -1;  ///< < 0: steps_per_cycle / 4
  /// Empty when usable; else names the field (non-finite, F_N < 0, period <= 0, counts < 1 or
  /// a run of more than 2^62 steps).
  std::string validate() const;
  int lead() const noexcept;  ///< the lead-in steps actually used
  std::size_t size() const noexcept;  ///< number of load points (= steps)
  double dt() const noexcept { return period / steps_per_cycle; }
  double cycle_start() const noexcept { return (ramp_steps + lead()) * dt(); }
  /// Load point i (0 .. size() - 1), computed from i alone (no state, no drift).
  LoadPoint3d at(std::size_t i) const noexcept;
};

/// A 3-D load produced point by point (load_history.hpp); the march starts from the unloaded
/// grazing state at t = 0 and takes one step to every point, in order.
using LoadSource3d = LoadSourceOf<LoadPoint3d>;
/// The orbit as a source. Throws InputError when orbit.validate() fails.
LoadSource3d orbit_source(const EllipticOrbit& orbit);

/// One row of the series: the state after the step and the step's increments.
struct Fretting3dSample {
  long step = 0;  ///< 0: the start state
  double t = 0;
  Eigen::Vector2d F_T{0, 0};
  double F_N = 0;
  Eigen::Vector2d P_T{0, 0};
  double P_N = 0, g = 0;
  Eigen::Vector2d w_T{0, 0};
  double w_N = 0;
  Eigen::Vector2d w_Ti{0, 0};    ///< accumulated irreversible slip (the slip path)
  Eigen::Vector2d Dw_Ti{0, 0};   ///< the step's slip increment
  double lambda = 0;             ///< the step's multiplier |D Dw_T^i|
  double Dw_w = 0;               ///< the step's wear increment (from the step's solution)
  double w_w = 0;                ///< accumulated wear depth
  SolutionType type = SolutionType::kStick;  ///< the step's solution type
  int count = 1;                 ///< number of step solutions
  bool complete = true;          ///< the step's enumeration was proved complete
  double dissipation = 0;        ///< P_T1 . Dw_T^i + P_N1 Dw^w of the step (42)
  long cycle = -1;               ///< orbit cycle of the step (-1: ramp or lead-in)
};

using Fretting3dOptions = SimulationOptionsOf<Fretting3dSample, ContactParameters3d>;
template <>
std::string Fretting3dOptions::validate() const;
using Fretting3dResult = SimulationResultOf<Fretting3dSample, double>;

/// Runs the march. Throws InputError for invalid options or load.
Fretting3dResult simulate_fretting_3d(const LoadSource3d& load, const Fretting3dOptions& options);
Fretting3dResult simulate_fretting_3d(const EllipticOrbit& orbit, const Fretting3dOptions& options);

}  // namespace cpkit::rate
