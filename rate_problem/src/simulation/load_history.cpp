#include "cpkit/rate_problem/simulation/load_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"

namespace cpkit::rate {

std::string LoadHistory::validate() const {
  if (points.empty()) return "the load history is empty";
  std::ostringstream msg;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const LoadPoint& p = points[i];
    if (!std::isfinite(p.t) || !std::isfinite(p.F_T) || !std::isfinite(p.F_N)) {
      msg << "load point " << i << " (t = " << p.t << ") has a non-finite value";
      return msg.str();
    }
    if (i > 0 && !(p.t > points[i - 1].t)) {
      msg << "load point " << i << ": t = " << p.t << " does not increase (previous "
          << points[i - 1].t << ")";
      return msg.str();
    }
  }
  if (!std::isfinite(period) || period < 0) return "period must be finite and >= 0";
  if (!std::isfinite(cycle_start)) return "cycle_start must be finite";
  return {};
}

CsvRow parse_csv_row(const std::string& line_in, bool header_allowed, const std::string& where,
                     std::vector<double>& out) {
  out.clear();
  std::string line = line_in.substr(0, line_in.find('#'));
  for (char& ch : line)
    if (ch == ',' || ch == ';' || ch == '\t' || ch == '\r') ch = ' ';
  std::istringstream ls(line);
  std::vector<std::string> tokens;
  for (std::string t; ls >> t;) tokens.push_back(t);
  if (tokens.empty()) return CsvRow::kBlank;
  // A header names the columns: none of its tokens starts like a number (so that "0x10, 1, 2"
  // or "1e-400, 0, 1" on the first line is an error, not a header skipped in silence).
  const auto number_like = [](const std::string& t) {
    const char c = t[0];
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
  };
  std::vector<double> values;
  for (const std::string& t : tokens) {
    double v = 0;
    const NumberText r = parse_decimal(t, v);
    if (r == NumberText::kOk) {
      values.push_back(v);
      continue;
    }
    if (header_allowed && r == NumberText::kNotANumber &&
        std::none_of(tokens.begin(), tokens.end(), number_like))
      return CsvRow::kHeader;
    throw InputError(where + ": " + describe_number(r, t));
  }
  out = std::move(values);
  return CsvRow::kNumbers;
}

void for_each_csv_row(const std::string& text, const std::string& origin,
                      const std::function<void(const std::vector<double>&, const std::string&)>& row) {
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  bool header_allowed = true;
  std::vector<double> v;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string where = origin + ":" + std::to_string(lineno);
    const CsvRow kind = parse_csv_row(line, header_allowed, where, v);
    if (kind == CsvRow::kBlank) continue;
    header_allowed = false;
    if (kind == CsvRow::kHeader) continue;
    row(v, where);
  }
}

LoadHistory parse_load_csv(const std::string& text, const std::string& origin) {
  LoadHistory h;
  for_each_csv_row(text, origin, [&](const std::vector<double>& v, const std::string& where) {
    if (v.size() != 3) throw InputError(where + ": expected three columns t, F_T, F_N");
    h.points.push_back({v[0], v[1], v[2]});
  });
  const std::string m = h.validate();
  if (!m.empty()) throw InputError(origin + ": " + m);
  return h;
}

LoadHistory read_load_csv(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError("cannot open load history '" + path + "'");
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_load_csv(ss.str(), path);
}

std::string FrettingCycle::validate() const {
  std::ostringstream msg;
  if (!std::isfinite(F_N) || F_N < 0) msg << "F_N = " << F_N << " must be finite and >= 0";
  else if (!std::isfinite(amplitude) || amplitude < 0)
    msg << "amplitude = " << amplitude << " must be finite and >= 0";
  else if (!std::isfinite(period) || !(period > 0)) msg << "period = " << period << " must be > 0";
  else if (cycles < 1) msg << "cycles = " << cycles << " must be >= 1";
  else if (steps_per_cycle < 4) msg << "steps_per_cycle = " << steps_per_cycle << " must be >= 4";
  else if (ramp_steps < 1) msg << "ramp_steps = " << ramp_steps << " must be >= 1";
  return msg.str();
}

LoadSource fretting_source(const FrettingCycle& c) {
  throw_if_invalid(c.validate(), "fretting cycle");
  LoadSource src;
  const std::size_t ramp = static_cast<std::size_t>(c.ramp_steps);
  src.size = ramp + static_cast<std::size_t>(c.cycles) * static_cast<std::size_t>(c.steps_per_cycle);
  const double dt = c.period / c.steps_per_cycle;
  const double t_ramp = c.ramp_steps * dt;
  src.period = c.period;
  src.cycle_start = t_ramp;
  src.at = [c, ramp, dt, t_ramp](std::size_t i) -> LoadPoint {
    if (i < ramp) {
      const double r = static_cast<double>(i + 1);
      return {r * dt, 0.0, c.F_N * r / c.ramp_steps};
    }
    const long k = static_cast<long>(i - ramp) + 1;
    const double two_pi = 2 * std::acos(-1.0);
    const double phase = static_cast<double>(k % c.steps_per_cycle) / c.steps_per_cycle;
    return {t_ramp + k * dt, c.amplitude * std::sin(two_pi * phase), c.F_N};
  };
  return src;
}

static LoadHistory materialize(const LoadSource& src) {
  LoadHistory h;
  h.points.reserve(src.size);
  for (std::size_t i = 0; i < src.size; ++i) h.points.push_back(src.at(i));
  h.period = src.period;
  h.cycle_start = src.cycle_start;
  return h;
}

LoadHistory fretting_history(const FrettingCycle& c) { return materialize(fretting_source(c)); }

LoadSource history_source(const LoadHistory& h) {
  LoadSource src;
  src.size = h.points.size();
  src.at = [&h](std::size_t i) { return h.points[i]; };
  src.period = h.period;
  src.cycle_start = h.cycle_start;
  return src;
}

std::string LoadRamp::validate() const {
  std::ostringstream msg;
  if (!std::isfinite(F_T0) || !std::isfinite(F_N0) || !std::isfinite(F_T1) ||
      !std::isfinite(F_N1))
    msg << "ramp loads must be finite";
  else if (!std::isfinite(duration) || !(duration > 0))
    msg << "duration = " << duration << " must be > 0";
  else if (steps < 1)
    msg << "steps = " << steps << " must be >= 1";
  return msg.str();
}

LoadSource ramp_source(const LoadRamp& r) {
  throw_if_invalid(r.validate(), "ramp");
  LoadSource src;
  const bool offset = r.F_T0 != 0 || r.F_N0 != 0;
  const double dt = r.duration / r.steps;
  src.size = static_cast<std::size_t>(r.steps) + (offset ? 1 : 0);
  src.at = [r, offset, dt](std::size_t i) -> LoadPoint {
    // When the start is not zero a first step goes from the unloaded state to it.
    if (offset && i == 0) return {dt, r.F_T0, r.F_N0};
    const double t0 = offset ? dt : 0.0;
    const int k = static_cast<int>(i) + (offset ? 0 : 1);
    const double s = static_cast<double>(k) / r.steps;
    return {t0 + k * dt, r.F_T0 + s * (r.F_T1 - r.F_T0), r.F_N0 + s * (r.F_N1 - r.F_N0)};
  };
  return src;
}

LoadHistory ramp_history(const LoadRamp& r) { return materialize(ramp_source(r)); }

}  // namespace cpkit::rate
