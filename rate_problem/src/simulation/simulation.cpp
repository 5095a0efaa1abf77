#include "cpkit/rate_problem/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "step_march.hpp"

namespace cpkit::rate {

std::string_view to_string(SimulationOutcome o) noexcept {
  switch (o) {
    case SimulationOutcome::kCompleted: return "completed";
    case SimulationOutcome::kNoSolution: return "no_solution";
    case SimulationOutcome::kContinuum: return "continuum";
    case SimulationOutcome::kAmbiguous: return "ambiguous";
    case SimulationOutcome::kBranchStop: return "branch_stop";
    case SimulationOutcome::kNumericalFailure: return "numerical_failure";
  }
  return "unknown";
}

std::string SimulationOptions::validate() const {
  StepProblem p;
  p.params = params;
  p.wear = wear;
  std::string m = p.validate();
  if (!m.empty()) return m;
  m = heat.validate();
  if (!m.empty()) return "heat: " + m;
  if (!(tol > 0) || !std::isfinite(tol)) return "tol must be finite and > 0";
  if (record_every < 0) return "record_every must be >= 0";
  if (max_branch_records < 0) return "max_branch_records must be >= 0";
  return {};
}

StateLabel step_state_label(const ContactParameters& params, double P_T, double P_N,
                            double g) noexcept {
  if (P_N <= 0) return g < 0 ? StateLabel::kA : StateLabel::kB;
  const double kc = params.criterion == Criterion::kSoftening ? params.k() : 0.0;
  const double Y = params.mu * P_N - kc * P_N * P_N;
  return std::abs(P_T) >= Y ? StateLabel::kD : StateLabel::kC;
}

namespace {

/// Running sums of the march (copied into the result at the end).
struct Sums {
  double work_abs = 0, wear_integral = 0, total_slip = 0, thermal = 0;
};

/// The name of the first non-finite quantity of a new state or of the running sums, or null.
const char* first_non_finite(const SimulationSample& s, const Sums& r) noexcept {
  struct {
    const char* name;
    double v;
  } const q[] = {{"P_T", s.P_T}, {"P_N", s.P_N}, {"w_T", s.w_T}, {"w_N", s.w_N},
                 {"w_w", s.w_w}, {"w_Ti", s.w_Ti}, {"g", s.g}, {"the dissipation", s.dissipation},
                 {"the dissipated energy", s.dissipation_total},
                 {"the external work", s.work_total}, {"the stored energy", s.stored},
                 {"the temperature", s.temperature}, {"the work scale", r.work_abs},
                 {"the wear integral", r.wear_integral}, {"the total slip", r.total_slip},
                 {"the thermal dissipation", r.thermal}};
  for (const auto& x : q)
    if (!std::isfinite(x.v)) return x.name;
  return nullptr;
}

std::string describe(const SimulationSample& s) {
  std::ostringstream o;
  o.precision(10);
  o << "t = " << s.t << " (step " << s.step << "), state " << to_string(s.state)
    << ": P_T = " << s.P_T << ", P_N = " << s.P_N << ", g = " << s.g << ", w_T = " << s.w_T
    << ", w_N = " << s.w_N << ", w^w = " << s.w_w << ", F = (" << s.F_T << ", " << s.F_N << ")";
  return o.str();
}

/// Checks the first load point; returns the index of the first point to march to (1 when point
/// 0 is the unloaded start at t <= 0, whose t then becomes the start time of `cur`).
std::size_t start_of_run(const LoadPoint& front, SimulationSample& cur, double& t_prev) {
  if (!std::isfinite(front.t) || !std::isfinite(front.F_T) || !std::isfinite(front.F_N))
    throw InputError("load history: load point 0 (t = " + std::to_string(front.t) +
                     ") has a non-finite value");
  if (front.t > 0) return 0;
  // A leading unloaded point at t <= 0 is the start of the run; any other load needs t > 0.
  if (front.F_T != 0 || front.F_N != 0)
    throw InputError("load history: the run starts unloaded at t = 0, so the first point "
                     "needs t > 0 unless it is the unloaded start (F = 0); got t = " +
                     std::to_string(front.t));
  t_prev = front.t;
  cur.t = front.t;
  return 1;
}

/// Points of a generated history are checked as they are reached.
void check_load_point(const LoadPoint& lp, std::size_t k, double t_last) {
  if (!std::isfinite(lp.t) || !std::isfinite(lp.F_T) || !std::isfinite(lp.F_N))
    throw InputError("load history: load point " + std::to_string(k) + " (t = " +
                     std::to_string(lp.t) + ") has a non-finite value");
  if (!(lp.t > t_last))
    throw InputError("load history: load point " + std::to_string(k) + ": t = " +
                     std::to_string(lp.t) + " does not increase (previous " +
                     std::to_string(t_last) + ")");
}

/// The load point in the stop messages: "t (load (F_T, F_N))".
std::string load_text(const LoadPoint& lp) {
  return num_text(lp.t) + " (load (" + num_text(lp.F_T) + ", " + num_text(lp.F_N) + "))";
}

/// Why a step has no solution to march on (pts.n == 0), with the outcome that says it.
std::string no_solution_why(const StepPoints& pts, const StepProblem& sp,
                            SimulationResult::Outcome& outcome) {
  std::ostringstream m;
  if (pts.infinite) {
    outcome = SimulationResult::Outcome::kContinuum;
    m << "the step's solutions form a continuum (degenerate data); no rule can choose. ";
  } else {
    outcome = SimulationResult::Outcome::kNoSolution;
    if (pts.undecided > 0)
      m << "no step solution was verified, and " << pts.undecided
        << " candidate(s) could be neither verified nor rejected (ill-conditioned data: "
           "inconclusive). ";
    else
      m << "the step has no solution (complete active-set enumeration: no separation, "
           "stick or slip solution satisfies the step NCP). ";
    if (sp.params.criterion == Criterion::kSoftening && sp.params.k() > 0)
      m << "Criterion (35) admits no P_N above 3 P_s mu / k_a = " << sp.params.mu / sp.params.k()
        << " (condition (46)). ";
  }
  return m.str();
}

/// The branch rule 'closest': the solution with the smallest |DP_T| + |DP_N| + (detA/D0)|Dw_Ti|.
int closest_solution(const StepPoints& pts, double xi_weight) {
  int best = 0;
  double bd = INFINITY;
  for (int i = 0; i < pts.n; ++i) {
    const StepValues& v = pts.points[i].values;
    const double d = std::abs(v.DP_T) + std::abs(v.DP_N) + xi_weight * std::abs(v.Dw_Ti);
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return best;
}

/// The state after a step to `lp` along `chosen`, placed exactly on its active constraints, with
/// the step's dissipation and the energy totals (no check of finiteness here); dW is the work
/// of the external load over the step (trapezoidal rule).
SimulationSample advance(const SimulationSample& cur, const LoadPoint& lp, const StepPoint& chosen,
                         int count, const ContactParameters& a, double kc, double& dW) {
  const StepValues& v = chosen.values;
  SimulationSample nx = cur;
  nx.t = lp.t;
  nx.F_T = lp.F_T;
  nx.F_N = lp.F_N;
  nx.type = chosen.type;
  nx.count = count;
  nx.w_T = cur.w_T + v.Dw_T;
  nx.w_N = cur.w_N + v.Dw_N;
  nx.w_w = cur.w_w + v.Dw_w;
  nx.w_Ti = cur.w_Ti + v.Dw_Ti;
  const detail::PlacedPoint placed = detail::place_on_constraints(v, chosen.type, a.mu, kc);
  nx.P_N = placed.P_N;
  nx.P_T = placed.P_T;
  nx.g = placed.g;
  nx.state = step_state_label(a, nx.P_T, nx.P_N, nx.g);
  // Thermodynamics.
  const double D = detail::step_dissipation(v);
  nx.dissipation = D;
  dW = detail::step_work(cur.F_T, cur.F_N, lp.F_T, lp.F_N, v);
  nx.work_total = cur.work_total + dW;
  nx.dissipation_total = cur.dissipation_total + D;
  nx.stored = 0.5 * (a.a11 * nx.w_T * nx.w_T + 2 * a.a12 * nx.w_T * nx.w_N +
                     a.a22 * nx.w_N * nx.w_N) +
              0.5 * a.C_T * nx.P_T * nx.P_T;
  return nx;
}

/// Slip and wear of a step of a cyclic history, added to the cycle its midpoint falls in.
void add_to_cycle(SimulationResult& res, const LoadSource& history, double t_prev, double t,
                  const StepValues& v) {
  std::size_t c = 0;
  if (!detail::step_cycle(history.period, history.cycle_start, t_prev, t, c)) return;
  if (c >= res.slip_per_cycle.size()) {
    res.slip_per_cycle.resize(c + 1, 0.0);
    res.wear_per_cycle.resize(c + 1, 0.0);
  }
  res.slip_per_cycle[c] += std::abs(v.Dw_Ti);  // <= total_slip: finite
  res.wear_per_cycle[c] += v.Dw_w;              // <= w_w - w_w(0): finite
}

/// The totals of the result from the last state and the running sums.
void finish(SimulationResult& res, const SimulationSample& cur, const Sums& sums, double min_D) {
  res.work_abs = sums.work_abs;
  res.wear_integral = sums.wear_integral;
  res.total_slip = sums.total_slip;
  res.thermal_dissipation = sums.thermal;
  res.final_state = cur;
  res.wear_depth = cur.w_w;
  res.external_work = cur.work_total;
  res.stored_energy = cur.stored;
  res.dissipation = cur.dissipation_total;
  res.min_step_dissipation = min_D;
  res.energy_error = std::abs(res.external_work - res.stored_energy - res.dissipation) /
                     std::max(res.work_abs, 1e-300);
  if (res.outcome == SimulationResult::Outcome::kCompleted)
    res.message = detail::completed_message(res.steps, describe(cur));
}

}  // namespace

SimulationResult simulate(const LoadHistory& history, const SimulationOptions& opt) {
  throw_if_invalid(history.validate(), "load history");
  return simulate(history_source(history), opt);
}

SimulationResult simulate(const LoadSource& history, const SimulationOptions& opt) {
  throw_if_invalid(opt.validate(), "simulation");
  if (history.size == 0 || !history.at) throw InputError("load history: the load history is empty");
  if (!std::isfinite(history.period) || history.period < 0)
    throw InputError("load history: period must be finite and >= 0");
  if (!std::isfinite(history.cycle_start))
    throw InputError("load history: cycle_start must be finite");
  const ContactParameters& a = opt.params;
  const double xi_weight = a.detA() / a.D0();
  SimulationResult res;
  StepProblem sp;
  sp.params = a;
  sp.wear = opt.wear;
  const double cw = sp.wear_coefficient();
  const double kc = sp.softening();

  // The state: unloaded, grazing (state b), at t = 0.
  SimulationSample cur;
  cur.t = 0;
  cur.temperature = opt.heat.T_initial;
  cur.state = StateLabel::kB;
  double T = opt.heat.T_initial;
  res.max_temperature = T;
  const std::size_t n = history.size;
  const bool streaming = static_cast<bool>(opt.on_sample);
  auto record = [&](const SimulationSample& smp) {
    if (streaming) opt.on_sample(smp);
    else res.series.push_back(smp);
  };
  if (opt.record_every > 0 && !streaming) res.series.reserve(n / opt.record_every + 2);
  double t_prev = 0;
  // The start sample waits for the first point (a leading unloaded point sets its t).
  const std::size_t first = start_of_run(history.at(0), cur, t_prev);
  if (opt.record_every > 0) record(cur);
  double t_last = cur.t;
  double min_D = 0;
  Sums sums;
  StepPoints pts;
  for (std::size_t k = first; k < n; ++k) {
    const LoadPoint lp = history.at(k);
    if (k > 0) check_load_point(lp, k, t_last);
    t_last = lp.t;
    sp.state.P_T0 = cur.P_T;
    sp.state.P_N0 = cur.P_N;
    sp.state.g0 = cur.g;
    sp.load.dF_T = lp.F_T - cur.F_T;
    sp.load.dF_N = lp.F_N - cur.F_N;
    const StepNcp ncp = build_step_ncp_unchecked(sp);
    enumerate_step_points(sp, ncp, pts, opt.tol);
    if (pts.unrepresentable > 0) {
      // As `cpkit step` and `cpkit rate`: a solution beyond double's range is refused.
      std::ostringstream m;
      m << "step to t = " << lp.t << " (load (" << lp.F_T << ", " << lp.F_N
        << ")): a solution is not representable in double precision (it overflows in these "
           "units)";
      throw InputError(m.str());
    }
    if (pts.n == 0) {
      const std::string why = no_solution_why(pts, sp, res.outcome);
      res.message = detail::stop_message(load_text(lp), why, describe(cur));
      break;
    }
    int best = 0;
    if (pts.n > 1) {
      best = closest_solution(pts, xi_weight);
      ++res.branch_steps;
      if (static_cast<int>(res.branch_points.size()) < opt.max_branch_records) {
        BranchPoint bp;
        bp.step = res.steps + 1;
        bp.t = lp.t;
        bp.count = pts.n;
        for (int i = 0; i < pts.n; ++i) bp.types |= 1u << static_cast<int>(pts.points[i].type);
        bp.chosen = pts.points[best].type;
        res.branch_points.push_back(bp);
      }
      if (opt.branch_rule == BranchRule::kStop) {
        res.outcome = SimulationResult::Outcome::kBranchStop;
        res.message = detail::stop_message(num_text(lp.t),
                                           detail::branch_stop_why(static_cast<std::size_t>(pts.n)),
                                           describe(cur));
        break;
      }
    }
    const StepPoint& chosen = pts.points[best];
    const StepValues& v = chosen.values;
    res.max_residual = std::max(res.max_residual, ncp.residual(step_unknowns(v)));
    double dW = 0;
    SimulationSample nx = advance(cur, lp, chosen, pts.n, a, kc, dW);
    nx.step = res.steps + 1;
    if (nx.dissipation < 0) min_D = std::min(min_D, detail::relative_dissipation(v, a.mu));
    // The running sums after this step (committed below once everything is finite).
    Sums next = sums;
    next.work_abs += std::abs(dW);
    next.wear_integral += cw * std::max(v.P_N1, 0.0) * std::abs(v.Dw_Ti);
    next.total_slip += std::abs(v.Dw_Ti);
    double T_next = T;
    if (opt.heat.enabled) {
      const double dt = lp.t - t_prev;
      next.thermal += thermal_dissipation(opt.heat, T, dt);
      T_next = heat_step(opt.heat, T, std::max(nx.dissipation, 0.0), dt);
    }
    nx.temperature = T_next;
    if (const char* bad = first_non_finite(nx, next)) {
      // Data beyond the range of double (e.g. loads near 1e300, whose energies overflow): an
      // honest stop before this step, never a "completed" run with inf/NaN in its results.
      res.outcome = SimulationResult::Outcome::kNumericalFailure;
      res.message = detail::stop_message(
          num_text(lp.t),
          std::string(bad) +
              " would not be finite (the values exceed the range of double; rescale the data). ",
          describe(cur));
      break;
    }
    sums = next;
    T = T_next;
    res.max_temperature = std::max(res.max_temperature, T);
    add_to_cycle(res, history, t_prev, lp.t, v);
    t_prev = lp.t;
    cur = nx;
    ++res.steps;
    if (opt.record_every > 0 && (res.steps % opt.record_every == 0 || k + 1 == n))
      record(cur);
  }
  finish(res, cur, sums, min_D);
  return res;
}

}  // namespace cpkit::rate
