// The quasi-static simulation of one point (docs/simulation.md) and its load histories
// (fretting, ramp); the simulation's time series comes back as numpy arrays.
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"

namespace cpkit::py {
namespace {

rate::HeatOptions heat_from(const pyb::object& heat) {
  rate::HeatOptions h;
  if (heat.is_none()) return h;
  const pyb::dict d = heat.cast<pyb::dict>();
  h.enabled = true;
  for (const auto& kv : d) {
    const std::string key = pyb::str(kv.first);
    if (key == "heat_capacity") h.heat_capacity = finite_number(kv.second, "heat.heat_capacity");
    else if (key == "T_ref") h.T_ref = finite_number(kv.second, "heat.T_ref");
    else if (key == "T_initial") h.T_initial = finite_number(kv.second, "heat.T_initial");
    else if (key == "T_body" || key == "conductance") {
      const auto v = kv.second.cast<std::vector<double>>();
      if (v.size() != 2) throw InputError("heat." + key + " must hold two numbers (bodies 1, 2)");
      double* dst = key == "T_body" ? h.T_body : h.conductance;
      dst[0] = v[0];
      dst[1] = v[1];
    } else {
      throw InputError("heat: unknown key '" + key +
                       "' (valid: heat_capacity, T_ref, T_initial, T_body, conductance)");
    }
  }
  return h;
}

pyb::dict simulate(const pyb::object& params, const Vec& t, const Vec& F_T, const Vec& F_N,
                   double period, double cycle_start, const std::string& wear_law, double k_M,
                   const pyb::object& heat, const std::string& branch_rule, double tol,
                   int record_every) {
  if (t.size() != F_T.size() || t.size() != F_N.size())
    throw InputError("load history: t, F_T and F_N must have the same length (got " +
                     std::to_string(t.size()) + ", " + std::to_string(F_T.size()) + ", " +
                     std::to_string(F_N.size()) + ")");
  // The history and the recorded series (one sample per step at record_every = 1).
  check_memory(static_cast<double>(t.size()) * (sizeof(rate::LoadPoint) + sizeof(rate::SimulationSample)),
               "a simulation of " + std::to_string(t.size()) + " load points");
  rate::LoadHistory h;
  h.period = period;
  h.cycle_start = cycle_start;
  for (Eigen::Index i = 0; i < t.size(); ++i) h.points.push_back({t[i], F_T[i], F_N[i]});
  throw_if_invalid(h.validate(), "load history");
  rate::SimulationOptions o;
  o.params = parameters_from(params);
  o.wear = wear_from(wear_law, k_M);
  o.heat = heat_from(heat);
  const auto br = rate::branch_rule_from_string(branch_rule);
  if (!br) throw InputError("branch_rule must be 'closest' or 'stop', got '" + branch_rule + "'");
  o.branch_rule = *br;
  o.tol = tol;
  o.record_every = record_every;
  throw_if_invalid(o.validate(), "simulation");
  rate::SimulationResult r = without_gil([&] { return rate::simulate(h, o); });
  using S = rate::SimulationSample;
  const auto& s = r.series;
  pyb::dict series;
  series["step"] = column(s, [](const S& x) { return static_cast<double>(x.step); });
  series["t"] = column(s, [](const S& x) { return x.t; });
  series["F_T"] = column(s, [](const S& x) { return x.F_T; });
  series["F_N"] = column(s, [](const S& x) { return x.F_N; });
  series["P_T"] = column(s, [](const S& x) { return x.P_T; });
  series["P_N"] = column(s, [](const S& x) { return x.P_N; });
  series["w_T"] = column(s, [](const S& x) { return x.w_T; });
  series["w_N"] = column(s, [](const S& x) { return x.w_N; });
  series["w_w"] = column(s, [](const S& x) { return x.w_w; });
  series["w_Ti"] = column(s, [](const S& x) { return x.w_Ti; });
  series["g"] = column(s, [](const S& x) { return x.g; });
  series["count"] = column(s, [](const S& x) { return static_cast<double>(x.count); });
  series["dissipation"] = column(s, [](const S& x) { return x.dissipation; });
  series["dissipation_total"] = column(s, [](const S& x) { return x.dissipation_total; });
  series["work_total"] = column(s, [](const S& x) { return x.work_total; });
  series["stored"] = column(s, [](const S& x) { return x.stored; });
  series["temperature"] = column(s, [](const S& x) { return x.temperature; });
  pyb::list states, types;
  for (const auto& x : s) {
    states.append(std::string(rate::to_string(x.state)));
    types.append(std::string(rate::to_string(x.type)));
  }
  series["state"] = states;
  series["type"] = types;
  pyb::dict d;
  d["series"] = series;
  d["outcome"] = std::string(rate::to_string(r.outcome));
  d["message"] = r.message;
  d["steps"] = r.steps;
  d["branch_steps"] = r.branch_steps;
  d["wear_depth"] = r.wear_depth;
  d["wear_integral"] = r.wear_integral;
  d["total_slip"] = r.total_slip;
  d["slip_per_cycle"] = r.slip_per_cycle;
  d["wear_per_cycle"] = r.wear_per_cycle;
  d["external_work"] = r.external_work;
  d["stored_energy"] = r.stored_energy;
  d["dissipation"] = r.dissipation;
  d["energy_error"] = r.energy_error;
  d["min_step_dissipation"] = r.min_step_dissipation;
  d["thermal_dissipation"] = r.thermal_dissipation;
  d["max_temperature"] = r.max_temperature;
  d["max_residual"] = r.max_residual;
  return d;
}

pyb::dict history_arrays(const rate::LoadHistory& h) {
  Vec t(static_cast<Eigen::Index>(h.points.size())), ft(t.size()), fn(t.size());
  for (std::size_t i = 0; i < h.points.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    t[k] = h.points[i].t;
    ft[k] = h.points[i].F_T;
    fn[k] = h.points[i].F_N;
  }
  pyb::dict d;
  d["t"] = to_numpy(t);
  d["F_T"] = to_numpy(ft);
  d["F_N"] = to_numpy(fn);
  d["period"] = h.period;
  d["cycle_start"] = h.cycle_start;
  return d;
}

}  // namespace

void bind_simulation(pyb::module_& m) {
  m.def("simulate", &simulate);
  m.def("fretting_history", [](double F_N, double amplitude, double period, int cycles,
                               int steps_per_cycle, int ramp_steps) {
    rate::FrettingCycle c{F_N, amplitude, period, cycles, steps_per_cycle, ramp_steps};
    throw_if_invalid(c.validate(), "fretting");
    check_memory((static_cast<double>(cycles) * steps_per_cycle + ramp_steps) * 3 * sizeof(double),
                 "a fretting history of " + std::to_string(cycles) + " x " +
                     std::to_string(steps_per_cycle) + " steps");
    return history_arrays(rate::fretting_history(c));
  });
  m.def("ramp_history", [](double F_T0, double F_N0, double F_T1, double F_N1, double duration,
                           int steps) {
    rate::LoadRamp r{F_T0, F_N0, F_T1, F_N1, duration, steps};
    throw_if_invalid(r.validate(), "ramp");
    check_memory(static_cast<double>(steps) * 3 * sizeof(double),
                 "a ramp of " + std::to_string(steps) + " steps");
    return history_arrays(rate::ramp_history(r));
  });
}

}  // namespace cpkit::py
