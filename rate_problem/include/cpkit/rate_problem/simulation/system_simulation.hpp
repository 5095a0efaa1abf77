#pragma once
/// \file system_simulation.hpp
/// Quasi-static simulation of N contact points coupled through A (docs/simulation.md,
/// "N points"): the one-point march of simulation.hpp, every step solved by the N-point step
/// enumeration (system_step.hpp) and verified by its unit-free NCP residual.
///
/// - Start: the system's points' current values (P_T, P_N, g), displacements w = 0, F = 0
///   (a system whose points carry forces must give the load that holds them as the first
///   load point; the march does not check it).
/// - Several solutions: BranchRule::kClosest takes the one closest to the previous state in
///   sum_i |DP_T,i| + |DP_N,i| + (det A_i / D0_i)|Dw_Ti,i| (A_i: point i's diagonal block);
///   kStop stops. No solution: the run stops and says when and why. A step whose enumeration
///   was not proved complete (system_step.hpp: m >= 3 points slipping with wear) is counted
///   in `incomplete_steps`; when it found no solution the run stops as inconclusive.
/// - After a step each point is put on its active constraints (as for one point).
/// - Checks per point: the dissipation (42) D_i = P_T1 Dw_Ti + P_N1 Dw^w_i >= 0; the wear depth
///   equals Archard's integral sum k_i P_N1,i |Dw_Ti,i| (both accumulated); the interface
///   temperature by the one-point heat balance per point (the same HeatOptions for all). The
///   global energy balance W_ext = sum (F0 + F1)/2 . Dw = E - E_0 + sum_i D_i with
///   E = w.A w / 2 + sum_i C_T,i P_T,i^2 / 2.
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// A load point of an N-point history: F (2N, interleaved T_1, N_1, ...).
struct SystemLoadPoint {
  double t = 0;
  Eigen::VectorXd F;
};

/// A CSV load history for `n_points` points: rows t, F_T1, F_N1, ..., F_TN, F_NN (numbers,
/// comments and a header as parse_load_csv). Throws InputError naming `origin` and the line for
/// a row of another width, and for an empty history.
std::vector<SystemLoadPoint> parse_system_load_csv(const std::string& text,
                                                   const std::string& origin, int n_points);

/// An N-point load history produced point by point (load_history.hpp).
using SystemLoadSource = LoadSourceOf<SystemLoadPoint>;

/// The one-point fretting cycle through two load patterns: F(t) = F_T(t) e_T + F_N(t) e_N with
/// F_T, F_N the one-point cycle (fretting_source) and e_T, e_N 2N-vectors (a system's
/// `patterns`: the first tangential, the second normal). Throws InputError.
SystemLoadSource system_fretting_source(const FrettingCycle& cycle, const Eigen::VectorXd& e_T,
                                        const Eigen::VectorXd& e_N);
/// A stored history (rows t, F (2N)); it must outlive the source.
SystemLoadSource system_history_source(const std::vector<SystemLoadPoint>& points,
                                       double period = 0);

/// The state after a step (per point vectors of length N; w of length 2N).
struct SystemSimulationSample {
  long step = 0;
  double t = 0;
  Eigen::VectorXd F;                     ///< 2N
  Eigen::VectorXd w;                     ///< 2N, total displacements (T, N interleaved)
  Eigen::VectorXd P_T, P_N, g, w_w, w_Ti;  ///< N
  Eigen::VectorXd temperature;           ///< N (T_initial when heat is off)
  std::vector<StateLabel> state;         ///< N, contact state a-d after the step
  std::vector<SolutionType> type;        ///< N, the step's solution type per point
  int count = 1;                         ///< number of step solutions found
  bool complete = true;                  ///< the step's enumeration was proved complete
  double dissipation_total = 0, work_total = 0, stored = 0;
};

using SystemSimulationOptions = SimulationOptionsOf<SystemSimulationSample, std::monostate>;
template <>
std::string SystemSimulationOptions::validate() const;
using SystemSimulationResult = SimulationResultOf<SystemSimulationSample, Eigen::VectorXd>;

/// Runs the march. Throws InputError for invalid options, system or load (sizes, NaN, t not
/// increasing, N above max_points).
SystemSimulationResult simulate_system(const ContactSystem& system, const SystemLoadSource& load,
                                       const SystemSimulationOptions& options);

}  // namespace cpkit::rate
