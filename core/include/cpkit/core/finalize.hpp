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

/// Re-checks the Farkas certificate y >= 0, M^T y <= 0, q^T y < 0 from the data
/// (core/src/certificate.cpp, docs/conventions.md). Negative entries of y are dropped and y is
/// scaled by a power of two (exactly) to ||y||_inf in [1, 2); cert.y is replaced by the vector
/// the proof is about. Then, in this order:
/// 1. exact: the signs of q^T y and of every (M^T y)_j are evaluated without rounding error
///    (error-free products and sums); no tolerance is involved, so no magnitude can excuse a
///    positive (M^T y)_j;
/// 2. exact, after snapping y to a nearby vector of small integers (continued fractions with a
///    common denominator): recovers the exact certificate a floating-point y approximates when
///    M^T y = 0 must hold exactly in some columns (integer or otherwise exactly representable
///    data);
/// 3. within rounding, componentwise: (M^T y)_j <= gamma_{n+1} (|M|^T y)_j for every column
///    and q^T y < -gamma_{n+1} |q|^T y: y is then an exact certificate of a problem whose entries
///    differ from the data by at most the rounding error of forming M^T y (relative, entry by
///    entry, so one large entry excuses nothing elsewhere). cert.exact is false.
/// Updates cert.checked, cert.exact, cert.q_dot_y, cert.max_MTy (accurately rounded values).
bool check_certificate(const LcpProblem& problem, Certificate& cert);

}  // namespace cpkit
