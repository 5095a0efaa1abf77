#pragma once
/// \file fb_newton.hpp
/// Globalized semismooth Newton method on the Fischer-Burmeister reformulation of NCPs, MCPs,
/// LCPs and box LCPs [De Luca-Facchinei-Kanzow 1996], [Billups 1995, Ch. 2] (box version),
/// [Chen-Chen-Kanzow 2000] (penalized variant). Full account: docs/fb_newton.md.
///
/// Problem (cpkit's convention): MCP(F, l, u) with l <= x <= u,
///   x_i = l_i => F_i(x) >= 0,  x_i = u_i => F_i(x) <= 0,  l_i < x_i < u_i => F_i(x) = 0;
/// the NCP is l = 0, u = +inf; the LCP is F(z) = M z + q (w = F). Bounds may be infinite.
///
/// Reformulation: Phi(x) = 0 with, per component,
///   phi(a, b) = a + b - sqrt(a^2 + b^2)                       (zero iff a, b >= 0, a b = 0)
///   l finite, u = +inf :  Phi_i = phi(x_i - l_i, F_i)
///   l = -inf, u finite :  Phi_i = -phi(u_i - x_i, -F_i)
///   both finite        :  Phi_i = phi(x_i - l_i, -phi(u_i - x_i, -F_i))   (Billups' composition)
///   both infinite      :  Phi_i = F_i
/// and merit Psi = 0.5 ||Phi||^2. With penalty_lambda < 1 every phi above is replaced by the
/// penalized function lambda phi(a, b) + (1 - lambda) max(a, 0) max(b, 0).
///
/// Each iteration solves H d = -Phi with H = diag(Da) + diag(Db) F'(x) an element of the
/// B-subdifferential of Phi (at degenerate pairs a = b = 0 the limiting gradient along the
/// direction z = sum of the degenerate unit vectors, after De Luca-Facchinei-Kanzow), then takes
/// an Armijo step on Psi (non-monotone with nonmonotone_memory > 1). When H is singular or d is
/// not a sufficient descent direction (grad Psi . d > -descent_rho ||d||^descent_power) the step
/// is along -grad Psi = -H^T Phi instead. Psi can have local minimizers that are not solutions
/// (Billups' problem from x = 0): on stagnation a bounded watchdog of Newton steps without the
/// Armijo test is tried before giving up (options watchdog_steps, max_escapes).
///
/// Linear algebra: dense partial-pivoting LU for dense storage / dense Jacobians (LAPACK dgetrf
/// when cpkit was built with LAPACK, for n >= 32 except 100 <= n < 150; Eigen's PartialPivLU
/// otherwise; see docs/fb_newton.md); for sparse LCP storage or a
/// sparse Jacobian callback Eigen SparseLU (COLAMD ordering, pattern analysed once), or, when M
/// is symmetric, sparse LDL^T of the symmetric K = M + diag(Da/Db) with H = diag(Db) K
/// (residual-checked, falling back to SparseLU).
/// Without a Jacobian callback F' is approximated by forward differences with step
/// h_j = fd_step * max(1, |x_j|) (backward difference when x + h_j e_j is outside F's domain).
///
/// Stopping: ||x - mid(l, u, x - F(x))||_inf / scale <= tol with scale = 1 + max(||q||,
/// ||w|| - ||q||) for LCPs (1 + ||F|| for MCPs), never larger than finalize()'s; finalize()
/// then decides the status from the data. The trace records this stopping residual.
/// Guarantees: every accumulation point is a stationary point of Psi; for monotone F (PSD M)
/// stationary points solve the problem, and for P-matrices / uniformly P-functions the iterates
/// converge to the unique solution, locally Q-quadratically at BD-regular solutions with
/// Lipschitz F' [DFK 1996, Thms 11, 12]. It cannot prove infeasibility: an infeasible problem
/// ends with kStalled or kIterationLimit (never a solution status). On failure z holds the
/// iterate with the smallest stopping residual (the earliest on ties). Every result comes from
/// cpkit::finalize(). Workspaces are allocated once per call (no globals): concurrent calls are
/// safe.
#include <string>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp {

struct FbNewtonOptions {
  /// common.max_iterations = 0 means 200 Newton/gradient iterations (documented default).
  CommonOptions common;
  /// Armijo constant sigma in Psi(x + t d) <= Psi_ref + sigma t grad.d, in (0, 0.5).
  double armijo_sigma = 1e-4;
  /// Backtracking factor beta in (0, 1): t <- beta t after a rejected or undefined trial.
  double backtrack = 0.5;
  /// Smallest step length tried before the line search is declared failed.
  double min_step = 1e-12;
  /// Memory of the non-monotone (Grippo-Lampariello-Lucidi) reference Psi_ref = max of the last
  /// m values; 1 = monotone Armijo.
  int nonmonotone_memory = 1;
  /// Sufficient descent test for the Newton direction: grad.d <= -rho ||d||^p [DFK 1996], or
  /// grad.d <= -Psi (at least half the decrease rate -2 Psi of an exactly solved Newton system:
  /// keeps accurate Newton steps on ill-conditioned problems); else a gradient step.
  double descent_rho = 1e-8;
  double descent_power = 2.1;
  /// Watchdog escape from stagnation (a line-search failure, a stationary point of Psi that is
  /// not a solution, or 3 iterations in a row reducing Psi by less than a factor 1 - 1e-4):
  /// up to watchdog_steps Newton steps without the Armijo test (each halved only while Psi
  /// keeps falling along t = 1, 1/2, ..., or where F is undefined: the backstepping rule of
  /// Miranda-Fackler's CompEcon ncpsolve); the escape succeeds when Psi falls below its value
  /// at the stagnation point, otherwise the solver
  /// returns to the best point and stops with kStalled [Chamberlain et al. 1982; PATH's
  /// non-monotone stabilization, Ferris-Ralph 1995]. watchdog_steps = 0 disables it.
  int watchdog_steps = 10;
  /// Escapes allowed per solve.
  int max_escapes = 3;
  /// Penalized FB weight lambda in (0, 1]; 1 = plain Fischer-Burmeister [CCK 2000].
  double penalty_lambda = 1.0;
  /// Relative forward-difference step (used only without a Jacobian callback):
  /// h_j = fd_step * max(1, |x_j|); 0 means sqrt(machine epsilon) ~ 1.5e-8.
  double fd_step = 0.0;
  /// Warm start (size n, finite); empty: McpProblem::x0 when set, else the origin projected on
  /// the box [l, u] (for LCPs: z = 0).
  Vec x0;
  /// Empty when usable; otherwise names the bad field and value (n: problem size for x0).
  std::string validate(Eigen::Index n) const;
};

/// Solves the MCP (NCP when l = 0, u = +inf). Throws InputError for an invalid problem or options.
SolveResult solve_fb_newton(const McpProblem& problem, const FbNewtonOptions& options = {});
/// Solves the LCP (dense LU for dense storage, SparseLU for sparse storage).
SolveResult solve_fb_newton(const LcpProblem& problem, const FbNewtonOptions& options = {});
/// Solves the box LCP (storage as for the LCP).
SolveResult solve_fb_newton(const BoxLcpProblem& problem, const FbNewtonOptions& options = {});

/// Registry entry ("fb-newton"): LCP, box LCP and MCP; dense and sparse storage.
SolverEntry fb_newton_entry();

}  // namespace cpkit::lcp
