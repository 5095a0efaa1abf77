// The MPCC driver: relaxation/penalty sequence, then the piece-NLP polish (see mpcc.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cpkit/core/enum_names.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/mpcc.hpp"
#include "mpcc_nlp.hpp"

namespace cpkit::lcp {

namespace {

constexpr EnumName<MpccReformulation> kReformulationNames[] = {
    {MpccReformulation::kScholtes, "scholtes"},
    {MpccReformulation::kPenalty, "penalty"},
    {MpccReformulation::kPenalty, "l1-penalty"},
};
constexpr EnumName<NlpBackend> kBackendNames[] = {
    {NlpBackend::kIpopt, "ipopt"},
    {NlpBackend::kNlopt, "nlopt"},
};

}  // namespace

std::string_view to_string(MpccReformulation r) noexcept { return name_of(kReformulationNames, r); }

std::optional<MpccReformulation> mpcc_reformulation_from_string(std::string_view s) noexcept {
  return value_of(kReformulationNames, s);
}

std::string_view to_string(NlpBackend b) noexcept { return name_of(kBackendNames, b); }

std::optional<NlpBackend> nlp_backend_from_string(std::string_view s) noexcept {
  return value_of(kBackendNames, s);
}

namespace {

bool sized(const Vec& v, Eigen::Index n) { return v.size() == n; }

}  // namespace

std::string MpccProblem::validate() const {
  if (n <= 0) return "n = " + std::to_string(n) + " must be positive";
  if (m < 0 || p < 0) return "m and p must be non-negative";
  if (lower.size() != 0 && !sized(lower, n))
    return "lower has size " + std::to_string(lower.size()) + ", expected " + std::to_string(n);
  if (upper.size() != 0 && !sized(upper, n))
    return "upper has size " + std::to_string(upper.size()) + ", expected " + std::to_string(n);
  if (x0.size() != 0 && !sized(x0, n))
    return "x0 has size " + std::to_string(x0.size()) + ", expected " + std::to_string(n);
  if (x0.size() != 0 && !x0.allFinite()) return "x0 has non-finite entries";
  for (Eigen::Index i = 0; i < lower.size(); ++i)
    if (std::isnan(lower(i)) || lower(i) == std::numeric_limits<double>::infinity())
      return "lower[" + std::to_string(i) + "] is NaN or +inf";
  for (Eigen::Index i = 0; i < upper.size(); ++i)
    if (std::isnan(upper(i)) || upper(i) == -std::numeric_limits<double>::infinity())
      return "upper[" + std::to_string(i) + "] is NaN or -inf";
  if (lower.size() == n && upper.size() == n)
    for (Eigen::Index i = 0; i < n; ++i)
      if (lower(i) > upper(i)) return "lower[" + std::to_string(i) + "] > upper[" +
                                      std::to_string(i) + "]";
  if (objective && !gradient) return "objective given without gradient";
  if (m > 0) {
    if (!constraints || !constraint_jacobian) return "m > 0 but constraints or jacobian missing";
    if (!sized(c_lower, m) || !sized(c_upper, m)) return "c_lower/c_upper must have size m";
    for (Eigen::Index j = 0; j < m; ++j)
      if (std::isnan(c_lower(j)) || std::isnan(c_upper(j)) || c_lower(j) > c_upper(j))
        return "c_lower[" + std::to_string(j) + "] / c_upper[" + std::to_string(j) +
               "] are NaN or crossed";
  }
  if (p > 0 && (!G || !H || !G_jacobian || !H_jacobian))
    return "p > 0 but G, H or their Jacobians are missing";
  return {};
}

std::string MpccOptions::validate() const {
  if (auto msg = common.validate(); !msg.empty()) return msg;
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(t_initial)) return "t_initial = " + short_number(t_initial) + " must be > 0";
  if (!(t_factor > 0 && t_factor < 1)) return "t_factor = " + short_number(t_factor) + " must be in (0, 1)";
  if (!positive(t_min) || t_min > t_initial)
    return "t_min = " + short_number(t_min) + " must be in (0, t_initial]";
  if (!positive(rho_initial)) return "rho_initial = " + short_number(rho_initial) + " must be > 0";
  if (!(std::isfinite(rho_factor) && rho_factor > 1))
    return "rho_factor = " + short_number(rho_factor) + " must be > 1";
  if (!(rho_max >= rho_initial) || !std::isfinite(rho_max))
    return "rho_max = " + short_number(rho_max) + " must be finite and >= rho_initial";
  if (!positive(feasibility_tol)) return "feasibility_tol must be > 0";
  if (!positive(complementarity_tol)) return "complementarity_tol must be > 0";
  if (!positive(nlp_tol)) return "nlp_tol = " + short_number(nlp_tol) + " must be > 0";
  if (max_subproblems < 1) return "max_subproblems = " + std::to_string(max_subproblems) + " < 1";
  return {};
}

namespace {

/// ||x||_inf beyond kDivergence * (1 + ||x_start||_inf) counts as diverged.
constexpr double kDivergence = 1e10;

using detail::NlpEvaluator;
using detail::NlpOutcome;
using detail::PairMode;

/// Feasibility and complementarity of x, from the problem data only.
struct Measure {
  bool ok = false;
  double f = 0, complementarity = 0, infeasibility = 0, scale = 0;
  Vec G, H;
};

Measure measure(const MpccProblem& p, const Vec& x) {
  Measure r;
  if (x.size() != p.n || !x.allFinite()) return r;
  double inf = 0, scale = 0;
  for (Eigen::Index i = 0; i < p.n; ++i) {
    if (p.lower.size() == p.n) inf = std::max(inf, p.lower(i) - x(i));
    if (p.upper.size() == p.n) inf = std::max(inf, x(i) - p.upper(i));
  }
  if (p.objective && (!p.objective(x, r.f) || !std::isfinite(r.f))) return r;
  if (p.m > 0) {
    Vec c(p.m);
    if (!p.constraints(x, c) || c.size() != p.m || !c.allFinite()) return r;
    for (Eigen::Index j = 0; j < p.m; ++j)
      inf = std::max({inf, p.c_lower(j) - c(j), c(j) - p.c_upper(j)});
    scale = std::max(scale, c.lpNorm<Eigen::Infinity>());
  }
  double comp = 0;
  if (p.p > 0) {
    r.G.resize(p.p);
    r.H.resize(p.p);
    if (!p.G(x, r.G) || !p.H(x, r.H) || r.G.size() != p.p || r.H.size() != p.p ||
        !r.G.allFinite() || !r.H.allFinite())
      return r;
    for (Eigen::Index i = 0; i < p.p; ++i) {
      inf = std::max({inf, -r.G(i), -r.H(i)});
      comp = std::max(comp, std::abs(std::min(r.G(i), r.H(i))));
    }
    scale = std::max({scale, r.G.lpNorm<Eigen::Infinity>(), r.H.lpNorm<Eigen::Infinity>()});
  }
  r.ok = true;
  r.infeasibility = inf;
  r.complementarity = comp;
  r.scale = scale;
  return r;
}

struct Candidate {
  Vec x;
  Measure m;
  bool converged = false;
  bool piece = false;
};

class Driver {
 public:
  Driver(const MpccProblem& p, const MpccOptions& o) : p_(p), o_(o) {}

  MpccResult run() {
    Vec x = start();
    // 1. Relaxation or penalty sequence.
    if (p_.p == 0) {
      x = solve("nlp", 0.0, {}, 0.0, 0.0, x).x;
    } else if (o_.reformulation == MpccReformulation::kScholtes) {
      for (double t = o_.t_initial; t >= o_.t_min * (1 - 1e-12) && !stop(); t *= o_.t_factor) {
        const Step s = solve("scholtes", t, std::vector<PairMode>(p_.p, PairMode::kRelaxed), t,
                             0.0, x, std::min(1e-8, 1e-2 * t));
        if (s.usable && s.converged) x = s.x;  // warm start only from a converged NLP
        if (s.usable && s.converged && caller_stops(s.x)) return finish();
        if (s.accepted && s.converged) break;
        if (stagnating(s)) break;
      }
    } else {
      for (double rho = o_.rho_initial; rho <= o_.rho_max * (1 + 1e-12) && !stop();
           rho *= o_.rho_factor) {
        const Step s = solve("penalty", rho, std::vector<PairMode>(p_.p, PairMode::kPenalty), 0.0,
                             rho, x);
        if (s.usable && s.converged) x = s.x;  // an unbounded penalty NLP (small rho) diverges
        if (s.usable && s.converged && caller_stops(s.x)) return finish();
        if (s.accepted && s.converged) break;
        if (stagnating(s)) break;
      }
    }
    // 2. Piece polish: fix the side identified as zero; enumerate both sides of biactive pairs.
    if (p_.p > 0 && o_.polish && !stop()) polish(x);
    return finish();
  }

 private:
  struct Step {
    Vec x;
    bool usable = false, accepted = false, converged = false;
  };

  /// Three NLPs in a row that failed or did not lower the complementarity violation below
  /// 0.9 x the best so far: the sequence is stuck (e.g. at a local minimiser of the violation).
  bool stagnating(const Step& s) {
    const double comp = s.usable ? result_.subproblems.back().complementarity
                                 : std::numeric_limits<double>::infinity();
    if (s.converged && comp < 0.9 * best_comp_) {
      best_comp_ = comp;
      stuck_ = 0;
    } else {
      ++stuck_;
    }
    return stuck_ >= 3;
  }

  bool caller_stops(const Vec& x) {
    if (!o_.early_stop || !o_.early_stop(x)) return false;
    const Measure m = measure(p_, x);
    early_ = Candidate{x, m, result_.subproblems.back().nlp_converged, false};
    return true;
  }

  Vec start() const {
    Vec x = p_.x0.size() == p_.n ? p_.x0 : Vec::Zero(p_.n);
    if (p_.lower.size() == p_.n) x = x.cwiseMax(p_.lower);
    if (p_.upper.size() == p_.n) x = x.cwiseMin(p_.upper);
    return x;
  }

  bool stop() {
    if (timer_.exceeded(o_.common.time_limit_s)) time_out_ = true;
    return time_out_ || static_cast<int>(result_.subproblems.size()) >= o_.max_subproblems;
  }

  bool accepted(const Measure& m) const {
    return m.ok && m.infeasibility <= o_.feasibility_tol * (1 + m.scale) &&
           m.complementarity <= o_.complementarity_tol * (1 + m.scale);
  }

  Step solve(const char* kind, double parameter, std::vector<PairMode> modes, double t,
             double rho, const Vec& x0, double bound_relax = 1e-10) {
    Step step;
    Stopwatch sw;
    const NlpEvaluator nlp(p_, std::move(modes), t, rho);
    const double left = o_.common.time_limit_s - timer_.seconds();
    const NlpOutcome out = o_.backend == NlpBackend::kIpopt
                               ? detail::solve_nlp_ipopt(nlp, x0, o_, left, bound_relax)
                               : detail::solve_nlp_nlopt(nlp, x0, o_, left);
    if (out.time_limit) time_out_ = true;
    MpccSubproblem sub;
    sub.kind = kind;
    sub.parameter = parameter;
    sub.nlp_status = out.status;
    sub.nlp_converged = out.converged;
    sub.iterations = out.iterations;
    Measure m = measure(p_, out.x);
    // Diverged iterates (e.g. an unbounded penalty NLP) are never candidates.
    if (out.x.lpNorm<Eigen::Infinity>() > kDivergence * (1 + x0.lpNorm<Eigen::Infinity>()))
      m.ok = false;
    sub.objective = m.f;
    sub.complementarity = m.complementarity;
    sub.infeasibility = m.infeasibility;
    sub.seconds = sw.seconds();
    result_.iterations += out.iterations;
    result_.subproblems.push_back(sub);
    log(o_.common.log, o_.common.verbosity, LogLevel::kInfo,
        std::string("mpcc ") + kind + " " + short_number(parameter) + ": " + out.status + ", f = " +
            short_number(m.f) + ", complementarity = " + short_number(m.complementarity) +
            ", infeasibility = " + short_number(m.infeasibility));
    if (out.eval_failed) eval_failures_++;
    step.x = out.x;
    step.usable = m.ok;
    step.accepted = accepted(m);
    step.converged = out.converged;
    if (!m.ok) return step;
    if (step.accepted) {
      // Prefer converged NLPs, then pieces (exactly complementary) over relaxed points, then
      // the lowest objective.
      const bool piece = std::string(kind) == "piece";
      auto rank = [](bool converged, bool is_piece) { return 2 * converged + is_piece; };
      const int mine = rank(out.converged, piece);
      const bool better = !best_ || mine > rank(best_->converged, best_->piece) ||
                          (mine == rank(best_->converged, best_->piece) &&
                           m.f < best_->m.f - 1e-12 * (1 + std::abs(best_->m.f)));
      if (better) best_ = Candidate{out.x, m, out.converged, piece};
    } else {
      const double viol = std::max(m.complementarity, m.infeasibility) / (1 + m.scale);
      if (!least_violated_ || viol < least_violation_) {
        least_violated_ = Candidate{out.x, m, out.converged, false};
        least_violation_ = viol;
      }
    }
    return step;
  }

  void polish(const Vec& x) {
    const Measure m = measure(p_, x);
    if (!m.ok) return;
    const double theta = 1e-6 * (1 + m.scale);  // biactive: both sides below theta
    std::vector<PairMode> base(p_.p);
    std::vector<Eigen::Index> biactive;
    for (Eigen::Index i = 0; i < p_.p; ++i) {
      base[i] = m.G(i) <= m.H(i) ? PairMode::kFixG : PairMode::kFixH;
      if (std::max(m.G(i), m.H(i)) <= theta) biactive.push_back(i);
    }
    constexpr std::size_t kMaxBranchPairs = 4;
    if (biactive.size() > kMaxBranchPairs) biactive.clear();  // one piece: the smaller side
    const std::size_t pieces = std::size_t{1} << biactive.size();
    for (std::size_t mask = 0; mask < pieces && !stop(); ++mask) {
      std::vector<PairMode> modes = base;
      for (std::size_t b = 0; b < biactive.size(); ++b)
        modes[biactive[b]] = (mask >> b) & 1U ? PairMode::kFixH : PairMode::kFixG;
      solve("piece", 0.0, modes, 0.0, 0.0, x);
    }
  }

  MpccResult finish() {
    MpccResult& r = result_;
    r.seconds = timer_.seconds();
    if (early_) {
      r.stopped_early = true;
      r.x = early_->x;
      r.objective = early_->m.f;
      r.complementarity = early_->m.complementarity;
      r.infeasibility = early_->m.infeasibility;
      r.status = accepted(early_->m) && early_->converged ? Status::kSolved : Status::kStalled;
      r.message = std::to_string(r.subproblems.size()) + " NLP(s) with " +
                  std::string(to_string(o_.backend)) + " (" +
                  std::string(to_string(o_.reformulation)) + "); stopped early by the caller's test";
      return r;
    }
    const Candidate* c = best_ ? &*best_ : least_violated_ ? &*least_violated_ : nullptr;
    std::ostringstream msg;
    msg << r.subproblems.size() << " NLP(s) with " << to_string(o_.backend) << " ("
        << to_string(o_.reformulation) << (o_.polish ? " + piece polish" : "") << ")";
    if (c == nullptr) {
      r.status = time_out_ ? Status::kTimeLimit : Status::kNumericalFailure;
      r.x = start();
      msg << "; no usable point (callbacks failed or the NLP solver broke down)";
      r.message = msg.str();
      return r;
    }
    r.x = c->x;
    r.objective = c->m.f;
    r.complementarity = c->m.complementarity;
    r.infeasibility = c->m.infeasibility;
    if (best_ && best_->converged) {
      r.status = Status::kSolved;
      msg << "; feasible and complementary point from a converged NLP (local)";
    } else if (best_) {
      r.status = Status::kSolvedInaccurate;
      msg << "; feasible and complementary point, but its NLP did not report convergence";
    } else {
      r.status = time_out_ ? Status::kTimeLimit : Status::kStalled;
      msg << "; complementarity or feasibility still violated: complementarity = "
          << short_number(c->m.complementarity) << ", infeasibility = " << short_number(c->m.infeasibility);
    }
    if (eval_failures_ > 0) msg << "; " << eval_failures_ << " NLP(s) hit a failed evaluation";
    r.message = msg.str();
    return r;
  }

  const MpccProblem& p_;
  const MpccOptions& o_;
  Stopwatch timer_;
  MpccResult result_;
  std::optional<Candidate> best_, least_violated_, early_;
  double least_violation_ = 0;
  double best_comp_ = std::numeric_limits<double>::infinity();
  int stuck_ = 0;
  int eval_failures_ = 0;
  bool time_out_ = false;
};

}  // namespace

MpccResult solve_mpcc(const MpccProblem& problem, const MpccOptions& options) {
  throw_if_invalid(problem.validate(), "MPCC problem");
  throw_if_invalid(options.validate(), "MPCC options");
  return Driver(problem, options).run();
}

}  // namespace cpkit::lcp
