#pragma once
/// \file incremental_step.hpp
/// One implicit time step of the one-point contact problem (the incremental problem)
/// [Stromberg et al. 1996, Sec. 4 with eqns (35)/(38), (37), (41); working equations:
/// docs/model.md Sec. 3 and docs/simulation.md].
///
/// From a known state (P_T0, P_N0, g0 = w_N - w^w <= 0) and a load increment (DF_T, DF_N),
/// backward Euler with the wear law evaluated at the END of the step. Unknowns
/// z = (P_N1, l+, l-) >= 0 with Dw_T^i = xi = l+ - l- and
///   Dw^w = c_w P_N1 (l+ + l-)      (Archard (37): c_w = k = k_a / (3 P_s);
///                                    Mroz-Stupkiewicz (41) with Coulomb: c_w = k_M mu),
/// and the three complementarity pairs
///   P_N1  _|_  -g1,                 g1 = g0 + Dw_N - Dw^w           (new gap function)
///   l+    _|_  Y(P_N1) - P_T1,      l-  _|_  Y(P_N1) + P_T1,
/// where the yield limit is Y(P) = mu P (criterion (38), exact Coulomb) or
/// Y(P) = mu P - k P^2 (criterion (35) with W = p_N, friction softening, eqn (45)).
/// Equilibrium increments: DF - DP = A Dw, Dw_T = C_T DP_T + xi.
///
/// Derivation of (35): with W = p_N the normality rule (34) of F = |p_T| - mu p_N + k p_N W
/// gives dw_T^i = dlambda sgn p_T and dw^w = dlambda dF/dW = dlambda k p_N (the same Archard law
/// as (38)), while F <= 0 becomes |p_T| <= mu p_N - k p_N^2. The two friction rows together
/// imply Y(P_N1) >= 0, i.e. P_N1 <= mu/k: condition (46) is enforced by the step itself.
///
/// Scaled by D0 = a22 + C_T det A the NCP reads (model.md Sec. 3)
///   F(z) = M z + q + c z0 (z1 + z2) e0 - D0 k_c z0^2 (e1 + e2),  c = D0 c_w,
/// with M as for state b, k_c = k for (35) and 0 for (38). With c_w = 0 it is an LCP.
///
/// Units: forces and displacements in any consistent set (A force/length, C_T length/force).
/// Sign conventions: P_N >= 0 compressive, g = w_N - w^w <= 0 not penetrating.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "cpkit/core/problem.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/model/wear.hpp"
#include "cpkit/rate_problem/step/step_state.hpp"

namespace cpkit::rate {

/// The known state at the start of a step (step_state.hpp).
using StepState = StepStateOf<double>;

/// The load increment of a step.
struct LoadIncrement {
  double dF_T = 0, dF_N = 0;
};

/// One step: parameters, wear model, start state, load increment.
struct StepProblem {
  ContactParameters params;
  WearModel wear;
  StepState state;
  LoadIncrement load;

  /// Empty when usable; else names the bad field: parameters (ContactParameters::validate),
  /// k_M < 0 or NaN, Mroz with the softening criterion (unsupported), non-finite state or
  /// load, P_N0 < 0, g0 > 0, P_N0 > 0 with g0 < 0, |P_T0| above the yield limit Y(P_N0), all
  /// beyond a relative tolerance of 1e-10.
  std::string validate() const;
  /// c_w: Dw^w = c_w P_N1 |Dw_T^i| at a solution.
  double wear_coefficient() const noexcept;
  /// k_c: Y(P) = mu P - k_c P^2 (0 for the Coulomb criterion).
  double softening() const noexcept;
  /// Y(P) = mu P - k_c P^2.
  double yield(double P_N) const noexcept { return params.mu * P_N - softening() * P_N * P_N; }
};

/// The physical outputs of a step (docs/model.md Sec. 3).
struct StepValues {
  double DP_T = 0, DP_N = 0, Dw_T = 0, Dw_N = 0, Dw_Ti = 0, Dw_w = 0;
  double P_T1 = 0, P_N1 = 0, g1 = 0;
};

/// The step NCP in its scaled polynomial form (fixed size: used on hot paths).
struct StepNcp {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  double c = 0;        ///< D0 c_w (bilinear wear term of row 0)
  double d = 0;        ///< D0 k_c (quadratic softening term of rows 1 and 2)
  bool is_lcp() const noexcept { return c == 0 && d == 0; }
  /// F(z) (scaled by D0).
  Eigen::Vector3d F(const Eigen::Vector3d& z) const noexcept;
  /// dF/dz.
  Eigen::Matrix3d jacobian(const Eigen::Vector3d& z) const noexcept;
  /// Scaled natural residual ||min(z, F(z))||_inf / (1 + max(||q||_inf, ||terms||_inf)), the
  /// terms being |M||z| and the nonlinear terms (the rounding bound of F, as in residuals.hpp).
  double residual(const Eigen::Vector3d& z) const noexcept;
};

/// Builds the step NCP. Throws InputError when problem.validate() fails.
StepNcp build_step_ncp(const StepProblem& problem);
/// The same without validation (hot paths; inputs must be valid).
StepNcp build_step_ncp_unchecked(const StepProblem& problem) noexcept;

/// The step as an MCP/NCP for the general solvers (exact Jacobian). Throws InputError.
McpProblem step_as_mcp(const StepProblem& problem);
/// The step as an LCP (only when the wear coefficient is 0 and the criterion adds no term);
/// throws InputError otherwise.
LcpProblem step_as_lcp(const StepProblem& problem);

/// Physical outputs from the unknowns: DP_N = P_N1 - P_N0 and xi = Dw_T^i (the wear uses
/// |xi|: l+ l- > 0 only at P_N1 = 0, where the wear vanishes).
StepValues step_values(const StepProblem& problem, double DP_N, double xi) noexcept;
/// The NCP unknowns z = (P_N1, l+, l-) of a physical solution (l+ = max(xi, 0), ...).
Eigen::Vector3d step_unknowns(const StepValues& v) noexcept;

/// The step starts open: g0 < 0 beyond 1e-9 of the displacement scale |g0| + F (a11 + a22)
/// / det A + F C_T, F the largest of |P_T0|, |P_N0|, |dF_T|, |dF_N| (classify_step and the
/// enumeration's types decide `open` by it).
bool step_started_open(const StepProblem& problem) noexcept;

/// Type of a step solution: P_N1 = 0 with g1 < 0 is `separation` (`open` when the step
/// started open, g0 < 0); otherwise stick (Dw_T^i = 0) or slip+/slip- by the sign of Dw_T^i
/// (a grazing end P_N1 = 0, g1 = 0 with slip is the rate problem's zero-force slip).
SolutionType classify_step(const StepProblem& problem, const StepValues& v) noexcept;

}  // namespace cpkit::rate
