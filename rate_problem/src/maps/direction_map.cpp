// Direction map: exact critical directions, sectors between them (docs/maps.md).
#include "cpkit/rate_problem/maps/direction_map.hpp"

#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "critical_directions.hpp"
#include "direction_sectors.hpp"

namespace cpkit::rate {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;

LoadRate at_angle(double theta) noexcept { return {std::cos(theta), std::sin(theta)}; }

/// Evaluates the rate problem by the map's route and, when cross-checking, by enumeration.
struct Evaluator {
  const RatePrecomputed& pre;  // once per direction map (validated by precompute_rate_problem)
  RateMethod method;
  bool cross;
  int evaluations = 0;
  int disagreements = 0;
  int unreliable = 0;

  /// `on_line`: the load is a candidate critical direction, a tie by construction. There the
  /// routes' critical sign is within its rounding (the direction is rounded), both list the
  /// pieces of the load taken on the line (the summary the map wants) and flag it unreliable;
  /// that flag is expected and not counted.
  RateSummary operator()(const LoadRate& load, RateSummary& check, bool on_line = false) {
    const RateSummary s = summarize_rate_problem(pre, load, method);
    check = cross ? summarize_rate_problem(pre, load, RateMethod::kEnumerate) : s;
    ++evaluations;
    // a route that could not decide does not disagree: it is counted as unreliable
    if (!s.reliable || !check.reliable) {
      if (!on_line) ++unreliable;
    } else if (!same_solution_set(s, check)) {
      ++disagreements;
    }
    return s;
  }
};

struct Arc {
  double from = 0, to = 0;
  RateSummary summary, check;
  bool consistent = true;
};
}  // namespace

std::string MapOptions::validate() const {
  if (threads < 0) return "threads must be >= 0 (0: all cores), got " + std::to_string(threads);
  if (method != RateMethod::kEnumerate && method != RateMethod::kAnalytic)
    return "method must be 'enumerate' or 'analytic' (maps need every solution), got '" +
           std::string(to_string(method)) + "'";
  const double span = theta_to - theta_from;
  if (!std::isfinite(theta_from) || !std::isfinite(theta_to) || !(span > 0) ||
      span > 6.283185307179586476925286766559 * (1 + 1e-15))
    return "theta_from < theta_to <= theta_from + 2 pi needed, got [" +
           std::to_string(theta_from) + ", " + std::to_string(theta_to) + "]";
  return {};
}

DirectionMap compute_direction_map(const ContactParameters& params, const ContactState& state,
                                   const MapOptions& options) {
  throw_if_invalid(params.validate(), "parameters");
  throw_if_invalid(state.validate(params), "contact state");
  throw_if_invalid(options.validate(), "map options");

  DirectionMap map;
  map.cross_checked = options.method != RateMethod::kEnumerate;
  const RatePrecomputed pre = precompute_rate_problem(params, state);
  Evaluator eval{pre, options.method, map.cross_checked};

  const auto candidates = candidate_critical_directions(params, state);
  const std::size_t m = candidates.size();

  // Arcs between consecutive candidates (one full-circle arc when there is none).
  std::vector<Arc> arcs(m == 0 ? 1 : m);
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    Arc& a = arcs[i];
    if (m == 0) {
      a.from = 0;
      a.to = kTwoPi;
    } else {
      a.from = candidates[i].theta;
      a.to = i + 1 < m ? candidates[i + 1].theta : candidates[0].theta + kTwoPi;
    }
    const double w = a.to - a.from;
    a.summary = eval(at_angle(a.from + 0.5 * w), a.check);
    RateSummary c1, c2;
    const RateSummary q1 = eval(at_angle(a.from + 0.25 * w), c1);
    const RateSummary q3 = eval(at_angle(a.from + 0.75 * w), c2);
    a.consistent = same_solution_set(q1, a.summary) && same_solution_set(q3, a.summary) &&
                   same_solution_set(c1, a.check) && same_solution_set(c2, a.check);
  }
  for (const Arc& a : arcs)
    if (!a.consistent) ++map.inconsistent_sectors;

  // Candidates: critical when the solution set there or on either side differs.
  std::vector<CriticalDirectionResult> cand(m);
  std::vector<bool> is_critical(m, false);
  for (std::size_t i = 0; i < m; ++i) {
    cand[i].theta = candidates[i].theta;
    cand[i].load = candidates[i].load;
    cand[i].conditions = candidates[i].conditions;
    cand[i].summary = eval(candidates[i].load, cand[i].check, true);
    const Arc& before = arcs[(i + m - 1) % m];
    const Arc& after = arcs[i];
    is_critical[i] = !same_solution_set(cand[i].summary, before.summary) ||
                     !same_solution_set(cand[i].summary, after.summary) ||
                     !same_solution_set(before.summary, after.summary) ||
                     !same_solution_set(cand[i].check, before.check) ||
                     !same_solution_set(cand[i].check, after.check);
  }

  std::vector<std::size_t> crit;
  for (std::size_t i = 0; i < m; ++i)
    if (is_critical[i]) crit.push_back(i);

  sectors_from_arcs(arcs, cand, crit, map.sectors, map.critical,
                    [](DirectionSector& s, const Arc& a) {
                      s.summary = a.summary;
                      s.check = a.check;
                    });
  map.evaluations = eval.evaluations;
  map.disagreements = eval.disagreements;
  map.unreliable = eval.unreliable;
  return map;
}

}  // namespace cpkit::rate
