#include "cpkit/rate_problem/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
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

template <>
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

/// Why a step has no solution to march on (pts.n == 0), with the outcome that says it.
detail::MarchStop no_solution_stop(const StepPoints& pts, const StepProblem& sp) {
  std::ostringstream m;
  SimulationOutcome outcome = SimulationOutcome::kNoSolution;
  if (pts.infinite) {
    outcome = SimulationOutcome::kContinuum;
    m << "the step's solutions form a continuum (degenerate data); no rule can choose. ";
  } else {
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
  return {outcome, m.str()};
}

/// The march of one 2-D point (detail::run_march): every step by complete active-set
/// enumeration, verified by its NCP residual.
class PointMarch {
 public:
  using Point = LoadPoint;
  using Sample = SimulationSample;
  using Step = StepPoints;
  using Result = SimulationResult;
  using Options = SimulationOptions;
  static constexpr bool kCountsStoppedBranch = true;

  PointMarch(const SimulationOptions& opt, const LoadSource& load)
      : opt_(opt), load_(load), a_(opt.params), xi_weight_(a_.detA() / a_.D0()) {
    sp_.params = a_;
    sp_.wear = opt.wear;
    cw_ = sp_.wear_coefficient();
    kc_ = sp_.softening();
  }

  /// Unloaded, grazing (state b) at t = 0; a leading unloaded point at t <= 0 is the start of
  /// the run (its t becomes the start time); any other load needs t > 0.
  Sample start(const LoadPoint& front, double& t_prev, std::size_t& k0) const {
    check(front, 0, 0);
    Sample cur;
    cur.temperature = opt_.heat.T_initial;
    if (front.t > 0) return cur;
    if (front.F_T != 0 || front.F_N != 0)
      throw InputError("load history: the run starts unloaded at t = 0, so the first point "
                       "needs t > 0 unless it is the unloaded start (F = 0); got t = " +
                       std::to_string(front.t));
    t_prev = cur.t = front.t;
    k0 = 1;
    return cur;
  }

  /// Points of a generated history are checked as they are reached (point 0 also by start).
  void check(const LoadPoint& lp, std::size_t k, double t_last) const {
    if (!std::isfinite(lp.t) || !std::isfinite(lp.F_T) || !std::isfinite(lp.F_N))
      throw InputError("load history: load point " + std::to_string(k) + " (t = " +
                       std::to_string(lp.t) + ") has a non-finite value");
    if (k > 0 && !(lp.t > t_last))
      throw InputError("load history: load point " + std::to_string(k) + ": t = " +
                       std::to_string(lp.t) + " does not increase (previous " +
                       std::to_string(t_last) + ")");
  }

  std::optional<detail::MarchStop> solve(const Sample& cur, const LoadPoint& lp, StepPoints& pts,
                                         Result&) {
    sp_.state.P_T0 = cur.P_T;
    sp_.state.P_N0 = cur.P_N;
    sp_.state.g0 = cur.g;
    sp_.load.dF_T = lp.F_T - cur.F_T;
    sp_.load.dF_N = lp.F_N - cur.F_N;
    ncp_ = build_step_ncp_unchecked(sp_);
    enumerate_step_points(sp_, ncp_, pts, opt_.tol);
    if (pts.unrepresentable > 0) {
      // As `cpkit step` and `cpkit rate`: a solution beyond double's range is refused.
      std::ostringstream m;
      m << "step to t = " << lp.t << " (load (" << lp.F_T << ", " << lp.F_N
        << ")): a solution is not representable in double precision (it overflows in these "
           "units)";
      throw InputError(m.str());
    }
    return std::nullopt;
  }

  std::size_t count(const StepPoints& pts) const { return static_cast<std::size_t>(pts.n); }
  detail::MarchStop no_solution(const StepPoints& pts, Result&) const {
    return no_solution_stop(pts, sp_);
  }
  std::optional<detail::MarchStop> ambiguous(const StepPoints&) const { return std::nullopt; }

  /// The branch rule 'closest': the solution with the smallest |DP_T| + |DP_N| +
  /// (detA/D0)|Dw_Ti|; the first max_branch_records branch points are recorded.
  std::size_t choose(const StepPoints& pts, const LoadPoint& lp, Result& res) const {
    int best = 0;
    double bd = INFINITY;
    for (int i = 0; i < pts.n; ++i) {
      const StepValues& v = pts.points[i].values;
      const double d = std::abs(v.DP_T) + std::abs(v.DP_N) + xi_weight_ * std::abs(v.Dw_Ti);
      if (d < bd) {
        bd = d;
        best = i;
      }
    }
    if (static_cast<int>(res.branch_points.size()) < opt_.max_branch_records) {
      BranchPoint bp;
      bp.step = res.steps + 1;
      bp.t = lp.t;
      bp.count = pts.n;
      for (int i = 0; i < pts.n; ++i) bp.types |= 1u << static_cast<int>(pts.points[i].type);
      bp.chosen = pts.points[best].type;
      res.branch_points.push_back(bp);
    }
    return static_cast<std::size_t>(best);
  }

  /// The state after the step along the chosen solution, placed exactly on its active
  /// constraints, with the step's dissipation and the energy totals; the running sums are
  /// committed once everything is finite.
  std::optional<detail::MarchStop> advance(const Sample& cur, const LoadPoint& lp,
                                           const StepPoints& pts, std::size_t chosen,
                                           double t_prev, Result& res, Sample& nx) {
    const StepPoint& sol = pts.points[chosen];
    const StepValues& v = sol.values;
    res.max_residual = std::max(res.max_residual, ncp_.residual(step_unknowns(v)));
    nx.F_T = lp.F_T;
    nx.F_N = lp.F_N;
    nx.type = sol.type;
    nx.w_T = cur.w_T + v.Dw_T;
    nx.w_N = cur.w_N + v.Dw_N;
    nx.w_w = cur.w_w + v.Dw_w;
    nx.w_Ti = cur.w_Ti + v.Dw_Ti;
    const detail::PlacedPoint placed = detail::place_on_constraints(v, sol.type, a_.mu, kc_);
    nx.P_N = placed.P_N;
    nx.P_T = placed.P_T;
    nx.g = placed.g;
    nx.state = step_state_label(a_, nx.P_T, nx.P_N, nx.g);
    // Thermodynamics.
    const double D = detail::step_dissipation(v);
    nx.dissipation = D;
    const double dW = detail::step_work(cur.F_T, cur.F_N, lp.F_T, lp.F_N, v);
    nx.work_total = cur.work_total + dW;
    nx.dissipation_total = cur.dissipation_total + D;
    nx.stored = 0.5 * (a_.a11 * nx.w_T * nx.w_T + 2 * a_.a12 * nx.w_T * nx.w_N +
                       a_.a22 * nx.w_N * nx.w_N) +
                0.5 * a_.C_T * nx.P_T * nx.P_T;
    if (D < 0)
      res.min_step_dissipation =
          std::min(res.min_step_dissipation, detail::relative_dissipation(v, a_.mu));
    // The running sums after this step (committed below once everything is finite).
    Sums next = sums_;
    next.work_abs += std::abs(dW);
    next.wear_integral += cw_ * std::max(v.P_N1, 0.0) * std::abs(v.Dw_Ti);
    next.total_slip += std::abs(v.Dw_Ti);
    double T_next = cur.temperature;
    if (opt_.heat.enabled) {
      const double dt = lp.t - t_prev;
      next.thermal += thermal_dissipation(opt_.heat, cur.temperature, dt);
      T_next = heat_step(opt_.heat, cur.temperature, std::max(D, 0.0), dt);
    }
    nx.temperature = T_next;
    if (const char* bad = first_non_finite(nx, next)) {
      // Data beyond the range of double (e.g. loads near 1e300, whose energies overflow): an
      // honest stop before this step, never a "completed" run with inf/NaN in its results.
      return detail::MarchStop{
          SimulationOutcome::kNumericalFailure,
          std::string(bad) +
              " would not be finite (the values exceed the range of double; rescale the data). "};
    }
    sums_ = next;
    res.max_temperature = std::max(res.max_temperature, T_next);
    add_to_cycle(res, t_prev, lp.t, v);
    return std::nullopt;
  }

  /// The load of a stop: with its forces when the step has no solution.
  std::string at(const LoadPoint& lp, SimulationOutcome o) const {
    if (o != SimulationOutcome::kNoSolution && o != SimulationOutcome::kContinuum)
      return num_text(lp.t);
    return num_text(lp.t) + " (load (" + num_text(lp.F_T) + ", " + num_text(lp.F_N) + "))";
  }
  std::string describe(const Sample& s) const {
    std::ostringstream o;
    o.precision(10);
    o << "t = " << s.t << " (step " << s.step << "), state " << to_string(s.state)
      << ": P_T = " << s.P_T << ", P_N = " << s.P_N << ", g = " << s.g << ", w_T = " << s.w_T
      << ", w_N = " << s.w_N << ", w^w = " << s.w_w << ", F = (" << s.F_T << ", " << s.F_N << ")";
    return o.str();
  }

  /// The totals of the result from the last state and the running sums.
  void finish(Result& res) const {
    const Sample& cur = res.final_state;
    res.work_abs = sums_.work_abs;
    res.wear_integral = sums_.wear_integral;
    res.total_slip = sums_.total_slip;
    res.thermal_dissipation = sums_.thermal;
    res.wear_depth = cur.w_w;
    res.external_work = cur.work_total;
    res.stored_energy = cur.stored;
    res.dissipation = cur.dissipation_total;
    res.energy_error = std::abs(res.external_work - res.stored_energy - res.dissipation) /
                       std::max(res.work_abs, 1e-300);
  }

 private:
  /// Slip and wear of a step of a cyclic history, added to the cycle its midpoint falls in.
  void add_to_cycle(Result& res, double t_prev, double t, const StepValues& v) const {
    std::size_t c = 0;
    if (!detail::step_cycle(load_.period, load_.cycle_start, t_prev, t, c)) return;
    if (c >= res.slip_per_cycle.size()) {
      res.slip_per_cycle.resize(c + 1, 0.0);
      res.wear_per_cycle.resize(c + 1, 0.0);
    }
    res.slip_per_cycle[c] += std::abs(v.Dw_Ti);  // <= total_slip: finite
    res.wear_per_cycle[c] += v.Dw_w;              // <= w_w - w_w(0): finite
  }

  const SimulationOptions& opt_;
  const LoadSource& load_;
  const ContactParameters& a_;
  const double xi_weight_;
  StepProblem sp_;
  StepNcp ncp_;
  double cw_ = 0, kc_ = 0;
  Sums sums_;
};

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
  PointMarch march(opt, history);
  SimulationResult res;
  res.max_temperature = opt.heat.T_initial;
  if (opt.record_every > 0 && !opt.on_sample)
    res.series.reserve(history.size / opt.record_every + 2);
  detail::run_march(march, history, opt, res);
  return res;
}

}  // namespace cpkit::rate
