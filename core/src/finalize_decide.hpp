#pragma once
// The decision shared by every finalize() (LCP, box LCP, MCP: finalize.cpp; friction problems:
// friction_verdict.cpp), so that "solved" means the same everywhere.
#include <string>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::detail {

/// Appends text to a "; "-separated message.
void append(std::string& message, const std::string& text);
/// Sets r.status from r.residuals (natural <= tol: solved; <= tol_acceptable: inaccurate; a
/// refuted claimed solution: numerical failure), appending the reason to r.message.
void decide(SolveResult& r, bool claimed_solution, const CommonOptions& o);
/// False (and, for a claimed solution, numerical failure) when r.z has the wrong size or
/// non-finite entries.
bool usable_point(SolveResult& r, Eigen::Index n, bool claimed_solution);
/// For kinds with no certificate format (infeasibility is never granted without a checkable
/// proof): drops any certificate; true, with r refuted as numerical failure, when r claims
/// infeasibility. `kind` names the problem in the message ("an MCP").
bool refuse_infeasibility(SolveResult& r, const char* kind);

}  // namespace cpkit::detail
