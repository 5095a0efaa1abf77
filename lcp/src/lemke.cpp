// Lemke's complementary pivoting method [Cottle-Pang-Stone 1992, Sec. 4.4] with the
// lexicographic minimum-ratio test [CPS 1992, Sec. 4.9]. See lemke.hpp for the contract.
#include "cpkit/lcp/lemke.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "lemke_run.hpp"

namespace cpkit::lcp {
namespace {

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
  // Lexicographic rule [CPS 1992, Sec. 4.9]: the leaving variable minimizes the row
  // (value, B^{-1}(v, :)) / a_v; the values are tied already, so the columns of B^{-1} decide,
  // in the fixed order of the equations 0..n-1. The rows of B^{-1} are linearly independent,
  // so in exact arithmetic exactly one row is minimal: the basis path is that of the
  // perturbed problem q + (eps, eps^2, ...) and never revisits a basis.
  // Column j of W (w_j basic) is a unit column: only the row of w_j has an entry, exactly
  // 1 / a > 0 (no rounding), so w_j alone is dropped, in O(1). A column of R holds computed
  // entries: the candidates above the column's minimum by more than tie_level() times the
  // rows' scales max_j |B^{-1}(v, j)| / a_v (the rounding level) are dropped. Work: O(1) per
  // column of W, O(k) per candidate for the scales (computed at the first column of R), O(1)
  // per candidate and column of R: at most O(n) per candidate, never O(n^2) per pivot.
  for (size_t c = 0; c < tied_.size(); ++c) tied_pos_[static_cast<size_t>(tied_[c].var)] = c;
  auto drop = [&](size_t c) {
    tied_pos_[static_cast<size_t>(tied_[c].var)] = kNone;
    tied_[c] = tied_.back();
    if (!tied_scale_.empty()) tied_scale_[c] = tied_scale_.back();
    tied_.pop_back();
    if (!tied_scale_.empty()) tied_scale_.pop_back();
    if (c < tied_.size()) tied_pos_[static_cast<size_t>(tied_[c].var)] = c;
  };
  tied_scale_.clear();
  const double tie = tie_level();
  for (Eigen::Index j = 0; j < n_ && tied_.size() > 1; ++j) {
    if (basis_.rpos(j) < 0) {
      const size_t c = tied_pos_[static_cast<size_t>(n_ + 1 + j)];
      if (c != kNone) drop(c);
      continue;
    }
    if (tied_scale_.empty()) {
      basis_.enable_lexico_rows();
      for (const Candidate& t : tied_) {
        double row_max = 0, terms = 0;
        basis_.inverse_row_scales(t.var, row_max, terms);
        tied_scale_.push_back(row_max / t.a);
      }
    }
    double lo = INFINITY, lo_scale = 0;
    for (size_t c = 0; c < tied_.size(); ++c) {
      const double e = basis_.inverse_entry(tied_[c].var, j) / tied_[c].a;
      if (e < lo) lo = e, lo_scale = tied_scale_[c];
    }
    for (size_t c = tied_.size(); c-- > 0;) {
      const double e = basis_.inverse_entry(tied_[c].var, j) / tied_[c].a;
      if (e - lo > tie * (tied_scale_[c] + lo_scale)) drop(c);
    }
  }
  // Rows equal to rounding level in every column (not expected: they are independent): the
  // most stable pivot, deterministically.
  size_t best = 0;
  for (size_t c = 1; c < tied_.size(); ++c)
    if (tied_[c].a > tied_[best].a) best = c;
  const int var = tied_[best].var;
  for (const Candidate& t : tied_) tied_pos_[static_cast<size_t>(t.var)] = kNone;
  return var;
}

bool LemkeRun::admissible(const Candidate& c) {
  // Cheap bound first: for a w row, |G(i, entering)| + rowmax_G(i) ||dxz||_1 bounds its terms.
  const double level = tie_level();
  if (c.var > n_ && c.a > level * (std::abs(entering_ <= n_ ? basis_.g(c.var - n_ - 1,
                                                                        entering_)
                                                            : 0.0) +
                                   g_rowmax_[c.var - n_ - 1] * dxz_l1_))
    return true;
  return c.a > level * basis_.rate_terms(c.var, entering_, dxz_);
}

double LemkeRun::tie_level() {
  // Values and B^{-1} rows carry the rounding of the products that formed them (a few ulps
  // per term, k + 1 terms), and of the inverse itself when it has drifted: its componentwise
  // backward error as measured at the last accuracy check (every kCheckEvery pivots; the
  // check refactorizes beyond kRefactorTol) times a margin.
  if (tie_level_ < 0) tie_level_ = detail::tie_level(basis_.k() + 1, quality_);
  return tie_level_;
}

double LemkeRun::value_terms(int var) {
  if (var <= n_ || basis_.lexico_rows_enabled()) {
    double row_max = 0, terms = 0;
    basis_.inverse_row_scales(var, row_max, terms);
    return terms;
  }
  // A basic w_i = q_i + G(i, Z) x_Z without the rows X: its own terms, O(k).
  const Eigen::Index i = var - n_ - 1;
  double terms = std::abs(problem_.q[i]);
  for (int p = 0; p < basis_.k(); ++p)
    terms += std::abs(basis_.g(i, basis_.zcols()[static_cast<size_t>(p)])) *
             std::abs(basis_.xz()[p]);
  return terms;
}

int LemkeRun::ratio_test(bool initial, double& step) {
  // Candidates: basic variables that move towards their bound 0 (the z0 pivot: every basic
  // variable grows, and the most negative value / rate leaves).
  tie_level_ = -1;
  dxz_l1_ = basis_.k() > 0 ? dxz_.head(basis_.k()).lpNorm<1>() : 0.0;
  rate_max_ = std::max(dw_.lpNorm<Eigen::Infinity>(),
                       basis_.k() > 0 ? dxz_.head(basis_.k()).lpNorm<Eigen::Infinity>() : 0.0);
  const double sign = initial ? 1.0 : -1.0;
  const int k = basis_.k();
  // Collected into the preallocated cands_ (no push_back in this hot loop).
  Candidate* const first = cands_.data();
  Candidate* last = first;
  auto collect = [&] {
    last = first;
    for (int p = 0; p < k; ++p) {
      const double a = sign * dxz_[p], x = basis_.xz()[p];
      if (a > 0)
        *last++ = {basis_.zcols()[static_cast<size_t>(p)], a,
                   (initial ? x : std::max(x, 0.0)) / a};
    }
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = sign * dw_[i], x = basis_.w()[i];
      if (a > 0 && basis_.rpos(i) < 0)
        *last++ = {static_cast<int>(n_ + 1 + i), a, (initial ? x : std::max(x, 0.0)) / a};
    }
  };
  collect();
  int leaving = -1;
  // Fast path (no near ties, the usual case): the smallest ratio is an admissible pivot and
  // the second smallest lies beyond the near-tie window kTieTol (bounded from above without
  // O(k) work for a w; exact for a z).
  if (last - first >= 1) {
    const Candidate* c1 = first;
    double theta2 = INFINITY;
    for (const Candidate* c = first + 1; c != last; ++c) {
      if (c->theta < c1->theta) {
        theta2 = c1->theta;
        c1 = c;
      } else {
        theta2 = std::min(theta2, c->theta);
      }
    }
    if (std::isfinite(c1->theta) && admissible(*c1)) {
      double bound = 0;
      if (c1->var <= n_) {
        double row_max = 0;
        basis_.inverse_row_scales(c1->var, row_max, bound);
      } else {
        const Eigen::Index i = c1->var - n_ - 1;
        bound = std::abs(problem_.q[i]) +
                g_rowmax_[i] * (k > 0 ? basis_.xz().head(k).lpNorm<1>() : 0.0);
      }
      if (theta2 > c1->theta + kTieTol * (std::abs(c1->theta) + bound / c1->a))
        leaving = c1->var;
    }
  }
  const Span<Candidate> cands{first, last};
  std::vector<int> dropped;  // excluded_ marks to clear (rare: pivots that are noise)
  bool refreshed = drift_ == 0;
  while (leaving < 0) {
    // The minimum ratio among the candidates not excluded.
    const Candidate* best = nullptr;
    for (const Candidate& c : cands)
      if (!excluded_[static_cast<size_t>(c.var)] && (best == nullptr || c.theta < best->theta))
        best = &c;
    if (best == nullptr) break;  // ray
    if (!std::isfinite(best->theta)) {
      leaving = -2;
      break;
    }
    // A pivot entry that is rounding noise (below tie_level() times the size of its terms) is
    // not a pivot: drop the candidate and look again.
    if (!admissible(*best)) {
      excluded_[static_cast<size_t>(best->var)] = 1;
      dropped.push_back(best->var);
      continue;
    }
    // Ties: ratios that differ from the minimum by no more than their rounding, tie_level()
    // times the size of the ratios and of the terms of both values (a degenerate zero is "0
    // up to rounding of those terms"). Only candidates inside the near-tie window (kTieTol,
    // the terms of a basic w bounded cheaply by |q_i| + max_j |G(i, j)| ||x_Z||_1) are looked
    // at, so without near ties the test stays O(n), with no strided access to M.
    const double xz_l1 = k > 0 ? basis_.xz().head(k).lpNorm<1>() : 0.0;
    auto terms_bound = [&](const Candidate& c) {
      if (c.var <= n_) return value_terms(c.var);
      const Eigen::Index i = c.var - n_ - 1;
      return std::abs(problem_.q[i]) + g_rowmax_[i] * xz_l1;
    };
    const double best_bound = terms_bound(*best);
    const double window =
        best->theta + kTieTol * (std::abs(best->theta) + best_bound / best->a);
    double best_terms = -1;
    bool ambiguous = false;
    tied_.clear();
    for (const Candidate& c : cands) {
      if (excluded_[static_cast<size_t>(c.var)] || c.theta > window) continue;
      if (&c != best) {
        if (best_terms < 0) best_terms = value_terms(best->var);
        // The updated values carry the rounding of the updates since they were last computed
        // from the data (drift_): a decision within that of the limit is made again on fresh
        // values (O(n k), only then: exact ties and clear gaps do not pay for it). The terms of
        // c's value (O(k)) are needed only when c is not tied on the minimizer's terms alone.
        const double tie = tie_level();
        const double band = drift_ * (1 / c.a + 1 / best->a);
        double limit = best->theta + tie * (std::abs(best->theta) + best_terms / best->a);
        if (c.theta > limit - band) limit += tie * value_terms(c.var) / c.a;
        ambiguous = ambiguous || std::abs(c.theta - limit) <= band;
        if (c.theta > limit) continue;
        if (!admissible(c)) {
          excluded_[static_cast<size_t>(c.var)] = 1;  // noise, not a pivot
          dropped.push_back(c.var);
          continue;
        }
      }
      tied_.push_back(c);
    }
    if (ambiguous && !refreshed) {
      refreshed = true;
      basis_.recompute_values();
      drift_ = 0;
      collect();  // the same candidates (the rates are unchanged), fresh ratios
      continue;
    }
    // z0 among the tied leaves (the solution is reached), as in every Lemke variant.
    for (const Candidate& c : tied_)
      if (c.var == n_) leaving = c.var;
    if (leaving >= 0) break;
    if (tied_.size() == 1) {
      leaving = tied_[0].var;
    } else if (o_.lexicographic) {
      leaving = lexmin_of_tied();
    } else {
      // Plain rule (tests and demonstrations only): the smallest variable id.
      leaving = tied_[0].var;
      for (const Candidate& c : tied_) leaving = std::min(leaving, c.var);
    }
    break;
  }
  for (int v : dropped) excluded_[static_cast<size_t>(v)] = 0;
  if (leaving < 0) return leaving;
  const double x = value(leaving), r = rate(leaving);
  step = initial ? -x / r : std::max(0.0, x) / -r;
  return leaving;
}

std::string LemkeRun::invariant_violation() {
  // Every basic variable v: its row (value_v, B^{-1}(v, 0..n-1)) is lexicographically positive
  // [CPS 1992, Sec. 4.9; Murty 1988, Sec. 2.2]: the first entry beyond the rounding level
  // (tie_level() times the value's terms, resp. the row's largest entry) is positive. O(n^2).
  basis_.enable_lexico_rows();
  tie_level_ = -1;
  const double tie = tie_level();
  std::vector<int> basic(basis_.zcols().begin(), basis_.zcols().begin() + basis_.k());
  for (Eigen::Index i = 0; i < n_; ++i)
    if (basis_.rpos(i) < 0) basic.push_back(static_cast<int>(n_ + 1 + i));
  for (int v : basic) {
    double row_max = 0, terms = 0;
    basis_.inverse_row_scales(v, row_max, terms);
    const double x = value(v);
    int sign = x > tie * terms ? 1 : x < -tie * terms ? -1 : 0;
    for (Eigen::Index j = 0; j < n_ && sign == 0; ++j) {
      const double e = basis_.inverse_entry(v, j);
      sign = e > tie * row_max ? 1 : e < -tie * row_max ? -1 : 0;
    }
    if (sign <= 0) {
      std::ostringstream m;
      m << "lexicographic invariant violated: the row of " << var_name(v, n_)
        << " (value " << x << ") is not lexicographically positive";
      return m.str();
    }
  }
  return {};
}

bool LemkeRun::remember_basis(int entering, int leaving) {
  // Zobrist hash of the set of basic variables: XOR of one random key per basic variable,
  // updated in O(1) per pivot. A repeat means the lexicographic rule was violated (a bug or
  // a tie decided by rounding): it is reported instead of cycling to the pivot limit.
  auto key = [](int var) {
    uint64_t x = static_cast<uint64_t>(var) + 0x9E3779B97F4A7C15ull;  // splitmix64
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  };
  if (entering >= 0) hash_ ^= key(entering);
  if (leaving >= 0) hash_ ^= key(leaving);
  const uint64_t h = hash_ == 0 ? 1 : hash_;
  if (2 * (seen_count_ + 1) > seen_.size()) {  // keep the load below 1/2
    std::vector<uint64_t> old(std::max<size_t>(64, 2 * seen_.size()), 0);
    old.swap(seen_);
    seen_count_ = 0;
    for (uint64_t v : old)
      if (v != 0) {
        size_t i = v & (seen_.size() - 1);
        while (seen_[i] != 0) i = (i + 1) & (seen_.size() - 1);
        seen_[i] = v;
        ++seen_count_;
      }
  }
  size_t i = h & (seen_.size() - 1);
  while (seen_[i] != 0) {
    if (seen_[i] == h) return false;
    i = (i + 1) & (seen_.size() - 1);
  }
  seen_[i] = h;
  ++seen_count_;
  return true;
}

bool LemkeRun::find_certificate(const Vec& ray, Certificate& cert) {
  // Cheap candidates y for y >= 0, M^T y <= 0, q^T y < 0, each re-checked from the data by
  // check_certificate (finalize() checks the kept one again). For a copositive-plus M the
  // z-part of the ray is one [CPS 1992, Thm 4.4.13]; for other M the others often are:
  //  - minus the z0 row of B^{-1} (z0 = -row . q + ... must stay >= 0),
  //  - the w-part of the ray (M z_r + d z0_r), the covering vector d and the all-ones vector,
  //  - the unit vectors e_i (row i of M <= 0 with q_i < 0), O(n^2) in all.
  auto accept = [&](const Vec& y) {
    if (!y.allFinite() || !(y.minCoeff() >= 0) || !(y.maxCoeff() > 0)) return false;
    cert = Certificate{};
    cert.y = y.array() + 0.0;  // -0 entries (negated zeros) print as 0
    return check_certificate(problem_, cert);
  };
  if (accept(ray.head(n_))) return true;
  if (basis_.zpos(static_cast<int>(n_)) >= 0) {
    basis_.inverse_row(static_cast<int>(n_), row_cand_);
    if (accept(-row_cand_)) return true;
  }
  const Vec& c = basis_.artificial_column();  // internal units of z0: ray[n_] / beta_
  Vec wray = ray[n_] / beta_ * c;
  for (Eigen::Index j = 0; j < n_; ++j)
    if (ray[j] != 0) wray += ray[j] * Eigen::Map<const Vec>(basis_.gcol(static_cast<int>(j)), n_);
  if (accept(wray)) return true;
  if (o_.covering.size() == n_ && accept(o_.covering)) return true;
  if (accept(Vec::Ones(n_))) return true;
  const Mat& M = basis_.matrix();
  for (Eigen::Index i = 0; i < n_; ++i) {
    if (!(problem_.q[i] < 0) || !(M.row(i).maxCoeff() <= 0)) continue;
    if (accept(Vec::Unit(n_, i))) return true;
  }
  return false;
}

bool LemkeRun::check_accuracy(int pivots) {
  const bool forced = o_.refactor_every > 0 && pivots % o_.refactor_every == 0;
  if (!forced && pivots % kCheckEvery != 0) return true;
  if (forced || !inverse_accurate()) {
    if (!basis_.refactor()) return false;
    fresh_quality_ = quality_ = basis_.hinv_quality();
  }
  basis_.recompute_values();
  drift_ = 0;
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
  std::vector<int>& zset = s_.zset;
  zset.clear();
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(o_.warm_basis.size()); ++i)
    if (o_.warm_basis[static_cast<size_t>(i)] >= 0) zset.push_back(static_cast<int>(i));
  if (!basis_.reset(zset)) {
    add_message(claim, "warm basis ignored: its block M(Z, Z) is singular; cold start");
    zset.clear();
    basis_.reset(zset);
  }
  fresh_quality_ = quality_ = basis_.hinv_quality();
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
      claim.basis.reserve(static_cast<size_t>(n_));
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
  beta_ = mmax_ > 0 ? mmax_ : 1.0;
  const Vec& d = o_.covering.size() ? o_.covering : default_covering();
  Vec& rate0 = s_.rate0;
  rate0.resize(n_);
  Vec& c = s_.column;
  c.setZero(n_);
  for (Eigen::Index i = 0; i < n_; ++i) {
    rate0[i] = basis_.rpos(i) < 0 ? beta_ * d[i] : d[i];
    if (basis_.rpos(i) < 0) c[i] = rate0[i];
  }
  for (int j : zset) c.noalias() -= rate0[j] * Eigen::Map<const Vec>(basis_.gcol(j), n_);
  basis_.set_artificial_column(c);
  g_rowmax_ = c.cwiseAbs();  // row maxima of [M | c], column by column (contiguous)
  for (Eigen::Index j = 0; j < n_; ++j)
    g_rowmax_ = g_rowmax_.cwiseMax(basis_.matrix().col(j).cwiseAbs());
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
  remember_basis(-1, -1);
  {
    entering_ = z0var;
    basis_.direction(z0var, dxz_, dw_);
    double step = 0;
    const int leaving = ratio_test(true, step);
    if (leaving < 0 || !std::isfinite(step)) {
      // A finite basis cannot have a z0 that overflows unless the data span more than the
      // double range (e.g. M = 1e-320, q = -1: z = 1e320).
      claim.status = Status::kNumericalFailure;
      add_message(claim, "the initial z0 pivot overflows: the solution is not representable "
                         "in double precision (|M| and |q| too far apart)");
      claim.iterations = 0;
      basis_.current_point(claim.z, z0);
      return finish(std::move(claim));
    }
    basis_.pivot(z0var, leaving, step, dxz_, dw_);
    note_update(step);
    ++pivots;
    remember_basis(z0var, leaving);
    record(pivots, "z0-enters", z0var, leaving, step * beta_);
    if (o_.check_invariant) {
      if (auto v = invariant_violation(); !v.empty()) {
        claim.status = Status::kNumericalFailure;
        add_message(claim, v + " after pivot " + std::to_string(pivots));
        claim.iterations = pivots;
        basis_.current_point(claim.z, z0);
        return finish(std::move(claim));
      }
    }
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
    const int leaving = ratio_test(false, step);
    if (leaving == -2 || (leaving >= 0 && !std::isfinite(step))) {
      claim.status = Status::kNumericalFailure;
      add_message(claim, "the step overflows after " + std::to_string(pivots) +
                             " pivots: the solution is not representable in double precision");
      break;
    }
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
      Certificate cand;
      if (find_certificate(ray, cand)) {
        claim.status = Status::kInfeasible;
        claim.certificate = cand;
        claim.message += "; infeasibility certificate y >= 0, M^T y <= 0, q^T y < 0 found";
      } else {
        claim.message += "; no infeasibility certificate (M not known copositive-plus)";
      }
      break;
    }
    basis_.pivot(entering, leaving, step, dxz_, dw_);
    note_update(step);
    ++pivots;
    if (!remember_basis(entering, leaving)) {
      record(pivots, "pivot", entering, leaving, step);
      claim.status = Status::kCycleDetected;
      add_message(claim, "basis repeated at pivot " + std::to_string(pivots) +
                             (o_.lexicographic
                                  ? " (the lexicographic rule never revisits a basis: a bug, "
                                    "please report this problem)"
                                  : " (plain tie-breaking cycles; use the lexicographic rule)"));
      break;
    }
    if (o_.check_invariant && leaving != z0var) {
      if (auto v = invariant_violation(); !v.empty()) {
        record(pivots, "pivot", entering, leaving, step);
        claim.status = Status::kNumericalFailure;
        add_message(claim, v + " after pivot " + std::to_string(pivots));
        break;
      }
    }
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
      claim.basis.reserve(static_cast<size_t>(n_));
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
  if (covering.size() != 0) {
    if (covering.size() != n)
      return "covering vector has size " + std::to_string(covering.size()) + ", expected " +
             std::to_string(n);
    for (Eigen::Index i = 0; i < n; ++i)
      if (!(covering[i] > 0) || !std::isfinite(covering[i]))
        return "covering vector entry " + std::to_string(i) +
               " must be positive and finite (got " + num_text(covering[i]) + ")";
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

// Largest n whose arrays are kept per thread between calls (O(n^2) doubles: 2 x 64^2 x 8 bytes
// for H^{-1} and G(:, Z), plus X when a tie occurred).
constexpr Eigen::Index kReuseMaxN = 64;

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
    LemkeStorage storage;
    LemkeRun run(problem, dense, options, storage);
    return run.run();
  }
  // Small problems reuse this thread's arrays (no allocation in the run when n repeats, issue
  // 27); a large one, or a nested call while they are in use, gets its own.
  thread_local LemkeStorage reused;
  thread_local bool in_use = false;
  if (problem.size() <= kReuseMaxN && !in_use) {
    in_use = true;
    struct Release {
      ~Release() { in_use = false; }
    } release;
    LemkeRun run(problem, problem.M, options, reused);
    return run.run();
  }
  LemkeStorage storage;
  LemkeRun run(problem, problem.M, options, storage);
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
