#pragma once
/// \file simulation_json.hpp
/// The JSON of a one-point simulation: the summary `cpkit simulate` writes (--summary, --json;
/// docs/simulation.md, "Summary"), written once here for the program, Python and tests. Values
/// are in the units of the settings (forces as F, displacements as w, energies force x
/// displacement, temperatures as T_ref).
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/rate_problem/simulation/simulate_config.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"

namespace cpkit::rate {

/// One recorded sample: step, t, F_T, F_N, P_T, P_N, w_T, w_N, w_w, w_Ti, g, state (a-d),
/// temperature.
nlohmann::json simulation_sample_json(const SimulationSample& s);

/// The summary of a run: outcome, message, steps, final (a sample), final_wear_depth,
/// wear_integral, total_slip, slip_per_cycle, wear_per_cycle, energy{...}, branch_points{count,
/// rule, recorded}, max_step_residual, temperature{final, max} (heat on), wear_law, criterion, and
/// settings (the merged settings `s`, enough to reproduce the run). The program adds "run".
nlohmann::json simulation_summary_json(const SimulationResult& r, const SimulateSettings& s);

/// The summary of an N-point run of system `sys` (file `s.system`): input{system, name, load,
/// fretting{F_N, amplitude, period, cycles, steps_per_cycle, ramp_steps} or file}, outcome
/// ("inconclusive" when r.inconclusive), message, steps, n_points, final{t, P_T, P_N, g, w_w,
/// w_Ti} (arrays per point), final_wear_depth, wear_integral, total_slip, wear_per_cycle,
/// energy{external_work, stored, dissipation, work_abs, balance_error_rel,
/// min_step_dissipation_rel}, branch_points{count, rule}, incomplete_steps, complete,
/// max_step_residual, temperature{final, max} (heat on). The program adds cpkit_version and run.
nlohmann::json system_simulation_summary_json(const SystemSimulationResult& r,
                                              const SimulateSettings& s, const ContactSystem& sys);

/// The summary of a 3-D fretting run under `orbit` with options `o` (docs/contact_3d.md):
/// dim 3, input{system (the file name `system`), name, point{A, mu, C_T, k_a, P_s, alpha},
/// wear{law, k_M}, orbit{F_N, a_X, a_Y, angle, period, cycles, steps_per_cycle, ramp_steps,
/// lead_steps}, branch_rule, every}, outcome, message, steps, final (a sample),
/// final_wear_depth, wear_integral, total_slip, total_lambda, the per-cycle slip and wear
/// arrays, dissipation, min_step_dissipation_rel, branch_points{count, rule},
/// incomplete_steps, local_steps, enumeration_missed, complete (no incomplete step and not
/// ambiguous), max_step_residual. The program adds cpkit_version and run.
nlohmann::json fretting_3d_summary_json(const Fretting3dResult& r, const EllipticOrbit& orbit,
                                        const Fretting3dOptions& o, const std::string& system,
                                        const std::string& name);

/// Writes `j` as JSON text (indent 1; invalid UTF-8 in strings replaced by U+FFFD) and a line
/// end to `path`, creating its folder (open_output). InputError naming the path on failure.
void write_json_file(const std::string& path, const nlohmann::json& j);

}  // namespace cpkit::rate
