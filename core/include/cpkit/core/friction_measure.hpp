#pragma once
/// \file friction_measure.hpp
/// The measure that decides "solved" for a 3-D frictional contact answer (issue 35): cpkit's
/// unit-free number (friction_verdict.hpp, the default) or one of the field's two published
/// normalisations of the natural map, so that a tolerance means what FCLIB's papers and Siconos
/// mean by it. docs/friction_contact.md ("The field's measure") and docs/conventions.md.
///
/// With E = ||(r_i - P_K(r_i - u_hat_i))_i||_2 (all contacts, problem units, u = W r + q):
///   relative_q   = E / ||q||_2                      (E itself when ||q||_2 <= DBL_EPSILON)
///   relative_max = E / max(||q||_2, ||r||_2, ||u||_2) (E itself when that max <= DBL_EPSILON)
/// relative_max is Siconos' fc3d_compute_error with norm = ||q||_2; relative_q is the measure of
/// FCLIB's benchmark [Acary, Bremond, Huber, INRIA RR-9118, 2018]. Neither divides by zero: a
/// problem with q = 0 is judged by the absolute E (Siconos' rule).
///
/// The unit-free verdict stays the trust check in every measure: an answer is "solved" in a
/// relative measure only when that measure is <= tol AND the unit-free number accepts it
/// (unit_free <= tol_acceptable, finite). An answer the unit-free verdict refutes or cannot
/// verify (a plausible r with a tiny relative error on a badly scaled problem, a diverging r)
/// is never "solved", in any measure.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit {

enum class FrictionMeasure { kUnitFree, kRelativeQ, kRelativeMax };

/// "unit_free", "relative_q", "relative_max" (the CLI's --measure words and the JSON's).
const char* to_string(FrictionMeasure m) noexcept;
/// The inverse of to_string; std::nullopt for any other word.
std::optional<FrictionMeasure> friction_measure_from_string(std::string_view name) noexcept;
/// "unit_free, relative_q, relative_max" (messages).
std::string friction_measure_names();
/// As friction_measure_from_string; InputError "unknown measure 'x' for OPTION (valid: ...)".
FrictionMeasure parse_friction_measure(const std::string& name, const std::string& option);

/// The error of `errors` in measure m.
double measured(const FrictionErrors& errors, FrictionMeasure m) noexcept;

/// Re-decides result.status in measure m, as finalize() decides in the unit-free number
/// (finalize_decide.hpp): the measure <= tol solved, <= tol_acceptable solved_inaccurate, above
/// that numerical_failure ("not a solution in relative_q"); but only when the verdict accepted
/// r (result.status is solved or solved_inaccurate, as finalize() or a global problem's verdict
/// decided, and unit_free <= tol_acceptable): otherwise result is left as it is (never a
/// solution). Appends the reason to result.message. m = kUnitFree, or no r of the problem's
/// size: result is unchanged.
void decide_in_measure(const FrictionContactProblem& problem, SolveResult& result,
                       const CommonOptions& options, FrictionMeasure m);
/// The same with `errors` = friction_errors(problem, result.z) already computed by the caller
/// (one verdict instead of two on the hot path of a small solve).
void decide_in_measure(const FrictionContactProblem& problem, SolveResult& result,
                       const CommonOptions& options, FrictionMeasure m,
                       const FrictionErrors& errors);

}  // namespace cpkit
