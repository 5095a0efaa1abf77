// `cpkit simulate`: quasi-static fretting simulation with friction, wear and heat
// (docs/simulation.md; library: cpkit/rate_problem/simulation/simulation.hpp).
//
//   cpkit simulate --config FILE.json [options overriding the file]
//   cpkit simulate --a11 X --a12 X --a22 X --mu X [--C_T X --k_a X --P_s X --criterion 38|35]
//                  [--load fretting|ramp|csv] [--F_N X --amplitude X --cycles N
//                  --steps-per-cycle N --period X --ramp-steps N] [--load-csv FILE]
//                  [--heat --heat-capacity X --T-ref X --T-initial X --T-body T1 T2
//                  --conductance C1 C2] [--branch-rule closest|stop]
//                  [--csv OUT.csv] [--summary OUT.json] [--plot PREFIX] [--every N] [--json]
//   cpkit simulate --system POINT3D.json --orbit aX aY ...   ("dim": 3: run_simulate_3d below)
//
// Exit codes: 0 the run completed, 1 it stopped (no solution, a continuum, a branch point
// with --branch-rule stop, or numerical_failure: values beyond the range of double; the reason
// on stdout/in the summary), 2 bad input (also an output file that cannot be written).
#include <algorithm>
#include <climits>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "model_options.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/report/simulation_csv.hpp"
#include "cpkit/rate_problem/report/simulation_json.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"
#include "cpkit/rate_problem/simulation/simulate_config.hpp"
#include "simulation_outputs.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::cli {
namespace {

// ---- "dim": 3 system files ----
// `cpkit simulate --system FILE` with a "dim": 3 file: fretting of one 3-D point under an
// elliptic tangential load orbit (docs/contact_3d.md, "Fretting with an elliptic load orbit";
// library: cpkit/rate_problem/simulation/fretting_3d.hpp).
//
//   cpkit simulate --system POINT3D.json --orbit aX aY [--orbit-angle RAD] [--lead-steps N]
//                  [--F_N X --period X --cycles N --steps-per-cycle N --ramp-steps N]
//                  [--wear-law archard|mroz --k_M X] [--branch-rule closest|stop]
//                  [--csv OUT.csv] [--summary OUT.json] [--plot PREFIX] [--every N] [--json]
//
// Exit codes: 0 completed, 1 stopped (no solution, a branch point with --branch-rule stop,
// numerical failure), 5 stopped at a step with several solutions whose enumeration is not
// proved complete (ambiguous), 2 bad input (N > 1 points, a start state other than grazing,
// options of the 2-D simulation, bad values), 4 the figures were asked for and are missing.
/// The options only the 3-D run has (registered by add_simulate_3d_options).
struct Simulate3dArgs {
  std::vector<double> orbit;  ///< a_X a_Y
  double orbit_angle = 0;
  bool angle_given = false;
  int lead_steps = -1;
  bool lead_given = false;
  /// The first 3-D option given ("--orbit", ...), or empty.
  std::string first_given() const;
};

/// What the 3-D run takes from the 2-D command's parsed options.
struct Simulate3dCommon {
  std::string system;
  rate::SystemFile file;  ///< the system file, read once (its dim is 3)
  std::map<std::string, double> num;  ///< numeric options given (key without "--")
  std::string wear_law, branch_rule, csv, summary, plot;
  int every = 1;
  bool every_given = false;
  bool json = false;
  /// Options of the 2-D simulation given on the command line (refused with a "dim": 3 file).
  std::vector<std::string> other_given;
};

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

int count_option(const Simulate3dCommon& c, const char* key, int dflt) {
  const auto it = c.num.find(key);
  if (it == c.num.end()) return dflt;
  const double d = it->second;
  if (!(d == std::floor(d)) || d < 1 || d > INT_MAX)
    throw InputError(std::string("--") + key + " must be an integer in [1, " +
                     std::to_string(INT_MAX) + "], got " + num_text(d));
  return static_cast<int>(d);
}

int run_simulate_3d(const Simulate3dArgs& a3, const Simulate3dCommon& c) {
  const rate::ContactSystem3d sys = rate::parse_contact_system_3d(c.file);
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
  rate::EllipticOrbit orbit;
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
  rate::check_simulation_steps(static_cast<std::int64_t>(std::min<std::size_t>(orbit.size(), INT64_MAX)),
                         true, "lead_steps + ramp_steps + cycles x steps_per_cycle");

  rate::Fretting3dOptions o;
  o.params = sys.point_parameters(0);
  if (!c.wear_law.empty()) {
    o.wear.law = wear_law_option(c.wear_law);
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
  if (!c.branch_rule.empty()) o.branch_rule = branch_rule_option(c.branch_rule);
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
    f << rate::fretting_3d_csv_header();
    o.record_every = c.every_given ? c.every : 1;
    o.on_sample = [&f](const rate::Fretting3dSample& x) { rate::write_fretting_3d_csv_row(f, x); };
  } else {
    o.record_every = 0;  // summary only: nothing is kept
  }
  const rate::Fretting3dResult r = rate::simulate_fretting_3d(orbit, o);
  if (f.is_open()) finish_output(f, csv);

  nlohmann::json j = rate::fretting_3d_summary_json(r, orbit, o, c.system, sys.name);
  j["cpkit_version"] = CPKIT_VERSION;
  j["run"] = run_echo();
  if (!summary.empty()) write_json_file(summary, j);
  if (c.json) {
    print_json(j);
  } else {
    std::cout << "simulate (3-D point): " << rate::to_string(r.outcome) << " after " << r.steps
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
  if (!draw_and_name_outputs("cpkit_plot_fretting_3d.py", csv, summary, c.plot,
                             {"_orbit", "_wear"}))
    return kExitInternal;  // the figures were asked for and are missing
  switch (r.outcome) {
    case rate::Fretting3dResult::Outcome::kCompleted: return kExitOk;
    case rate::Fretting3dResult::Outcome::kAmbiguous: return kExitInconclusive;
    default: return kExitNoSolution;
  }
}


// N-point system files (docs/simulation.md, "N points"): the run of rate::simulate_system, its
// CSV streamed row by row, its JSON summary and figures.
/// A csv load for N points: rows t, F_T1, F_N1, ..., F_TN, F_NN ('#' comments, optional header).
std::vector<rate::SystemLoadPoint> read_system_csv(const std::string& path, int N) {
  return rate::parse_system_load_csv(
      rate::read_bounded(path, rate::kMaxLoadCsvBytes, "load history"), path, N);
}

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
    f << rate::system_simulation_csv_header(N);
    o.record_every = s.every;
    o.on_sample = [&f](const rate::SystemSimulationSample& x) {
      rate::write_system_simulation_csv_row(f, x);
    };
  } else {
    o.record_every = 0;
  }
  const rate::SystemSimulationResult r = rate::simulate_system(sys, load, o);
  if (f.is_open()) finish_output(f, csv);
  nlohmann::json j = rate::system_simulation_summary_json(r, s, sys);
  j["cpkit_version"] = CPKIT_VERSION;
  const auto& fs = r.final_state;
  std::string summary = s.summary;
  if (summary.empty() && !s.plot.empty()) summary = s.plot + ".json";
  if (!summary.empty()) write_json_file(summary, j);
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
  // A requested picture that could not be drawn is a failure (exit 4), as for one point.
  if (!draw_and_name_outputs("cpkit_plot_system_simulation.py", csv, summary, s.plot,
                             {"_wear", "_slip"}))
    return kExitInternal;
  if (r.outcome == rate::SimulationResult::Outcome::kCompleted) return kExitOk;
  return r.inconclusive ? kExitInconclusive : kExitNoSolution;
}



struct SimArgs {
  std::string config;
  std::map<std::string, double> num;  // numeric options given on the command line
  std::string criterion, wear_law, load, load_csv, branch_rule, csv, summary, plot, system;
  std::vector<double> T_body, conductance;
  bool heat = false, json = false;
  int every = 1;
  bool every_given = false;
  Simulate3dArgs three_d;  // --orbit ...: a "dim": 3 system (run_simulate_3d)
};

using Settings = rate::SimulateSettings;

void apply_args(const SimArgs& a, Settings& s) {
  auto& P = s.opt.params;
  auto num = [&](const char* key, double& dst) {
    const auto it = a.num.find(key);
    if (it != a.num.end()) {
      dst = it->second;
      return true;
    }
    return false;
  };
  if (num("a11", P.a11)) s.have[0] = true;
  if (num("a12", P.a12)) s.have[1] = true;
  if (num("a22", P.a22)) s.have[2] = true;
  if (num("mu", P.mu)) s.have[3] = true;
  num("C_T", P.C_T);
  num("k_a", P.k_a);
  num("P_s", P.P_s);
  num("k_M", s.opt.wear.k_M);
  num("F_N", s.fretting.F_N);
  num("amplitude", s.fretting.amplitude);
  if (num("period", s.fretting.period)) s.csv_period = s.fretting.period;
  // Counts are read as numbers (1e6 is accepted) and must be integers that fit an int; their
  // ranges and the run's total size are checked by validate_simulate_settings.
  auto count = [&](const char* key, int& dst) {
    double d;
    if (!num(key, d)) return;
    if (!(d == std::floor(d)) || d < INT_MIN || d > INT_MAX)
      throw InputError(std::string("--") + key + " must be an integer in [" +
                       std::to_string(INT_MIN) + ", " + std::to_string(INT_MAX) + "], got " +
                       num_text(d));
    dst = static_cast<int>(d);
  };
  count("cycles", s.fretting.cycles);
  count("steps-per-cycle", s.fretting.steps_per_cycle);
  count("ramp-steps", s.fretting.ramp_steps);
  num("F_T0", s.ramp.F_T0);
  num("F_N0", s.ramp.F_N0);
  num("F_T1", s.ramp.F_T1);
  num("F_N1", s.ramp.F_N1);
  num("duration", s.ramp.duration);
  count("steps", s.ramp.steps);
  num("heat-capacity", s.opt.heat.heat_capacity);
  num("T-ref", s.opt.heat.T_ref);
  num("T-initial", s.opt.heat.T_initial);
  if (!a.T_body.empty()) {
    s.opt.heat.T_body[0] = a.T_body[0];
    s.opt.heat.T_body[1] = a.T_body[1];
  }
  if (!a.conductance.empty()) {
    s.opt.heat.conductance[0] = a.conductance[0];
    s.opt.heat.conductance[1] = a.conductance[1];
  }
  if (a.heat) s.opt.heat.enabled = true;
  if (!a.criterion.empty()) s.opt.params.criterion = criterion_option(a.criterion);
  if (!a.wear_law.empty()) s.opt.wear.law = wear_law_option(a.wear_law);
  if (!a.branch_rule.empty()) s.opt.branch_rule = branch_rule_option(a.branch_rule);
  if (!a.load.empty()) s.load_type = a.load;
  if (!a.load_csv.empty()) {
    s.load_csv = a.load_csv;
    if (a.load.empty()) s.load_type = "csv";
  }
  if (!a.csv.empty()) s.csv = a.csv;
  if (!a.summary.empty()) s.summary = a.summary;
  if (!a.plot.empty()) s.plot = a.plot;
  if (a.every_given) s.every = a.every;
  if (!a.system.empty()) s.system = a.system;
}

/// The time series, written row by row as the simulation produces it (never held in memory).
class CsvSeries {
 public:
  explicit CsvSeries(const std::string& path) : path_(path), f_(open_output(path)) {
    f_.precision(12);
    f_ << rate::simulation_csv_header();
  }
  void write(const rate::SimulationSample& s) { rate::write_simulation_csv_row(f_, s); }
  void close() { finish_output(f_, path_); }

 private:
  std::string path_;
  std::ofstream f_;
};

nlohmann::json summary_json(const rate::SimulationResult& r, const Settings& s) {
  nlohmann::json j = rate::simulation_summary_json(r, s);
  j["run"] = run_echo();  // version and command line
  return j;
}

/// A "dim": 3 system: one 3-D point under an elliptic load orbit (run_simulate_3d); the options
/// of the 2-D simulation are passed on to be refused there.
int run_3d(const SimArgs& a, const rate::SystemFile& file) {
  Simulate3dCommon c;
  c.system = a.system;
  c.file = file;
  c.num = a.num;
  c.wear_law = a.wear_law;
  c.branch_rule = a.branch_rule;
  c.csv = a.csv;
  c.summary = a.summary;
  c.plot = a.plot;
  c.every = a.every;
  c.every_given = a.every_given;
  c.json = a.json;
  static const char* const used[] = {"F_N", "period", "cycles", "steps-per-cycle", "ramp-steps",
                                     "k_M"};
  for (const auto& kv : a.num)
    if (std::find(std::begin(used), std::end(used), kv.first) == std::end(used))
      c.other_given.push_back("--" + kv.first);
  if (!a.config.empty()) c.other_given.push_back("--config");
  if (!a.criterion.empty()) c.other_given.push_back("--criterion");
  if (!a.load.empty()) c.other_given.push_back("--load");
  if (!a.load_csv.empty()) c.other_given.push_back("--load-csv");
  if (a.heat) c.other_given.push_back("--heat");
  if (!a.T_body.empty()) c.other_given.push_back("--T-body");
  if (!a.conductance.empty()) c.other_given.push_back("--conductance");
  return run_simulate_3d(a.three_d, c);
}

int run(const SimArgs& a) {
  // No output may be an input (issue 24, item 8): refused before anything is read or written.
  refuse_outputs_over_inputs("cpkit simulate", simulation_output_files(a.csv, a.summary, a.plot),
                             {{"--config", a.config}, {"--system", a.system},
                              {"--load-csv", a.load_csv}});
  // A system file is read once (a pipe can be read only once) and dispatched on its dimension.
  std::optional<rate::SystemFile> file;
  if (!a.system.empty()) {
    file = rate::read_system_file(a.system);
    if (file->dim == 3) return run_3d(a, *file);
  }
  if (const std::string o = a.three_d.first_given(); !o.empty())
    throw InputError(o + " needs a \"dim\": 3 system file (--system FILE; docs/contact_3d.md)");
  Settings s;
  if (!a.config.empty()) rate::read_simulate_config(a.config, s);
  apply_args(a, s);
  // The config names its own system, load and outputs: the same check on what it gives.
  refuse_outputs_over_inputs("cpkit simulate", simulation_output_files(s.csv, s.summary, s.plot),
                             {{"--config", a.config}, {"system", s.system},
                              {"load csv", s.load_csv}});
  if (!s.system.empty() && !file) file = rate::read_system_file(s.system);  // the config's
  if (file && file->dim == 3)
    throw InputError("the config's system '" + s.system + "' has \"dim\": 3: simulate it from the "
                     "command line (cpkit simulate --system FILE --orbit aX aY ...)");
  // Command-line options of another load type, or heat options without --heat, would have no
  // effect: errors, never silence.
  auto only_with = [&](std::initializer_list<const char*> keys, const std::string& needs) {
    for (const char* k : keys)
      if (a.num.count(k))
        throw InputError(std::string("--") + k + " has no effect here: it needs " + needs);
  };
  if (s.load_type != "fretting")
    only_with({"F_N", "amplitude", "cycles", "steps-per-cycle", "ramp-steps"},
              "--load fretting (the load is " + s.load_type + ")");
  if (s.load_type != "ramp")
    only_with({"F_T0", "F_N0", "F_T1", "F_N1", "duration", "steps"},
              "--load ramp (the load is " + s.load_type + ")");
  if (s.load_type == "ramp")
    only_with({"period"}, "--load fretting or csv (the load is ramp)");
  if (!s.opt.heat.enabled) {
    only_with({"heat-capacity", "T-ref", "T-initial"}, "--heat (or heat.enabled)");
    if (!a.T_body.empty() || !a.conductance.empty())
      throw InputError(std::string(!a.T_body.empty() ? "--T-body" : "--conductance") +
                       " has no effect here: it needs --heat (or heat.enabled)");
  }
  // Wear options that would have no effect are errors (from the command line or the config).
  const bool mroz = s.opt.wear.law == rate::WearLaw::kMrozStupkiewicz;
  if (!mroz && s.opt.wear.k_M != 0)
    throw InputError("k_M (--k_M, wear.k_M) is the Mroz-Stupkiewicz wear constant: it needs the "
                     "wear law mroz (--wear-law mroz, wear.law)");
  if (mroz && s.opt.wear.k_M == 0)
    throw InputError("the wear law mroz needs k_M > 0 (--k_M, wear.k_M); for no wear use the "
                     "default law archard with k_a = 0");
  if (mroz && s.opt.params.k_a != 0)
    throw InputError("k_a (--k_a, parameters.k_a) has no effect with the wear law mroz: its wear "
                     "constant is k_M");
  // Everything is checked (model, load, sizes) before the history is allocated.
  rate::validate_simulate_settings(s);
  if (file) return run_system_simulation(s, *file, a.json);
  std::string csv = s.csv;
  if (csv.empty() && !s.plot.empty()) csv = s.plot + ".csv";
  // The series goes to its file as it is produced; without a file nothing is recorded, so the
  // memory does not grow with the steps (issue 14).
  std::unique_ptr<CsvSeries> series;
  if (!csv.empty()) {
    series = std::make_unique<CsvSeries>(csv);
    s.opt.record_every = s.every;
    s.opt.on_sample = [&series](const rate::SimulationSample& smp) { series->write(smp); };
  } else {
    s.opt.record_every = 0;
  }
  rate::LoadHistory stored;
  const rate::LoadSource load = rate::make_simulate_source(s, stored);
  const rate::SimulationResult r = rate::simulate(load, s.opt);
  if (series) series->close();
  const nlohmann::json sum = summary_json(r, s);
  std::string summary = s.summary;
  if (summary.empty() && !s.plot.empty()) summary = s.plot + ".json";
  if (!summary.empty()) write_json_file(summary, sum);
  if (a.json) {
    print_json(sum);
  } else {
    std::cout << "simulate: " << rate::to_string(r.outcome) << " after " << r.steps
              << " steps\n  " << r.message << "\n"
              << "  final wear depth " << r.wear_depth << " (Archard integral "
              << r.wear_integral << "), total slip " << r.total_slip << "\n"
              << "  energy: work " << r.external_work << " = stored " << r.stored_energy
              << " + dissipation " << r.dissipation << " (relative error " << r.energy_error
              << ")\n  branch points: " << r.branch_steps << "\n";
    if (s.opt.heat.enabled)
      std::cout << "  temperature: final " << r.final_state.temperature << ", max "
                << r.max_temperature << "\n";
  }
  if (!draw_and_name_outputs("cpkit_plot_simulation.py", csv, summary, s.plot,
                             {"_loop", "_wear", "_state"}))
    return kExitInternal;  // the figures were asked for and are missing
  return r.outcome == rate::SimulationResult::Outcome::kCompleted ? kExitOk : kExitNoSolution;
}

}  // namespace

void add_simulate_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<SimArgs>();
  auto* cmd = app.add_subcommand(
      "simulate", "Quasi-static fretting simulation with friction, wear and heat "
                  "(docs/simulation.md)");
  cmd->add_option("--config", a->config, "JSON settings (docs/examples/fretting.json)");
  cmd->add_option("--system", a->system,
                  "N-point system file (docs/file_formats.md): simulate N points (docs/simulation.md)");
  struct NumOpt {
    const char* name;
    const char* help;
  };
  static const NumOpt nums[] = {
      {"a11", "stiffness A11"}, {"a12", "stiffness A12"}, {"a22", "stiffness A22"},
      {"mu", "friction coefficient"}, {"C_T", "tangential compliance"},
      {"k_a", "Archard wear coefficient"}, {"P_s", "hardness"},
      {"k_M", "Mroz-Stupkiewicz wear constant"}, {"F_N", "fretting: normal load"},
      {"amplitude", "fretting: tangential load amplitude"}, {"period", "fretting/csv: period"},
      {"cycles", "fretting: number of cycles"}, {"steps-per-cycle", "fretting: steps per cycle"},
      {"ramp-steps", "fretting: steps of the initial normal-load ramp"},
      {"F_T0", "ramp: initial F_T"}, {"F_N0", "ramp: initial F_N"},
      {"F_T1", "ramp: final F_T"}, {"F_N1", "ramp: final F_N"}, {"duration", "ramp: duration"},
      {"steps", "ramp: steps"}, {"heat-capacity", "heat capacity per area C"},
      {"T-ref", "reference temperature T0"}, {"T-initial", "initial interface temperature"}};
  for (const auto& n : nums) {
    const std::string key = n.name;
    cmd->add_option_function<double>("--" + key, [a, key](const double& v) { a->num[key] = v; },
                                     n.help);
  }
  cmd->add_option("--criterion", a->criterion, "38 (Coulomb, default) or 35 (softening)");
  cmd->add_option("--wear-law", a->wear_law, "archard (default) or mroz");
  cmd->add_option("--load", a->load, "fretting (default), ramp or csv");
  cmd->add_option("--load-csv", a->load_csv, "load history CSV: t, F_T, F_N");
  cmd->add_flag("--heat", a->heat, "compute the interface temperature");
  cmd->add_option("--T-body", a->T_body, "body temperatures T1 T2")->expected(2);
  cmd->add_option("--conductance", a->conductance, "contact conductances c1 c2")->expected(2);
  cmd->add_option("--branch-rule", a->branch_rule, "closest (default) or stop");
  cmd->add_option("--csv", a->csv, "write the time series here");
  cmd->add_option("--summary", a->summary, "write the JSON summary here");
  cmd->add_option("--plot", a->plot, "figures PREFIX_loop/_wear/_state .png/.svg");
  cmd->add_option_function<int>(
      "--every", [a](const int& v) { a->every = v; a->every_given = true; },
      "keep every n-th step in the series (default 1; 0: none)");
  cmd->add_flag("--json", a->json, "print the JSON summary");
  add_simulate_3d_options(cmd, a->three_d);
  cmd->callback([a, &ctx]() { ctx.exit_code = run(*a); });
}

}  // namespace cpkit::cli
