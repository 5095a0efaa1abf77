#pragma once
/// \file step_solvers_3d.hpp
/// Solvers of one implicit step of a 3-D contact point (step_3d.hpp): a second-order-cone
/// Fischer-Burmeister semismooth Newton method, an Ipopt MPCC fallback, the faceted
/// (polygonal) problem, a solver chain and a multistart. Formulas: docs/contact_3d.md,
/// "Solvers of the 3-D step".
///
/// Every solver works in units normalized by the problem's force scale F0 (the largest of
/// |DF|, |P_T0|, P_N0 and |A| |g0|) and stiffness scale |A| (largest entry), so that its
/// iterates and verdicts do not depend on the user's units; every solution it returns is
/// verified on the ORIGINAL problem by step_3d_residual <= 1e-9 (tol below).
///
/// What they can claim: FB-SOC and Ipopt find one solution near a start, never the absence of
/// others; multistart collects distinct verified solutions and can never prove that the list
/// is complete (it says complete = false). Only enumerate_step_3d (exact) and the faceted LCP
/// without wear (complete enumeration of the polygonal problem, an approximation of the
/// elliptic law) make statements about all solutions.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"

namespace cpkit::rate {

/// A start point of the iterative solvers: end forces and the plastic multiplier.
struct Step3dStart {
  Eigen::Vector2d P_T1{0, 0};
  double P_N1 = 0;
  double lambda = 0;
};

/// Options of the iterative solvers: the common options (core/options.hpp) with the step's
/// defaults, step_3d_solver_options(): tol = tol_acceptable = 1e-9 (acceptance on
/// step_3d_residual), max_iterations = 100 (FB-SOC Newton iterations, 0 = 100; Ipopt: per NLP,
/// 0 = Ipopt's 500), time_limit_s = 10 (Ipopt: for the whole MPCC sequence).
CommonOptions step_3d_solver_options();

/// The outcome of one iterative solve: the common SolveResult (status, iterations,
/// line_search_steps, gradient_steps, seconds, message; z = (P_T1, P_N1, lambda) in the
/// problem's units, residuals.natural = step_3d_residual) with the step's solution. The status
/// is granted only by finalize_step_3d.
using Step3dSolveResult = StepSolveResultOf<Step3dSolution>;

/// The verdict, as finalize() for an LCP (core/finalize.hpp): recomputes the solution (type,
/// residual) from claim.solution.values and the problem data; kSolved when step_3d_residual
/// <= tol, kSolvedInaccurate up to tol_acceptable, whatever was claimed; a claimed solution
/// the data refute becomes kNumericalFailure; other claimed failures are kept.
void finalize_step_3d(const Step3dProblem& problem, Step3dSolveResult& claim,
                      const CommonOptions& options);

/// SOC Fischer-Burmeister semismooth Newton on z = (P_T1, P_N1, lambda): equations
/// fb(P_N1, -g1) = 0 and phi_soc(x, y) = x + y - sqrt(x o x + y o y) = 0 with
/// x = (mu P_N1, D^-1 P_T1), y = (lambda, -D Dw_T^i); an element of the generalized Jacobian
/// (Fukushima-Luo-Tseng 2001 spectral formulas, limiting elements on bd K and at w = 0), Armijo
/// line search on 0.5 |Phi|^2 with a steepest-descent fallback. Fixed-size, no allocation in
/// the loop. Start: `start`, or the start state (P_T0, P_N0, lambda = 0) when null.
/// Throws InputError for an invalid problem or options.
Step3dSolveResult solve_step_3d_fb_soc(const Step3dProblem& problem,
                                       const CommonOptions& options = step_3d_solver_options(),
                                        const Step3dStart* start = nullptr);

/// The step as an MPCC solved by Ipopt (cpkit::lcp::solve_mpcc, Scholtes relaxation): variables
/// (P_T1, P_N1, lambda), pairs 0 <= P_N1 _|_ -g1 >= 0 and 0 <= lambda _|_ mu^2 P_N1^2 -
/// ||P_T1||^2 >= 0, equalities mu P_N1 D Dw_T^i = lambda D^-1 P_T1 (normality), objective
/// 0.5 |z - start|^2 (selects the solution near the start); each converged NLP point is
/// polished by FB-SOC Newton and accepted only through step_3d_residual. Throws InputError.
Step3dSolveResult solve_step_3d_ipopt(const Step3dProblem& problem,
                                      const CommonOptions& options = step_3d_solver_options(),
                                       const Step3dStart* start = nullptr);

/// The faceted step: the ellipse replaced by the inscribed polygon of k vertices
/// D (cos theta_i, sin theta_i), theta_i = 2 pi i / k (as faceted_rate_3d.hpp). Facet j has the
/// outward unit normal n_j and support h_j; friction rows lambda_j _|_ mu P_N1 - n_j.P_T1 / h_j,
/// flow Dw_T^i = sum_j lambda_j n_j / h_j, wear c_w P_N1 sum_j lambda_j.
struct FacetedStep3dResult {
  Step3dSolutionSet set;  ///< physical solutions (values of the polygonal law), deduplicated;
                          ///< each solution's residual measures it against the ELLIPTIC law
  int facets = 0;
  int size = 0;           ///< the complementarity problem's size: k (LCP, P_N1 eliminated by
                          ///< g1 = 0) without wear, 1 + k (NCP) with wear
  bool lcp = true;        ///< no wear: an LCP enumerated completely; else an NCP (multistart)
  long long nodes = 0;    ///< LCP enumeration nodes
  double seconds = 0;
};
/// Without wear (c_w = 0): separation directly, and every contact solution of the LCP of size k
/// in lambda_j (g1 = 0 gives P_N1 affinely) by
/// cpkit::lcp::enumerate_all (complete as that enumeration). With wear: the NCP solved by the
/// registry's MCP solvers ("fb-newton" from `n_starts` seeded starts, "ipopt" from two) and
/// complete = false. Throws InputError for invalid input or k outside [3, 64].
FacetedStep3dResult solve_step_3d_faceted(const Step3dProblem& problem, int facets,
                                          int n_starts = 16, std::uint64_t seed = 1);

struct Step3dChainOptions {
  /// Links tried in order until one gives a verified solution: "exact" (enumerate_step_3d,
  /// the solution closest to the start state, i.e. smallest |DP|), "fb-soc", "ipopt".
  std::vector<std::string> chain = {"exact", "fb-soc", "ipopt"};
  CommonOptions solver = step_3d_solver_options();
  /// Empty when usable; names the bad field (empty chain, unknown link name, solver options).
  std::string validate() const;
};

/// The common SolveResult of the chain: status kSolved when a link gave a verified solution
/// (solver = that link), else the last attempt's status; attempts = every link tried (residual =
/// step_3d_residual of its answer, inf when it gave none); merit 0.
using Step3dChainResult = StepSolveResultOf<Step3dSolution>;

/// One verified solution by the chain. Throws InputError for invalid input or options.
Step3dChainResult solve_step_3d(const Step3dProblem& problem,
                                const Step3dChainOptions& options = {});

/// Distinct verified solutions from FB-SOC at the start state and at `n_starts` deterministic
/// pseudo-random starts (seeded), and from Ipopt at the start state and every fourth start.
/// complete is always false: local solvers cannot prove that no other solution exists (the
/// message says so). Throws InputError for invalid input or n_starts < 0.
Step3dSolutionSet multistart_step_3d(const Step3dProblem& problem, int n_starts,
                                     std::uint64_t seed = 1);

/// Sorts solutions (separation/open, stick, slip by angle) and drops duplicates (end forces
/// equal to 1e-7 relative to the problem's force scale). Exposed for the CLI and tests.
void sort_and_dedup_step_3d(const Step3dProblem& problem, std::vector<Step3dSolution>& sols);

}  // namespace cpkit::rate
