#pragma once
/// \file solvers.hpp
/// The registry of every LCP/NCP solver in cpkit::lcp (built once, immutable, thread-safe).
#include "cpkit/core/registry.hpp"

namespace cpkit::lcp {

/// All registered solvers, in the order of the automatic chain.
const SolverRegistry& solvers();

}  // namespace cpkit::lcp
