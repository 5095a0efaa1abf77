// The structured path of enumerate_all (enumerate.hpp) for block-bipartite LCPs (bimatrix
// games): the vertices of two polytopes and their completely labelled pairs.
#include "cpkit/lcp/enumerate.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/residuals.hpp"
#include "enumerate_detail.hpp"
#include "rounding_ties.hpp"

namespace cpkit::lcp::detail {
namespace {

// ---------------------------------------------------------------------------------------------
// Structured path: block-bipartite LCPs M = [[0, M12], [M21, 0]] with q > 0, M12 < 0, M21 < 0
// (bimatrix games, M12 = -A, M21 = -B^T). The solutions are exactly the pairs (x, y) of
// vertices of the polytopes P = {x >= 0, q2 + M21 x >= 0} and Q = {y >= 0, q1 + M12 y >= 0}
// whose label sets (tight inequalities, indexed by the LCP index i: z_i = 0 or w_i = 0) cover
// all n indices [von Stengel 2002, Handbook of Game Theory 3, Ch. 45, Sec. 3] - the vertex
// enumeration approach of lrsnash. Both polytopes are bounded (M12, M21 < 0) and contain 0.
// Each polytope's vertex graph is traversed by simplex pivots on a dictionary. The path is
// taken only when every vertex is nondegenerate (no basic variable near zero, no ratio tie);
// otherwise it reports failure and the general engine runs. Every equilibrium is re-solved
// from the original data and checked with the same tests as the general engine.

/// A set of LCP indices of any size (the labels of a polytope vertex, a cobasis): one bit per
/// index in 64-bit words, so that games are bounded by time and memory, not by a mask width.
class IndexSet {
 public:
  IndexSet() = default;
  explicit IndexSet(int n) : w_(static_cast<size_t>((n + 63) / 64), 0) {}
  void set(int i) { w_[size_t(i) >> 6] |= std::uint64_t(1) << (i & 63); }
  void reset(int i) { w_[size_t(i) >> 6] &= ~(std::uint64_t(1) << (i & 63)); }
  bool test(int i) const { return (w_[size_t(i) >> 6] >> (i & 63)) & 1u; }
  int count() const {
    int c = 0;
    for (std::uint64_t x : w_) c += __builtin_popcountll(x);
    return c;
  }
  /// True when every index below n is in this set or in `o`.
  bool covers_with(const IndexSet& o, int n) const {
    for (int i = 0; i < n; ++i)
      if (!test(i) && !o.test(i)) return false;
    return true;
  }
  /// The indices below n that are not in this set.
  IndexSet complement(int n) const {
    IndexSet c(n);
    for (int i = 0; i < n; ++i)
      if (!test(i)) c.set(i);
    return c;
  }
  bool operator==(const IndexSet& o) const { return w_ == o.w_; }
  size_t hash() const { return hash_words(w_.data(), w_.size()); }
  const std::vector<std::uint64_t>& words() const { return w_; }
  static size_t hash_words(const std::uint64_t* w, size_t count) {
    std::uint64_t h = 0;
    for (size_t k = 0; k < count; ++k) {  // splitmix64 finalizer per word
      std::uint64_t z = h ^ (w[k] + 0x9e3779b97f4a7c15ull);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      h = z ^ (z >> 31);
    }
    return static_cast<size_t>(h);
  }

 private:
  std::vector<std::uint64_t> w_;
};
struct IndexSetHash {
  size_t operator()(const IndexSet& s) const { return s.hash(); }
};

/// A set of IndexSets of one width, stored flat: the keys' words in one array and open
/// addressing (linear probing) over indices into it - no allocation per key, so that the
/// traversal's millions of membership tests stay in cache-friendly memory.
class FlatIndexSets {
 public:
  /// Inserts s (of the width of the first key); true when it was not there yet.
  bool insert(const IndexSet& s) {
    const std::vector<std::uint64_t>& w = s.words();
    if (width_ == 0) width_ = w.size();
    if ((size_ + 1) * 2 > slots_.size()) grow();
    size_t at = s.hash() & (slots_.size() - 1);
    for (;; at = (at + 1) & (slots_.size() - 1)) {
      const std::uint32_t k = slots_[at];
      if (k == kEmpty) break;
      if (std::equal(w.begin(), w.end(), words_.begin() + std::ptrdiff_t(size_t(k) * width_)))
        return false;
    }
    slots_[at] = static_cast<std::uint32_t>(size_);
    words_.insert(words_.end(), w.begin(), w.end());
    ++size_;
    return true;
  }
  size_t size() const { return size_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  void grow() {
    std::vector<std::uint32_t> old = std::move(slots_);
    slots_.assign(std::max<size_t>(64, old.size() * 2), kEmpty);
    for (std::uint32_t k : old) {
      if (k == kEmpty) continue;
      size_t at = hash_at(k) & (slots_.size() - 1);
      while (slots_[at] != kEmpty) at = (at + 1) & (slots_.size() - 1);
      slots_[at] = k;
    }
  }
  size_t hash_at(std::uint32_t k) const {
    return IndexSet::hash_words(&words_[size_t(k) * width_], width_);
  }
  std::vector<std::uint64_t> words_;
  std::vector<std::uint32_t> slots_;
  size_t width_ = 0, size_ = 0;
};

/// Bases kept by the traversal of one polytope: the memory bound of the structured path (each
/// costs a hash-set entry; the open bases on the stack are bounded separately).
constexpr size_t kMaxPolytopeBases = 20'000'000;
constexpr size_t kMaxOpenBytes = size_t(2) << 30;  // 2 GiB of open bases on the stack


/// The depth-first traversal of polytope_vertices (below): the dictionary in hand, its scales,
/// and the decisions made on it.
class PolytopeTraversal {
 public:
  PolytopeTraversal(const Mat& D, const Vec& b_in, const std::vector<int>& var_labels,
                    const std::vector<int>& row_labels, int n_in)
      : b(b_in), var_label(var_labels), row_label(row_labels), n(n_in),
        m(static_cast<int>(D.rows())), d(static_cast<int>(D.cols())), w(m + 1),
        open_bytes(sizeof(Open) + sizeof(int) * size_t(m + d) + 64),
        dict_bytes(sizeof(double) * size_t(m) * size_t(d + w)),
        tau(detail::tie_level(m + 1, 0.0)),
        gamma(4.0 * (m + 1) * std::numeric_limits<double>::epsilon()),
        A(m, d + m), P0(Mat::Zero(m, w)), AB(m, m), AN(m, d), col_of(static_cast<size_t>(n), -1),
        u(m), pmax(m), terms(m) {
    // (D, b) come from enumerate_all's equilibrated data: each row and each column of D in a unit
    // of its own, so the column maxima below compare numbers of one unit.
    for (int r = 0; r < m; ++r) b_l1 += std::abs(b(r));
    // The system s - D v = b + (perturbation): A x = P0 with A = [-D | I], P0 = [b | I]; the
    // column of a variable in A by its label.
    A.leftCols(d) = -D;
    A.rightCols(m).setIdentity();
    P0.col(0) = b;
    P0.rightCols(m).setIdentity();
    for (int c = 0; c < d; ++c) col_of[size_t(var_label[c])] = c;
    for (int r = 0; r < m; ++r) col_of[size_t(row_label[r])] = d + r;
  }

  Structured run(std::vector<IndexSet>& masks, Deadline& deadline);

 private:
  struct State {
    std::vector<double> T;  // basic_r = beta_r + sum_c T[r d + c] nonbasic_c
    std::vector<double> R;  // R[r w + 0] = beta_r, R[r w + 1 + k] = P_rk (lexicographic part)
    std::vector<int> bl, nl;  // labels of the basic / nonbasic variables
  };
  /// A basis waiting on the stack: its dictionary while the stack's dictionaries fit in
  /// kStackDictBytes (fast: no refactorisation), else only its labels and the visit it is one
  /// pivot (r0, c) from (memory O(m + d)).
  struct Open {
    State s;
    long long parent = -1;
    int r0 = -1, c = -1;
  };
  static constexpr size_t kStackDictBytes = size_t(64) << 20;
  // Pivot entries: a candidate below -kTie times its column's largest entry, too small to call
  // between kZero and kTie. A basic value above kGrayHi times the largest is positive on an
  // updated dictionary (smaller ones are decided on a fresh one, see classify).
  static constexpr double kZero = 1e-10, kGrayHi = 1e-7, kTie = 1e-9;
  enum { kDecided, kNeedsFresh, kCannotDecide };
  static constexpr int kFail = -2;  ///< leaving_row: the path cannot decide (kUndecided)

  /// The dictionary of basis s.bl from the data: x_B = A_B^-1 P0 - A_B^-1 A_N x_N.
  bool refactor(State& st) {
    for (int r = 0; r < m; ++r) AB.col(r) = A.col(col_of[size_t(st.bl[r])]);
    for (int c = 0; c < d; ++c) AN.col(c) = A.col(col_of[size_t(st.nl[c])]);
    const Eigen::PartialPivLU<Mat> lu(AB);
    const Mat Rm = lu.solve(P0), Tm = -lu.solve(AN);
    if (!Rm.allFinite() || !Tm.allFinite()) return false;
    st.T.resize(size_t(m) * d);
    st.R.resize(size_t(m) * w);
    for (int r = 0; r < m; ++r) {
      for (int c = 0; c < d; ++c) st.T[size_t(r) * d + c] = Tm(r, c);
      for (int k = 0; k < w; ++k) st.R[size_t(r) * w + k] = Rm(r, k);
    }
    return true;
  }
  /// Pivot in place: nonbasic c enters, basic r0 leaves.
  void pivot(State& st, int r0, int c) const {
    const double p = st.T[size_t(r0) * d + c];
    double* tp = &st.T[size_t(r0) * d];
    double* rp = &st.R[size_t(r0) * w];
    for (int cc = 0; cc < d; ++cc) tp[cc] = cc == c ? 1.0 / p : -tp[cc] / p;
    for (int k = 0; k < w; ++k) rp[k] = -rp[k] / p;
    for (int r = 0; r < m; ++r) {
      if (r == r0) continue;
      double* tr = &st.T[size_t(r) * d];
      const double f = tr[c];
      if (f == 0) continue;
      double* rr = &st.R[size_t(r) * w];
      for (int cc = 0; cc < d; ++cc) tr[cc] = cc == c ? f * tp[cc] : tr[cc] + f * tp[cc];
      for (int k = 0; k < w; ++k) rr[k] += f * rp[k];
    }
    std::swap(st.bl[size_t(r0)], st.nl[size_t(c)]);
  }
  void reset_scales() {
    std::fill(pmax.begin(), pmax.end(), -1.0);
    std::fill(terms.begin(), terms.end(), -1.0);
    u_ready = false;
  }
  double row_pmax(int r) {
    if (pmax[size_t(r)] < 0) {
      double x = 0;
      for (int k = 1; k < w; ++k) x = std::max(x, std::abs(s.R[size_t(r) * w + k]));
      pmax[size_t(r)] = x;
    }
    return pmax[size_t(r)];
  }
  void ensure_u() {
    if (u_ready) return;
    for (int j = 0; j < m; ++j) {
      double sum = std::abs(b(j));
      for (int k = 0; k < m; ++k)
        sum += std::abs(A(j, col_of[size_t(s.bl[k])])) * std::abs(s.R[size_t(k) * w]);
      u[size_t(j)] = sum;
    }
    u_ready = true;
  }
  double row_terms(int r) {
    if (terms[size_t(r)] < 0) {
      ensure_u();
      double x = 0;
      for (int j = 0; j < m; ++j) x += std::abs(s.R[size_t(r) * w + 1 + j]) * u[size_t(j)];
      terms[size_t(r)] = x;
    }
    return terms[size_t(r)];
  }
  // The basic values of a dictionary: positive, or zero (a degenerate vertex: the label is
  // added to `lab`, and the row must be lexicographically positive). A value that is small
  // against the largest (<= kGrayHi of it) is judged against the componentwise forward error
  // bound of a fresh solve, |dx_r| <= gamma sum_j |A_B^-1|_rj (|A_B| |x_B| + |b|)_j
  // [Higham 2002, Thm. 7.4] (A_B^-1 is the perturbation block of R): zero within 10 bounds,
  // positive beyond 1e4 bounds, too close to call between. A fixed fraction of the largest value
  // was not scale-aware: an 18 x 18 game with payoffs up to 1000 has a vertex with a genuine
  // basic value 8e-8 times the largest (fresh and pivoted dictionaries agree to 1e-15).
  int classify(bool is_fresh, IndexSet& labels) {
    double bmax = 0;
    for (int r = 0; r < m; ++r) bmax = std::max(bmax, std::abs(s.R[size_t(r) * w]));
    for (int r = 0; r < m; ++r) {
      const double* row = &s.R[size_t(r) * w];
      const double v = row[0];
      if (v > kGrayHi * bmax) continue;  // clearly positive
      if (!is_fresh) return kNeedsFresh;
      const double err = gamma * row_terms(r);
      if (std::abs(v) <= 10 * err) {
        labels.set(s.bl[r]);  // degenerate: a basic variable at zero
        // lexicographically positive: the first entry of the row's perturbation part beyond
        // its rounding (tau times the row's largest entry; the same rule as Lemke's invariant)
        const double level = tau * row_pmax(r);
        int k = 1;
        while (k < w && std::abs(row[k]) <= level) ++k;
        if (k == w || row[k] < 0) return kCannotDecide;  // not lexicographically feasible
      } else if (!(v >= 1e4 * err)) {
        return kCannotDecide;  // negative, or too close to zero to call
      }
    }
    return kDecided;
  }
  // Lexicographic order of rows r and t for the entering column (pivot entries -a_r, -a_t > 0):
  // -1 when r's row / a_r comes first, 1 when t's does, 0 when they are equal at the rounding
  // level in every column (not for independent rows: the path gives up), 2 when the updated
  // dictionary is too close to call (it is then recomputed from the data).
  int lex_order(int r, double ar, int t, double at, bool is_fresh) {
    const double* x = &s.R[size_t(r) * w];
    const double* y = &s.R[size_t(t) * w];
    const double pr = x[0] / ar, pt = y[0] / at, diff = pr - pt;
    if (!is_fresh) {
      // the terms of beta_r are at most max_j |A_B^-1(r, j)| ||b||_1: a cheap bound, O(w)
      const double near = detail::kTieWindow * (std::abs(pr) + std::abs(pt) +
                                                b_l1 * (row_pmax(r) / ar + row_pmax(t) / at));
      if (std::abs(diff) > near) return diff < 0 ? -1 : 1;
      return 2;
    }
    const double sizes = std::abs(pr) + std::abs(pt) + row_terms(r) / ar + row_terms(t) / at;
    if (std::abs(diff) > tau * sizes) return diff < 0 ? -1 : 1;
    const double level = tau * (row_pmax(r) / ar + row_pmax(t) / at);
    for (int k = 1; k < w; ++k) {
    const double e = x[k] / ar - y[k] / at;
    if (std::abs(e) > level) return e < 0 ? -1 : 1;
    }
    return 0;
  }
  /// The leaving row of entering column c by the lexicographic ratio test (-1: an unbounded
  /// edge), kFail when the path cannot decide; a near tie is decided on a dictionary fresh from
  /// the data (fresh is then set).
  int leaving_row(int c, bool& fresh) {
    int best = -1;
    for (bool again = true; again;) {  // twice at most: a near tie is decided on fresh data
      again = false;
      double tmax = 0;
      for (int r = 0; r < m; ++r) tmax = std::max(tmax, std::abs(s.T[size_t(r) * d + c]));
      best = -1;
      for (int r = 0; r < m; ++r) {
        const double a = s.T[size_t(r) * d + c];
        if (!(a < -kTie * tmax)) {
          if (a < -kZero * tmax) return kFail;  // pivot too small to call
          continue;
        }
        if (best < 0) {
          best = r;
          continue;
        }
        const int order = lex_order(r, -a, best, -s.T[size_t(best) * d + c], fresh);
        if (order == 2) {
          if (!refactor(s)) return kFail;
          fresh = again = true;
          reset_scales();
          break;
        }
        if (order == 0) return kFail;  // not for independent perturbations
        if (order < 0) best = r;
      }
    }
    return best;
  }

  const Vec& b;
  const std::vector<int>& var_label;
  const std::vector<int>& row_label;
  const int n, m, d, w;  // w: columns of the right-hand side: beta, then the perturbation P
  const size_t open_bytes, dict_bytes;
  size_t stack_dicts = 0;  // bytes of the dictionaries on the stack
  // Ties of ratios and of perturbation entries: at the rounding level of a dictionary fresh
  // from the data (rounding_ties.hpp; a fresh LU's backward error is at the rounding floor),
  // relative to the size of the terms of each number; an updated dictionary only decides what
  // is clear beyond kTieWindow, anything nearer is decided on a dictionary fresh from the data.
  const double tau, gamma;
  double b_l1 = 0;
  Mat A, P0, AB, AN;
  std::vector<int> col_of;
  // Scales of the current dictionary s, computed when first needed (-1: not yet): pmax[r] =
  // max_j |A_B^-1(r, j)| (the row's perturbation part), and on a fresh dictionary u = |A_B|
  // |x_B| + |b| and terms[r] = sum_j |A_B^-1|_rj u_j, the forward-error scale of beta_r.
  std::vector<double> u, pmax, terms;
  bool u_ready = false;
  State s;
};

Structured PolytopeTraversal::run(std::vector<IndexSet>& masks, Deadline& deadline) {
  FlatIndexSets seen_basis, seen_vertex;
  {
    IndexSet m0(n);
    for (int c = 0; c < d; ++c) m0.set(var_label[c]);
    seen_basis.insert(m0);
  }
  masks.clear();
  std::vector<Open> stack;
  {
    Open root;
    root.s.bl = row_label;
    root.s.nl = var_label;
    stack.push_back(std::move(root));
  }
  long long in_hand = -1, visits = 0;
  while (!stack.empty()) {
    if (deadline.passed(64)) return Structured::kTimeLimit;
    Open o = std::move(stack.back());
    stack.pop_back();
    bool fresh = false;  // the dictionary was just computed from the data (no pivot chain)
    if (!o.s.T.empty()) {
      stack_dicts -= dict_bytes;
      s = std::move(o.s);
    } else if (o.parent >= 0 && o.parent == in_hand) {
      pivot(s, o.r0, o.c);
    } else {
      s.bl = std::move(o.s.bl);
      s.nl = std::move(o.s.nl);
      if (!refactor(s)) return Structured::kUndecided;
      fresh = true;
    }
    reset_scales();
    in_hand = visits++;
    IndexSet cob(n);
    for (int c = 0; c < d; ++c) cob.set(s.nl[c]);
    IndexSet lab = cob;
    int verdict = classify(fresh, lab);
    if (verdict == kNeedsFresh) {  // a small value: decide it on a dictionary fresh from the data
      if (!refactor(s)) return Structured::kUndecided;
      fresh = true;
      reset_scales();
      lab = cob;
      verdict = classify(true, lab);
    }
    if (verdict != kDecided) return Structured::kUndecided;
    if (seen_vertex.insert(lab)) masks.push_back(std::move(lab));
    for (int c = 0; c < d; ++c) {
      const int best = leaving_row(c, fresh);
      if (best == kFail) return Structured::kUndecided;
      if (best < 0) return Structured::kUndecided;  // unbounded edge: not a polytope
      IndexSet nb = cob;
      nb.reset(s.nl[c]);
      nb.set(s.bl[best]);
      if (!seen_basis.insert(nb)) continue;
      if (seen_basis.size() > kMaxPolytopeBases ||
          (stack.size() + 1) * open_bytes + stack_dicts > kMaxOpenBytes)
        return Structured::kMemory;
      Open child;
      if (stack_dicts + dict_bytes <= kStackDictBytes) {
        child.s = s;
        pivot(child.s, best, c);
        stack_dicts += dict_bytes;
      } else {
        child.s.bl = s.bl;
        child.s.nl = s.nl;
        std::swap(child.s.bl[size_t(best)], child.s.nl[size_t(c)]);
        child.parent = in_hand;
        child.r0 = best;
        child.c = c;
      }
      stack.push_back(std::move(child));
    }
  }
  return Structured::kAnswered;
}



/// Vertices of the polytope {v >= 0, b + D v >= 0} (D: m x d, b > 0, bounded), each as the
/// set of its labels (LCP index of every tight inequality: var_label[c] for v_c = 0,
/// row_label[r] for row r; labels are below n). Traverses the vertex graph depth-first by
/// simplex pivots on a dictionary with the lexicographic ratio test (b perturbed by
/// (e, e^2, ...) [Dantzig-Orden-Wolfe 1955]), so that degenerate vertices are handled: every
/// lexicographically feasible basis is visited once and each geometric vertex is reported once
/// with all its tight inequalities. Open bases on the stack keep their dictionaries up to
/// kStackDictBytes; beyond it only their labels (memory O(m + d) each): such a basis one pivot
/// from the dictionary in hand is reached by that pivot, any other is refactorised from the
/// data. kUndecided on an unbounded edge, a tie, or a basic value too close to zero to call.
Structured polytope_vertices(const Mat& D, const Vec& b, const std::vector<int>& var_label,
                             const std::vector<int>& row_label, int n,
                             std::vector<IndexSet>& masks, Deadline& deadline) {
  PolytopeTraversal t(D, b, var_label, row_label, n);
  return t.run(masks, deadline);
}

/// Solves the (possibly overdetermined, consistent) system M[rows, cols] x = -q[rows] into
/// z[cols]; false when the columns are rank deficient.
bool solve_face(const Mat& M, const Vec& q, const std::vector<int>& rows,
                const std::vector<int>& cols, Vec& z) {
  const int a = static_cast<int>(rows.size()), c = static_cast<int>(cols.size());
  if (c == 0) return true;
  if (a < c) return false;
  Mat B(a, c);
  Vec rhs(a);
  // rows equilibrated (each equation w_i = 0 in its own units): the rank decision at the
  // relative threshold below must not compare the equations with each other (a player's rows
  // in units 1e-10 of the others were "rank deficient", and the game went to the general engine)
  for (int i = 0; i < a; ++i) {
    double rm = 0;
    for (int j = 0; j < c; ++j) rm = std::max(rm, std::abs(M(rows[i], cols[j])));
    if (!(rm > 0)) rm = 1;
    rhs(i) = -q(rows[i]) / rm;
    for (int j = 0; j < c; ++j) B(i, j) = M(rows[i], cols[j]) / rm;
  }
  Eigen::ColPivHouseholderQR<Mat> qr(B);
  qr.setThreshold(1e-10);
  if (qr.rank() < c) return false;
  const Vec x = qr.solve(rhs);
  for (int j = 0; j < c; ++j) z(cols[j]) = x(j);
  return true;
}

/// Completely labelled pairs (indices into pm, qm): label sets covering all n indices. A vertex
/// in two pairs may lie on a continuum (maximal Nash subsets are products of faces): then
/// false, and the general engine (which lists pieces) answers. When every vertex has exactly
/// as many labels as its polytope's dimension (nondegenerate), a pair's label sets are exact
/// complements and are matched through a hash table; otherwise every pair is tested.
bool complementary_pairs(const std::vector<IndexSet>& pm, const std::vector<IndexSet>& qm, int k,
                         int n, std::vector<std::pair<size_t, size_t>>& pairs) {
  const int l = n - k;
  const bool nondegenerate =
      std::all_of(pm.begin(), pm.end(), [&](const IndexSet& s) { return s.count() == k; }) &&
      std::all_of(qm.begin(), qm.end(), [&](const IndexSet& s) { return s.count() == l; });
  std::vector<int> qcount(qm.size(), 0);
  pairs.clear();
  if (nondegenerate) {
    std::unordered_map<IndexSet, size_t, IndexSetHash> q_index;
    for (size_t b = 0; b < qm.size(); ++b) q_index.emplace(qm[b], b);
    for (size_t a = 0; a < pm.size(); ++a) {
      const auto it = q_index.find(pm[a].complement(n));
      if (it == q_index.end()) continue;
      if (++qcount[it->second] > 1) return false;
      pairs.emplace_back(a, it->second);
    }
    return true;
  }
  for (size_t a = 0; a < pm.size(); ++a) {
    int c = 0;
    for (size_t b = 0; b < qm.size(); ++b)
      if (pm[a].covers_with(qm[b], n)) {
        if (++c > 1 || ++qcount[b] > 1) return false;
        pairs.emplace_back(a, b);
      }
  }
  return true;
}

}  // namespace

/// The structured path; kAnswered when it produced the complete answer in `out`; kUndecided
/// leaves `out` untouched (the general engine must run); on a budget (time, memory) `out`
/// says complete = false and why.
Structured try_bipartite(const EnumerationOptions& opt, SolutionSet& out, Deadline& deadline) {
  const Mat& M = out.M;
  const Vec& q = out.q;
  const int n = static_cast<int>(q.size());
  const double tol = opt.tol;
  if (!(q.minCoeff() > 0)) return Structured::kUndecided;
  int k = -1;
  for (int kk = 1; kk < n && k < 0; ++kk)
    if ((M.topLeftCorner(kk, kk).array() == 0).all() &&
        (M.bottomRightCorner(n - kk, n - kk).array() == 0).all())
      k = kk;
  if (k < 0) return Structured::kUndecided;
  const int l = n - k;
  const Mat M12 = M.topRightCorner(k, l), M21 = M.bottomLeftCorner(l, k);
  if (!(M12.maxCoeff() < 0) || !(M21.maxCoeff() < 0)) return Structured::kUndecided;
  std::vector<int> xl(k), yl(l);
  for (int i = 0; i < k; ++i) xl[i] = i;
  for (int j = 0; j < l; ++j) yl[j] = k + j;
  std::vector<IndexSet> pm, qm;
  Structured st = polytope_vertices(M21, q.tail(l), xl, yl, n, pm, deadline);
  if (st == Structured::kAnswered) st = polytope_vertices(M12, q.head(k), yl, xl, n, qm, deadline);
  if (st == Structured::kTimeLimit || st == Structured::kMemory) {
    out.complete = false;
    out.structured = true;
    out.nodes = static_cast<long long>(pm.size() + qm.size());
    out.message = st == Structured::kTimeLimit
                      ? "time limit reached while enumerating the players' polytopes (" +
                            std::to_string(out.nodes) + " vertices so far)"
                      : "memory bound of the polytope enumeration reached (" +
                            std::to_string(kMaxPolytopeBases) + " bases or " +
                            std::to_string(kMaxOpenBytes >> 20) + " MiB of open bases)";
    return st;
  }
  if (st != Structured::kAnswered) return st;
  std::vector<std::pair<size_t, size_t>> pairs;
  if (!complementary_pairs(pm, qm, k, n, pairs)) return Structured::kUndecided;
  std::vector<ExtremeSolution> sols;
  std::vector<int> rows_y, cols_x, rows_x, cols_y;
  for (const auto& [a, bq] : pairs) {
    const IndexSet& lp = pm[a];
    const IndexSet& lq = qm[bq];
    // x_i > 0 off lp (i < k), rows w_j = 0 (j >= k) in lp; y_j > 0 off lq, rows w_i = 0 in lq
    std::vector<char> in_s(n, 0), zero_w(n, 0);
    rows_y.clear(), cols_x.clear(), rows_x.clear(), cols_y.clear();
    for (int i = 0; i < k; ++i) {
      if (!lp.test(i)) { in_s[i] = 1; cols_x.push_back(i); }
      if (lq.test(i)) { zero_w[i] = 1; rows_x.push_back(i); }
    }
    for (int j = k; j < n; ++j) {
      if (!lq.test(j)) { in_s[j] = 1; cols_y.push_back(j); }
      if (lp.test(j)) { zero_w[j] = 1; rows_y.push_back(j); }
    }
    Vec z = Vec::Zero(n);
    if (!solve_face(M, q, rows_y, cols_x, z) || !solve_face(M, q, rows_x, cols_y, z))
      return Structured::kUndecided;
    if (!z.allFinite()) return Structured::kUndecided;
    const double zs = z.cwiseAbs().maxCoeff();
    Vec wv = M * z + q;
    for (int i = 0; i < n; ++i) {
      const double sc = std::abs(q(i)) + (M.row(i).cwiseAbs() * z.cwiseAbs())(0);
      if (!finite(sc) || !finite(wv(i))) return Structured::kUndecided;  // the engine decides
      if (in_s[i] && !(z(i) > tol * zs))
        return Structured::kUndecided;  // a support entry at zero: let the engine judge
      if (zero_w[i]) {
        if (std::abs(wv(i)) > kGray * tol * sc) return Structured::kUndecided;  // inaccurate solve
        wv(i) = 0;
      } else if (std::abs(wv(i)) <= tol * sc) {
        wv(i) = 0;
      } else if (wv(i) < 0) {
        return Structured::kUndecided;
      }
      if (z(i) != 0 && wv(i) != 0) return Structured::kUndecided;  // not complementary
    }
    ExtremeSolution e;
    e.z = z;
    e.w = wv;
    e.basis.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) e.basis[size_t(i)] = in_s[i] ? i : ~i;
    sols.push_back(std::move(e));
  }
  out.solutions = std::move(sols);
  out.complete = true;
  out.infinite = false;
  out.nodes = static_cast<long long>(pm.size() + qm.size());
  out.leaves = static_cast<long long>(out.solutions.size());
  out.message.clear();
  out.structured = true;
  return Structured::kAnswered;
}

}  // namespace cpkit::lcp::detail
