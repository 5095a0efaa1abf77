#pragma once
/// \file nsgs.hpp
/// Nonsmooth Gauss-Seidel ("nsgs") for the local 3-D frictional contact problem
/// (friction_problem.hpp) [Jean 1999; Acary, Bremond, Huber 2018, Sec. 4]: sweeps over the
/// contacts in order; contact i's step solves its one-contact problem u_i = W_ii r_i + b_i,
/// b_i = q_i + sum_{j != i} W_ij r_j, and takes a solution from the current r_i on
/// (one_contact_newton.hpp, r_i's own state first: r_i = 0 with b_N >= 0 stays 0; r_i strictly
/// inside the cone takes the stick solution -W_ii^-1 b_i (inverse computed once) when that is in
/// the cone; r_i on the cone's boundary takes the slip solution that Newton's method on the slip
/// direction finds from r_i's; then the other states, as Siconos' NSGS starts its local Newton
/// at r_i). What that does not solve takes every solution in closed form (one_contact.hpp) and
/// the one closest to r_i. These follow r_i's branch of solutions
/// (issue 35: KaplasTower 21.9M -> 2.8M instructions per sweep). u = W r + q is kept up to date
/// column by column (W need not be symmetric), and recomputed from the data at every
/// convergence test.
///
/// Rank-deficient W: a block W_ii whose smallest singular value is below 1e-10 times its largest
/// (or W_ii = 0) is regularised by a proximal term: the step solves u = (W_ii + rho I) r +
/// (b_i - rho r_i^old), rho = 1e-2 max(|W_ii|_max, |W|_max) (the proximal-point local solve
/// [Acary et al. 2018, Sec. 4.3]); its fixed points are exactly the solutions.
///
/// Stopping: the unit-free residual of friction_verdict.hpp (the verdict's own number) <= tol.
/// It costs several sweeps, so it is computed after the first sweep, then when the light measure
/// max |dr| / max(|r|_inf, r_ref) of the sweep times (verdict / light measure at the last test)
/// predicts tol, and at least every 20 sweeps, at the last sweep, and after every sweep when
/// a trace is recorded. Every result comes from finalize(const FrictionContactProblem&, ...):
/// z = r, w = u. On failure z holds the tested iterate with the smallest residual.
/// Defaults: common.max_iterations = 0 means 2000 sweeps. Deterministic; allocation-free sweeps.
#include <Eigen/Core>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

struct NsgsOptions {
  CommonOptions common;
  /// Warm start r (size 3 n_c, finite); empty: r = 0.
  Eigen::VectorXd r0;
};

/// Solves the problem; throws InputError when it (or r0) is invalid.
SolveResult solve_nsgs(const FrictionContactProblem& problem, const NsgsOptions& options = {});

/// Registry entry "nsgs" (friction problems only).
SolverEntry nsgs_entry();

}  // namespace cpkit::lcp::friction
