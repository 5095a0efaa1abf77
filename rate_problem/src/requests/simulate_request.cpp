// The run of a `cpkit simulate` request (simulate_request.hpp): the checks in the order the
// program has always made them (so a request with several faults gets the same message), the
// one-point, N-point and 3-D runs, their files and their summaries.
#include "cpkit/rate_problem/requests/simulate_request.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/report/simulation_csv.hpp"
#include "cpkit/rate_problem/report/simulation_json.hpp"
#include "cpkit/rate_problem/report/simulation_text.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {
namespace {

/// A named choice (--criterion, --wear-law, --branch-rule) or InputError "MUST, got 'NAME'".
template <class T>
T choice(const std::optional<T>& value, const char* must, const std::string& name) {
  if (!value) throw InputError(std::string(must) + ", got '" + name + "'");
  return *value;
}

/// A numeric option's name in messages (without "--") and its field.
struct NumberOption {
  const char* name;
  std::optional<double> SimulateNumbers::*field;
};

/// Every numeric option, in the order of their names (the order the 3-D route reports them).
const NumberOption kNumberOptions[] = {
    {"C_T", &SimulateNumbers::C_T},
    {"F_N", &SimulateNumbers::F_N},
    {"F_N0", &SimulateNumbers::F_N0},
    {"F_N1", &SimulateNumbers::F_N1},
    {"F_T0", &SimulateNumbers::F_T0},
    {"F_T1", &SimulateNumbers::F_T1},
    {"P_s", &SimulateNumbers::P_s},
    {"T-initial", &SimulateNumbers::T_initial},
    {"T-ref", &SimulateNumbers::T_ref},
    {"a11", &SimulateNumbers::a11},
    {"a12", &SimulateNumbers::a12},
    {"a22", &SimulateNumbers::a22},
    {"amplitude", &SimulateNumbers::amplitude},
    {"cycles", &SimulateNumbers::cycles},
    {"duration", &SimulateNumbers::duration},
    {"heat-capacity", &SimulateNumbers::heat_capacity},
    {"k_M", &SimulateNumbers::k_M},
    {"k_a", &SimulateNumbers::k_a},
    {"mu", &SimulateNumbers::mu},
    {"period", &SimulateNumbers::period},
    {"ramp-steps", &SimulateNumbers::ramp_steps},
    {"steps", &SimulateNumbers::steps},
    {"steps-per-cycle", &SimulateNumbers::steps_per_cycle}};

/// A count given as a number: an integer in [lo, INT_MAX], else InputError naming the option.
void count_option(const std::optional<double>& d, const char* key, long long lo, int& dst) {
  if (!d) return;
  if (!(*d == std::floor(*d)) || *d < static_cast<double>(lo) || *d > INT_MAX)
    throw InputError(std::string("--") + key + " must be an integer in [" + std::to_string(lo) +
                     ", " + std::to_string(INT_MAX) + "], got " + num_text(*d));
  dst = static_cast<int>(*d);
}

/// The series file, written row by row as the run produces it (never held in memory); without
/// a file nothing is recorded, so the memory does not grow with the steps (issue 14).
class Series {
 public:
  Series(std::string path, const std::string& header) : path_(std::move(path)) {
    if (path_.empty()) return;
    f_ = open_output(path_);
    f_.precision(12);
    f_ << header;
  }
  /// Sends every `every`-th sample of the run (options `o`) to the file as `row` writes it.
  template <class Options, class Sample>
  void attach(Options& o, int every, void (*row)(std::ostream&, const Sample&)) {
    o.record_every = path_.empty() ? 0 : every;
    if (!path_.empty()) o.on_sample = [this, row](const Sample& x) { row(f_, x); };
  }
  void close() {
    if (f_.is_open()) finish_output(f_, path_);
  }

 private:
  std::string path_;
  std::ofstream f_;
};

/// The files of a run (--csv and --summary default to PLOT.csv and PLOT.json with --plot) and
/// its figures.
SimulateOutcome outputs(const std::string& csv, const std::string& summary,
                        const std::string& plot, const char* script,
                        std::vector<std::string> figures) {
  SimulateOutcome o;
  o.csv = csv.empty() && !plot.empty() ? plot + ".csv" : csv;
  o.summary_file = summary.empty() && !plot.empty() ? plot + ".json" : summary;
  o.plot = plot;
  o.plot_script = script;
  o.figures = std::move(figures);
  return o;
}

/// The exit code of every march: 0 completed; 5 stopped at a step whose enumeration is not
/// proved complete (N points: no solution found; 3-D: several, ambiguous); else 1 (no solution,
/// a continuum, a branch point with the rule 'stop', numerical failure).
template <class Sample, class PerPoint>
ExitCode exit_code(const SimulationResultOf<Sample, PerPoint>& r) {
  if (r.outcome == SimulationOutcome::kCompleted) return kExitOk;
  return r.inconclusive || r.outcome == SimulationOutcome::kAmbiguous ? kExitInconclusive
                                                                      : kExitNoSolution;
}

/// One 3-D point under an elliptic load orbit (fretting_3d.hpp); the options of the 2-D
/// simulation are refused.
SimulateOutcome run_3d(const SimulateRequest& a, const SystemFile& file) {
  const ContactSystem3d sys = parse_contact_system_3d(file);
  if (sys.n_points() != 1)
    throw InputError(a.system + ": " + std::to_string(sys.n_points()) +
                     " points; the 3-D simulation (fretting with an elliptic load orbit) is for "
                     "one point (\"dim\": 3 with one point)");
  std::vector<std::string> other;  // options of the 2-D simulation given
  const SimulateNumbers& n = a.numbers;
  using N = SimulateNumbers;
  for (const NumberOption& o : kNumberOptions) {
    const auto f = o.field;
    if ((n.*f).has_value() && f != &N::F_N && f != &N::period && f != &N::cycles &&
        f != &N::steps_per_cycle && f != &N::ramp_steps && f != &N::k_M)
      other.push_back(std::string("--") + o.name);
  }
  const std::pair<bool, const char*> flags[] = {
      {!a.config.empty(), "--config"},  {!a.criterion.empty(), "--criterion"},
      {!a.load.empty(), "--load"},      {!a.load_csv.empty(), "--load-csv"},
      {a.heat, "--heat"},               {!a.T_body.empty(), "--T-body"},
      {!a.conductance.empty(), "--conductance"}};
  for (const auto& f : flags)
    if (f.first) other.emplace_back(f.second);
  if (!other.empty())
    throw InputError(other.front() +
                     " has no effect with a \"dim\": 3 system (the file gives the point's "
                     "parameters; the load is the elliptic orbit: --orbit, --orbit-angle, "
                     "--lead-steps, --F_N, --period, --cycles, --steps-per-cycle, --ramp-steps)");
  if (sys.points[0].state.state != 'b')
    throw InputError(a.system + ": the simulation starts unloaded and grazing (state b, "
                     "P = 0, F = 0); the file gives state " +
                     std::string(1, sys.points[0].state.state));
  if (a.orbit.size() != 2)
    throw InputError("a \"dim\": 3 simulation needs --orbit aX aY (the half-axes of the "
                     "tangential load orbit)");
  EllipticOrbit orbit;
  orbit.a_X = a.orbit[0];
  orbit.a_Y = a.orbit[1];
  orbit.angle = a.orbit_angle.value_or(0.0);
  orbit.lead_steps = a.lead_steps.value_or(-1);
  if (a.lead_steps && *a.lead_steps < 0)
    throw InputError("--lead-steps must be >= 0, got " + std::to_string(*a.lead_steps));
  orbit.F_N = n.F_N.value_or(orbit.F_N);
  orbit.period = n.period.value_or(orbit.period);
  count_option(n.cycles, "cycles", 1, orbit.cycles);
  count_option(n.steps_per_cycle, "steps-per-cycle", 1, orbit.steps_per_cycle);
  count_option(n.ramp_steps, "ramp-steps", 1, orbit.ramp_steps);
  throw_if_invalid(orbit.validate(), "orbit");
  // Capped as the N-point runs (kMaxSystemSimulationSteps: 0.2 ms a step).
  check_simulation_steps(static_cast<std::int64_t>(std::min<std::size_t>(orbit.size(), INT64_MAX)),
                         true, "lead_steps + ramp_steps + cycles x steps_per_cycle");

  Fretting3dOptions o;
  o.params = sys.point_parameters(0);
  if (!a.wear_law.empty())
    o.wear.law = choice(wear_law_from_string(a.wear_law), "--wear-law must be archard or mroz",
                        a.wear_law);
  o.wear.k_M = n.k_M.value_or(o.wear.k_M);
  const bool mroz = o.wear.law == WearLaw::kMrozStupkiewicz;
  if (!mroz && n.k_M)
    throw InputError("--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
  if (mroz && !(o.wear.k_M > 0))
    throw InputError("the wear law mroz needs --k_M > 0; for no wear use archard with k_a = 0");
  if (mroz && o.params.k_a != 0)
    throw InputError(a.system + ": k_a has no effect with the wear law mroz (its constant is "
                     "--k_M); set k_a to 0 in the file");
  if (!a.branch_rule.empty())
    o.branch_rule = choice(branch_rule_from_string(a.branch_rule),
                           "--branch-rule must be closest or stop", a.branch_rule);
  if (a.every && *a.every < 0) throw InputError("--every must be >= 0");
  throw_if_invalid(o.validate(), a.system);

  SimulateOutcome out = outputs(a.csv, a.summary, a.plot, "cpkit_plot_fretting_3d.py",
                                {"_orbit", "_wear"});
  Series series(out.csv, fretting_3d_csv_header());
  series.attach(o, a.every.value_or(1), &write_fretting_3d_csv_row);
  const Fretting3dResult r = simulate_fretting_3d(orbit, o);
  series.close();
  out.summary = fretting_3d_summary_json(r, orbit, o, a.system, sys.name);
  out.summary["cpkit_version"] = a.version;
  out.summary["run"] = a.run;
  if (!out.summary_file.empty()) write_json_file(out.summary_file, out.summary);
  out.text = fretting_3d_text(r, o.wear.law);
  out.exit_code = exit_code(r);
  return out;
}

/// N points (docs/simulation.md, "N points"): the fretting cycle through the system's patterns
/// or a csv load with t and 2N forces per row.
SimulateOutcome run_system(const SimulateSettings& s, const SystemFile& file,
                           const SimulateRequest& a) {
  const ContactSystem sys = parse_contact_system(file);
  const int N = sys.n_points();
  SystemLoadSource load;
  std::vector<SystemLoadPoint> stored;
  if (s.load_type == "fretting") {
    if (!sys.pattern1 || !sys.pattern2)
      throw InputError("system '" + s.system + "' has no patterns: the fretting cycle is "
                       "applied through them (F = F_T(t) e1 + F_N(t) e2); give patterns or a csv load");
    load = system_fretting_source(s.fretting, *sys.pattern1, *sys.pattern2);
  } else {
    stored = parse_system_load_csv(read_bounded(s.load_csv, kMaxLoadCsvBytes, "load history"),
                                   s.load_csv, N);
    check_simulation_steps(static_cast<std::int64_t>(stored.size()), true, "the rows of the CSV");
    load = system_history_source(stored, s.csv_period);
  }
  SystemSimulationOptions o;
  o.heat = s.opt.heat;
  o.branch_rule = s.opt.branch_rule;
  o.tol = s.opt.tol;
  SimulateOutcome out = outputs(s.csv, s.summary, s.plot, "cpkit_plot_system_simulation.py",
                                {"_wear", "_slip"});
  Series series(out.csv, system_simulation_csv_header(N));
  series.attach(o, s.every, &write_system_simulation_csv_row);
  const SystemSimulationResult r = simulate_system(sys, load, o);
  series.close();
  // The summary file has no "run" (the program adds it to what it prints).
  out.summary = system_simulation_summary_json(r, s, sys);
  out.summary["cpkit_version"] = a.version;
  if (!out.summary_file.empty()) write_json_file(out.summary_file, out.summary);
  out.text = system_simulation_text(r);
  out.exit_code = exit_code(r);
  return out;
}

/// One 2-D point under the load of the settings (fretting, ramp or csv).
SimulateOutcome run_one_point(SimulateSettings& s, const SimulateRequest& a) {
  SimulateOutcome out = outputs(s.csv, s.summary, s.plot, "cpkit_plot_simulation.py",
                                {"_loop", "_wear", "_state"});
  Series series(out.csv, simulation_csv_header());
  series.attach(s.opt, s.every, &write_simulation_csv_row);
  LoadHistory stored;
  const LoadSource load = make_simulate_source(s, stored);
  const SimulationResult r = simulate(load, s.opt);
  series.close();
  out.summary = simulation_summary_json(r, s);
  out.summary["run"] = a.run;  // version and command line
  if (!out.summary_file.empty()) write_json_file(out.summary_file, out.summary);
  out.text = simulation_text(r, s.opt.heat.enabled);
  out.exit_code = exit_code(r);
  return out;
}

/// The options given over the settings (a config's or the defaults).
void apply_options(const SimulateRequest& a, SimulateSettings& s) {
  auto& P = s.opt.params;
  const SimulateNumbers& n = a.numbers;
  auto set = [](const std::optional<double>& v, double& dst) {
    if (v) dst = *v;
    return v.has_value();
  };
  if (set(n.a11, P.a11)) s.have[0] = true;
  if (set(n.a12, P.a12)) s.have[1] = true;
  if (set(n.a22, P.a22)) s.have[2] = true;
  if (set(n.mu, P.mu)) s.have[3] = true;
  set(n.C_T, P.C_T);
  set(n.k_a, P.k_a);
  set(n.P_s, P.P_s);
  set(n.k_M, s.opt.wear.k_M);
  set(n.F_N, s.fretting.F_N);
  set(n.amplitude, s.fretting.amplitude);
  if (set(n.period, s.fretting.period)) s.csv_period = s.fretting.period;
  // Counts must be integers that fit an int; their ranges and the run's total size are
  // checked by validate_simulate_settings.
  count_option(n.cycles, "cycles", INT_MIN, s.fretting.cycles);
  count_option(n.steps_per_cycle, "steps-per-cycle", INT_MIN, s.fretting.steps_per_cycle);
  count_option(n.ramp_steps, "ramp-steps", INT_MIN, s.fretting.ramp_steps);
  set(n.F_T0, s.ramp.F_T0);
  set(n.F_N0, s.ramp.F_N0);
  set(n.F_T1, s.ramp.F_T1);
  set(n.F_N1, s.ramp.F_N1);
  set(n.duration, s.ramp.duration);
  count_option(n.steps, "steps", INT_MIN, s.ramp.steps);
  set(n.heat_capacity, s.opt.heat.heat_capacity);
  set(n.T_ref, s.opt.heat.T_ref);
  set(n.T_initial, s.opt.heat.T_initial);
  if (!a.T_body.empty()) std::copy_n(a.T_body.begin(), 2, s.opt.heat.T_body);
  if (!a.conductance.empty()) std::copy_n(a.conductance.begin(), 2, s.opt.heat.conductance);
  if (a.heat) s.opt.heat.enabled = true;
  if (!a.criterion.empty())
    P.criterion = choice(criterion_from_string(a.criterion), "--criterion must be 38 or 35",
                         a.criterion);
  if (!a.wear_law.empty())
    s.opt.wear.law = choice(wear_law_from_string(a.wear_law), "--wear-law must be archard or mroz",
                            a.wear_law);
  if (!a.branch_rule.empty())
    s.opt.branch_rule = choice(branch_rule_from_string(a.branch_rule),
                               "--branch-rule must be closest or stop", a.branch_rule);
  if (!a.load.empty()) s.load_type = a.load;
  if (!a.load_csv.empty()) {
    s.load_csv = a.load_csv;
    if (a.load.empty()) s.load_type = "csv";
  }
  if (!a.csv.empty()) s.csv = a.csv;
  if (!a.summary.empty()) s.summary = a.summary;
  if (!a.plot.empty()) s.plot = a.plot;
  if (a.every) s.every = *a.every;
  if (!a.system.empty()) s.system = a.system;
}

/// Options that would have no effect (another load type's, heat options without heat, wear
/// constants of the other law) are errors, never silence.
void refuse_without_effect(const SimulateRequest& a, const SimulateSettings& s) {
  const SimulateNumbers& n = a.numbers;
  auto only_with = [&](std::initializer_list<NumberOption> options, const std::string& needs) {
    for (const NumberOption& o : options)
      if ((n.*o.field).has_value())
        throw InputError(std::string("--") + o.name + " has no effect here: it needs " + needs);
  };
  using N = SimulateNumbers;
  if (s.load_type != "fretting")
    only_with({{"F_N", &N::F_N}, {"amplitude", &N::amplitude}, {"cycles", &N::cycles},
               {"steps-per-cycle", &N::steps_per_cycle}, {"ramp-steps", &N::ramp_steps}},
              "--load fretting (the load is " + s.load_type + ")");
  if (s.load_type != "ramp")
    only_with({{"F_T0", &N::F_T0}, {"F_N0", &N::F_N0}, {"F_T1", &N::F_T1}, {"F_N1", &N::F_N1},
               {"duration", &N::duration}, {"steps", &N::steps}},
              "--load ramp (the load is " + s.load_type + ")");
  if (s.load_type == "ramp")
    only_with({{"period", &N::period}}, "--load fretting or csv (the load is ramp)");
  if (!s.opt.heat.enabled) {
    only_with({{"heat-capacity", &N::heat_capacity}, {"T-ref", &N::T_ref},
               {"T-initial", &N::T_initial}},
              "--heat (or heat.enabled)");
    if (!a.T_body.empty() || !a.conductance.empty())
      throw InputError(std::string(!a.T_body.empty() ? "--T-body" : "--conductance") +
                       " has no effect here: it needs --heat (or heat.enabled)");
  }
  const bool mroz = s.opt.wear.law == WearLaw::kMrozStupkiewicz;
  if (!mroz && s.opt.wear.k_M != 0)
    throw InputError("k_M (--k_M, wear.k_M) is the Mroz-Stupkiewicz wear constant: it needs the "
                     "wear law mroz (--wear-law mroz, wear.law)");
  if (mroz && s.opt.wear.k_M == 0)
    throw InputError("the wear law mroz needs k_M > 0 (--k_M, wear.k_M); for no wear use the "
                     "default law archard with k_a = 0");
  if (mroz && s.opt.params.k_a != 0)
    throw InputError("k_a (--k_a, parameters.k_a) has no effect with the wear law mroz: its wear "
                     "constant is k_M");
}

}  // namespace

SimulateOutcome run_simulate_request(
    const SimulateRequest& a, const std::function<void(const SimulateSettings&)>& check_outputs) {
  // A system file is read once (a pipe can be read only once) and dispatched on its dimension.
  std::optional<SystemFile> file;
  if (!a.system.empty()) {
    file = read_system_file(a.system);
    if (file->dim == 3) return run_3d(a, *file);
  }
  const char* three_d = !a.orbit.empty() ? "--orbit"
                        : a.orbit_angle  ? "--orbit-angle"
                        : a.lead_steps   ? "--lead-steps"
                                         : nullptr;
  if (three_d)
    throw InputError(std::string(three_d) +
                     " needs a \"dim\": 3 system file (--system FILE; docs/contact_3d.md)");
  SimulateSettings s;
  if (!a.config.empty()) read_simulate_config(a.config, s);
  apply_options(a, s);
  // The config names its own system, load and outputs: the program checks them too.
  if (check_outputs) check_outputs(s);
  if (!s.system.empty() && !file) file = read_system_file(s.system);  // the config's
  if (file && file->dim == 3)
    throw InputError("the config's system '" + s.system + "' has \"dim\": 3: simulate it from the "
                     "command line (cpkit simulate --system FILE --orbit aX aY ...)");
  refuse_without_effect(a, s);
  // Everything is checked (model, load, sizes) before the history is allocated.
  validate_simulate_settings(s);
  if (file) return run_system(s, *file, a);
  return run_one_point(s, a);
}

}  // namespace cpkit::rate
