#pragma once
// The tiny-LCP routes (n <= 4): the C API with solver "auto" or "lemke", and the auto chain.
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp {

/// True for the solvers whose answer on a tiny LCP with exactly one solution is that solution
/// ("auto" and "lemke"), so that the closed enumeration may answer for them.
bool small_lcp_route(int n, const SolverEntry& entry);

/// The per-call path (no allocation, nothing built): for small_lcp_route(n, entry), the one
/// solution of (M column-major n x n, q) when it is provably unique: for n <= 3 and M provably
/// a P-matrix (every principal minor positive beyond rounding), the complementary basic solution
/// whose signs hold; otherwise every solution enumerated in closed form (lcp::enumerate_small),
/// when there is exactly one. When its unit-free residual (small_lcp_natural: the number finalize() decides
/// by) is at most tol, writes z, w = M z + q and that residual, and returns true: the verdict
/// finalize() gives is kSolved. Otherwise returns false with nothing decided, and the caller
/// takes solve_small_unique() / the registered solver, which decide as always.
bool solve_small_fast(int n, const double* M, const double* q, double tol, double* z, double* w,
                      double& natural);

/// The same route through the library's types: when the enumeration finds exactly one
/// solution, it is THE answer any solver that returns one must give; it is decided by
/// finalize() into `r` (0 iterations) and true is returned when finalize() accepts it.
/// Otherwise (not small_lcp_route, no or several solutions, a rejected candidate) returns false
/// and the caller runs the registered solver.
bool solve_small_unique(const LcpProblem& p, const SolverEntry& entry, const CommonOptions& o,
                        SolveResult& r);

}  // namespace cpkit::lcp
