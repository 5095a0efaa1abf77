#pragma once
/// \file friction_errors.hpp
/// The errors of a candidate r of a 3-D frictional contact problem in the three measures
/// (friction_verdict.hpp computes them; friction_measure.hpp decides in one of them).
namespace cpkit {

/// Errors of a candidate r. The natural map per contact is r_i - P_K(r_i - u_hat_i); E is the
/// Euclidean norm of all of them together, in the problem's units.
struct FrictionErrors {
  double unit_free = 0;     ///< the acceptance number of friction_verdict.hpp (unit-free)
  double relative_q = 0;    ///< E / ||q||_2 [Acary, Bremond, Huber 2018] (E when ||q||_2 <= eps)
  double relative_max = 0;  ///< E / max(||q||_2, ||r||_2, ||u||_2) (E when that max <= eps)
};
// relative_max is Siconos 4.4's fc3d_compute_error(problem, r, u, tol, options, norm, &error)
// with norm = ||q||_2 (what its solvers pass): it divides E by max(norm, ||r||_2, ||u||_2) when
// that exceeds DBL_EPSILON (checked against python3-siconos). relative_q divides by ||q||_2 under
// the same guard. Both are information: they depend on the problem's units.

}  // namespace cpkit
