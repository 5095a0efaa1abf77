#pragma once
/// \file json.hpp
/// The JSON of rate-problem and incremental-step results, one point and N points: the objects
/// `cpkit rate --json` and `cpkit step --json` print (docs/cli.md), written once here for the
/// program, Python and tests. Field names are stable. Units are the input's: rates and
/// increments of forces as dF / DF, of displacements as dF times the compliance A^-1; end
/// values as P and g; signs as in docs/contact_model.md. 3-D results: json_3d.hpp.
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::rate {

struct RateOutcome;  // report/rate_outcome.hpp

// Rate problem.

/// {"dP_T", "dP_N", "dw_T", "dw_N", "dw_Ti", "dw_w"}: numbers (one point).
nlohmann::json rates_json(const Rates& r);
/// The same fields, each an array with one number per point (N points).
nlohmann::json rates_json(const SystemRates& r);

/// A one-point solution set: complete; count ("inf" when infinite) if complete, else found (a
/// single solver's solutions, never a count); enumerated_count from `reference` (the complete set
/// a single solver's point was checked against; null: none); types (sorted names); solutions
/// (type, kind, rates | start[, start_closed, end, end_closed | direction]); Lambda, D_plus,
/// D_minus, unique_for_all_directions (the quantities that decide the set).
nlohmann::json rate_set_json(const RateSolutionSet& s, const RateSolutionSet* reference = nullptr);

/// An N-point solution set: complete; count or found as above; message (when not empty);
/// solutions (types per point, kind, values | start[, ...]). The program adds the input echo.
nlohmann::json system_rate_set_json(const SystemRateSolutionSet& s);

/// The object `cpkit rate --json` prints for an outcome (report/rate_outcome.hpp): one point,
/// rate_set_json (with the enumerated reference of a single solver); N points and 3-D systems,
/// the set with "cpkit_version" (`version`), "input" (system, name, dF, method; 3-D: facets)
/// and "n_points" (3-D: "dim": 3). The program adds "run".
nlohmann::json rate_outcome_json(const RateOutcome& outcome, const std::string& version);

// Incremental step.

/// {"DP_T", "DP_N", "Dw_T", "Dw_N", "Dw_Ti", "Dw_w", "P_T1", "P_N1", "g1"}: numbers.
nlohmann::json step_values_json(const StepValues& v);

/// Every solution of a one-point step (`--all`): count ("inf" when infinite), types (sorted
/// names), continuous_count, complete, message (when not complete), solutions (type, kind,
/// values | start[, start_closed, end, end_closed | direction], jump, residual).
nlohmann::json step_set_json(const StepSolutionSet& s);

/// One solver chain's answer: status, solver, type and values (when a solution), residual,
/// attempts (solver, status, residual, seconds, message), message; with `all` (the enumeration
/// an active-set answer was picked from; null: none) solutions_found ("inf" when infinite),
/// listed (1) and enumeration_complete.
nlohmann::json step_result_json(const StepSolveResult& r, const StepSolutionSet* all = nullptr);

/// The step's input echo of an N-point system: {"name", "A" (rows), "points" (mu, C_T, k_a,
/// P_s, P_T, P_N, g per point)}, in the units of the system file.
nlohmann::json contact_system_json(const ContactSystem& system);

/// Every solution of an N-point step: count, complete, notes, solutions (types per point,
/// values: each field an array with one number per point, residual). The program adds
/// cpkit_version, input and n_points.
nlohmann::json system_step_set_json(const SystemStepSolutionSet& s);

struct StepOutcome;  // report/step_outcome.hpp

/// The object `cpkit step --json` prints for the answer of a request (run_step_request), every
/// route: one 2-D point (step_set_json, or step_result_json with the enumeration an active-set
/// answer was picked from), N 2-D points and 3-D points (with "cpkit_version" and "input": the
/// request's echo). The program adds "run".
nlohmann::json step_outcome_json(const StepOutcome& outcome, const std::string& cpkit_version);

}  // namespace cpkit::rate
