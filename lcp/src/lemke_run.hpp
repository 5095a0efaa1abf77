#pragma once
// Private to lemke.cpp (included there only: one translation unit): the tolerances of Lemke's
// method and the per-call state LemkeRun, whose members are defined in lemke.cpp.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "lemke_basis.hpp"
#include "rounding_ties.hpp"

namespace cpkit::lcp {
namespace {

using detail::LemkeBasis;

// Tolerances, all relative to the size of the terms that produced the number being tested
// (so invariant under q -> a q, (M, q) -> b (M, q) and row/column scalings of the data).
// Ties, and pivot entries that are noise, are decided at the rounding level of the computed
// numbers (tie_level()): a few ulps per basic variable, or the measured backward error of the
// basis inverse when that is larger, never above kTieTol, which itself only bounds the window
// in which a tie is looked for. A fixed 1e-9 used as the tie criterion merged real
// differences (DART's Lemke_12D contact LCP, q spanning 0.01 and 1e-10: ratios 1.8e-10 apart,
// 1e5 times their rounding), and the "tie" broken on the B^{-1} columns alone was not the
// lexicographic minimum: a basic variable went negative, the invariant broke and degenerate
// pivots cycled (issue 24, item 7). A fixed pivot tolerance of 1e-11 likewise dropped real
// pivot entries (a P-matrix with det 3 * 2^-40 ended on a false secondary ray).
// The rule is shared with the enumeration's lexicographic simplex (rounding_ties.hpp).
constexpr double kTieTol = detail::kTieWindow;  // window for near ties (times ratio + terms)
constexpr int kCheckEvery = 16;       // pivots between accuracy checks of the basis inverse
constexpr double kRefactorTol = 1e-10;  // relative residual that triggers a refactorization

// A range [first, last) of a preallocated array, for range-for.
template <class T>
struct Span {
  T* first;
  T* last;
  T* begin() const { return first; }
  T* end() const { return last; }
};

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

// A blocking candidate of the ratio test: basic `var` changes at rate -a (a > 0; the
// initial z0 pivot: +a), ratio theta = value / a.
struct LemkeCandidate {
  int var;
  double a, theta;
};

/// The arrays of a LemkeRun (its basis' included), kept by solve_lemke per thread and reused
/// by the next call on a problem of the same size: a small problem then solves without heap
/// allocations in the run (issue 27). Every entry that is read is set by the run first.
struct LemkeStorage {
  detail::LemkeBasisStorage basis;
  Vec dxz, dw, row_best, row_cand, g_rowmax, row_max, covering, rate0, column;
  std::vector<LemkeCandidate> cands, tied;
  std::vector<double> tied_scale;
  std::vector<size_t> tied_pos;
  std::vector<char> excluded;
  std::vector<uint64_t> seen;
  std::vector<int> zset;
};

/// Per-call state of one Lemke run (no hidden state shared between calls: the arrays of
/// `storage` are reset by the constructor).
class LemkeRun {
 public:
  LemkeRun(const LcpProblem& problem, const Mat& M, const LemkeOptions& o, LemkeStorage& storage)
      : problem_(problem),
        o_(o),
        n_(problem.size()),
        s_(storage),
        basis_(M, problem.q, &storage.basis),
        dxz_(storage.dxz),
        dw_(storage.dw),
        row_best_(storage.row_best),
        row_cand_(storage.row_cand),
        cands_(storage.cands),
        tied_(storage.tied),
        tied_scale_(storage.tied_scale),
        tied_pos_(storage.tied_pos),
        g_rowmax_(storage.g_rowmax),
        excluded_(storage.excluded),
        seen_(storage.seen),
        row_max_(storage.row_max) {
    dxz_.setZero(n_ + 1);
    dw_.setZero(n_);
    row_best_.resize(n_);
    row_cand_.resize(n_);
    mmax_ = n_ > 0 ? M.cwiseAbs().maxCoeff() : 0.0;
    qmax_ = problem.q.lpNorm<Eigen::Infinity>();
    if (n_ > 0) row_max_ = M.cwiseAbs().rowwise().maxCoeff();
    else row_max_.resize(0);
    cands_.resize(static_cast<size_t>(n_ + 1));
    tied_.clear();
    tied_.reserve(static_cast<size_t>(n_ + 1));
    tied_scale_.clear();
    tied_scale_.reserve(static_cast<size_t>(n_ + 1));
    excluded_.assign(static_cast<size_t>(2 * n_ + 1), 0);
    tied_pos_.assign(static_cast<size_t>(2 * n_ + 1), kNone);
    seen_.assign(kSeenStart, 0);  // the capacity of a previous run is kept
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
  using Candidate = LemkeCandidate;
  // Lexicographic minimum of (value, B^{-1} row) / a over tied_ (>= 2 candidates).
  int lexmin_of_tied();
  // Relative rounding level of the computed values, ratios and B^{-1} rows at this pivot
  // (computed once per ratio test, on a near tie only): ties are differences below it.
  double tie_level();
  // Size of the terms of the value of basic `var` (the scale its rounding is relative to).
  double value_terms(int var);
  // Debug/test mode (LemkeOptions::check_invariant): every row of [value, B^{-1}] of a basic
  // variable is lexicographically positive at the rounding level; else a message naming it.
  std::string invariant_violation();
  // The pivot entry a of `c` is above tie_level() times the size of its terms (not noise).
  bool admissible(const Candidate& c);
  // Minimum-ratio test with the lexicographic tie-break for the current direction. `initial`:
  // the z0 pivot (basic variables grow; the most negative ratio leaves). -1: no blocking
  // variable (ray); -2: no finite ratio (numerical failure).
  int ratio_test(bool initial, double& step);
  // Adds the rounding of the value updates of a pivot with step t to drift_ (O(n)).
  void note_update(double t) {
    const int k = basis_.k();
    double x_max = basis_.w().lpNorm<Eigen::Infinity>();
    if (k > 0) x_max = std::max(x_max, basis_.xz().head(k).lpNorm<Eigen::Infinity>());
    drift_ += 2 * std::numeric_limits<double>::epsilon() * (std::abs(t) * rate_max_ + x_max);
  }
  // Cycle guard: records the current basis; false when it was visited before.
  bool remember_basis(int entering, int leaving);
  // Candidate certificates at a secondary ray; true when one passes check_certificate.
  bool find_certificate(const Vec& ray, Certificate& cert);
  void record(int iteration, const char* kind, int entering, int leaving, double step);
  SolveResult finish(SolveResult claim);
  bool check_accuracy(int pivots);
  // The updated inverse is as accurate as a fresh one could be (backward error at most
  // kRefactorTol, or within a factor 1e3 of the last freshly computed inverse's).
  bool inverse_accurate() {
    quality_ = basis_.hinv_quality();
    return quality_ <= std::max(kRefactorTol, 1e3 * fresh_quality_);
  }

  const LcpProblem& problem_;
  const LemkeOptions& o_;
  Eigen::Index n_;
  LemkeStorage& s_;
  LemkeBasis basis_;
  Vec &dxz_, &dw_, &row_best_, &row_cand_;
  std::vector<Candidate> &cands_, &tied_;
  std::vector<double>& tied_scale_;
  static constexpr size_t kNone = static_cast<size_t>(-1);
  static constexpr size_t kSeenStart = 64;  // initial size of seen_ (a power of 2)
  std::vector<size_t>& tied_pos_;    // per variable id: position in tied_ (kNone: not tied)
  Vec& g_rowmax_;                    // max_j |G(i, j)| per row (G = [M | c])
  double dxz_l1_ = 0;                // ||dxz||_1 of the current direction
  std::vector<char>& excluded_;      // per variable id, reset after each ratio test
  std::vector<uint64_t>& seen_;      // open-addressing set of basis hashes (0 = empty)
  size_t seen_count_ = 0;
  uint64_t hash_ = 0;                // Zobrist hash of the current basis
  std::vector<TraceEntry> trace_;
  double mmax_ = 0;            // max |M_ij|
  double gmax_ = 1;            // max |[M | c]_ij| (set with the artificial column c)
  double qmax_ = 0;            // ||q||_inf
  double beta_ = 1;            // internal z0 = user z0 / beta_ (see run())
  Vec& row_max_;               // max_j |M_ij| per row (default_covering)

  /// The default covering vector: all ones when the rows of [M q] have comparable sizes
  /// (within kRowSpread), else each row in its own units, d_i = r_i / max r (r_i = max_j
  /// |M_ij|, or |q_i| for a zero row, or max r for a zero row and q_i = 0). With d = 1 a row
  /// scaled by 1e-16 gets a z0 rate 1e16 times its own entries, and the bases along the path
  /// mix those units until one is numerically singular (issue 24: a 40x40 SPD matrix with
  /// rows scaled by 10^-(i mod 17) ended in numerical_failure). Row scaling M -> D M,
  /// q -> D q then scales d by D and leaves the path unchanged.
  /// Written into s_.covering (returned).
  const Vec& default_covering() {
    constexpr double kRowSpread = 1024;
    Vec& r = s_.covering;
    r.resize(n_);
    double rmax = 0;
    for (Eigen::Index i = 0; i < n_; ++i) {
      r[i] = row_max_[i];
      if (!(r[i] > 0)) r[i] = std::abs(problem_.q[i]);
      rmax = std::max(rmax, r[i]);
    }
    if (!(rmax > 0) || !std::isfinite(rmax)) return r.setOnes();
    double rmin = rmax;
    for (Eigen::Index i = 0; i < n_; ++i)
      if (r[i] > 0) rmin = std::min(rmin, r[i]);
    if (rmax <= kRowSpread * rmin) return r.setOnes();
    for (Eigen::Index i = 0; i < n_; ++i) r[i] = r[i] > 0 ? r[i] / rmax : 1.0;
    return r;
  }
  int entering_ = -1;          // the variable entering at the current pivot
  double tie_level_ = -1;      // tie_level() of the current ratio test (-1: not computed)
  double drift_ = 0;           // rounding bound of the updated values since recomputed
  double rate_max_ = 0;        // max |rate| of the current direction
  double fresh_quality_ = 0;  // hinv_quality() right after the last refactorization
  double quality_ = 0;        // hinv_quality() at the last accuracy check (for tie_level())
  Stopwatch clock_;
};

}  // namespace
}  // namespace cpkit::lcp
