#include "cpkit/rate_problem/report/simulation_json.hpp"

#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/report/simulation_csv.hpp"

#include <fstream>
#include <string>
#include <vector>

namespace cpkit::rate {
namespace {

/// The fields a one-point and a 3-D summary share (same names, same meaning): outcome,
/// message, steps, final (the sample `final`), final_wear_depth, wear_integral, total_slip and
/// the per-cycle slip and wear.
template <class Result>
nlohmann::json run_totals(const Result& r, nlohmann::json final) {
  return {{"outcome", std::string(to_string(r.outcome))}, {"message", r.message},
          {"steps", r.steps}, {"final", std::move(final)}, {"final_wear_depth", r.wear_depth},
          {"wear_integral", r.wear_integral}, {"total_slip", r.total_slip},
          {"slip_per_cycle", r.slip_per_cycle}, {"wear_per_cycle", r.wear_per_cycle}};
}

}  // namespace

nlohmann::json simulation_sample_json(const SimulationSample& s) {
  return {{"step", s.step}, {"t", s.t}, {"F_T", s.F_T}, {"F_N", s.F_N}, {"P_T", s.P_T},
          {"P_N", s.P_N}, {"w_T", s.w_T}, {"w_N", s.w_N}, {"w_w", s.w_w}, {"w_Ti", s.w_Ti},
          {"g", s.g}, {"state", std::string(to_string(s.state))},
          {"temperature", s.temperature}};
}

nlohmann::json simulation_summary_json(const SimulationResult& r, const SimulateSettings& s) {
  nlohmann::json j = run_totals(r, simulation_sample_json(r.final_state));
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

namespace {
std::vector<double> vec(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }
std::vector<double> pair(const Eigen::Vector2d& v) { return {v(0), v(1)}; }
}  // namespace

nlohmann::json system_simulation_summary_json(const SystemSimulationResult& r,
                                              const SimulateSettings& s, const ContactSystem& sys) {
  nlohmann::json j;
  j["input"] = {{"system", s.system}, {"name", sys.name}, {"load", s.load_type}};
  if (s.load_type == "fretting")
    j["input"]["fretting"] = {{"F_N", s.fretting.F_N}, {"amplitude", s.fretting.amplitude},
                              {"period", s.fretting.period}, {"cycles", s.fretting.cycles},
                              {"steps_per_cycle", s.fretting.steps_per_cycle},
                              {"ramp_steps", s.fretting.ramp_steps}};
  else
    j["input"]["file"] = s.load_csv;
  j["outcome"] = std::string(r.inconclusive ? "inconclusive" : to_string(r.outcome));
  j["message"] = r.message;
  j["steps"] = r.steps;
  j["n_points"] = sys.n_points();
  const auto& fs = r.final_state;
  j["final"] = {{"t", fs.t}, {"P_T", vec(fs.P_T)}, {"P_N", vec(fs.P_N)}, {"g", vec(fs.g)},
                {"w_w", vec(fs.w_w)}, {"w_Ti", vec(fs.w_Ti)}};
  j["final_wear_depth"] = vec(fs.w_w);
  j["wear_integral"] = vec(r.wear_integral);
  j["total_slip"] = vec(r.total_slip);
  nlohmann::json wpc = nlohmann::json::array();
  for (const auto& w : r.wear_per_cycle) wpc.push_back(vec(w));
  j["wear_per_cycle"] = wpc;
  j["energy"] = {{"external_work", r.external_work}, {"stored", r.stored_energy},
                 {"dissipation", vec(r.dissipation)}, {"work_abs", r.work_abs},
                 {"balance_error_rel", r.energy_error},
                 {"min_step_dissipation_rel", vec(r.min_step_dissipation)}};
  j["branch_points"] = {{"count", r.branch_steps},
                        {"rule", std::string(to_string(s.opt.branch_rule))}};
  j["incomplete_steps"] = r.incomplete_steps;
  j["complete"] = r.incomplete_steps == 0;
  j["max_step_residual"] = r.max_residual;
  if (s.opt.heat.enabled)
    j["temperature"] = {{"final", vec(fs.temperature)}, {"max", vec(r.max_temperature)}};
  return j;
}

nlohmann::json fretting_3d_summary_json(const Fretting3dResult& r, const EllipticOrbit& orbit,
                                        const Fretting3dOptions& o, const std::string& system,
                                        const std::string& name) {
  const ContactParameters3d& p = o.params;
  nlohmann::json j;
  j["dim"] = 3;
  nlohmann::json A = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) A.push_back({p.A(i, 0), p.A(i, 1), p.A(i, 2)});
  j["input"] = {
      {"system", system},
      {"name", name},
      {"point", {{"A", A}, {"mu", p.mu}, {"C_T", p.C_T}, {"k_a", p.k_a}, {"P_s", p.P_s},
                 {"alpha", pair(p.alpha)}}},
      {"wear", {{"law", std::string(to_string(o.wear.law))}, {"k_M", o.wear.k_M}}},
      {"orbit", {{"F_N", orbit.F_N}, {"a_X", orbit.a_X}, {"a_Y", orbit.a_Y},
                 {"angle", orbit.angle}, {"period", orbit.period}, {"cycles", orbit.cycles},
                 {"steps_per_cycle", orbit.steps_per_cycle}, {"ramp_steps", orbit.ramp_steps},
                 {"lead_steps", orbit.lead()}}},
      {"branch_rule", std::string(to_string(o.branch_rule))},
      {"every", o.record_every}};
  j.update(run_totals(r, fretting_3d_sample_json(r.final_state)));
  j["total_lambda"] = r.total_lambda;
  j["wear_X_per_cycle"] = r.wear_X_per_cycle;
  j["wear_Y_per_cycle"] = r.wear_Y_per_cycle;
  j["dissipation"] = r.dissipation;
  j["min_step_dissipation_rel"] = r.min_step_dissipation;
  j["branch_points"] = {{"count", r.branch_steps},
                        {"rule", std::string(to_string(o.branch_rule))}};
  j["incomplete_steps"] = r.incomplete_steps;
  j["local_steps"] = r.local_steps;
  j["enumeration_missed"] = r.enumeration_missed;
  j["complete"] = r.incomplete_steps == 0 && r.outcome != Fretting3dResult::Outcome::kAmbiguous;
  j["max_step_residual"] = r.max_residual;
  return j;
}

void write_json_file(const std::string& path, const nlohmann::json& j) {
  std::ofstream f = open_output(path);
  f << j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  finish_output(f, path);
}

}  // namespace cpkit::rate
