#pragma once
/// \file step_json.hpp
/// The JSON of incremental-step results, one point and N points: the objects `cpkit step --json`
/// prints (docs/cli.md), written once here for the program, Python and tests. Increments and
/// end values are in the units of the input (forces as DF and P, displacements as g), signs as
/// in docs/contact_model.md.
#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"

namespace cpkit::rate {

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

/// Every solution of an N-point step: count, complete, notes, solutions (types per point,
/// values: each field an array with one number per point, residual). The program adds
/// cpkit_version, input and n_points.
nlohmann::json system_step_set_json(const SystemStepSolutionSet& s);

}  // namespace cpkit::rate
