#pragma once
/// \file result.hpp
/// What every solver returns (through finalize()).
#include <optional>
#include <string>
#include <vector>

#include "cpkit/core/friction_errors.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/status.hpp"

namespace cpkit {

/// Farkas-type proof that an LCP has no solution: y >= 0, M^T y <= 0, q^T y < 0
/// (then y^T w = (M^T y)^T z + q^T y < 0 for every z >= 0, so w >= 0 is impossible).
struct Certificate {
  Vec y;
  bool checked = false;      ///< set by finalize() after re-checking from the data
  bool exact = false;        ///< checked with exact signs (else within componentwise rounding)
  double q_dot_y = 0;        ///< q^T y (negative), recomputed by finalize()
  double max_MTy = 0;        ///< max_i (M^T y)_i (<= tolerance), recomputed by finalize()
};

/// One row of the optional per-iteration trace (PATH-style log).
struct TraceEntry {
  int iteration = 0;
  double residual = 0;       ///< solver's merit (e.g. ||Phi|| or natural residual)
  double step = 0;           ///< step length taken
  std::string kind;          ///< e.g. "newton", "gradient", "pivot", "z0-enters"
  int entering = -1;         ///< pivoting solvers: entering variable index
  int leaving = -1;          ///< pivoting solvers: leaving variable index
};

/// How one solver of a chain ended (SolveResult::attempts).
struct Attempt {
  std::string solver;
  Status status = Status::kNotRun;
  double residual = 0;
  double seconds = 0;
  std::string message;
  int iterations = 0;        ///< that attempt's iterations (0 when not counted)
};

struct SolveResult {
  Status status = Status::kNotRun;
  std::string solver;        ///< registry name of the solver that produced z
  Vec z;                     ///< candidate (solution when is_solution(status))
  Vec w;                     ///< w = M z + q (F(x) for MCPs), recomputed by finalize()
  Residuals residuals;       ///< recomputed by finalize()
  int iterations = 0;        ///< iterations, or pivots for pivoting methods
  int function_evals = 0;
  int jacobian_evals = 0;
  int line_search_steps = 0;
  int gradient_steps = 0;
  double seconds = 0;        ///< wall time of the solve
  std::optional<Certificate> certificate;  ///< only with kInfeasible (checked)
  std::optional<Vec> ray;    ///< Lemke: direction of the secondary ray in (z, z0) space
  std::vector<int> basis;    ///< pivoting methods: final complementary basis (i: z_i, ~i: w_i)
  std::vector<TraceEntry> trace;
  std::vector<Attempt> attempts;  ///< solver chains: every attempt, in order
  std::string message;       ///< human-readable account of the outcome
  /// Frictional contact problems: z's errors in the three measures, computed by finalize()
  /// with `residuals` (so that deciding in another measure needs no second verdict); empty
  /// for every other problem kind and when finalize() judged no point.
  std::optional<FrictionErrors> friction_errors;
};

/// Makes a used result (its vectors' storage kept) the claim of a solver that found z
/// without iterating: status and solver set, every count 0, every other field cleared.
/// Callers on a per-call hot path reuse one result this way instead of building a new one.
inline void reuse_as_claim(SolveResult& r, Status status, const char* solver) {
  r.status = status;
  r.solver = solver;
  r.iterations = r.function_evals = r.jacobian_evals = r.line_search_steps = r.gradient_steps = 0;
  r.seconds = 0;
  r.certificate.reset();
  r.ray.reset();
  r.basis.clear();
  r.trace.clear();
  r.attempts.clear();
  r.message.clear();
  r.friction_errors.reset();
}

}  // namespace cpkit
