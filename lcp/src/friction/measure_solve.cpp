// A solve judged in a chosen measure (measure_solve.hpp).
#include "cpkit/lcp/friction/measure_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "cpkit/core/short_number.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/friction/faceted.hpp"

namespace cpkit::lcp::friction {
namespace {

using Clock = std::chrono::steady_clock;

/// The errors of r, or nullopt when r is not an answer of the problem's size.
std::optional<FrictionErrors> errors_of(const FrictionContactProblem& p, const SolveResult& r) {
  if (r.z.size() == 0 || r.z.size() != p.q.size() || !r.z.allFinite()) return std::nullopt;
  return friction_errors(p, r.z);
}

/// Accepted by the verdict: a solution (finalize(), or a global problem's verdict) whose
/// unit-free number is within tol_acceptable.
bool trusted(const SolveResult& r, const std::optional<FrictionErrors>& e, const CommonOptions& o) {
  return is_solution(r.status) && e && e->unit_free <= o.tol_acceptable;
}

/// The tightening loop of the header comment: `first` is the answer at the caller's tolerance,
/// whose solve began at `start` (the time limit counts from there); resolve(options, best)
/// gives the next answer at options.tol (unit-free).
template <class Resolve>
SolveResult tighten(const FrictionContactProblem& p, SolveResult first, double first_tol,
                    const CommonOptions& o, FrictionMeasure m, Clock::time_point start,
                    Resolve resolve) {
  if (m == FrictionMeasure::kUnitFree) return first;
  SolveResult best = std::move(first);
  int iterations = best.iterations;
  double seconds = best.seconds;
  double t = first_tol;
  int solves = 1;
  for (int k = 0; k < kMaxTightenings; ++k) {
    const auto e = errors_of(p, best);
    if (!trusted(best, e, o)) break;  // the unit-free verdict refutes it: a lower tol will not help
    const double v = measured(*e, m);
    if (v <= o.tol) break;
    const std::optional<double> next = next_unit_free_tol(t, v, o.tol);
    const double left =
        o.time_limit_s - std::chrono::duration<double>(Clock::now() - start).count();
    if (!next || !(left > 0)) break;
    t = *next;
    CommonOptions tighter = o;
    tighter.tol = t;
    tighter.tol_acceptable = o.tol_acceptable;
    tighter.time_limit_s = left;
    SolveResult r = resolve(tighter, best);
    ++solves;
    iterations += r.iterations;
    seconds += r.seconds;
    if (better_in_measure(p, r, best, o, m)) best = std::move(r);
  }
  best.iterations = iterations;
  best.seconds = seconds;
  if (solves > 1)
    best.message += (best.message.empty() ? "" : "; ") + std::string("unit-free tol lowered to ") +
                    short_number(t) + " to reach " + to_string(m) + " (" +
                    std::to_string(solves) + " solves)";
  // The best was finalized at a lower unit-free tol: decide again at the caller's (whatever
  // the measure, a lower tolerance must not have called solved what the caller's does not).
  decide_in_measure(p, best, o, m);
  return best;
}

}  // namespace

double first_unit_free_tol(const CommonOptions& o, FrictionMeasure m) {
  if (m == FrictionMeasure::kUnitFree) return o.tol;
  return std::max(o.tol, std::min(o.tol_acceptable, kFirstTolFactor * o.tol));
}

std::optional<double> next_unit_free_tol(double t, double measured_value, double tol) {
  if (!(measured_value > tol) || !(t > kMinUnitFreeTol)) return std::nullopt;
  const double factor = std::min(0.1, 0.5 * tol / measured_value);
  return std::max(kMinUnitFreeTol, t * factor);
}

bool better_in_measure(const FrictionContactProblem& p, const SolveResult& b, const SolveResult& a,
                       const CommonOptions& o, FrictionMeasure m) {
  const auto eb = errors_of(p, b), ea = errors_of(p, a);
  const bool tb = trusted(b, eb, o), ta = trusted(a, ea, o);
  if (tb != ta) return tb;
  if (!eb) return false;
  if (!ea) return true;
  return measured(*eb, m) < measured(*ea, m);
}

SolveResult solve_in_measure(const FrictionContactProblem& p, const SolverEntry& entry,
                             const CommonOptions& o, FrictionMeasure m) {
  auto solve = [&](const CommonOptions& oo) {
    SolveResult r = entry.solve_fc(p, oo);
    if (r.solver.empty()) r.solver = entry.info.name;
    return r;
  };
  const auto start = Clock::now();
  CommonOptions first_options = o;
  first_options.tol = first_unit_free_tol(o, m);
  SolveResult first = solve(first_options);
  return tighten(p, std::move(first), first_options.tol, o, m, start,
                 [&](const CommonOptions& oo, const SolveResult&) { return solve(oo); });
}

SolveResult refine_in_measure(const FrictionContactProblem& p, SolveResult answer,
                              const CommonOptions& o, FrictionMeasure m) {
  const std::string solver = answer.solver;
  SolveResult out = tighten(p, std::move(answer), o.tol, o, m, Clock::now(),
                            [&](const CommonOptions& oo, const SolveResult& best) {
                              return polish_on_true_cone(p, best.z, oo);
                            });
  out.solver = solver;  // the answer found by `solver`, polished
  return out;
}

}  // namespace cpkit::lcp::friction
