#include "cpkit/rate_problem/simulation/simulate_config.hpp"

#include <climits>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"

namespace cpkit::rate {
namespace {

using nlohmann::json;

/// A JSON value for a message (invalid UTF-8 replaced, long values cut, at bounded cost).
std::string shown(const json& v) { return json_excerpt(v, 40); }

double get_num(const json& v, const std::string& field) {
  if (!v.is_number()) throw InputError(field + " must be a number, got " + shown(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(field + " must be a finite number");
  return d;
}

/// An integer in [lo, hi]: a JSON integer, or a number with an integral value (1e3).
int get_int(const json& v, const std::string& field, long long lo, long long hi) {
  const std::string range = " [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(hi))
      throw InputError(field + " = " + std::to_string(u) + " is out of range" + range);
    return static_cast<int>(u);
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (i < lo || i > hi)
      throw InputError(field + " = " + std::to_string(i) + " is out of range" + range);
    return static_cast<int>(i);
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!std::isfinite(d) || d != std::floor(d))
      throw InputError(field + " must be an integer, got " + shown(v));
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
      throw InputError(field + " = " + shown(v) + " is out of range" + range);
    return static_cast<int>(d);
  }
  throw InputError(field + " must be an integer, got " + shown(v));
}

std::string get_str(const json& v, const std::string& field) {
  if (!v.is_string()) throw InputError(field + " must be a string, got " + shown(v));
  return v.get<std::string>();
}

void need_object(const json& v, const std::string& field) {
  if (!v.is_object()) throw InputError(field + " must be an object, got " + shown(v));
}

void set_criterion(SimulateSettings& s, const json& v, const std::string& field) {
  std::string c;
  if (v.is_number()) {
    // 38 and 35 are equation numbers: integers only (38.7 is not criterion 38).
    c = std::to_string(get_int(v, field, 0, 99));
  } else {
    c = get_str(v, field);
  }
  const auto crit = rate::criterion_from_string(c);
  if (!crit) throw InputError(field + " must be 38 or 35, got " + shown(v));
  s.opt.params.criterion = *crit;
}

/// The largest count a field may hold (the sizes are checked together later).
constexpr long long kIntMax = INT_MAX;

void parse_parameters(const json& v, SimulateSettings& s) {
  need_object(v, "parameters");
  auto& P = s.opt.params;
  for (auto p = v.begin(); p != v.end(); ++p) {
    const std::string& k = p.key();
    const std::string f = "parameters." + k;
    if (k == "a11") { P.a11 = get_num(*p, f); s.have[0] = true; }
    else if (k == "a12") { P.a12 = get_num(*p, f); s.have[1] = true; }
    else if (k == "a22") { P.a22 = get_num(*p, f); s.have[2] = true; }
    else if (k == "mu") { P.mu = get_num(*p, f); s.have[3] = true; }
    else if (k == "C_T") P.C_T = get_num(*p, f);
    else if (k == "k_a") P.k_a = get_num(*p, f);
    else if (k == "P_s") P.P_s = get_num(*p, f);
    else if (k == "criterion") set_criterion(s, *p, f);
    else throw InputError("unknown key " + f);
  }
}

void parse_wear(const json& v, SimulateSettings& s) {
  need_object(v, "wear");
  for (auto p = v.begin(); p != v.end(); ++p) {
    const std::string f = "wear." + p.key();
    if (p.key() == "law") {
      const std::string w = get_str(*p, f);
      const auto law = rate::wear_law_from_string(w);
      if (!law) throw InputError(f + " must be archard or mroz, got " + shown(*p));
      s.opt.wear.law = *law;
    } else if (p.key() == "k_M") {
      s.opt.wear.k_M = get_num(*p, f);
    } else {
      throw InputError("unknown key " + f);
    }
  }
}

/// A path from the config file: relative ones are relative to the config file's folder (one
/// base for every path in the file: load.file, output.*, system; command-line paths use the
/// working directory).
std::string config_path(const json& v, const std::string& field, const std::string& dir) {
  const std::string file = get_str(v, field);
  if (file.empty()) throw InputError(field + " must not be empty");
  return file[0] == '/' ? file : dir + "/" + file;
}

void parse_load(const json& v, const std::string& dir, SimulateSettings& s) {
  need_object(v, "load");
  for (auto p = v.begin(); p != v.end(); ++p) {
    const std::string& k = p.key();
    const std::string f = "load." + k;
    if (k == "type") s.load_type = get_str(*p, f);
    else if (k == "F_N") s.fretting.F_N = get_num(*p, f);
    else if (k == "amplitude") s.fretting.amplitude = get_num(*p, f);
    else if (k == "period") { s.fretting.period = get_num(*p, f); s.csv_period = s.fretting.period; }
    else if (k == "cycles") s.fretting.cycles = get_int(*p, f, 1, kIntMax);
    else if (k == "steps_per_cycle") s.fretting.steps_per_cycle = get_int(*p, f, 4, kIntMax);
    else if (k == "ramp_steps") s.fretting.ramp_steps = get_int(*p, f, 1, kIntMax);
    else if (k == "F_T0") s.ramp.F_T0 = get_num(*p, f);
    else if (k == "F_N0") s.ramp.F_N0 = get_num(*p, f);
    else if (k == "F_T1") s.ramp.F_T1 = get_num(*p, f);
    else if (k == "F_N1") s.ramp.F_N1 = get_num(*p, f);
    else if (k == "duration") s.ramp.duration = get_num(*p, f);
    else if (k == "steps") s.ramp.steps = get_int(*p, f, 1, kIntMax);
    else if (k == "file") s.load_csv = config_path(*p, f, dir);
    else throw InputError("unknown key " + f);
  }
}

void parse_heat(const json& v, SimulateSettings& s) {
  need_object(v, "heat");
  auto& H = s.opt.heat;
  for (auto p = v.begin(); p != v.end(); ++p) {
    const std::string& k = p.key();
    const std::string f = "heat." + k;
    if (k == "enabled") {
      if (!p->is_boolean()) throw InputError(f + " must be true or false, got " + shown(*p));
      H.enabled = p->get<bool>();
    } else if (k == "heat_capacity") H.heat_capacity = get_num(*p, f);
    else if (k == "T_ref") H.T_ref = get_num(*p, f);
    else if (k == "T_initial") H.T_initial = get_num(*p, f);
    else if (k == "T_body" || k == "conductance") {
      if (!p->is_array() || p->size() != 2)
        throw InputError(f + " must be an array of two numbers, got " + shown(*p));
      double* dst = k == "T_body" ? H.T_body : H.conductance;
      dst[0] = get_num((*p)[0], f + "[0]");
      dst[1] = get_num((*p)[1], f + "[1]");
    } else {
      throw InputError("unknown key " + f);
    }
  }
}

void parse_output(const json& v, const std::string& dir, SimulateSettings& s) {
  need_object(v, "output");
  for (auto p = v.begin(); p != v.end(); ++p) {
    const std::string& k = p.key();
    const std::string f = "output." + k;
    if (k == "csv") s.csv = config_path(*p, f, dir);
    else if (k == "summary") s.summary = config_path(*p, f, dir);
    else if (k == "plot") s.plot = config_path(*p, f, dir);
    else if (k == "every") s.every = get_int(*p, f, 0, kIntMax);
    else throw InputError("unknown key " + f);
  }
}

/// Bytes the run keeps: the per-cycle sums, and the load history when it is read from a CSV
/// file (fretting and ramp loads are generated point by point, and the time series is
/// streamed to its file as it is produced, so neither grows with the steps).
double run_bytes(double steps, double cycles, bool stored_history) {
  return (stored_history ? steps * sizeof(rate::LoadPoint) : 0.0) + 2 * cycles * sizeof(double);
}

}  // namespace

void parse_simulate_config(const std::string& text, const std::string& origin,
                           const std::string& dir, SimulateSettings& s) {
  // The one JSON parser of the readers (core/json_read.hpp): nesting, number range (1e400,
  // 1e-400) and duplicate keys are refused with the line.
  const json j = parse_json_bounded(text, "config '" + origin + "'",
                                    "a config needs 3: {\"heat\": {\"T_body\": [...]}}");
  if (!j.is_object()) throw InputError("config '" + origin + "': the top level must be an object");
  try {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      const json& v = it.value();
      if (k == "parameters") parse_parameters(v, s);
      else if (k == "wear") parse_wear(v, s);
      else if (k == "load") parse_load(v, dir, s);
      else if (k == "heat") parse_heat(v, s);
      else if (k == "branch_rule") {
        const std::string r = get_str(v, k);
        const auto rule = rate::branch_rule_from_string(r);
        if (!rule) throw InputError("branch_rule must be closest or stop, got " + shown(v));
        s.opt.branch_rule = *rule;
      } else if (k == "output") parse_output(v, dir, s);
      else if (k == "system") s.system = config_path(v, k, dir);
      else if (k == "name" || k == "note") {
        // free text
      } else {
        throw InputError("unknown key '" + k + "'");
      }
    }
  } catch (const InputError& e) {
    throw InputError("config '" + origin + "': " + e.what());
  }
}

std::string read_bounded(const std::string& path, std::size_t max_bytes, const std::string& what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("cannot open " + what + " '" + path + "'");
  std::string text;
  char buf[1 << 16];
  while (f) {
    f.read(buf, sizeof buf);
    text.append(buf, static_cast<std::size_t>(f.gcount()));
    if (text.size() > max_bytes)
      throw InputError(what + " '" + path + "' is larger than " +
                       byte_text(static_cast<double>(max_bytes)));
  }
  if (f.bad()) throw InputError("error reading " + what + " '" + path + "'");
  return text;
}

void read_simulate_config(const std::string& path, SimulateSettings& s) {
  const std::string text = read_bounded(path, kMaxConfigBytes, "config");
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string(".") : path.substr(0, slash);
  parse_simulate_config(text, path, dir.empty() ? std::string("/") : dir, s);
}

void check_simulation_steps(std::int64_t steps, bool system, const std::string& what) {
  const std::int64_t cap = system ? kMaxSystemSimulationSteps : kMaxSimulationSteps;
  if (steps > cap)
    throw InputError("the run would take " + std::to_string(steps) + " steps (" + what +
                     "); the cap is " + std::to_string(cap) + " steps (" +
                     (system ? "kMaxSystemSimulationSteps, N points or a 3-D point"
                             : "kMaxSimulationSteps") +
                     "): use fewer steps or cycles");
}

void check_history_memory(std::int64_t steps, const SimulateSettings& s) {
  const double cycles =
      s.load_type == "fretting" ? static_cast<double>(s.fretting.cycles) : 0.0;
  const double bytes = run_bytes(static_cast<double>(steps), cycles, s.load_type == "csv");
  if (bytes > static_cast<double>(kMemoryLimitBytes))
    throw InputError("the run would need about " + byte_text(bytes) + " of memory (" +
                     std::to_string(steps) + " steps, " +
                     (s.load_type == "csv" ? std::string("the load history held in memory")
                                           : std::string("two numbers per cycle")) +
                     "); the limit is " + byte_text(static_cast<double>(kMemoryLimitBytes)) +
                     ": use fewer steps or cycles");
}

void validate_simulate_settings(const SimulateSettings& s) {
  const char* names[] = {"a11", "a12", "a22", "mu"};
  if (!s.system.empty()) {
    // The system file gives every point's parameters.
    for (int i = 0; i < 4; ++i)
      if (s.have[i])
        throw InputError(std::string(names[i]) + " cannot be combined with a system file (the "
                         "system gives every point's parameters)");
    if (s.opt.params.criterion != rate::Criterion::kCoulomb ||
        s.opt.wear.law != rate::WearLaw::kArchard)
      throw InputError("a system simulation supports the Coulomb criterion (38) with Archard "
                       "wear (37) only");
    if (s.load_type != "fretting" && s.load_type != "csv")
      throw InputError("a system simulation's load type must be fretting (through the system's "
                       "patterns) or csv (t and 2N forces per row), got '" + s.load_type + "'");
  }
  for (int i = 0; i < 4 && s.system.empty(); ++i)
    if (!s.have[i])
      throw InputError(std::string(names[i]) + " is required (--" + names[i] +
                       " or parameters." + names[i] + " in --config)");
  if (s.every < 0) throw InputError("every must be >= 0, got " + std::to_string(s.every));
  if ((!s.csv.empty() || !s.plot.empty()) && s.every == 0)
    throw InputError("a CSV or plot needs every >= 1");
  // every thins the time series; without a series file it would change nothing
  if (s.every != 1 && s.csv.empty() && s.plot.empty())
    throw InputError("every = " + std::to_string(s.every) + " (--every, output.every) has no "
                     "effect without a time series: give --csv FILE or --plot PREFIX "
                     "(output.csv, output.plot)");
  rate::SimulationOptions o = s.opt;
  o.record_every = s.every;
  if (s.system.empty()) throw_if_invalid(o.validate(), "simulation");
  else throw_if_invalid(o.heat.validate(), "heat");
  if (s.load_type == "fretting") {
    throw_if_invalid(s.fretting.validate(), "fretting cycle");
    const std::int64_t steps = std::int64_t{s.fretting.ramp_steps} +
                               std::int64_t{s.fretting.cycles} * s.fretting.steps_per_cycle;
    check_history_memory(steps, s);
    check_simulation_steps(steps, !s.system.empty(), "ramp_steps + cycles x steps_per_cycle");
  } else if (s.load_type == "ramp") {
    throw_if_invalid(s.ramp.validate(), "ramp");
    check_history_memory(std::int64_t{s.ramp.steps} + 1, s);
    check_simulation_steps(std::int64_t{s.ramp.steps} + 1, !s.system.empty(), "the ramp's steps");
  } else if (s.load_type == "csv") {
    if (s.load_csv.empty()) throw InputError("load type csv needs a file (--load-csv or load.file)");
    if (!(std::isfinite(s.csv_period) && s.csv_period >= 0))
      throw InputError("the csv load's period must be finite and >= 0");
  } else {
    throw InputError("load type must be fretting, ramp or csv, got '" + s.load_type + "'");
  }
}

rate::LoadSource make_simulate_source(const SimulateSettings& s, rate::LoadHistory& storage) {
  if (s.load_type == "fretting") return rate::fretting_source(s.fretting);
  if (s.load_type == "ramp") return rate::ramp_source(s.ramp);
  storage = make_simulate_history(s);
  return rate::history_source(storage);
}

rate::LoadHistory make_simulate_history(const SimulateSettings& s) {
  if (s.load_type == "fretting") return rate::fretting_history(s.fretting);
  if (s.load_type == "ramp") return rate::ramp_history(s.ramp);
  if (s.load_type == "csv") {
    // Read with a bound: a path such as /dev/zero must not grow a string without end.
    rate::LoadHistory h =
        rate::parse_load_csv(read_bounded(s.load_csv, kMaxLoadCsvBytes, "load history"), s.load_csv);
    check_history_memory(static_cast<std::int64_t>(h.points.size()), s);
    check_simulation_steps(static_cast<std::int64_t>(h.points.size()), false, "the rows of the CSV");
    h.period = s.csv_period;
    h.cycle_start = 0;
    return h;
  }
  throw InputError("load type must be fretting, ramp or csv, got '" + s.load_type + "'");
}

}  // namespace cpkit::rate
