#pragma once
/// \file report.hpp
/// Text and JSON reports of a result (for the CLI and logs). JSON field names are stable:
/// status, solver, z, w, iterations, residual (scaled natural residual), residuals{...},
/// seconds, message, certificate{y, q_dot_y, max_MTy} (when infeasible), ray, attempts, trace.
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/core/result.hpp"

namespace cpkit {

/// A short multi-line human-readable report.
std::string to_text(const SolveResult& result);
nlohmann::json to_json(const SolveResult& result);
nlohmann::json to_json(const Residuals& residuals);
nlohmann::json to_json(const Vec& v);  ///< array of numbers (non-finite as null)

}  // namespace cpkit
