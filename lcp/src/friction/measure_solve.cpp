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
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/friction/prox.hpp"

namespace cpkit::lcp::friction {
namespace {

using Clock = std::chrono::steady_clock;

/// The errors of r, or nullopt when r is not an answer of the problem's size: those finalize()
/// stored with its verdict, else computed (a result decided without finalize()).
std::optional<FrictionErrors> errors_of(const FrictionContactProblem& p, const SolveResult& r) {
  if (r.z.size() == 0 || r.z.size() != p.q.size() || !r.z.allFinite()) return std::nullopt;
  if (r.friction_errors) return r.friction_errors;
  return friction_errors(p, r.z);
}

/// Accepted by the verdict: a solution (finalize(), or a global problem's verdict) whose
/// unit-free number is within tol_acceptable.
bool trusted(const SolveResult& r, const std::optional<FrictionErrors>& e, const CommonOptions& o) {
  return is_solution(r.status) && e && e->unit_free <= o.tol_acceptable;
}

/// better_in_measure (header) with both answers' errors already computed.
bool better_in_measure(const SolveResult& b, const std::optional<FrictionErrors>& eb,
                       const SolveResult& a, const std::optional<FrictionErrors>& ea,
                       const CommonOptions& o, FrictionMeasure m) {
  const bool tb = trusted(b, eb, o), ta = trusted(a, ea, o);
  if (tb != ta) return tb;
  if (!eb) return false;
  if (!ea) return true;
  return measured(*eb, m) < measured(*ea, m);
}

// The tightening loop of the header comment: `first` is the answer at the caller's tolerance,
/// whose solve began at `start` (the time limit counts from there); resolve(options, best)
/// gives the next answer at options.tol (unit-free).
template <class Resolve>
SolveResult tighten(const FrictionContactProblem& p, SolveResult first, double first_tol,
                    const CommonOptions& o, FrictionMeasure m, Clock::time_point start,
                    Resolve resolve) {
  if (m == FrictionMeasure::kUnitFree) return first;
  SolveResult best = std::move(first);
  std::optional<FrictionErrors> best_e = errors_of(p, best);  // finalize()'s, as a rule
  int iterations = best.iterations;
  double seconds = best.seconds;
  double t = first_tol;
  int solves = 1;
  for (int k = 0; k < kMaxTightenings; ++k) {
    if (!trusted(best, best_e, o)) break;  // the verdict refutes it: a lower tol will not help
    const double v = measured(*best_e, m);
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
    std::optional<FrictionErrors> r_e = errors_of(p, r);
    if (better_in_measure(r, r_e, best, best_e, o, m)) {
      best = std::move(r);
      best_e = r_e;
    }
  }
  best.iterations = iterations;
  best.seconds = seconds;
  if (solves > 1)
    best.message += (best.message.empty() ? "" : "; ") + std::string("unit-free tol lowered to ") +
                    short_number(t) + " to reach " + to_string(m) + " (" +
                    std::to_string(solves) + " solves)";
  // The best was finalized at a lower unit-free tol: decide again at the caller's (whatever
  // the measure, a lower tolerance must not have called solved what the caller's does not).
  if (best_e)
    decide_in_measure(p, best, o, m, *best_e);
  else
    decide_in_measure(p, best, o, m);
  return best;
}

// The solver whose answer `from` is, run again from it (its own warm start) at `o`: nsgs goes on
// sweeping, prox and fb-soc go on from there, where a solve from r = 0 would redo the work of
// the first (KaplasTower in relative_q: 1,776 sweeps from 0 again, 1,1xx from the answer).
// Other solvers (no warm start) solve again from the start.
std::optional<SolveResult> resolve_from(const FrictionContactProblem& p, const std::string& solver,
                                        const CommonOptions& o, const Eigen::VectorXd& from) {
  if (from.size() != p.q.size() || !from.allFinite()) return std::nullopt;
  if (solver == "nsgs") {
    NsgsOptions no;
    no.common = o;
    no.r0 = from;
    return solve_nsgs(p, no);
  }
  if (solver == "prox") {
    ProxOptions po;
    po.common = o;
    po.r0 = from;
    return solve_prox(p, po);
  }
  if (solver == "fb-soc") {
    FbSocOptions fo;
    fo.common = o;
    fo.r0 = from;
    return solve_fb_soc(p, fo);
  }
  return std::nullopt;
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
  return better_in_measure(b, errors_of(p, b), a, errors_of(p, a), o, m);
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
                 [&](const CommonOptions& oo, const SolveResult& best) {
                   // best.solver: the solver that found it (auto names the one in its chain).
                   std::optional<SolveResult> warm = resolve_from(p, best.solver, oo, best.z);
                   if (!warm) return solve(oo);
                   if (warm->solver.empty()) warm->solver = best.solver;
                   return std::move(*warm);
                 });
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
