#pragma once
/// \file step_3d.hpp
/// One implicit time step of one three-dimensional contact point with the elliptic friction and
/// wear law [Stromberg, Johansson & Klarbring 1996, eqns (38)-(41)]; derivation:
/// docs/contact_3d.md, "The implicit step" (eqns (3D.20)-(3D.27)).
///
/// From a known state (P_T0, P_N0, g0 = w_N - w^w <= 0) and a load increment DF, backward Euler
/// with the flow and the wear evaluated at the END of the step:
///   equilibrium       DF - DP = A Dw,   Dw_T = C_T DP_T + Dw_T^i,
///   normality         Dw_T^i = lambda D^-2 P_T1 / ||P_T1||   (lambda >= 0, D = diag(alpha)),
///   wear              Dw^w = c_w P_N1 lambda,
///   contact           P_N1 >= 0,  g1 = g0 + Dw_N - Dw^w <= 0,  P_N1 g1 = 0,
///   friction          ||P_T1|| <= mu P_N1,  lambda (mu P_N1 - ||P_T1||) = 0.
/// Both wear laws give the same c_w: Archard's anisotropic (40), Dw^w = k P_N1 |D Dw_T^i| with
/// |D Dw_T^i| = lambda, gives c_w = k = k_a / (3 P_s); Mroz-Stupkiewicz (41),
/// Dw^w = k_M P_T1 . Dw_T^i = k_M lambda ||P_T1|| = k_M mu P_N1 lambda on the cone, gives
/// c_w = k_M mu. The friction conditions are a complementarity problem over the second-order
/// cone K = {(x0, x1) : x0 >= |x1|} after the change of variables that maps the ellipse to a
/// circle: x = (mu P_N1, D^-1 P_T1) in K, y = (lambda, -D Dw_T^i) in K, x . y = 0 (3D.22).
///
/// Units: any consistent set (A force/length, C_T length/force, k and k_M 1/force).
/// Signs: P_N >= 0 compressive; g <= 0 not penetrating; slip along the ellipse's outer normal.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/wear.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/step/step_result.hpp"
#include "cpkit/rate_problem/step/step_state.hpp"

namespace cpkit::rate {

/// The known state at the start of a step (step_state.hpp): P_T0 = (P_TX0, P_TY0).
using Step3dState = StepStateOf<Eigen::Vector2d>;

/// One step: parameters (A, mu, C_T, k_a, P_s, alpha), wear law, start state, load increment.
struct Step3dProblem {
  ContactParameters3d params;
  rate::WearModel wear;  ///< Archard (40) with k = k_a/(3 P_s), or Mroz-Stupkiewicz (41) with k_M
  Step3dState state;
  Eigen::Vector3d DF{0, 0, 0};  ///< (DF_TX, DF_TY, DF_N)

  /// Empty when usable; else names the bad field: parameters (ContactParameters3d::validate),
  /// k_M < 0 or NaN, non-finite state or load, P_N0 < 0, g0 > 0, P_N0 > 0 with g0 < 0,
  /// ||P_T0|| above mu P_N0 (relative tolerance 1e-10).
  std::string validate() const;
  /// c_w of Dw^w = c_w P_N1 lambda (see the file comment).
  double wear_coefficient() const noexcept;
};

/// The physical outputs of a step.
struct Step3dValues {
  Eigen::Vector2d DP_T{0, 0}, Dw_T{0, 0}, Dw_Ti{0, 0}, P_T1{0, 0};
  double DP_N = 0, Dw_N = 0, Dw_w = 0, P_N1 = 0, g1 = 0;
  double lambda = 0;  ///< plastic multiplier = |D Dw_T^i|
};

/// Physical outputs from the end forces (P_T1, P_N1) and the multiplier lambda: Dw from
/// equilibrium, Dw_T^i = Dw_T - C_T DP_T, Dw^w = c_w P_N1 lambda, g1 = g0 + Dw_N - Dw^w.
/// (At P_T1 = 0 the flow direction is not defined; Dw_T^i is then whatever equilibrium gives.)
Step3dValues step_3d_values(const Step3dProblem& problem, const Eigen::Vector2d& P_T1,
                            double P_N1, double lambda) noexcept;

/// Scale-free residual of a candidate solution: the largest of (i) equilibrium relative to its
/// terms, (ii) the contact pair min(P_N1, -g1) relative to the force and gap scales, (iii) the
/// second-order-cone natural residual |x - Proj_K(x - y)| of (3D.22) relative to |x| + |y|
/// (covers the cone, the flow direction, lambda = |D Dw_T^i| and complementarity), (iv) the
/// products x . y and P_N1 g1 relative to (1 + |first|)(1 + |second|) (a huge multiplier over a
/// tiny force cannot hide in (iii)'s denominator), each
/// evaluated in units normalized by the problem's own force and stiffness scales. A solution
/// of every solver is accepted only when this is at most the solver's tolerance (1e-9).
double step_3d_residual(const Step3dProblem& problem, const Step3dValues& v) noexcept;

/// Type of a step solution: P_N1 = 0 is `separation` (`open` when the step started open,
/// g0 < 0); otherwise stick (lambda = 0) or slip.
SolutionType classify_step_3d(const Step3dProblem& problem, const Step3dValues& v) noexcept;

/// One solution with its type, slip direction (unit vector of Dw_T^i; zero without slip) and
/// residual.
struct Step3dSolution {
  SolutionType type = SolutionType::kStick;
  Step3dValues values;
  Eigen::Vector2d slip_direction{0, 0};
  double slip_angle = 0;  ///< atan2 of slip_direction, (-pi, pi]
  double residual = 0;    ///< step_3d_residual
};

/// Fills type, slip direction, angle and residual of a solution from its values.
Step3dSolution make_step_3d_solution(const Step3dProblem& problem, const Step3dValues& v);

/// The solutions of one 3-D point (step_result.hpp), in the order separation/open, stick, slip
/// by angle.
using Step3dSolutionSet = StepSolutionSetOf<Step3dSolution>;

/// Every solution of the step, exactly (docs/contact_3d.md, "Every solution of a step"):
/// separation and stick are linear; a slip solution has P_T1 = mu P_N1 D t(phi) and the three
/// equilibrium rows are linear in (P_N1, lambda, P_N1 lambda), so the slip directions are the
/// zeros of a trigonometric polynomial of degree 4 (degree 2 without wear), at most 8, found as
/// the unit-circle roots of a degree-8 polynomial (companion matrix), refined by Newton's method
/// on the three equations, with a completeness certificate (simple roots, signs of the
/// trigonometric polynomial alternating between them, a dense sign scan agreeing); otherwise
/// complete = false with the reason. Every listed solution passes step_3d_residual <= 1e-9.
/// Throws InputError for invalid input.
Step3dSolutionSet enumerate_step_3d(const Step3dProblem& problem);

}  // namespace cpkit::rate
