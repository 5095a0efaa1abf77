#pragma once
// The one-contact route of the C API's friction solves: one contact with solver "auto" or
// "nsgs".
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::capi {

/// For one contact and the solvers "auto" and "nsgs": every solution of the contact in closed
/// form (lcp::friction::one_contact_solutions: separation, stick, the slips). When there is
/// exactly one, it is THE answer any solver that returns one must give; it is decided by the
/// friction finalize() (the verdict) into `r` (0 iterations) and true is returned when the
/// verdict accepts it. Otherwise the caller runs the registered solver.
bool solve_one_contact_unique(const FrictionContactProblem& p, const SolverEntry& entry,
                              const CommonOptions& o, SolveResult& r);

}  // namespace cpkit::capi
