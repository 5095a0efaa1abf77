#include "cpkit/rate_problem/report/simulation_json.hpp"

#include <string>
#include <vector>

namespace cpkit::rate {

nlohmann::json simulation_sample_json(const SimulationSample& s) {
  return {{"step", s.step}, {"t", s.t}, {"F_T", s.F_T}, {"F_N", s.F_N}, {"P_T", s.P_T},
          {"P_N", s.P_N}, {"w_T", s.w_T}, {"w_N", s.w_N}, {"w_w", s.w_w}, {"w_Ti", s.w_Ti},
          {"g", s.g}, {"state", std::string(to_string(s.state))},
          {"temperature", s.temperature}};
}

nlohmann::json simulation_summary_json(const SimulationResult& r, const SimulateSettings& s) {
  nlohmann::json j;
  j["outcome"] = std::string(to_string(r.outcome));
  j["message"] = r.message;
  j["steps"] = r.steps;
  j["final"] = simulation_sample_json(r.final_state);
  j["final_wear_depth"] = r.wear_depth;
  j["wear_integral"] = r.wear_integral;
  j["total_slip"] = r.total_slip;
  j["slip_per_cycle"] = r.slip_per_cycle;
  j["wear_per_cycle"] = r.wear_per_cycle;
  j["energy"] = {{"external_work", r.external_work}, {"stored", r.stored_energy},
                 {"dissipation", r.dissipation}, {"work_abs", r.work_abs},
                 {"balance_error_rel", r.energy_error},
                 {"min_step_dissipation_rel", r.min_step_dissipation},
                 {"thermal_dissipation", r.thermal_dissipation}};
  nlohmann::json bps = nlohmann::json::array();
  for (const auto& b : r.branch_points) {
    std::vector<std::string> types;
    for (int t = 0; t < 5; ++t)
      if (b.types & (1u << t))
        types.emplace_back(to_string(static_cast<SolutionType>(t)));
    bps.push_back({{"step", b.step}, {"t", b.t}, {"count", b.count}, {"types", types},
                   {"chosen", std::string(to_string(b.chosen))}});
  }
  j["branch_points"] = {{"count", r.branch_steps}, {"rule", std::string(to_string(s.opt.branch_rule))},
                        {"recorded", bps}};
  j["max_step_residual"] = r.max_residual;
  if (s.opt.heat.enabled) j["temperature"] = {{"final", r.final_state.temperature}, {"max", r.max_temperature}};
  j["wear_law"] = std::string(to_string(s.opt.wear.law));
  j["criterion"] = std::string(to_string(s.opt.params.criterion));
  // The settings actually used (config file and command line merged): with them the summary
  // alone reproduces the run, even when the config file has changed since.
  const auto& pp = s.opt.params;
  nlohmann::json set;
  set["parameters"] = {{"a11", pp.a11}, {"a12", pp.a12}, {"a22", pp.a22}, {"mu", pp.mu},
                       {"C_T", pp.C_T}, {"k_a", pp.k_a}, {"P_s", pp.P_s},
                       {"criterion", std::string(to_string(pp.criterion))}};
  set["wear"] = {{"law", std::string(to_string(s.opt.wear.law))}, {"k_M", s.opt.wear.k_M}};
  nlohmann::json load = {{"type", s.load_type}};
  if (s.load_type == "fretting")
    load.update({{"F_N", s.fretting.F_N}, {"amplitude", s.fretting.amplitude},
                 {"period", s.fretting.period}, {"cycles", s.fretting.cycles},
                 {"steps_per_cycle", s.fretting.steps_per_cycle},
                 {"ramp_steps", s.fretting.ramp_steps}});
  else if (s.load_type == "ramp")
    load.update({{"F_T0", s.ramp.F_T0}, {"F_N0", s.ramp.F_N0}, {"F_T1", s.ramp.F_T1},
                 {"F_N1", s.ramp.F_N1}, {"duration", s.ramp.duration}, {"steps", s.ramp.steps}});
  else
    load.update({{"file", s.load_csv}, {"period", s.csv_period}});
  set["load"] = load;
  const auto& h = s.opt.heat;
  set["heat"] = {{"enabled", h.enabled}, {"heat_capacity", h.heat_capacity}, {"T_ref", h.T_ref},
                 {"T_initial", h.T_initial}, {"T_body", {h.T_body[0], h.T_body[1]}},
                 {"conductance", {h.conductance[0], h.conductance[1]}}};
  set["branch_rule"] = std::string(to_string(s.opt.branch_rule));
  set["every"] = s.every;
  j["settings"] = set;
  return j;
}

}  // namespace cpkit::rate
