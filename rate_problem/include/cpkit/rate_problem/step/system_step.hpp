#pragma once
/// \file system_step.hpp
/// One implicit time step of N contact points coupled through a condensed stiffness A
/// (docs/model.md "N contact points"; docs/simulation.md "N points"): the one-point step of
/// incremental_step.hpp point by point [Stromberg et al. 1996, Sec. 4, eqns (37), (38)].
///
/// From the start state of every point (P_T0, P_N0, g0 = w_N - w^w <= 0, taken from the
/// system's points: SystemPoint::P_T, P_N, g) and a load increment DF (2N, interleaved
/// T_1, N_1, T_2, N_2, ...), backward Euler with Archard wear at the end of the step:
///   DF - DP = A Dw,   Dw_T,i = C_T,i DP_T,i + Dw_Ti,i,   Dw^w_i = k_i P_N1,i |Dw_Ti,i|,
///   k_i = k_a,i / (3 P_s,i), and per point the three complementarity pairs of the one-point
///   step: P_N1 _|_ -g1 (g1 = g0 + Dw_N - Dw^w), l+ _|_ mu P_N1 - P_T1, l- _|_ mu P_N1 + P_T1,
///   with Dw_Ti = l+ - l-. Only the Coulomb criterion (38) is supported for N points.
///
/// All solutions by enumeration of the 4^N active sets (per point: separation P_N1 = P_T1 = 0;
/// stick Dw_Ti = 0, g1 = 0; slip s = +-1: s P_T1 = mu P_N1, g1 = 0). Dw (2N) and DP_T (N) are
/// eliminated once per problem (an LU factorisation of the 3N x 3N equilibrium/compatibility
/// system), leaving 2N unknowns u = (P_N1, Dw_Ti). In an active set with m points slipping
/// with wear (k_i > 0) there are 2N - m linear equations and m bilinear ones:
/// - m = 0: a square linear system (with all k_a = 0 the step is an LCP of size 3N);
/// - m = 1: the solutions of the linear part form a line; on it the bilinear row is a scalar
///   quadratic, solved exactly;
/// - m = 2: a plane; the two rows are conics in it. Their common points are the roots of the
///   Sylvester resultant (a quartic, companion-matrix eigenvalues) with both conics' roots in
///   the second coordinate, polished by Newton. Two conics without a common component meet in
///   at most 4 points (Bezout) and every one is found: the set is proved complete;
/// - m >= 3: when the active set's wear-free solution is near its sign conditions (within 10%
///   of the force and displacement scales), Newton (with continuation in the wear
///   coefficients) finds the root that grows out of it (the small-wear root); other roots
///   may exist: the result says complete = false and why.
/// Degenerate active sets (the linear part singular and consistent: a continuum; or a
/// resultant that vanishes identically) are not resolved: complete = false with the set named.
/// The enumeration runs in the problem's own units (force unit: the largest force of the data;
/// length unit: that over max|A_ij|), so its tolerances are unit-free and loads near 1e308 or
/// subnormal ones are answered; a solution double cannot hold throws InputError ("not
/// representable"). Every candidate is verified twice, by the unit-free residual of the step
/// NCP (system_step_as_mcp, core/residuals.hpp) and by the step's laws checked from the data
/// point by point (equilibrium, P_N1 >= 0, g1 <= 0, P_N1 g1 = 0, |P_T1| <= mu P_N1, slip on the
/// limit); one that misses either bound by less than 1e3 eps cond(A) is undecided (not listed,
/// complete = false), and beyond cond(A) = 1e9 the set is never called complete. Duplicates
/// are merged; types are judged on the system's scales.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/core/problem.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_result.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// One step of an N-point system: the system (with its points' current values) and DF (2N).
struct SystemStepProblem {
  ContactSystem system;
  Eigen::VectorXd DF;
  /// Empty when usable; else names the field and point (sizes, A not SPD, NaN, P_N < 0, g > 0,
  /// P_N > 0 with g < 0, |P_T| > mu P_N, the softening criterion (unsupported)).
  std::string validate() const;
};

/// One solution: per point its type and step outputs.
struct SystemStepSolution {
  std::vector<SolutionType> types;  ///< per point
  std::vector<StepValues> values;   ///< per point (DP_T, DP_N, Dw_T, Dw_N, Dw_Ti, Dw_w, P_T1, P_N1, g1)
  double residual = 0;              ///< unit-free natural residual of the step NCP
};

/// The solutions of the N-point step (step_result.hpp). `complete` is true only when every
/// active set was solved by a method that finds every root, no candidate was undecided, and
/// cond(A) <= 1e9; why not is said in `notes` (one line per unresolved active set), and
/// `message` is the first of them.
struct SystemStepSolutionSet : StepSolutionSetOf<SystemStepSolution> {
  std::vector<std::string> notes;  ///< why not complete (one line per unresolved active set)
  long active_sets = 0;            ///< active sets examined (4^N)
};

struct SystemStepOptions {
  double tol = 1e-9;   ///< acceptance on the unit-free residual
  int max_points = 8;  ///< enumeration limit (4^N active sets)
};

/// All solutions of the step. Throws InputError for an invalid problem, N > max_points, or a
/// problem or solution that double cannot represent even in the problem's own units.
SystemStepSolutionSet enumerate_system_step(const SystemStepProblem& problem,
                                            const SystemStepOptions& options = {});

/// The step as an NCP in z = (P_N1, l+, l-) per point (3N, interleaved), exact Jacobian; an
/// LCP (wear term zero) when all k_a = 0. Throws InputError.
McpProblem system_step_as_mcp(const SystemStepProblem& problem);

/// Per-point outputs of the unknowns P_N1 (N) and Dw_Ti (N). Throws InputError.
std::vector<StepValues> system_step_values(const SystemStepProblem& problem,
                                           const Eigen::VectorXd& P_N1,
                                           const Eigen::VectorXd& Dw_Ti);

/// The one-point step problem of point i alone (its diagonal block of A, its state, its two
/// load components): used for the per-point type names and by the N = 1 checks.
StepProblem point_step_problem(const SystemStepProblem& problem, int i);

}  // namespace cpkit::rate
