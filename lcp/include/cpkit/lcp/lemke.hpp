#pragma once
/// \file lemke.hpp
/// Lemke's complementary pivoting method for dense LCPs [Cottle-Pang-Stone 1992, Sec. 4.4],
/// with the lexicographic minimum-ratio test so that degenerate problems never cycle.
///
/// Problem: z >= 0, w = M z + q >= 0, z . w = 0 (cpkit's convention), augmented with the
/// artificial variable z0 >= 0 and the covering vector d > 0:  w = M z + q + d z0.
///
/// Guarantees: terminates (lexicographic rule, finite number of bases) with a solution, a
/// secondary ray, or at the pivot/time limit. Lemke solves every LCP with a P-matrix, and for a
/// copositive-plus M a secondary ray proves infeasibility [CPS 1992, Thm 4.4.13].
/// Lexicographic rule [CPS 1992, Sec. 4.9]: ties in the minimum ratio are broken by the rows
/// of the basis inverse divided by the pivot entries, column by column; the rows are
/// independent, so no basis repeats. Ties and noise are judged at the rounding level
/// tau = max(64 eps (k + 1), 4 omega) (omega: the inverse's measured componentwise backward
/// error; capped at 1e-9): ratios within tau of the ratio and of the size of the terms of the
/// values, entries of B^{-1} within tau of the rows' scales, pivot entries below tau times
/// the size of their own terms. All tolerances are relative to the terms of the number
/// tested: invariant under q -> a q, (M, q) -> b (M, q) and row/column scalings.
/// Cycle guard: a repeated basis (hash of the set of basic variables per pivot) ends the run
/// with Status::kCycleDetected (a bug-class outcome) instead of cycling to the pivot limit.
/// On a secondary ray cheap candidate certificates y (the z-part of the ray, minus the z0 row
/// of the basis inverse, the w-part of the ray, d, all ones, unit vectors) are checked for
/// y >= 0, M^T y <= 0, q^T y < 0 and finalize() re-checks the one kept before kInfeasible is
/// reported; otherwise the result is kRayTermination with the ray (z-part then z0-part, size
/// n + 1) in `result.ray`. A step that overflows (a solution doubles cannot represent, e.g.
/// M = 1e-320, q = -1) is kNumericalFailure with a message.
/// On failure z holds the last basic solution (z0 dropped) and is not a solution.
///
/// result.iterations counts the pivots, the initial z0 pivot included (q >= 0: no pivot).
/// Trace (CommonOptions::record_trace): one TraceEntry per pivot with kind "z0-enters",
/// "pivot" or "z0-leaves", entering/leaving variable ids (0..n-1: z_i, n: z0, n+1+i: w_i),
/// step = the value of the entering variable, residual = z0 after the pivot.
///
/// Work per pivot: O(n k + k^2) with k the number of basic z's (the basis inverse is kept in
/// block form: only the k x k inverse of M's basic block is updated, plus, once a tie has
/// occurred, the n x k rows of the basic w's); tie-breaking costs at most O(n) per tied row.
/// The inverse's accuracy is checked every 16 pivots from the data and it is recomputed when
/// the check fails.
/// Sparse input is densified when n <= kLemkeMaxDensify, else the result is kUnsupported.
/// Memory: for a dense problem with n <= 64 the arrays of a run are kept per thread and reused
/// by the next call (no heap allocation inside the run when n repeats; about 100 KB per thread
/// at most); the answer never depends on earlier calls (bit-identical to a fresh thread's).
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp {

/// Largest sparse LCP that solve_lemke densifies (larger ones: Status::kUnsupported).
constexpr Eigen::Index kLemkeMaxDensify = 2000;

struct LemkeOptions {
  CommonOptions common;  ///< max_iterations = 0: pivot limit 50 * (n + 1) + 1000 (documented)
  /// Covering vector d > 0 for z0, size n. Empty: all ones when the rows of M have comparable
  /// sizes (max_j |M_ij| within a factor 1024 of each other), else d_i = max_j |M_ij| / max |M|
  /// (each row in its own units: the path does not depend on the units of the rows).
  Vec covering;
  /// Optional warm start: a complementary basis, basis[i] = i (z_i basic) or ~i (w_i basic),
  /// e.g. SolveResult::basis of a previous solve of a nearby problem. When its basic solution
  /// is a solution it is returned (after verification) with 0 pivots; otherwise Lemke starts
  /// from it with the covering vector applied in that basis' coordinates (docs/solvers.md).
  /// A warm basis whose block M(Z, Z) is singular is ignored (cold start, noted in message).
  std::vector<int> warm_basis;
  /// > 0: recompute the basis inverse from the data every that many pivots (in addition to
  /// the automatic accuracy check); 0: only when the automatic check fails.
  int refactor_every = 0;
  /// true: the lexicographic ratio test (never cycles). false: ties broken by the smallest
  /// variable id ("plain" Lemke, which can cycle): for tests and demonstrations of the cycle
  /// guard only.
  bool lexicographic = true;
  /// Debug/test mode: after every pivot, check the invariant of the lexicographic rule (every
  /// row of [values, B^{-1}] of a basic variable lexicographically positive, at the rounding
  /// level; O(n^2) per pivot). A violation ends the run with Status::kNumericalFailure and a
  /// message naming the row (the final pivot, z0 leaving, is not checked).
  bool check_invariant = false;
  /// Empty when usable for a problem of size n; otherwise names the bad field.
  std::string validate(Eigen::Index n) const;
};

/// Solves the LCP; throws InputError for invalid problems/options (sizes, NaN/Inf, d <= 0).
SolveResult solve_lemke(const LcpProblem& problem, const LemkeOptions& options = {});

/// Registry entry ("lemke").
SolverEntry lemke_entry();

}  // namespace cpkit::lcp
