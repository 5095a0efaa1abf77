#pragma once
/// \file simulation_json.hpp
/// The JSON of a one-point simulation: the summary `cpkit simulate` writes (--summary, --json;
/// docs/simulation.md, "Summary"), written once here for the program, Python and tests. Values
/// are in the units of the settings (forces as F, displacements as w, energies force x
/// displacement, temperatures as T_ref).
#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/simulation/simulate_config.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"

namespace cpkit::rate {

/// One recorded sample: step, t, F_T, F_N, P_T, P_N, w_T, w_N, w_w, w_Ti, g, state (a-d),
/// temperature.
nlohmann::json simulation_sample_json(const SimulationSample& s);

/// The summary of a run: outcome, message, steps, final (a sample), final_wear_depth,
/// wear_integral, total_slip, slip_per_cycle, wear_per_cycle, energy{...}, branch_points{count,
/// rule, recorded}, max_step_residual, temperature{final, max} (heat on), wear_law, criterion, and
/// settings (the merged settings `s`, enough to reproduce the run). The program adds "run".
nlohmann::json simulation_summary_json(const SimulationResult& r, const SimulateSettings& s);

}  // namespace cpkit::rate
