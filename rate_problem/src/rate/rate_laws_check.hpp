#pragma once
// Internal: the N-point rate laws checked on physical rates from the data alone (A, dF, the
// points' states), independently of the LCP route that produced the rates. Every listed point,
// every end of a segment and every ray of the N-point rate problem passes this check before it
// is printed (issue 24, item 4).
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::rate::detail {

/// Acceptance bound on rate_laws_violation: far above the rounding of a well-conditioned solve
/// (1e-14), far below any real violation.
inline constexpr double kRateLawTol = 1e-8;

/// Largest violation, unit-free, of the rate laws of the type tuple `types` by the physical
/// rates x (6N stacked: dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w; N each) under the load rate dF
/// (2N; zero for a ray's direction, which must solve the homogeneous problem):
///   equilibrium dF - dP = A dw and dw_T = C_T dP_T + dw_Ti (componentwise, relative to the
///   size of their terms), and per point the laws of its state and type (docs/contact_model.md):
///   a: dP = 0, dw_Ti = dw_T, dw^w = 0; b separation: dP = 0, dw_N <= 0; b stick: dw_N = dw_Ti
///   = 0, |dP_T| <= mu dP_N; b slip s: dw_N = 0, dP_T = s mu dP_N >= 0, s dw_Ti >= 0; c: stick;
///   d stick: dw_N = dw_Ti = 0, s dP_T <= mu_eff dP_N; d slip: dw_Ti = s lambda, dw_N = dw^w =
///   kappa lambda, lambda >= 0, s dP_T = mu_eff dP_N.
/// Sign and zero tests of forces are relative to force_scale, of displacement rates to
/// disp_scale (the solution set's scales): invariant under any change of units.
double rate_laws_violation(const ContactSystem& S, const Eigen::VectorXd& dF,
                           const Eigen::VectorXd& x, const std::vector<SolutionType>& types,
                           double force_scale, double disp_scale);

}  // namespace cpkit::rate::detail
