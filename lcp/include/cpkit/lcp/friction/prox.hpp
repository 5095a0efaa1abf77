#pragma once
/// \file prox.hpp
/// Proximal point method for the local 3-D frictional contact problem (friction_problem.hpp),
/// as Acary-Bremond-Huber's PROX [Acary, Bremond, Huber, INRIA RR-9118, 2018, Sec. 8] and
/// Siconos' fc3d_proximal:
///   r_{k+1} solves the problem with (W + alpha_k I, q - alpha_k r_k),
/// whose fixed points are exactly the solutions (u = W r + q when r_{k+1} = r_k). The added
/// alpha I makes every 3x3 diagonal block positive definite, so a rank-deficient (or zero) W
/// is normal input.
///
/// alpha_k (PROX's rule, made unit-free, with a geometric decrease):
///   alpha_0 = min(alpha0, sigma e_0^nu) w_scale,
///   alpha_k = min(sigma e_k^nu w_scale, alpha_{k-1} / shrink)   after a converged inner solve,
///   alpha_k = 10 alpha_{k-1}                                     after a failed one (PROX's),
/// with e_k the verdict's unit-free error of r_k (friction_verdict.hpp, capped at 1) and w_scale
/// the largest entry of |diag W| (||W||_max when the diagonal is zero; 1 for W = 0), so that
/// alpha has W's units. PROX's rule alone (alpha0 = 0, shrink = 1) lets alpha fall only as e
/// does, and the unit-free e falls slowly at first: 20-35 outer iterations on the FCLIB files
/// (79 on Rover1039, 184 on fclib_local_problem_test); with the defaults 4-7 on all 12, the
/// number Siconos' PROX needs (4-5). alpha0 = 0.05 (was 0.5) with the Alart-Curnier inner
/// solve: 3-6 outer iterations on the 12 local files, 5 on Capsules-i122 and -i101 (PROX: 4).
/// alpha stays in [1e-10, 1e10] w_scale (a floor and a cap in W's units). Once an inner solve
/// has failed, the decrease is gentler (shrink_after_failure): a problem whose regularised
/// problems fail below some alpha is approached in smaller steps instead of alternating between
/// a failed alpha / shrink and 10 times that; and each inner solve is then given at most
/// newton_after_failure Newton steps (one that needs more is likely one that fails).
/// Inner solver (ProxInner::kGaussSeidel): block Gauss-Seidel over the contacts on the regularised
/// problem, each contact's 3x3 problem (block W_ii + alpha I) solved exactly by
/// one_contact_nearest() (one_contact.hpp: the solution nearest the current r_i). The inner solve
/// stops when a sweep changes r by at most max(e_k / 10, tol / 10) relative to the size of r
/// (the internal tolerance adapted to the outer error, as PROX does). ProxInner::kFbSoc and
/// kAlartCurnier (the default) solve each regularised problem by fb-soc's semismooth Newton from
/// r_k to the outer tol instead (its unit-free verdict is relative to q - alpha r_k, which a
/// large alpha inflates), on the FB or on Alart-Curnier's function (PROX's own choice is
/// NSN_AC [Acary et al. 2018]), taking a Newton step whole where the line search would damp it
/// below full_step_below (as NSN_AC does when its line search fails): with a small alpha the
/// first step from r_k moves far along W's near-kernel, then Newton converges in a few steps.
///
/// Units: r in the problem's units (u per W); every test is relative (unit-free): the same
/// problem in other units gives the same iterates, scaled. Result through finalize().
/// Deterministic. result.iterations = outer (proximal) iterations; function_evals = sweeps.
#include <Eigen/Core>
#include <string>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// The solver of each regularised problem.
enum class ProxInner {
  kGaussSeidel,  ///< block Gauss-Seidel, exact one-contact steps
  kFbSoc,        ///< semismooth Newton fb-soc (fb_soc.hpp) from r_k (BoxesStack1, 52 contacts,
                 ///< rank 78/156: 0.14 s; Gauss-Seidel had not converged after 20 s)
  kAlartCurnier, ///< the same Newton loop on Alart-Curnier's function (FbSocOptions::
                 ///< alart_curnier), as PROX's internal NSN_AC: the default (fb-soc Newton
                 ///< steps 345 -> 132 on Capsules-i122-1617, 140 -> 38 on Capsules-i101-404)
};

struct ProxOptions {
  CommonOptions common;  ///< max_iterations: outer iterations (0: 500)
  Eigen::VectorXd r0;    ///< starting r (empty: r = 0), 3 per contact
  double sigma = 5;      ///< alpha = sigma e^nu w_scale (PROX's defaults sigma = 5, nu = 1)
  double nu = 1;
  double alpha0 = 0.05;  ///< cap of the first alpha, in w_scale units (0: sigma e_0^nu alone)
  double shrink = 30;   ///< alpha_k <= alpha_{k-1} / shrink after a converged inner solve (>= 1)
  /// The shrink once an inner solve has failed (>= 1; shrink when that is smaller): alpha / 30 then failed
  /// again and again on RockPile_tob1 (mu = 1), each failure ~50 wasted Newton steps and 10
  /// alpha; with alpha / 3 prox solves it (relative_q 9.5e-12, 75 outer steps, where it stood
  /// at 1.6e-5 after 30 s; docs/benchmarks.md, h73). No inner solve fails on the 16 files of docs/benchmarks.md: their steps are unchanged.
  double shrink_after_failure = 3;
  /// Newton steps of each inner solve (kFbSoc, kAlartCurnier) once an inner solve has failed
  /// (0: no cap, fb-soc's own stop): a failed solve ran to fb-soc's 50-step stagnation stop.
  /// RockPile_tob1: 1,612 -> 735 Newton steps (7.0 -> 3.7 s of CPU); shrink_after_failure = 4,
  /// which alone stalls at 4e-6, then solves it too. The 16 files: no failure, no change.
  int newton_after_failure = 15;
  int max_sweeps = 0;  ///< Gauss-Seidel sweeps per inner solve (0: 200)
  /// The Newton inner solves' FbSocOptions::full_step_below: a Newton step damped below this t
  /// is taken whole (Newton steps 132 -> 29 on Capsules-i122-1617, 38 -> 24 on -i101-404; 0: off)
  double full_step_below = 0.1;
  ProxInner inner = ProxInner::kAlartCurnier;
  /// Empty when usable for a problem with n = 3 n_c rows; otherwise names the bad field.
  std::string validate(Eigen::Index n) const;
};

/// Solves the problem; throws InputError on an invalid problem or options.
SolveResult solve_prox(const FrictionContactProblem& problem, const ProxOptions& options = {});

/// Registry entry "prox" (friction problems only).
SolverEntry prox_entry();

}  // namespace cpkit::lcp::friction
