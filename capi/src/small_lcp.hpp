#pragma once
// The tiny-LCP route of the C API: n <= 4 with solver "auto" or "lemke".
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::capi {

/// For n <= 4 and the solvers "auto" and "lemke": enumerates every solution of `p` in closed
/// form (lcp::enumerate_small, allocation-free). When that finds exactly one solution (a finite
/// set, complete, nothing ambiguous or dropped) it is THE answer any solver that returns one
/// must give; it is decided by finalize() into `r` (0 iterations) and true is returned when
/// finalize() accepts it. Otherwise (n > 4, another solver, no or several solutions, a rejected
/// candidate) returns false and the caller runs the registered solver.
bool solve_small_unique(const LcpProblem& p, const SolverEntry& entry, const CommonOptions& o,
                        SolveResult& r);

}  // namespace cpkit::capi
