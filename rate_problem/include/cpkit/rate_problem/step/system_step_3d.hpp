#pragma once
/// \file system_step_3d.hpp
/// One implicit time step of N three-dimensional contact points coupled through a condensed
/// stiffness A (3N x 3N, interleaved (T_X1, T_Y1, N1, T_X2, ...), as ContactSystem3d). Per
/// point i the equations of the one-point step (step_3d.hpp, docs/contact_3d.md (3D.20)):
///   Dw_T,i = C_T,i DP_T,i + Dw_T,i^i,   Dw_T,i^i = lambda_i D_i^-2 P_T1,i / ||P_T1,i||,
///   Dw^w_i = c_w,i P_N1,i lambda_i,   g1_i = g0_i + Dw_N,i - Dw^w_i,
///   P_N1,i _|_ -g1_i,   x_i = (mu_i P_N1,i, D_i^-1 P_T1,i) in K _|_ y_i = (lambda_i, -D_i Dw_T,i^i) in K,
/// coupled through equilibrium DF - DP = A Dw (3N). Section "N coupled points" of
/// docs/contact_3d.md, section 8.
///
/// What the solvers can claim: the semismooth Newton method finds one solution near its start;
/// the multistart collects distinct verified solutions and never claims completeness (there is
/// no complete enumeration of the coupled 3-D step). A result counts as a solution only when
/// system_step_3d_residual <= 1e-9.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// One step of N coupled 3-D points.
struct SystemStep3dProblem {
  ContactSystem3d system;           ///< A (3N x 3N) and the points' parameters (their state
                                    ///< letters and dF are not used: `states` and `DF` are)
  std::vector<Step3dState> states;  ///< per point: P_T0, P_N0, g0 (N)
  rate::WearModel wear;             ///< one law for all points (Archard: each point's k_a/(3 P_s))
  Eigen::VectorXd DF;               ///< load increment (3N, interleaved)

  int n_points() const noexcept { return system.n_points(); }
  /// Empty when usable; else names the field and point: sizes (A 3N x 3N, N states, DF 3N,
  /// N >= 1), A not finite / symmetric / positive definite, each point as
  /// Step3dProblem::validate (parameters, state, wear).
  std::string validate() const;
  /// Point i alone: its diagonal 3x3 block of A, its state, its three load components.
  Step3dProblem point_problem(int i) const;
};

/// One solution: per point its type, values, slip direction and angle (Step3dSolution; each
/// point's `residual` is its own terms of system_step_3d_residual) and the system residual.
struct SystemStep3dSolution {
  std::vector<Step3dSolution> points;
  double residual = 0;  ///< system_step_3d_residual
};

/// The solutions of N coupled 3-D points (step_result.hpp). There is no complete enumeration
/// of the coupled 3-D step: its multistart says complete = false.
using SystemStep3dSolutionSet = StepSolutionSetOf<SystemStep3dSolution>;

/// Per-point values from the end forces P1 (3N, interleaved) and the multipliers lambda (N):
/// Dw = A^-1 (DF - DP), Dw_T^i = Dw_T - C_T DP_T, Dw^w = c_w P_N1 lambda, g1 = g0 + Dw_N - Dw^w.
/// Throws InputError for wrong sizes.
std::vector<Step3dValues> system_step_3d_values(const SystemStep3dProblem& problem,
                                                const Eigen::VectorXd& P1,
                                                const Eigen::VectorXd& lambda);

/// Scale-free residual: per point the terms of step_3d_residual other than equilibrium
/// (consistency of the values, the contact pair, the SOC natural residual and the
/// complementarity products), and equilibrium DF - DP - A Dw over all 3N rows relative to its
/// terms; all in units normalized by the system's force scale (largest of |DF|, |P_T0|, P_N0,
/// |A| |g0| over all points) and stiffness scale |A|. INFINITY for wrong sizes or non-finite
/// values.
double system_step_3d_residual(const SystemStep3dProblem& problem,
                               const std::vector<Step3dValues>& values) noexcept;

/// Per-point types (classify_step_3d with the system's scales), slip directions, per-point and
/// system residuals.
SystemStep3dSolution make_system_step_3d_solution(const SystemStep3dProblem& problem,
                                                  const std::vector<Step3dValues>& values);

/// The common SolveResult (status granted by the system verdict: kSolved when
/// system_step_3d_residual <= tol, as finalize_step_3d) with the system's solution.
using SystemStep3dSolveResult = StepSolveResultOf<SystemStep3dSolution>;

/// Semismooth Newton on the 4N unknowns z_i = (P_TX1, P_TY1, P_N1, lambda)_i with, per point,
/// the scalar FB function of the contact pair and the SOC FB function of (x_i, y_i) (as
/// solve_step_3d_fb_soc), dense LU of the 4N x 4N generalized Jacobian, Armijo line search on
/// 0.5 |Phi|^2 with a steepest-descent fallback; accepted only when system_step_3d_residual
/// <= options.tol and each FB function is small against its arguments. Start: `start` (N
/// entries) or the start states with lambda = 0. Throws InputError for invalid input.
SystemStep3dSolveResult solve_system_step_3d_fb_soc(
    const SystemStep3dProblem& problem, const CommonOptions& options = step_3d_solver_options(),
                                                     const std::vector<Step3dStart>* start = nullptr);

/// Distinct verified solutions of FB-SOC Newton from the start state and `n_starts`
/// deterministic pseudo-random starts (seeded). complete is always false (the message says how
/// many runs verified). Throws InputError for invalid input or n_starts < 0.
SystemStep3dSolutionSet multistart_system_step_3d(const SystemStep3dProblem& problem,
                                                  int n_starts, std::uint64_t seed = 1);

}  // namespace cpkit::rate
