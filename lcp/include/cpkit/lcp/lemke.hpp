#pragma once
/// \file lemke.hpp
/// Lemke's complementary pivoting method for dense LCPs [Cottle-Pang-Stone 1992, Sec. 4.4],
/// with the lexicographic minimum-ratio test so that degenerate problems never cycle.
///
/// Problem: z >= 0, w = M z + q >= 0, z . w = 0 (cpkit's convention).
/// Guarantees: terminates (lexicographic rule) with a solution or a secondary ray. For
/// copositive-plus M a secondary ray proves infeasibility [CPS 1992, Thm 4.4.13]; the ray's
/// certificate y >= 0, M^T y <= 0, q^T y < 0 is re-checked by finalize() before kInfeasible is
/// reported; otherwise the result is kRayTermination with the ray in `result.ray`.
/// On failure z holds the last basic solution (z0 dropped) and is not a solution.
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp {

struct LemkeOptions {
  CommonOptions common;  ///< max_iterations = 0: pivot limit 50 * (n + 1) + 1000 (documented)
  Vec covering;          ///< covering vector d > 0 for z0 (empty: all ones)
  /// Optional warm start: a complementary basis, basis[i] = i (z_i basic) or ~i (w_i basic).
  /// When it is feasible for q the method returns it (after verification) without pivoting;
  /// otherwise Lemke starts from it as documented in docs/solvers.md.
  std::vector<int> warm_basis;
  int refactor_every = 0;  ///< pivots between refactorizations of the basis; 0: automatic
  std::string validate(Eigen::Index n) const;
};

/// Solves the LCP; throws InputError for invalid problems/options (sizes, NaN/Inf, d <= 0).
SolveResult solve_lemke(const LcpProblem& problem, const LemkeOptions& options = {});

/// Registry entry ("lemke").
SolverEntry lemke_entry();

}  // namespace cpkit::lcp
