// Lemke's complementary pivoting method [Cottle-Pang-Stone 1992, Sec. 4.4] with the
// lexicographic minimum-ratio test [CPS 1992, Sec. 4.9]. See lemke.hpp for the contract.
#include "cpkit/lcp/lemke.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "lemke_basis.hpp"

namespace cpkit::lcp {
namespace {

using detail::LemkeBasis;

constexpr double kPivotTol = 1e-11;   // relative size of an admissible pivot
constexpr double kDegenTol = 1e-12;   // relative size below which a basic value counts as 0
constexpr double kTieTol = 1e-9;      // relative tie in the minimum ratio
constexpr int kCheckEvery = 16;       // pivots between accuracy checks of the basis inverse
constexpr double kRefactorTol = 1e-10;  // relative residual that triggers a refactorization

void add_message(SolveResult& r, const std::string& text) {
  r.message += (r.message.empty() ? "" : "; ") + text;
}

int default_pivot_limit(Eigen::Index n) { return static_cast<int>(50 * (n + 1) + 1000); }

// Textbook names for messages: z1..zn, z0 (artificial), w1..wn (1-based, unlike the ids).
std::string var_name(int var, Eigen::Index n) {
  if (var < n) return "z" + std::to_string(var + 1);
  if (var == n) return "z0";
  return "w" + std::to_string(var - n);
}

/// Per-call state of one Lemke run (no hidden state shared between calls).
class LemkeRun {
 public:
  LemkeRun(const LcpProblem& problem, const Mat& M, const LemkeOptions& o)
      : problem_(problem),
        o_(o),
        n_(problem.size()),
        basis_(M, problem.q),
        dxz_(Vec::Zero(n_ + 1)),
        dw_(Vec::Zero(n_)),
        row_best_(n_),
        row_cand_(n_) {
    mmax_ = n_ > 0 ? M.cwiseAbs().maxCoeff() : 0.0;
    qmax_ = problem.q.lpNorm<Eigen::Infinity>();
    tied_.reserve(static_cast<size_t>(n_ + 1));
    tied_div_.reserve(static_cast<size_t>(n_ + 1));
  }

  SolveResult run();

 private:
  // Rate of increase of the basic variable `var` along the current direction.
  double rate(int var) const {
    return var <= n_ ? dxz_[basis_.zpos(var)] : dw_[var - n_ - 1];
  }
  double value(int var) const {
    return var <= n_ ? basis_.xz()[basis_.zpos(var)] : basis_.w()[var - n_ - 1];
  }
  // Lexicographic minimum of (value, B^{-1} row) / divisor over the tied candidates.
  int lexmin_of_tied();
  // Minimum-ratio test for the current direction; -1: no blocking variable (ray).
  int ratio_test(double& step);
  // Leaving variable of the initial z0 pivot (lexmin of (x_i, B^{-1}_i) / d_i).
  int initial_leaving(const Vec& dtilde);
  void record(int iteration, const char* kind, int entering, int leaving, double step);
  SolveResult finish(SolveResult claim);
  bool check_accuracy(int pivots);
  // The updated inverse is as accurate as a fresh one could be (backward error at most
  // kRefactorTol, or within a factor 1e3 of the last freshly computed inverse's).
  bool inverse_accurate() {
    return basis_.hinv_quality() <= std::max(kRefactorTol, 1e3 * fresh_quality_);
  }

  const LcpProblem& problem_;
  const LemkeOptions& o_;
  Eigen::Index n_;
  LemkeBasis basis_;
  Vec dxz_, dw_, row_best_, row_cand_;
  std::vector<int> tied_;
  std::vector<double> tied_div_;
  std::vector<TraceEntry> trace_;
  double mmax_ = 0;            // max |M_ij|
  double gmax_ = 1;            // max |[M | c]_ij| (set with the artificial column c)
  double qmax_ = 0;            // ||q||_inf
  double beta_ = 1;            // internal z0 = user z0 / beta_ (see run())
  int entering_ = -1;          // the variable entering at the current pivot
  double fresh_quality_ = 0;  // hinv_quality() right after the last refactorization
  Stopwatch clock_;
};

void LemkeRun::record(int iteration, const char* kind, int entering, int leaving, double step) {
  if (!o_.common.record_trace) return;
  Vec z;
  double z0 = 0;
  basis_.current_point(z, z0);
  TraceEntry e;
  e.iteration = iteration;
  e.kind = kind;
  e.entering = entering;
  e.leaving = leaving;
  e.step = step;
  e.residual = z0 * beta_;  // z0 for the covering vector d as given
  trace_.push_back(std::move(e));
}

int LemkeRun::lexmin_of_tied() {
  // (value_i, B^{-1}_i) / div_i compared component by component; the values are tied already.
  size_t best = 0;
  basis_.inverse_row(tied_[0], row_best_);
  row_best_ /= tied_div_[0];
  for (size_t c = 1; c < tied_.size(); ++c) {
    basis_.inverse_row(tied_[c], row_cand_);
    row_cand_ /= tied_div_[c];
    const double scale = std::max(row_best_.lpNorm<Eigen::Infinity>(),
                                  row_cand_.lpNorm<Eigen::Infinity>());
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = row_cand_[i], b = row_best_[i];
      if (std::abs(a - b) <= kTieTol * std::max(std::abs(a), std::abs(b)) + 1e-13 * scale)
        continue;
      if (a < b) {
        best = c;
        row_best_.swap(row_cand_);
      }
      break;
    }
  }
  return tied_[best];
}

int LemkeRun::initial_leaving(const Vec& dtilde) {
  // Every basic variable x_i grows at rate dtilde_i > 0 with z0; the one that must grow most,
  // argmin x_i / dtilde_i, leaves (lexicographically, for degenerate starts).
  double best = INFINITY;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const int var = static_cast<int>(basis_.rpos(i) < 0 ? n_ + 1 + i : i);
    best = std::min(best, value(var) / dtilde[i]);
  }
  tied_.clear();
  tied_div_.clear();
  for (Eigen::Index i = 0; i < n_; ++i) {
    const int var = static_cast<int>(basis_.rpos(i) < 0 ? n_ + 1 + i : i);
    const double r = value(var) / dtilde[i];
    if (r <= best + kTieTol * std::abs(best)) {
      tied_.push_back(var);
      tied_div_.push_back(dtilde[i]);
    }
  }
  return tied_.size() == 1 ? tied_[0] : lexmin_of_tied();
}

int LemkeRun::ratio_test(double& step) {
  // Scale-aware tolerances (invariant under scaling M, q and the units of z): a pivot entry
  // must exceed kPivotTol relative to the size of the pivot column's terms; a basic value below
  // kDegenTol relative to the size of its kind of values counts as a degenerate zero.
  const int k = basis_.k();
  const double dz_norm = k > 0 ? dxz_.head(k).lpNorm<Eigen::Infinity>() : 0.0;
  const double dz_scale = entering_ <= n_ ? std::max(1.0, dz_norm) : dz_norm;  // z enters at rate 1
  const double tol_z = kPivotTol * dz_scale;
  const double tol_w = kPivotTol * gmax_ * dz_scale;
  const double xz_tol = kDegenTol * (k > 0 ? basis_.xz().head(k).lpNorm<Eigen::Infinity>() : 0.0);
  const double w_tol = kDegenTol * std::max(basis_.w().lpNorm<Eigen::Infinity>(), qmax_);
  // Pass 1: the minimum ratio.
  double best = INFINITY;
  for (int p = 0; p < k; ++p) {
    const double a = -dxz_[p];
    if (a > tol_z) {
      const double x = basis_.xz()[p];
      best = std::min(best, (x > xz_tol ? x : 0.0) / a);
    }
  }
  for (Eigen::Index i = 0; i < n_; ++i) {
    if (basis_.rpos(i) >= 0) continue;
    const double a = -dw_[i];
    if (a > tol_w) {
      const double x = basis_.w()[i];
      best = std::min(best, (x > w_tol ? x : 0.0) / a);
    }
  }
  if (!(best < INFINITY)) return -1;
  // Pass 2: the tied rows.
  tied_.clear();
  tied_div_.clear();
  const double limit = best * (1.0 + kTieTol);
  for (int p = 0; p < k; ++p) {
    const double a = -dxz_[p];
    if (a > tol_z) {
      const double x = basis_.xz()[p];
      if ((x > xz_tol ? x : 0.0) / a <= limit) {
        tied_.push_back(basis_.zcols()[static_cast<size_t>(p)]);
        tied_div_.push_back(a);
      }
    }
  }
  for (Eigen::Index i = 0; i < n_; ++i) {
    if (basis_.rpos(i) >= 0) continue;
    const double a = -dw_[i];
    if (a > tol_w) {
      const double x = basis_.w()[i];
      if ((x > w_tol ? x : 0.0) / a <= limit) {
        tied_.push_back(static_cast<int>(n_ + 1 + i));
        tied_div_.push_back(a);
      }
    }
  }
  const int leaving = tied_.size() == 1 ? tied_[0] : lexmin_of_tied();
  step = std::max(0.0, value(leaving)) / -rate(leaving);
  return leaving;
}

bool LemkeRun::check_accuracy(int pivots) {
  const bool forced = o_.refactor_every > 0 && pivots % o_.refactor_every == 0;
  if (!forced && pivots % kCheckEvery != 0) return true;
  if (forced || !inverse_accurate()) {
    if (!basis_.refactor()) return false;
    fresh_quality_ = basis_.hinv_quality();
  }
  basis_.recompute_values();
  return true;
}

SolveResult LemkeRun::finish(SolveResult claim) {
  claim.solver = "lemke";
  claim.trace = std::move(trace_);
  SolveResult r = finalize(problem_, std::move(claim), o_.common);
  r.seconds = clock_.seconds();
  if (o_.common.log != nullptr)
    log(o_.common.log, o_.common.verbosity, LogLevel::kInfo,
        "lemke: " + std::string(to_string(r.status)) + " after " +
            std::to_string(r.iterations) + " pivots");
  return r;
}

SolveResult LemkeRun::run() {
  SolveResult claim;
  double z0 = 0;
  // Starting basis: all w basic, or the warm basis.
  std::vector<int> zset;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(o_.warm_basis.size()); ++i)
    if (o_.warm_basis[static_cast<size_t>(i)] >= 0) zset.push_back(static_cast<int>(i));
  if (!basis_.reset(zset)) {
    add_message(claim, "warm basis ignored: its block M(Z, Z) is singular; cold start");
    zset.clear();
    basis_.reset(zset);
  }
  fresh_quality_ = basis_.hinv_quality();
  // Is the starting basic solution already a solution? (q >= 0 for the cold start.)
  basis_.current_point(claim.z, z0);
  const bool start_feasible =
      (basis_.k() == 0 || basis_.xz().head(basis_.k()).minCoeff() >= 0.0) &&
      basis_.w().minCoeff() >= 0.0;
  if (start_feasible || (basis_.k() == 0 && problem_.q.minCoeff() >= 0.0)) {
    Vec w;
    const Residuals res = lcp_residuals(problem_, claim.z, w);
    if (res.natural <= o_.common.tol || basis_.k() == 0) {
      claim.status = Status::kSolved;
      claim.iterations = 0;
      for (Eigen::Index i = 0; i < n_; ++i)
        claim.basis.push_back(basis_.zpos(static_cast<int>(i)) >= 0 ? static_cast<int>(i)
                                                                   : ~static_cast<int>(i));
      return finish(std::move(claim));
    }
  }
  // Covering vector in the coordinates of the starting basis: z0 raises every basic variable
  // at rate rate0_i: c = rate0 on W rows minus M(:, Z) rate0_Z. Internally z0 is measured in
  // the units of z (the w-rates are d_i * beta_ with beta_ = max |M_ij|), so that z and z0
  // share the scale-aware tolerances; this rescales z0 only and leaves the path unchanged.
  // User-facing values of z0 (trace, ray) are converted back to the units of d.
  const Vec d = o_.covering.size() ? o_.covering : Vec::Ones(n_);
  beta_ = mmax_ > 0 ? mmax_ : 1.0;
  Vec rate0(n_);
  Vec c = Vec::Zero(n_);
  for (Eigen::Index i = 0; i < n_; ++i) {
    rate0[i] = basis_.rpos(i) < 0 ? beta_ * d[i] : d[i];
    if (basis_.rpos(i) < 0) c[i] = rate0[i];
  }
  for (int j : zset) c.noalias() -= rate0[j] * Eigen::Map<const Vec>(basis_.gcol(j), n_);
  basis_.set_artificial_column(c);
  gmax_ = std::max({mmax_, c.lpNorm<Eigen::Infinity>(), 1e-300});

  const int limit =
      o_.common.max_iterations > 0 ? o_.common.max_iterations : default_pivot_limit(n_);
  const int z0var = static_cast<int>(n_);
  int pivots = 0;
  int entering = z0var;
  if (limit < 1) {
    claim.status = Status::kIterationLimit;
    return finish(std::move(claim));
  }
  // Initial pivot: z0 enters.
  {
    basis_.direction(z0var, dxz_, dw_);
    const int leaving = initial_leaving(rate0);
    const double step = -value(leaving) / rate(leaving);
    basis_.pivot(z0var, leaving, step, dxz_, dw_);
    ++pivots;
    record(pivots, "z0-enters", z0var, leaving, step * beta_);
    // The complement of the leaving variable enters next.
    entering = leaving < n_ ? leaving + static_cast<int>(n_) + 1 : leaving - static_cast<int>(n_) - 1;
  }
  while (true) {
    if (pivots >= limit) {
      claim.status = Status::kIterationLimit;
      add_message(claim, "pivot limit " + std::to_string(limit) + " reached");
      break;
    }
    if (clock_.exceeded(o_.common.time_limit_s)) {
      claim.status = Status::kTimeLimit;
      add_message(claim, "time limit reached after " + std::to_string(pivots) + " pivots");
      break;
    }
    entering_ = entering;
    basis_.direction(entering, dxz_, dw_);
    if (!dxz_.head(basis_.k()).allFinite() || !dw_.allFinite()) {
      claim.status = Status::kNumericalFailure;
      add_message(claim, "non-finite pivot column");
      break;
    }
    double step = 0;
    const int leaving = ratio_test(step);
    if (leaving < 0) {
      // Secondary ray: the entering variable grows without bound.
      Vec ray = Vec::Zero(n_ + 1);
      if (entering <= n_) ray[entering] = 1.0;
      for (int p = 0; p < basis_.k(); ++p) ray[basis_.zcols()[static_cast<size_t>(p)]] = dxz_[p];
      ray[n_] *= beta_;  // z0 for the covering vector d as given
      claim.ray = ray;
      claim.status = Status::kRayTermination;
      add_message(claim, "secondary ray after " + std::to_string(pivots) + " pivots (" +
                             var_name(entering, n_) + " unblocked)");
      // Candidate certificates, kept only when the data confirm them.
      Certificate cand;
      cand.y = ray.head(n_);
      bool ok = check_certificate(problem_, cand);
      if (!ok && basis_.zpos(z0var) >= 0) {
        basis_.inverse_row(z0var, row_cand_);
        cand.y = -row_cand_;
        ok = check_certificate(problem_, cand);
      }
      if (ok) {
        claim.status = Status::kInfeasible;
        claim.certificate = cand;
        claim.message += "; infeasibility certificate y >= 0, M^T y <= 0, q^T y < 0 found";
      } else {
        claim.message += "; no infeasibility certificate (M not known copositive-plus)";
      }
      break;
    }
    basis_.pivot(entering, leaving, step, dxz_, dw_);
    ++pivots;
    if (leaving == z0var) {
      record(pivots, "z0-leaves", entering, leaving, step);
      claim.status = Status::kSolved;
      break;
    }
    record(pivots, "pivot", entering, leaving, step);
    entering = leaving < n_ ? leaving + static_cast<int>(n_) + 1 : leaving - static_cast<int>(n_) - 1;
    if (!check_accuracy(pivots)) {
      claim.status = Status::kNumericalFailure;
      add_message(claim, "basis became singular after " + std::to_string(pivots) + " pivots");
      break;
    }
  }
  claim.iterations = pivots;
  if (claim.status == Status::kSolved) {
    // The final basis is complementary: recompute its values from the data (refactorizing
    // first when the inverse fails the accuracy check).
    if (!inverse_accurate() && !basis_.refactor()) {
      claim.status = Status::kNumericalFailure;
      add_message(claim, "final basis is singular");
    } else {
      basis_.recompute_values();
      for (Eigen::Index i = 0; i < n_; ++i)
        claim.basis.push_back(basis_.zpos(static_cast<int>(i)) >= 0 ? static_cast<int>(i)
                                                                   : ~static_cast<int>(i));
    }
  }
  basis_.current_point(claim.z, z0);
  if (claim.status == Status::kSolved) claim.z = claim.z.cwiseMax(0.0);
  return finish(std::move(claim));
}

}  // namespace

std::string LemkeOptions::validate(Eigen::Index n) const {
  if (auto m = common.validate(); !m.empty()) return m;
  // Messages are built only on error (this runs on every solve).
  auto num = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (covering.size() != 0) {
    if (covering.size() != n)
      return "covering vector has size " + std::to_string(covering.size()) + ", expected " +
             std::to_string(n);
    for (Eigen::Index i = 0; i < n; ++i)
      if (!(covering[i] > 0) || !std::isfinite(covering[i]))
        return "covering vector entry " + std::to_string(i) +
               " must be positive and finite (got " + num(covering[i]) + ")";
  }
  if (!warm_basis.empty()) {
    if (static_cast<Eigen::Index>(warm_basis.size()) != n)
      return "warm_basis has size " + std::to_string(warm_basis.size()) + ", expected " +
             std::to_string(n);
    for (size_t i = 0; i < warm_basis.size(); ++i) {
      const int zi = static_cast<int>(i);
      if (warm_basis[i] != zi && warm_basis[i] != ~zi)
        return "warm_basis[" + std::to_string(i) + "] must be " + std::to_string(zi) +
               " (z basic) or " + std::to_string(~zi) + " (w basic), got " +
               std::to_string(warm_basis[i]);
    }
  }
  if (refactor_every < 0)
    return "refactor_every must be >= 0 (got " + std::to_string(refactor_every) + ")";
  return {};
}

SolveResult solve_lemke(const LcpProblem& problem, const LemkeOptions& options) {
  throw_if_invalid(problem.validate(), "lemke: problem");
  throw_if_invalid(options.validate(problem.size()), "lemke: options");
  if (problem.is_sparse()) {
    if (problem.size() > kLemkeMaxDensify) {
      SolveResult claim;
      claim.solver = "lemke";
      claim.status = Status::kUnsupported;
      add_message(claim, "lemke is a dense method: sparse LCPs are densified only up to n = " +
                      std::to_string(kLemkeMaxDensify) + " (n = " +
                      std::to_string(problem.size()) + ")");
      return finalize(problem, std::move(claim), options.common);
    }
    const Mat dense = problem.dense_M();
    LemkeRun run(problem, dense, options);
    return run.run();
  }
  LemkeRun run(problem, problem.M, options);
  return run.run();
}

SolverEntry lemke_entry() {
  SolverEntry e;
  e.info.name = "lemke";
  e.info.description =
      "Lemke's complementary pivoting method, lexicographic ratio test [Cottle-Pang-Stone 1992, "
      "Sec. 4.4]";
  e.info.dense = true;
  e.info.sparse = true;  // densified up to kLemkeMaxDensify
  e.solve_lcp = [](const LcpProblem& p, const CommonOptions& o) {
    LemkeOptions lo;
    lo.common = o;
    return solve_lemke(p, lo);
  };
  return e;
}

}  // namespace cpkit::lcp
