// Fretting of one 3-D point under an elliptic load orbit (fretting_3d.hpp).
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include <Eigen/Cholesky>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "../model/unit_scaling.hpp"
#include "step_march.hpp"

namespace cpkit::rate {

std::string EllipticOrbit::validate() const {
  std::ostringstream m;
  if (!std::isfinite(F_N) || !std::isfinite(a_X) || !std::isfinite(a_Y) ||
      !std::isfinite(angle) || !std::isfinite(period))
    m << "F_N, a_X, a_Y, angle and period must be finite";
  else if (F_N < 0)
    m << "F_N = " << F_N << " must be >= 0";
  else if (!(period > 0))
    m << "period = " << period << " must be > 0";
  else if (cycles < 1)
    m << "cycles = " << cycles << " must be >= 1";
  else if (steps_per_cycle < 2)
    m << "steps_per_cycle = " << steps_per_cycle << " must be >= 2";
  else if (ramp_steps < 1)
    m << "ramp_steps = " << ramp_steps << " must be >= 1";
  else if (!std::isfinite(period / steps_per_cycle) || !(period / steps_per_cycle > 0))
    m << "period / steps_per_cycle must be a positive finite time step";
  return m.str();
}

int EllipticOrbit::lead() const noexcept { return lead_steps < 0 ? steps_per_cycle / 4 : lead_steps; }

std::size_t EllipticOrbit::size() const noexcept {
  return static_cast<std::size_t>(ramp_steps) + static_cast<std::size_t>(lead()) +
         static_cast<std::size_t>(cycles) * static_cast<std::size_t>(steps_per_cycle);
}

LoadPoint3d EllipticOrbit::at(std::size_t i) const noexcept {
  const double h = dt();
  const std::size_t ramp = static_cast<std::size_t>(ramp_steps);
  const std::size_t lead_n = static_cast<std::size_t>(lead());
  const double c = std::cos(angle), s = std::sin(angle);
  auto rotate = [c, s](double x, double y) { return Eigen::Vector2d(c * x - s * y, s * x + c * y); };
  LoadPoint3d p;
  if (i < ramp) {
    const double r = static_cast<double>(i + 1);
    p.t = r * h;
    p.F_N = F_N * r / ramp_steps;
    return p;
  }
  p.F_N = F_N;
  if (i < ramp + lead_n) {
    const double r = static_cast<double>(i - ramp + 1);
    p.t = static_cast<double>(i + 1) * h;
    p.F_T = rotate(a_X * r / static_cast<double>(lead_n), 0.0);
    return p;
  }
  const std::size_t k = i - ramp - lead_n + 1;  // 1 .. cycles * steps_per_cycle
  const std::size_t spc = static_cast<std::size_t>(steps_per_cycle);
  const double two_pi = 2 * std::acos(-1.0);
  // The phase from k modulo the cycle: exact at every cycle end, no drift over long runs.
  const double phase = two_pi * static_cast<double>(k % spc) / static_cast<double>(spc);
  p.t = cycle_start() + static_cast<double>(k) * h;
  p.F_T = rotate(a_X * std::cos(phase), a_Y * std::sin(phase));
  return p;
}

LoadSource3d orbit_source(const EllipticOrbit& orbit) {
  throw_if_invalid(orbit.validate(), "elliptic orbit");
  LoadSource3d src;
  src.size = orbit.size();
  src.at = [orbit](std::size_t i) { return orbit.at(i); };
  src.period = orbit.period;
  src.cycle_start = orbit.cycle_start();
  return src;
}

template <>
std::string Fretting3dOptions::validate() const {
  if (std::string m = params.validate(); !m.empty()) return m;
  if (!std::isfinite(wear.k_M) || wear.k_M < 0)
    return "k_M = " + std::to_string(wear.k_M) + " must be finite and >= 0";
  if (record_every < 0) return "record_every must be >= 0";
  return {};
}

namespace {

bool finite(const Fretting3dSample& s) noexcept {
  return s.P_T.allFinite() && std::isfinite(s.P_N) && std::isfinite(s.g) && s.w_T.allFinite() &&
         std::isfinite(s.w_N) && s.w_Ti.allFinite() && std::isfinite(s.w_w) &&
         std::isfinite(s.dissipation);
}

/// Slip equations near a start, for a step whose enumeration found nothing and is not proved
/// complete (near-double roots of the slip condition): unknowns z = (phi, P_N1, lambda) with
/// P_T1 = mu P_N1 D t(phi), equations g1 = 0 and Dw_T^i = lambda D^-1 t(phi) (equilibrium by
/// step_3d_values). Newton with a central-difference Jacobian and backtracking; a root counts
/// only as a slip solution with P_N1 > 0, lambda > 0 and step_3d_residual <= 1e-9.
bool local_slip_solution(const Step3dProblem& user, Step3dSolution& out) {
  // Newton works with the ellipse in its own unit (lambda / E); the answer is the user's.
  Step3dProblem p = user;
  const double E = detail::normalize_ellipse(p.params);
  const Eigen::Vector2d al = p.params.alpha;
  const double mu = p.params.mu;
  auto F = [&](const Eigen::Vector3d& z) -> Eigen::Vector3d {
    const Eigen::Vector2d t(std::cos(z(0)), std::sin(z(0)));
    const Eigen::Vector2d PT = mu * z(1) * (al.asDiagonal() * t);
    const Step3dValues v = step_3d_values(p, PT, z(1), z(2));
    const Eigen::Vector2d flow = z(2) * (al.cwiseInverse().asDiagonal() * t);
    return Eigen::Vector3d(v.g1, v.Dw_Ti(0) - flow(0), v.Dw_Ti(1) - flow(1));
  };
  const Eigen::Vector2d DF_T = p.DF.head<2>();
  const Eigen::Vector2d t_state = al.cwiseInverse().asDiagonal() * p.state.P_T0;
  const Eigen::Vector2d t_load = al.cwiseInverse().asDiagonal() * DF_T;
  std::vector<double> phis;
  if (t_state.norm() > 0) phis.push_back(std::atan2(t_state(1), t_state(0)));
  if (t_load.norm() > 0) phis.push_back(std::atan2(t_load(1), t_load(0)));
  if (phis.empty()) return false;
  const double PN0 = std::max(p.state.P_N0 + p.DF(2), 1e-3 * (p.state.P_N0 + std::abs(p.DF(2))));
  const Eigen::Matrix2d Att = p.params.A.topLeftCorner<2, 2>();
  const double lam_est = (al.asDiagonal() * Att.llt().solve(DF_T)).norm();
  if (!(PN0 > 0) || !(lam_est > 0)) return false;
  for (const double phi0 : phis)
    for (const double f : {1.0, 0.1, 10.0, 0.01}) {
      Eigen::Vector3d z(phi0, PN0, f * lam_est);
      for (int it = 0; it < 60; ++it) {
        const Eigen::Vector3d r = F(z);
        if (!r.allFinite()) break;
        Eigen::Matrix3d J;
        for (int c = 0; c < 3; ++c) {
          const double h = 1e-7 * std::max(std::abs(z(c)), c == 0 ? 1.0 : 1e-6 * (PN0 + lam_est));
          Eigen::Vector3d zp = z, zm = z;
          zp(c) += h;
          zm(c) -= h;
          J.col(c) = (F(zp) - F(zm)) / (2 * h);
        }
        const Eigen::Vector3d dz = J.fullPivLu().solve(-r);
        if (!dz.allFinite()) break;
        // P_N1 and lambda stay positive (a full step that leaves them halves them instead).
        auto trial = [&z, &dz](double step) {
          Eigen::Vector3d zn = z + step * dz;
          for (int c = 1; c < 3; ++c)
            if (!(zn(c) > 0)) zn(c) = 0.5 * z(c);
          return zn;
        };
        double step = 1;
        Eigen::Vector3d zn = trial(step);
        for (int b = 0; b < 30 && !(F(zn).norm() < r.norm()); ++b) {
          step *= 0.5;
          zn = trial(step);
        }
        z = zn;
        if (!z.allFinite()) break;
        const Eigen::Vector2d t(std::cos(z(0)), std::sin(z(0)));
        Step3dValues v = step_3d_values(p, mu * z(1) * (al.asDiagonal() * t), z(1), z(2));
        v.lambda *= E;
        const Step3dSolution sol = make_step_3d_solution(user, v);
        if (sol.type == SolutionType::kSlip && sol.residual <= 1e-9) {
          out = sol;
          return true;
        }
      }
    }
  return false;
}

/// The march of one 3-D point (detail::run_march): every step by enumerate_step_3d, a step it
/// finds no solution of by the local fallback.
class OrbitMarch {
 public:
  using Point = LoadPoint3d;
  using Sample = Fretting3dSample;
  using Step = Step3dSolutionSet;
  using Result = Fretting3dResult;
  using Options = Fretting3dOptions;
  /// A step the rule 'stop' stops at is not counted in branch_steps (as ever in 3-D).
  static constexpr bool kCountsStoppedBranch = false;

  OrbitMarch(const Fretting3dOptions& opt, const LoadSource3d& load)
      : opt_(opt), load_(load), par_(opt.params),
        mroz_(opt.wear.law == rate::WearLaw::kMrozStupkiewicz),
        k_archard_(par_.k_a / (3 * par_.P_s)) {
    sp_.params = par_;
    sp_.wear = opt.wear;
    // The branch rule's weight: the tangential stiffness with the normal DOF held, through the
    // compliance: K = (I + C_T S)^-1 S, S = A_TT - A_TN A_NT / A_NN (force/length).
    const Eigen::Matrix2d S = par_.A.topLeftCorner<2, 2>() -
                              par_.A.topRightCorner<2, 1>() * par_.A.bottomLeftCorner<1, 2>() /
                                  par_.A(2, 2);
    K_ = (Eigen::Matrix2d::Identity() + par_.C_T * S).partialPivLu().solve(S);
  }

  /// Unloaded, grazing, t = 0.
  Sample start(const LoadPoint3d&, double&, std::size_t&) const { return Sample{}; }

  void check(const LoadPoint3d& lp, std::size_t k, double t_last) const {
    if (!std::isfinite(lp.t) || !lp.F_T.allFinite() || !std::isfinite(lp.F_N))
      throw InputError("3-D fretting: load point " + std::to_string(k) + " is not finite");
    if (!(lp.t > t_last))
      throw InputError("3-D fretting: load point " + std::to_string(k) + ": t = " +
                       std::to_string(lp.t) + " does not increase");
  }

  std::optional<detail::MarchStop> solve(const Sample& cur, const LoadPoint3d& lp, Step& set,
                                         Result& res) {
    sp_.state.P_T0 = cur.P_T;
    sp_.state.P_N0 = cur.P_N;
    sp_.state.g0 = cur.g;
    sp_.DF << lp.F_T - cur.F_T, lp.F_N - cur.F_N;
    set = enumerate_step_3d(sp_);
    if (set.count() > 0 || !opt_.local_fallback) return std::nullopt;
    Step3dSolution sol;
    if (!local_slip_solution(sp_, sol)) return std::nullopt;
    // A verified solution the enumeration did not list: its "complete" was wrong.
    if (set.complete) {
      ++res.enumeration_missed;
      if (res.first_missed.empty()) {
        std::ostringstream m;
        m.precision(17);
        m << "step " << res.steps + 1 << ": P_T0 = (" << sp_.state.P_T0(0) << ", "
          << sp_.state.P_T0(1) << "), P_N0 = " << sp_.state.P_N0 << ", g0 = " << sp_.state.g0
          << ", DF = (" << sp_.DF(0) << ", " << sp_.DF(1) << ", " << sp_.DF(2) << ")";
        res.first_missed = m.str();
      }
    }
    set.complete = false;
    set.solutions.push_back(sol);
    ++res.local_steps;
    return std::nullopt;
  }

  std::size_t count(const Step& set) const { return static_cast<std::size_t>(set.count()); }

  detail::MarchStop no_solution(const Step& set, Result&) const {
    return {SimulationOutcome::kNoSolution,
            set.complete ? "the step has no solution (complete enumeration). "
                         : "no solution found and the enumeration is not proved complete (" +
                               set.message + "). "};
  }

  std::optional<detail::MarchStop> ambiguous(const Step& set) const {
    if (set.complete) return std::nullopt;
    return detail::MarchStop{SimulationOutcome::kAmbiguous,
                             "the step has " + std::to_string(set.count()) +
                                 " solutions and its enumeration is not proved complete (" +
                                 set.message + "): no rule can choose honestly. "};
  }

  /// The branch rule 'closest': the smallest |DP_T| + |DP_N| + |K Dw_T^i|.
  std::size_t choose(const Step& set, const LoadPoint3d&, Result&) const {
    std::size_t best = 0;
    double bd = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < set.solutions.size(); ++i) {
      const Step3dValues& v = set.solutions[i].values;
      const double d = v.DP_T.norm() + std::abs(v.DP_N) + (K_ * v.Dw_Ti).norm();
      if (d < bd) {
        bd = d;
        best = i;
      }
    }
    return best;
  }

  std::optional<detail::MarchStop> advance(const Sample& cur, const LoadPoint3d& lp,
                                           const Step& set, std::size_t chosen, double t_last,
                                           Result& res, Sample& nx) {
    // A step taken with several solutions was proved complete (else ambiguous).
    if (!set.complete) ++res.incomplete_steps;
    const Step3dSolution& sol = set.solutions[chosen];
    const Step3dValues& v = sol.values;
    res.max_residual = std::max(res.max_residual, sol.residual);
    nx.F_T = lp.F_T;
    nx.F_N = lp.F_N;
    nx.type = sol.type;
    nx.complete = set.complete;
    nx.w_T = cur.w_T + v.Dw_T;
    nx.w_N = cur.w_N + v.Dw_N;
    // A stick step has no irreversible slip (Dw_T - C_T DP_T is rounding there).
    const bool stick = sol.type == SolutionType::kStick;
    const Eigen::Vector2d Dw_Ti = stick ? Eigen::Vector2d::Zero() : v.Dw_Ti;
    nx.Dw_Ti = Dw_Ti;
    nx.w_Ti = cur.w_Ti + Dw_Ti;
    nx.lambda = sol.type == SolutionType::kSlip ? v.lambda : 0.0;
    nx.Dw_w = v.Dw_w;
    nx.w_w = cur.w_w + v.Dw_w;
    // The state exactly on its active constraints.
    if (v.P_N1 <= 0 || sol.type == SolutionType::kSeparation || sol.type == SolutionType::kOpen) {
      nx.P_N = 0;
      nx.P_T.setZero();
      nx.g = std::min(v.g1, 0.0);
    } else {
      nx.P_N = v.P_N1;
      nx.g = 0;
      nx.P_T = v.P_T1;
      const double nrm = (par_.alpha.cwiseInverse().asDiagonal() * v.P_T1).norm();
      const double Y = par_.mu * v.P_N1;
      if (nrm > 0 && (sol.type == SolutionType::kSlip || nrm > Y)) nx.P_T *= Y / nrm;
    }
    const double D = v.P_T1.dot(Dw_Ti) + v.P_N1 * v.Dw_w;
    const double D_scale = v.P_T1.norm() * Dw_Ti.norm() + std::abs(v.P_N1 * v.Dw_w);
    nx.dissipation = D;
    const double lam = (par_.alpha.asDiagonal() * Dw_Ti).norm();
    const double wear_law = mroz_ ? opt_.wear.k_M * v.P_T1.dot(Dw_Ti)
                                  : k_archard_ * std::max(v.P_N1, 0.0) * lam;
    if (!finite(nx) || !std::isfinite(wear_law))
      return detail::MarchStop{
          SimulationOutcome::kNumericalFailure,
          "the next state would not be finite (values beyond the range of double; rescale). "};
    // Negative beyond rounding (the step's residual tolerance) is reported.
    if (D < -1e-9 * D_scale) res.min_step_dissipation = std::min(res.min_step_dissipation, D / D_scale);
    res.dissipation += D;
    res.wear_integral += wear_law;
    res.total_slip += Dw_Ti.norm();
    res.total_lambda += lam;
    nx.cycle = -1;
    std::size_t c = 0;
    if (detail::step_cycle(load_.period, load_.cycle_start, t_last, lp.t, c)) {
      nx.cycle = static_cast<long>(c);
      if (c >= res.slip_per_cycle.size()) {
        res.slip_per_cycle.resize(c + 1, 0.0);
        res.wear_per_cycle.resize(c + 1, 0.0);
        res.wear_X_per_cycle.resize(c + 1, 0.0);
        res.wear_Y_per_cycle.resize(c + 1, 0.0);
      }
      res.slip_per_cycle[c] += Dw_Ti.norm();
      res.wear_per_cycle[c] += v.Dw_w;
      if (lam > 0) {
        const double ax = par_.alpha(0) * Dw_Ti(0), ay = par_.alpha(1) * Dw_Ti(1);
        res.wear_X_per_cycle[c] += v.Dw_w * ax * ax / (lam * lam);
        res.wear_Y_per_cycle[c] += v.Dw_w * ay * ay / (lam * lam);
      }
    }
    return std::nullopt;
  }

  /// The load of a stop: its time and forces, 10 digits.
  std::string at(const LoadPoint3d& lp, SimulationOutcome) const {
    return num_text(lp.t, 10) + " (load (" + num_text(lp.F_T(0), 10) + ", " +
           num_text(lp.F_T(1), 10) + ", " + num_text(lp.F_N, 10) + "))";
  }
  std::string describe(const Sample& s) const {
    std::ostringstream o;
    o.precision(10);
    o << "t = " << s.t << " (step " << s.step << "): P_T = (" << s.P_T(0) << ", " << s.P_T(1)
      << "), P_N = " << s.P_N << ", g = " << s.g << ", w^w = " << s.w_w << ", F = (" << s.F_T(0)
      << ", " << s.F_T(1) << ", " << s.F_N << ")";
    return o.str();
  }

  void finish(Result& res) const { res.wear_depth = res.final_state.w_w; }

 private:
  const Fretting3dOptions& opt_;
  const LoadSource3d& load_;
  const ContactParameters3d& par_;
  const bool mroz_;
  const double k_archard_;
  Eigen::Matrix2d K_;
  Step3dProblem sp_;
};

}  // namespace

Fretting3dResult simulate_fretting_3d(const EllipticOrbit& orbit, const Fretting3dOptions& opt) {
  return simulate_fretting_3d(orbit_source(orbit), opt);
}

Fretting3dResult simulate_fretting_3d(const LoadSource3d& load, const Fretting3dOptions& opt) {
  throw_if_invalid(opt.validate(), "3-D fretting");
  if (load.size == 0 || !load.at) throw InputError("3-D fretting: the load is empty");
  if (!std::isfinite(load.period) || load.period < 0 || !std::isfinite(load.cycle_start))
    throw InputError("3-D fretting: period and cycle_start must be finite, period >= 0");
  OrbitMarch march(opt, load);
  Fretting3dResult res;
  detail::run_march(march, load, opt, res);
  return res;
}

}  // namespace cpkit::rate
