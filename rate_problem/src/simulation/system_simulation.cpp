#include "cpkit/rate_problem/simulation/system_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "step_march.hpp"

namespace cpkit::rate {

SystemLoadSource system_fretting_source(const FrettingCycle& cycle, const Eigen::VectorXd& e_T,
                                        const Eigen::VectorXd& e_N) {
  if (e_T.size() != e_N.size() || e_T.size() == 0 || e_T.size() % 2 != 0)
    throw InputError("fretting through patterns: the two patterns need 2N numbers each");
  if (!e_T.allFinite() || !e_N.allFinite())
    throw InputError("fretting through patterns: a pattern value is not finite");
  const LoadSource one = fretting_source(cycle);
  SystemLoadSource s;
  s.size = one.size;
  s.period = one.period;
  s.cycle_start = one.cycle_start;
  s.at = [one, e_T, e_N](std::size_t k) {
    const LoadPoint p = one.at(k);
    return SystemLoadPoint{p.t, p.F_T * e_T + p.F_N * e_N};
  };
  return s;
}

SystemLoadSource system_history_source(const std::vector<SystemLoadPoint>& points, double period) {
  SystemLoadSource s;
  s.size = points.size();
  s.period = period;
  s.at = [&points](std::size_t k) { return points[k]; };
  return s;
}

template <>
std::string SystemSimulationOptions::validate() const {
  std::string m = heat.validate();
  if (!m.empty()) return "heat: " + m;
  if (!(tol > 0) || !std::isfinite(tol)) return "tol must be finite and > 0";
  if (record_every < 0) return "record_every must be >= 0";
  if (max_points < 1) return "max_points must be >= 1";
  return {};
}

namespace {

/// Per point: Archard k, the weight of the slip in the branch distance, C_T.
struct PointConstants {
  Eigen::VectorXd k, xi_weight, C_T;
};

PointConstants point_constants(const SystemStepProblem& sp, int N) {
  PointConstants c{Eigen::VectorXd(N), Eigen::VectorXd(N), Eigen::VectorXd(N)};
  for (int i = 0; i < N; ++i) {
    const StepProblem one = point_step_problem(sp, i);
    c.k[i] = one.params.k();
    c.xi_weight[i] = one.params.detA() / one.params.D0();
    c.C_T[i] = one.params.C_T;
  }
  return c;
}

/// The state the run starts from: the points' P and g of the system file, w = 0, F = 0.
SystemSimulationSample initial_sample(const ContactSystem& system, const SystemStepProblem& sp,
                                      const SystemSimulationOptions& opt) {
  const int N = system.n_points();
  SystemSimulationSample cur;
  cur.F = Eigen::VectorXd::Zero(2 * N);
  cur.w = Eigen::VectorXd::Zero(2 * N);
  cur.P_T.resize(N);
  cur.P_N.resize(N);
  cur.g.resize(N);
  for (int i = 0; i < N; ++i) {
    const SystemPoint& q = system.points[static_cast<std::size_t>(i)];
    cur.P_T[i] = q.P_T;
    cur.P_N[i] = q.P_N;
    cur.g[i] = q.g;
    cur.state.push_back(step_state_label(point_step_problem(sp, i).params, q.P_T, q.P_N, q.g));
  }
  cur.type.assign(static_cast<std::size_t>(N), SolutionType::kStick);
  cur.w_w = cur.w_Ti = Eigen::VectorXd::Zero(N);
  cur.temperature = Eigen::VectorXd::Constant(N, opt.heat.T_initial);
  return cur;
}

/// Enumerates the step's solutions into `set`; returns why a value is not representable in
/// double (loads near 1e308), or an empty string.
std::string enumerate_or_unrepresentable(const SystemStepProblem& sp, const SystemStepOptions& so,
                                         SystemStepSolutionSet& set) {
  if (!sp.DF.allFinite())  // e.g. from -1e308 to 1e308
    return "the load increment F - F_prev exceeds the range of double";
  try {
    set = enumerate_system_step(sp, so);
  } catch (const InputError& e) {
    if (std::string(e.what()).find("not representable") == std::string::npos) throw;
    return e.what();
  }
  return {};
}

/// Point i of `nx` after the step along `sol`, placed exactly on its active constraints, with
/// its dissipation, wear and heat added to `nx` and `res`. Returns the point's external work.
double advance_point(int i, const SystemStepSolution& sol, const SystemStepProblem& sp,
                     const PointConstants& pc, const SystemSimulationSample& cur,
                     const SystemLoadPoint& lp, double dt, const SystemSimulationOptions& opt,
                     SystemSimulationSample& nx, SystemSimulationResult& res) {
  const StepValues& v = sol.values[static_cast<std::size_t>(i)];
  const SolutionType ty = sol.types[static_cast<std::size_t>(i)];
  const ContactParameters a = point_step_problem(sp, i).params;
  nx.type[static_cast<std::size_t>(i)] = ty;
  nx.w[2 * i] += v.Dw_T;
  nx.w[2 * i + 1] += v.Dw_N;
  nx.w_w[i] += v.Dw_w;
  nx.w_Ti[i] += v.Dw_Ti;
  const double dW =
      detail::step_work(cur.F[2 * i], cur.F[2 * i + 1], lp.F[2 * i], lp.F[2 * i + 1], v);
  // The Coulomb criterion (38) only (a system refuses (35)): no softening.
  const detail::PlacedPoint placed = detail::place_on_constraints(v, ty, a.mu, 0.0);
  nx.P_N[i] = placed.P_N;
  nx.P_T[i] = placed.P_T;
  nx.g[i] = placed.g;
  nx.state[static_cast<std::size_t>(i)] = step_state_label(a, nx.P_T[i], nx.P_N[i], nx.g[i]);
  const double D = detail::step_dissipation(v);
  if (D < 0)
    res.min_step_dissipation[i] =
        std::min(res.min_step_dissipation[i], detail::relative_dissipation(v, a.mu));
  res.dissipation[i] += D;
  nx.dissipation_total += D;
  res.wear_integral[i] += pc.k[i] * std::max(v.P_N1, 0.0) * std::abs(v.Dw_Ti);
  res.total_slip[i] += std::abs(v.Dw_Ti);
  if (opt.heat.enabled)
    nx.temperature[i] = heat_step(opt.heat, cur.temperature[i], std::max(D, 0.0), dt);
  res.max_temperature[i] = std::max(res.max_temperature[i], nx.temperature[i]);
  return dW;
}

/// The march of N points (detail::run_march): every step by the N-point enumeration, verified
/// by its unit-free residual.
class SystemMarch {
 public:
  using Point = SystemLoadPoint;
  using Sample = SystemSimulationSample;
  using Step = SystemStepSolutionSet;
  using Result = SystemSimulationResult;
  using Options = SystemSimulationOptions;
  static constexpr bool kCountsStoppedBranch = true;

  SystemMarch(const ContactSystem& system, const SystemSimulationOptions& opt,
              const SystemLoadSource& load)
      : system_(system), opt_(opt), load_(load), N_(system.n_points()) {
    sp_.system = system;
    sp_.DF = Eigen::VectorXd::Zero(2 * N_);
    throw_if_invalid(sp_.validate(), "system");
    so_.tol = opt.tol;
    so_.max_points = opt.max_points;
    pc_ = point_constants(sp_, N_);
  }

  /// The system's points' current P and g, w = 0, F = 0 (and E0, their stored energy).
  Sample start(const SystemLoadPoint&, double&, std::size_t&) {
    Sample cur = initial_sample(system_, sp_, opt_);
    E0_ = 0.5 * ct_energy(cur.P_T);
    return cur;
  }

  void check(const SystemLoadPoint& lp, std::size_t step, double t_prev) const {
    if (lp.F.size() != 2 * N_)
      throw InputError("load point " + std::to_string(step) + " has " +
                       std::to_string(lp.F.size()) + " numbers; " + std::to_string(N_) +
                       " points need " + std::to_string(2 * N_));
    if (!std::isfinite(lp.t) || !lp.F.allFinite())
      throw InputError("load point " + std::to_string(step) + " has a non-finite value");
    if (!(lp.t > t_prev))
      throw InputError("load point " + std::to_string(step) + ": t = " + std::to_string(lp.t) +
                       " does not increase (previous " + std::to_string(t_prev) + ")");
  }

  /// A step whose increment or solution double cannot represent (loads near 1e308) stops the
  /// run as numerical_failure, as an energy beyond double's range does in advance().
  std::optional<detail::MarchStop> solve(const Sample& cur, const SystemLoadPoint& lp,
                                         Step& set, Result& res) {
    for (int i = 0; i < N_; ++i) {
      SystemPoint& q = sp_.system.points[static_cast<std::size_t>(i)];
      q.P_T = cur.P_T[i];
      q.P_N = cur.P_N[i];
      q.g = cur.g[i];
    }
    sp_.DF = lp.F - cur.F;
    const std::string unrepresentable = enumerate_or_unrepresentable(sp_, so_, set);
    if (!unrepresentable.empty())
      return detail::MarchStop{SimulationOutcome::kNumericalFailure, unrepresentable + ". "};
    if (!set.complete) ++res.incomplete_steps;
    return std::nullopt;
  }

  std::size_t count(const Step& set) const { return set.solutions.size(); }

  /// Why a step has no solution to march on; sets `inconclusive` when it is not proved.
  detail::MarchStop no_solution(const Step& set, Result& res) const {
    std::ostringstream m;
    if (set.complete) {
      m << "the step has no solution (complete enumeration of its 4^N active sets). ";
    } else {
      res.inconclusive = true;
      m << "no solution was found and the enumeration is not complete ("
        << (set.notes.empty() ? std::string() : set.notes.front()) << "). ";
    }
    return {SimulationOutcome::kNoSolution, m.str()};
  }
  std::optional<detail::MarchStop> ambiguous(const Step&) const { return std::nullopt; }

  /// The branch rule 'closest', summed over the points.
  std::size_t choose(const Step& set, const SystemLoadPoint&, Result&) const {
    std::size_t best = 0;
    double bd = INFINITY;
    for (std::size_t j = 0; j < set.solutions.size(); ++j) {
      double d = 0;
      for (int i = 0; i < N_; ++i) {
        const StepValues& v = set.solutions[j].values[static_cast<std::size_t>(i)];
        d += std::abs(v.DP_T) + std::abs(v.DP_N) + pc_.xi_weight[i] * std::abs(v.Dw_Ti);
      }
      if (d < bd) {
        bd = d;
        best = j;
      }
    }
    return best;
  }

  std::optional<detail::MarchStop> advance(const Sample& cur, const SystemLoadPoint& lp,
                                           const Step& set, std::size_t chosen, double t_prev,
                                           Result& res, Sample& nx) const {
    const SystemStepSolution& sol = set.solutions[chosen];
    res.max_residual = std::max(res.max_residual, sol.residual);
    nx.F = lp.F;
    nx.complete = set.complete;
    double dW = 0;
    const double dt = lp.t - t_prev;
    for (int i = 0; i < N_; ++i) dW += advance_point(i, sol, sp_, pc_, cur, lp, dt, opt_, nx, res);
    nx.work_total += dW;
    res.work_abs += std::abs(dW);
    nx.stored = 0.5 * nx.w.dot(system_.A * nx.w) + 0.5 * ct_energy(nx.P_T);
    if (!nx.w.allFinite() || !std::isfinite(nx.stored) || !std::isfinite(nx.work_total))
      return detail::MarchStop{SimulationOutcome::kNumericalFailure,
                               "the values exceed the range of double. "};
    add_to_cycle(res, t_prev, lp.t, sol);
    return std::nullopt;
  }

  /// The load of a stop: its time, as std::to_string writes it for a value beyond double.
  std::string at(const SystemLoadPoint& lp, SimulationOutcome o) const {
    return o == SimulationOutcome::kNumericalFailure ? std::to_string(lp.t) : num_text(lp.t);
  }
  std::string describe(const Sample& s) const {
    std::ostringstream o;
    o.precision(8);
    o << "t = " << s.t << " (step " << s.step << "), states ";
    for (std::size_t i = 0; i < s.state.size(); ++i) o << (i ? "/" : "") << to_string(s.state[i]);
    return o.str();
  }

  void finish(Result& res) const {
    const Sample& cur = res.final_state;
    res.external_work = cur.work_total;
    res.stored_energy = cur.stored;
    res.energy_error =
        std::abs(res.external_work - (res.stored_energy - E0_) - cur.dissipation_total) /
        std::max(res.work_abs, 1e-300);
    if (res.outcome == SimulationOutcome::kCompleted && res.incomplete_steps > 0)
      res.message += "; " + std::to_string(res.incomplete_steps) +
                     " steps had an enumeration not proved complete (m >= 3 points slipping "
                     "with wear)";
  }

 private:
  double ct_energy(const Eigen::VectorXd& P_T) const {
    return pc_.C_T.dot(P_T.cwiseProduct(P_T));
  }

  /// Wear of a step of a cyclic history, added per point to the cycle its midpoint falls in.
  void add_to_cycle(Result& res, double t_prev, double t, const SystemStepSolution& sol) const {
    std::size_t c = 0;
    if (!detail::step_cycle(load_.period, load_.cycle_start, t_prev, t, c)) return;
    while (res.wear_per_cycle.size() <= c) res.wear_per_cycle.push_back(Eigen::VectorXd::Zero(N_));
    for (int i = 0; i < N_; ++i)
      res.wear_per_cycle[c][i] += sol.values[static_cast<std::size_t>(i)].Dw_w;
  }

  const ContactSystem& system_;
  const SystemSimulationOptions& opt_;
  const SystemLoadSource& load_;
  const int N_;
  SystemStepProblem sp_;
  SystemStepOptions so_;
  PointConstants pc_;
  double E0_ = 0;
};

}  // namespace

SystemSimulationResult simulate_system(const ContactSystem& system, const SystemLoadSource& load,
                                       const SystemSimulationOptions& opt) {
  throw_if_invalid(opt.validate(), "simulation");
  const int N = system.n_points();
  if (N > opt.max_points)
    throw InputError("the N-point simulation enumerates 4^N active sets per step; " +
                     std::to_string(N) + " points exceed the limit of " +
                     std::to_string(opt.max_points));
  if (load.size == 0 || !load.at) throw InputError("load history: the load history is empty");
  SystemMarch march(system, opt, load);
  SystemSimulationResult res;
  res.wear_integral = res.total_slip = res.dissipation = res.min_step_dissipation =
      Eigen::VectorXd::Zero(N);
  res.max_temperature = Eigen::VectorXd::Constant(N, opt.heat.T_initial);
  detail::run_march(march, load, opt, res);
  return res;
}

std::vector<SystemLoadPoint> parse_system_load_csv(const std::string& text,
                                                   const std::string& origin, int N) {
  std::vector<SystemLoadPoint> pts;
  for_each_csv_row(text, origin, [&](const std::vector<double>& v, const std::string& where) {
    if (static_cast<int>(v.size()) != 2 * N + 1)
      throw InputError(where + ": " + std::to_string(v.size()) +
                       " values; a system of " + std::to_string(N) + " points needs t and " +
                       std::to_string(2 * N) + " forces");
    SystemLoadPoint p;
    p.t = v[0];
    p.F = Eigen::Map<const Eigen::VectorXd>(v.data() + 1, 2 * N);
    pts.push_back(p);
  });
  if (pts.empty()) throw InputError(origin + ": the load history is empty");
  return pts;
}

}  // namespace cpkit::rate
