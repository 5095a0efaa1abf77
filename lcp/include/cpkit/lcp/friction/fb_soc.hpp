#pragma once
/// \file fb_soc.hpp
/// Semismooth Newton on the second-order-cone Fischer-Burmeister reformulation ("fb-soc") of
/// the local 3-D frictional contact problem (friction_problem.hpp), for sparse W
/// [Fukushima, Luo, Tseng 2001; Acary, Bremond, Huber 2018, Sec. 3 (NSN_FB)].
///
/// Per contact, with u = W r + q, the cone change of variables
///   x = (mu r_N, r_T) in K_1,   y = (u_N + mu |u_T|, mu u_T) in K_1,   x . y = mu r . u_hat,
/// turns De Saxce's law into the SOC complementarity x in K_1, y in K_1, x . y = 0, i.e.
/// phi_FB(x, y) = x + y - sqrt(x o x + y o y) = 0 (Jordan product o); a contact with mu = 0 uses
/// (phi(r_N, u_N), r_T) with the scalar FB function phi. The FB kernels and their Jacobian
/// elements are cpkit's one implementation (cpkit/lcp/detail/fischer_burmeister.hpp, shared with the 3-D
/// step solvers). Phi(r) = 0 is solved by semismooth Newton: J = A + B W with A, B block diagonal
/// (the derivatives of phi with respect to r and u; at u_T = 0 the element d|u_T| = 0),
/// factorised by Eigen's SparseLU (COLAMD); a J that does not factorise is shifted,
/// J + delta I with delta = 1e-10, 1e-8, ... 1e-2 times |J|_max (rank-deficient W makes J singular
/// at sticking contacts). Line search: Armijo backtracking on Psi = |Phi|^2 / 2 (sigma = 1e-4,
/// factor 1/2), non-monotone for the Newton direction (reference: the largest Psi of the last
/// nonmonotone_memory iterates [Grippo, Lampariello, Lucidi 1986]); when the Newton direction is
/// not a descent direction or its search fails, a Levenberg-Marquardt direction
/// (J^T J + |Phi| I) d = -J^T Phi (SimplicialLDLT; bounded where J is singular, as at the
/// non-isolated solutions of rank-deficient W [Fan, Yuan 2005]), then -grad Psi = -J^T Phi, both
/// with monotone Armijo. On the FCLIB files neither reference wins everywhere (BoxesStack1 needs
/// the non-monotone one, Capsules-i100-889 the monotone one): "auto" runs both.
///
/// The problem is first scaled by powers of two (exactly) so that |q|_inf and |W|_max are in
/// [1, 2): the iterates do not depend on the problem's units. Stopping: the verdict's unit-free
/// residual (friction_verdict.hpp) <= tol; kStalled when that residual has not halved within 50
/// iterations (converging runs on the FCLIB files halve it at least every ~30). Every result
/// comes from finalize(); on failure z holds the iterate with the smallest residual. Defaults: common.max_iterations = 0 means 200.
/// Deterministic.
#include <Eigen/Core>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

struct FbSocOptions {
  CommonOptions common;
  /// Warm start r (size 3 n_c, finite); empty: r = 0.
  Eigen::VectorXd r0;
  /// Non-monotone memory of the Newton line search; 1 = monotone Armijo.
  int nonmonotone_memory = 8;
  /// Solve Phi_AC(r) = 0 instead, Alart and Curnier's function as Siconos' NSN_AC
  /// [Alart, Curnier 1991], with the same Newton loop, LU, line search and verdict: per contact,
  /// with z_N = r_N - rho u_N, z_T = r_T - rho u_T, rho = 1 / max |diag W_ii| (the scaled
  /// problem's) and the disk D(R) of radius R = mu max(0, z_N),
  ///   Phi_N = r_N - max(0, z_N),   Phi_T = r_T - P_D(R)(z_T).
  /// Its zeros are the same solutions (Coulomb's law with u_N is De Saxce's for every state).
  /// prox's inner solves use it: near a solution of a rank-deficient W it takes full Newton
  /// steps where the FB function's are damped to 1/128 or stall (docs/benchmarks.md, h59).
  bool alart_curnier = false;
  /// When the Newton step's line search ends below this t (or fails), the full Newton step is
  /// taken instead, as Siconos' nonsmooth Newton does when its Goldstein-Price search fails;
  /// never twice in a row, the best iterate is still the answer. 0 (the default): never.
  /// prox's inner solves use it: from r_k, the first step of a proximal sub-problem with a small
  /// alpha moves far along W's near-kernel and the line search would take it 1/1000 at a time
  /// (docs/benchmarks.md, h63).
  double full_step_below = 0;
};

/// Solves the problem; throws InputError when it (or r0) is invalid.
SolveResult solve_fb_soc(const FrictionContactProblem& problem, const FbSocOptions& options = {});

/// Registry entry "fb-soc" (friction problems only).
SolverEntry fb_soc_entry();

}  // namespace cpkit::lcp::friction
