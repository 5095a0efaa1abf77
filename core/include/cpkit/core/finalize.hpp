#pragma once
/// \file finalize.hpp
/// Algorithms claim, one function decides. Every solver returns through finalize().
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit {

/// Decides the status of `claim` from the problem data:
/// - recomputes w = M z + q and the residuals;
/// - natural <= tol: kSolved; <= tol_acceptable: kSolvedInaccurate (whatever was claimed);
/// - a claimed solution the data refute (or a z of wrong size / non-finite) becomes
///   kNumericalFailure with a message; other claimed failures are kept;
/// - kInfeasible is kept only if claim.certificate passes check_certificate(); otherwise the
///   status becomes kNumericalFailure (a refuted proof).
/// Fills w, residuals, certificate->checked, and times nothing (the solver sets seconds).
SolveResult finalize(const LcpProblem& problem, SolveResult claim, const CommonOptions& options);
SolveResult finalize(const BoxLcpProblem& problem, SolveResult claim, const CommonOptions& options);
/// MCP version: evaluates F at claim.z; an F outside its domain is a numerical failure.
SolveResult finalize(const McpProblem& problem, SolveResult claim, const CommonOptions& options);

/// Re-checks y >= 0, M^T y <= 0, q^T y < 0 from the data, with y normalised to ||y||_inf = 1
/// and tolerance tol on (M^T y)_i relative to ||M||_max and on q^T y relative to ||q||_inf.
/// Updates cert.checked, cert.q_dot_y, cert.max_MTy.
bool check_certificate(const LcpProblem& problem, Certificate& cert, double tol = 1e-10);

}  // namespace cpkit
