#include "simulate_system.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"
#include "simulation_outputs.hpp"

namespace cpkit::cli {
namespace {

/// A csv load for N points: rows t, F_T1, F_N1, ..., F_TN, F_NN ('#' comments, optional header).
std::vector<rate::SystemLoadPoint> read_system_csv(const std::string& path, int N) {
  return rate::parse_system_load_csv(
      rate::read_bounded(path, rate::kMaxLoadCsvBytes, "load history"), path, N);
}

std::vector<double> vec(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

}  // namespace

int run_system_simulation(const rate::SimulateSettings& s, const rate::SystemFile& file,
                          bool print_json_summary) {
  const rate::ContactSystem sys = rate::parse_contact_system(file);
  const int N = sys.n_points();
  rate::SystemLoadSource load;
  std::vector<rate::SystemLoadPoint> stored;
  if (s.load_type == "fretting") {
    if (!sys.pattern1 || !sys.pattern2)
      throw InputError("system '" + s.system + "' has no patterns: the fretting cycle is "
                       "applied through them (F = F_T(t) e1 + F_N(t) e2); give patterns or a csv load");
    load = rate::system_fretting_source(s.fretting, *sys.pattern1, *sys.pattern2);
  } else {
    stored = read_system_csv(s.load_csv, N);
    rate::check_simulation_steps(static_cast<std::int64_t>(stored.size()), true, "the rows of the CSV");
    load = rate::system_history_source(stored, s.csv_period);
  }
  rate::SystemSimulationOptions o;
  o.heat = s.opt.heat;
  o.branch_rule = s.opt.branch_rule;
  o.tol = s.opt.tol;
  std::string csv = s.csv;
  if (csv.empty() && !s.plot.empty()) csv = s.plot + ".csv";
  std::ofstream f;
  if (!csv.empty()) {
    f = open_output(csv);
    f.precision(12);
    f << "step,t";
    for (int i = 1; i <= N; ++i)
      for (const char* c : {"F_T", "F_N", "P_T", "P_N", "w_T", "w_N", "w_w", "w_Ti", "g", "state",
                            "type", "temperature"})
        f << ',' << c << '_' << i;
    f << ",count,complete,dissipation_total,work_total,stored\n";
    o.record_every = s.every;
    o.on_sample = [&f, N](const rate::SystemSimulationSample& x) {
      f << x.step << ',' << x.t;
      for (int i = 0; i < N; ++i)
        f << ',' << x.F[2 * i] << ',' << x.F[2 * i + 1] << ',' << x.P_T[i] << ',' << x.P_N[i]
          << ',' << x.w[2 * i] << ',' << x.w[2 * i + 1] << ',' << x.w_w[i] << ',' << x.w_Ti[i]
          << ',' << x.g[i] << ',' << rate::to_string(x.state[static_cast<std::size_t>(i)]) << ','
          << rate::to_string(x.type[static_cast<std::size_t>(i)]) << ',' << x.temperature[i];
      f << ',' << x.count << ',' << (x.complete ? 1 : 0) << ',' << x.dissipation_total << ','
        << x.work_total << ',' << x.stored << '\n';
    };
  } else {
    o.record_every = 0;
  }
  const rate::SystemSimulationResult r = rate::simulate_system(sys, load, o);
  if (f.is_open()) {
    f.flush();
    if (!f) throw InputError("error writing '" + csv + "' (disk full or not writable?)");
  }
  nlohmann::json j;
  j["cpkit_version"] = CPKIT_VERSION;
  j["input"] = {{"system", s.system}, {"name", sys.name}, {"load", s.load_type}};
  if (s.load_type == "fretting")
    j["input"]["fretting"] = {{"F_N", s.fretting.F_N}, {"amplitude", s.fretting.amplitude},
                              {"period", s.fretting.period}, {"cycles", s.fretting.cycles},
                              {"steps_per_cycle", s.fretting.steps_per_cycle},
                              {"ramp_steps", s.fretting.ramp_steps}};
  else
    j["input"]["file"] = s.load_csv;
  j["outcome"] = std::string(r.inconclusive ? "inconclusive" : rate::to_string(r.outcome));
  j["message"] = r.message;
  j["steps"] = r.steps;
  j["n_points"] = N;
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
                        {"rule", std::string(rate::to_string(s.opt.branch_rule))}};
  j["incomplete_steps"] = r.incomplete_steps;
  j["complete"] = r.incomplete_steps == 0;
  j["max_step_residual"] = r.max_residual;
  if (s.opt.heat.enabled)
    j["temperature"] = {{"final", vec(fs.temperature)}, {"max", vec(r.max_temperature)}};
  std::string summary = s.summary;
  if (summary.empty() && !s.plot.empty()) summary = s.plot + ".json";
  if (!summary.empty()) {
    std::ofstream sf = open_output(summary);
    sf << json_text(j) << '\n';
    sf.flush();
    if (!sf) throw InputError("error writing '" + summary + "' (disk full or not writable?)");
  }
  if (print_json_summary) {
    print_json(j);
  } else {
    std::cout << "simulate (" << N << " points): " << j["outcome"].get<std::string>() << " after "
              << r.steps << " steps\n  " << r.message << "\n  wear depth per point:";
    for (int i = 0; i < N; ++i) std::cout << ' ' << fs.w_w[i];
    std::cout << "\n  Archard integral per point:";
    for (int i = 0; i < N; ++i) std::cout << ' ' << r.wear_integral[i];
    std::cout << "\n  energy balance relative error " << r.energy_error << ", branch points "
              << r.branch_steps << ", steps not proved complete " << r.incomplete_steps << "\n";
  }
  std::vector<std::string> written;  // named at the end: the user sees what the run produced
  if (!csv.empty()) written.push_back(csv);
  if (!summary.empty()) written.push_back(summary);
  const bool plot_failed =
      !s.plot.empty() && !draw_simulation_figures("cpkit_plot_system_simulation.py", csv, summary,
                                                  s.plot, {"_wear", "_slip"}, written);
  for (const auto& w : written) std::cerr << "cpkit simulate: wrote " << w << '\n';
  // A requested picture that could not be drawn is a failure (exit 4), as for one point.
  if (plot_failed) return kExitInternal;
  if (r.outcome == rate::SimulationResult::Outcome::kCompleted) return kExitOk;
  return r.inconclusive ? kExitInconclusive : kExitNoSolution;
}

}  // namespace cpkit::cli
