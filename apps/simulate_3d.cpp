// `cpkit simulate --system FILE` with a "dim": 3 file (simulate_3d.hpp).
#include "simulate_3d.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <iostream>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"
#include "simulate_config.hpp"
#include "simulation_outputs.hpp"

namespace cpkit::cli {

std::string Simulate3dArgs::first_given() const {
  if (!orbit.empty()) return "--orbit";
  if (angle_given) return "--orbit-angle";
  if (lead_given) return "--lead-steps";
  return {};
}

void add_simulate_3d_options(CLI::App* cmd, Simulate3dArgs& a) {
  cmd->add_option("--orbit", a.orbit,
                  "dim 3: half-axes aX aY of the elliptic tangential load orbit "
                  "F_T = R(angle) (aX cos, aY sin) (aY < 0: clockwise)")
      ->expected(2);
  cmd->add_option_function<double>(
      "--orbit-angle", [&a](const double& v) { a.orbit_angle = v; a.angle_given = true; },
      "dim 3: rotation of the orbit in the tangential plane (rad, default 0)");
  cmd->add_option_function<int>(
      "--lead-steps", [&a](const int& v) { a.lead_steps = v; a.lead_given = true; },
      "dim 3: steps of the tangential lead-in from 0 to the orbit's start (default "
      "steps-per-cycle / 4)");
}

namespace {

int count_option(const Simulate3dCommon& c, const char* key, int dflt) {
  const auto it = c.num.find(key);
  if (it == c.num.end()) return dflt;
  const double d = it->second;
  if (!(d == std::floor(d)) || d < 1 || d > INT_MAX)
    throw InputError(std::string("--") + key + " must be an integer in [1, " +
                     std::to_string(INT_MAX) + "], got " + num_text(d));
  return static_cast<int>(d);
}

using Pair = std::vector<double>;
Pair pair(const Eigen::Vector2d& v) { return {v(0), v(1)}; }

nlohmann::json sample_json(const rate3d::Fretting3dSample& s) {
  return {{"step", s.step}, {"t", s.t}, {"F_T", pair(s.F_T)}, {"F_N", s.F_N},
          {"P_T", pair(s.P_T)}, {"P_N", s.P_N}, {"g", s.g}, {"w_T", pair(s.w_T)},
          {"w_N", s.w_N}, {"w_Ti", pair(s.w_Ti)}, {"w_w", s.w_w},
          {"type", std::string(rate3d::to_string(s.type))}};
}

}  // namespace

int run_simulate_3d(const Simulate3dArgs& a3, const Simulate3dCommon& c) {
  const rate3d::ContactSystem3d sys = rate3d::parse_contact_system_3d(c.file);
  if (sys.n_points() != 1)
    throw InputError(c.system + ": " + std::to_string(sys.n_points()) +
                     " points; the 3-D simulation (fretting with an elliptic load orbit) is for "
                     "one point (\"dim\": 3 with one point)");
  if (!c.other_given.empty())
    throw InputError(c.other_given.front() +
                     " has no effect with a \"dim\": 3 system (the file gives the point's "
                     "parameters; the load is the elliptic orbit: --orbit, --orbit-angle, "
                     "--lead-steps, --F_N, --period, --cycles, --steps-per-cycle, --ramp-steps)");
  if (sys.points[0].state.state != 'b')
    throw InputError(c.system + ": the simulation starts unloaded and grazing (state b, "
                     "P = 0, F = 0); the file gives state " +
                     std::string(1, sys.points[0].state.state));
  if (a3.orbit.size() != 2)
    throw InputError("a \"dim\": 3 simulation needs --orbit aX aY (the half-axes of the "
                     "tangential load orbit)");
  rate3d::EllipticOrbit orbit;
  orbit.a_X = a3.orbit[0];
  orbit.a_Y = a3.orbit[1];
  orbit.angle = a3.orbit_angle;
  orbit.lead_steps = a3.lead_steps;
  if (a3.lead_given && a3.lead_steps < 0)
    throw InputError("--lead-steps must be >= 0, got " + std::to_string(a3.lead_steps));
  auto num = [&](const char* key, double& dst) {
    if (const auto it = c.num.find(key); it != c.num.end()) dst = it->second;
  };
  num("F_N", orbit.F_N);
  num("period", orbit.period);
  orbit.cycles = count_option(c, "cycles", orbit.cycles);
  orbit.steps_per_cycle = count_option(c, "steps-per-cycle", orbit.steps_per_cycle);
  orbit.ramp_steps = count_option(c, "ramp-steps", orbit.ramp_steps);
  throw_if_invalid(orbit.validate(), "orbit");
  // Capped as the N-point runs (kMaxSystemSimulationSteps: 0.2 ms a step).
  check_simulation_steps(static_cast<std::int64_t>(std::min<std::size_t>(orbit.size(), INT64_MAX)),
                         true, "lead_steps + ramp_steps + cycles x steps_per_cycle");

  rate3d::Fretting3dOptions o;
  o.params = sys.point_parameters(0);
  if (!c.wear_law.empty()) {
    const auto law = rate::wear_law_from_string(c.wear_law);
    if (!law) throw InputError("--wear-law must be archard or mroz, got '" + c.wear_law + "'");
    o.wear.law = *law;
  }
  num("k_M", o.wear.k_M);
  const bool mroz = o.wear.law == rate::WearLaw::kMrozStupkiewicz;
  if (!mroz && c.num.count("k_M"))
    throw InputError("--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
  if (mroz && !(o.wear.k_M > 0))
    throw InputError("the wear law mroz needs --k_M > 0; for no wear use archard with k_a = 0");
  if (mroz && o.params.k_a != 0)
    throw InputError(c.system + ": k_a has no effect with the wear law mroz (its constant is "
                     "--k_M); set k_a to 0 in the file");
  if (!c.branch_rule.empty()) {
    const auto rule = rate::branch_rule_from_string(c.branch_rule);
    if (!rule)
      throw InputError("--branch-rule must be closest or stop, got '" + c.branch_rule + "'");
    o.branch_rule = *rule;
  }
  if (c.every_given && c.every < 0) throw InputError("--every must be >= 0");
  throw_if_invalid(o.validate(), c.system);

  std::string csv = c.csv;
  if (csv.empty() && !c.plot.empty()) csv = c.plot + ".csv";
  std::string summary = c.summary;
  if (summary.empty() && !c.plot.empty()) summary = c.plot + ".json";
  std::ofstream f;
  if (!csv.empty()) {
    f = open_output(csv);
    f.precision(12);
    f << "step,t,F_TX,F_TY,F_N,P_TX,P_TY,P_N,g,w_TX,w_TY,w_N,w_TiX,w_TiY,Dw_TiX,Dw_TiY,lambda,"
         "Dw_w,w_w,type,count,complete,dissipation,cycle\n";
    o.record_every = c.every_given ? c.every : 1;
    o.on_sample = [&f](const rate3d::Fretting3dSample& s) {
      f << s.step << ',' << s.t << ',' << s.F_T(0) << ',' << s.F_T(1) << ',' << s.F_N << ','
        << s.P_T(0) << ',' << s.P_T(1) << ',' << s.P_N << ',' << s.g << ',' << s.w_T(0) << ','
        << s.w_T(1) << ',' << s.w_N << ',' << s.w_Ti(0) << ',' << s.w_Ti(1) << ','
        << s.Dw_Ti(0) << ',' << s.Dw_Ti(1) << ',' << s.lambda << ',' << s.Dw_w << ',' << s.w_w
        << ',' << rate3d::to_string(s.type) << ',' << s.count << ',' << (s.complete ? 1 : 0)
        << ',' << s.dissipation << ',' << s.cycle << '\n';
    };
  } else {
    o.record_every = 0;  // summary only: nothing is kept
  }
  const rate3d::Fretting3dResult r = rate3d::simulate_fretting_3d(orbit, o);
  if (f.is_open()) {
    f.flush();
    if (!f) throw InputError("error writing '" + csv + "' (disk full or not writable?)");
  }

  const rate3d::Point3dParameters& p = o.params;
  nlohmann::json j;
  j["cpkit_version"] = CPKIT_VERSION;
  j["dim"] = 3;
  nlohmann::json A = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) A.push_back({p.A(i, 0), p.A(i, 1), p.A(i, 2)});
  j["input"] = {
      {"system", c.system},
      {"name", sys.name},
      {"point", {{"A", A}, {"mu", p.mu}, {"C_T", p.C_T}, {"k_a", p.k_a}, {"P_s", p.P_s},
                 {"alpha", pair(p.alpha)}}},
      {"wear", {{"law", std::string(rate::to_string(o.wear.law))}, {"k_M", o.wear.k_M}}},
      {"orbit", {{"F_N", orbit.F_N}, {"a_X", orbit.a_X}, {"a_Y", orbit.a_Y},
                 {"angle", orbit.angle}, {"period", orbit.period}, {"cycles", orbit.cycles},
                 {"steps_per_cycle", orbit.steps_per_cycle}, {"ramp_steps", orbit.ramp_steps},
                 {"lead_steps", orbit.lead()}}},
      {"branch_rule", std::string(rate::to_string(o.branch_rule))},
      {"every", o.record_every}};
  j["outcome"] = std::string(rate3d::to_string(r.outcome));
  j["message"] = r.message;
  j["steps"] = r.steps;
  j["final"] = sample_json(r.final_state);
  j["final_wear_depth"] = r.wear_depth;
  j["wear_integral"] = r.wear_integral;
  j["total_slip"] = r.total_slip;
  j["total_lambda"] = r.total_lambda;
  j["slip_per_cycle"] = r.slip_per_cycle;
  j["wear_per_cycle"] = r.wear_per_cycle;
  j["wear_X_per_cycle"] = r.wear_X_per_cycle;
  j["wear_Y_per_cycle"] = r.wear_Y_per_cycle;
  j["dissipation"] = r.dissipation;
  j["min_step_dissipation_rel"] = r.min_step_dissipation;
  j["branch_points"] = {{"count", r.branch_steps},
                        {"rule", std::string(rate::to_string(o.branch_rule))}};
  j["incomplete_steps"] = r.incomplete_steps;
  j["local_steps"] = r.local_steps;
  j["enumeration_missed"] = r.enumeration_missed;
  j["complete"] = r.incomplete_steps == 0 &&
                  r.outcome != rate3d::Fretting3dResult::Outcome::kAmbiguous;
  j["max_step_residual"] = r.max_residual;
  j["run"] = run_echo();
  if (!summary.empty()) {
    std::ofstream sf = open_output(summary);
    sf << json_text(j) << '\n';
    sf.flush();
    if (!sf) throw InputError("error writing '" + summary + "' (disk full or not writable?)");
  }
  if (c.json) {
    print_json(j);
  } else {
    std::cout << "simulate (3-D point): " << rate3d::to_string(r.outcome) << " after " << r.steps
              << " steps\n  " << r.message << "\n  wear depth " << r.wear_depth << " ("
              << (mroz ? "Mroz" : "Archard") << " integral " << r.wear_integral
              << "), slip path length " << r.total_slip << "\n";
    if (!r.wear_per_cycle.empty())
      std::cout << "  last cycle: wear " << r.wear_per_cycle.back() << " (by X slip "
                << r.wear_X_per_cycle.back() << ", by Y slip " << r.wear_Y_per_cycle.back()
                << "), slip " << r.slip_per_cycle.back() << "\n";
    std::cout << "  branch points " << r.branch_steps << ", steps not proved complete "
              << r.incomplete_steps << "\n";
    if (r.local_steps > 0)
      std::cout << "  steps solved by the local fallback " << r.local_steps
                << " (the enumeration had claimed none for " << r.enumeration_missed << ")\n";
  }
  std::vector<std::string> written;
  if (!csv.empty()) written.push_back(csv);
  if (!summary.empty()) written.push_back(summary);
  const bool plot_failed =
      !c.plot.empty() && !draw_simulation_figures("cpkit_plot_fretting_3d.py", csv, summary,
                                                  c.plot, {"_orbit", "_wear"}, written);
  for (const auto& w : written) std::cerr << "cpkit simulate: wrote " << w << '\n';
  if (plot_failed) return kExitInternal;
  switch (r.outcome) {
    case rate3d::Fretting3dResult::Outcome::kCompleted: return kExitOk;
    case rate3d::Fretting3dResult::Outcome::kAmbiguous: return kExitInconclusive;
    default: return kExitNoSolution;
  }
}

}  // namespace cpkit::cli
