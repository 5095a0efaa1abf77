#pragma once
/// \file json_3d.hpp
/// The JSON of 3-D results (docs/contact_3d.md): per-point rates, slip directions, one step
/// solution and one fretting sample, as `cpkit rate|step|simulate` print them for "dim": 3
/// systems, written once here for the program, Python and tests. Tangential quantities are
/// [x, y] pairs in the system's tangent frame; normal ones are numbers; units as the input's.
#include <nlohmann/json.hpp>
#include <vector>

#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"

namespace cpkit::rate {

/// {"dP_T", "dP_N", "dw_T", "dw_N", "dw_Ti", "dw_w"}, each an array with one entry per point
/// (a pair for the tangential fields, a number for the normal ones).
nlohmann::json rates_3d_json(const std::vector<Rates3d>& rates);

/// Adds "slip_direction" (unit [x, y] of dw_Ti) and "slip_angle" (atan2, radians) per point to
/// `e`, null where the point does not slip (type not slip, or dw_Ti = 0); nothing when no point
/// slips. `dw_source` holds the rates whose dw_Ti gives the direction (a ray's direction).
void add_slip_json(nlohmann::json& e, const std::vector<SolutionType>& types,
                   const std::vector<Rates3d>& dw_source);

/// The result part of a 3-D system's rate problem (docs/contact_3d.md): "route" (exact or
/// faceted), "complete", "time_limit_reached" (only when true), "count" (a number, or "inf" when
/// a solution is a ray) when complete else "found", "message" (when not empty) and "solutions":
/// per solution "types", "kind" (point or ray), "values" (a point) or "start", "start_closed" and
/// "direction" (a ray), and the slip directions (add_slip_json). The caller adds "input".
nlohmann::json system_rate_3d_json(const SystemRateRoute3d& r);

/// One step solution: type, P_T1 (pair), P_N1, DP and Dw ([T_x, T_y, N]), Dw_Ti (pair), Dw_w,
/// g1, lambda, slip_direction and slip_angle (null unless slip), residual.
nlohmann::json step_3d_solution_json(const Step3dSolution& s);

/// A solver chain's attempts: per attempt "solver", "solved" (status solved), "residual" (null
/// when not finite), "iterations", "seconds", "message".
nlohmann::json attempts_json(const std::vector<Attempt>& attempts);

/// The solutions part of a 3-D step: "complete" and "count" (complete) or "found", "message"
/// (when not empty) and "solutions" (step_3d_solution_json each). `with_count` false writes only
/// "message" and "solutions" (a solver chain's answer, which is no set).
nlohmann::json step_3d_set_json(const Step3dSolutionSet& set, bool with_count = true);

/// The same for N coupled 3-D points: per solution "points" (step_3d_solution_json each) and
/// "residual"; "complete": false and "found" (with_count), never a count (no complete
/// enumeration of the coupled step exists).
nlohmann::json system_step_3d_set_json(const SystemStep3dSolutionSet& set, bool with_count = true);

/// One fretting sample: step, t, F_T, P_T, w_T, w_Ti (pairs), F_N, P_N, g, w_N, w_w, type.
nlohmann::json fretting_3d_sample_json(const Fretting3dSample& s);

}  // namespace cpkit::rate
