#pragma once
/// \file rate_json.hpp
/// The JSON of rate-problem results, one point and N points: the objects `cpkit rate --json`
/// prints (docs/cli.md), written once here for the program, Python and tests. Field names are
/// stable; rates are in the units of the input (force rates in the units of dF, displacement
/// rates in those of dF times the compliance A^-1), signs as in docs/contact_model.md.
#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/one_point/rate_problem.hpp"
#include "cpkit/rate_problem/system/system_rate.hpp"

namespace cpkit::rate {

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

}  // namespace cpkit::rate
