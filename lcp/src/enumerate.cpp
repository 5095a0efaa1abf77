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
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "rounding_ties.hpp"

namespace cpkit::lcp {

std::string EnumerationOptions::validate() const {
  if (!(tol > 0 && tol <= 1e-3))
    return "EnumerationOptions::tol must lie in (0, 1e-3], got " + std::to_string(tol);
  if (max_size < 1 || max_size > kMaxEnumerationSize)
    return "EnumerationOptions::max_size must lie in [1, " + std::to_string(kMaxEnumerationSize) +
           "], got " + std::to_string(max_size);
  if (!(time_limit_s > 0)) return "EnumerationOptions::time_limit_s must be > 0";
  if (max_piece_dim < 1 || max_piece_dim > 8)
    return "EnumerationOptions::max_piece_dim must lie in [1, 8], got " +
           std::to_string(max_piece_dim);
  return {};
}

namespace {

using Mask = std::uint64_t;  // supports of the general engine (n <= kMaxEnumerationSize)
constexpr double kGray = 1e4;        // gray band of the sign tests (as enumerate_small)
constexpr double kHuge = std::numeric_limits<double>::max();

bool finite(double x) { return std::abs(x) <= kHuge; }

constexpr double kPivotTol = 1e-10;  // tableau pivot threshold, relative to its row/column
// A tableau row proves infeasibility when q'_r < -kPruneTol * |q'_r|-magnitude (the sum of the
// absolute values of the q-terms that make up q'_r, a bound of its round-off scale) and no free
// column can raise it (T(r, c) > tol * max_c |T(r, c)|). The q part and the T part are measured
// separately: they have different units, and a tiny T(r, c) > 0 can raise any q'_r < 0.
constexpr double kPruneTol = 1e-9;
// Relative round-off allowed in a tableau coefficient (against its row's largest entry) when
// bounding the round-off of q': kPruneTol * kCoefNoise (1e-15) is above the few-ulp error of a
// coefficient after a few pivots, so noise never proves infeasibility (only costs pruning).
constexpr double kCoefNoise = 1e-6;
constexpr double kLeafTol = 1e-8;    // leaf pre-filter (the decision is made on a fresh solve)

/// The wall-clock limit shared by every phase (search, pieces, post-processing).
class Deadline {
 public:
  explicit Deadline(double limit_s) : limit_(limit_s) {}
  /// True once the limit has passed (checks the clock every `every` calls).
  bool passed(int every = 1) {
    if (hit_) return true;
    if (++calls_ % every != 0) return false;
    hit_ = clock_.seconds() > limit_;
    return hit_;
  }
  bool hit() const { return hit_; }

 private:
  Stopwatch clock_;
  double limit_;
  long long calls_ = 0;
  bool hit_ = false;
};

std::vector<int> basis_of(Mask S, int n) {
  std::vector<int> b(n);
  for (int i = 0; i < n; ++i) b[i] = (S >> i) & 1u ? i : ~i;
  return b;
}

std::vector<int> indices_of(Mask S, int n) {
  std::vector<int> idx;
  for (int i = 0; i < n; ++i)
    if ((S >> i) & 1u) idx.push_back(i);
  return idx;
}

/// Directions of the pieces: rays, and vertex-pair differences (deduplicated, ||d||_inf = 1;
/// two directions are the same when they differ by <= 1e4 tol, relative to ||d|| = 1).
/// False when the deadline stopped it (the list is then partial).
bool fill_directions(SolutionSet& out, Deadline& deadline) {
  const double same = kGray * out.tol;
  auto add = [&](Vec d) {
    const double big = d.cwiseAbs().maxCoeff();
    if (!(big > 0) || !finite(big)) return;
    d /= big;
    for (const Vec& e : out.directions)
      if ((e - d).cwiseAbs().maxCoeff() <= same || (e + d).cwiseAbs().maxCoeff() <= same) return;
    out.directions.push_back(d);
  };
  for (const SolutionPiece& p : out.pieces) {
    for (const Vec& r : p.rays) add(r);
    for (size_t a = 0; a < p.vertices.size(); ++a) {
      if (deadline.passed()) return false;
      for (size_t b = a + 1; b < p.vertices.size(); ++b)
        add(out.solutions[p.vertices[b]].z - out.solutions[p.vertices[a]].z);
    }
  }
  return true;
}

template <int N>
void run_small(SolutionSet& out) {
  const Eigen::Matrix<double, N, N> M = out.M;
  const Eigen::Matrix<double, N, 1> q = out.q;
  SmallSolutionSet<N> s;
  enumerate_small<N>(M, q, s, out.tol);
  for (int k = 0; k < s.num_points; ++k) {
    ExtremeSolution e;
    e.z = s.z[k];
    e.w = s.w[k];
    e.basis = basis_of(s.support[k], N);
    out.solutions.push_back(std::move(e));
  }
  for (int k = 0; k < s.num_pieces; ++k) {
    SolutionPiece p;
    p.support = indices_of(s.pieces[k].support, N);
    for (int v = 0; v < s.num_points; ++v)
      if ((s.pieces[k].vertex_mask >> v) & 1u) p.vertices.push_back(v);
    for (int r = 0; r < s.pieces[k].num_rays; ++r) p.rays.push_back(s.pieces[k].rays[r]);
    out.pieces.push_back(std::move(p));
  }
  out.infinite = s.infinite;
  out.ambiguous = s.ambiguous;
  out.unrepresentable = s.unrepresentable;
  out.complete = s.dropped == 0 && s.ambiguous == 0;  // an ambiguous candidate was left out
  if (s.ambiguous > 0)
    out.message = std::to_string(s.ambiguous) +
                  " candidate(s) with a sign test too close to call: not listed";
  if (s.dropped > s.unrepresentable)
    out.message = "fixed-size capacity exceeded (" + std::to_string(s.dropped - s.unrepresentable) +
                  " dropped)";
}

/// Depth-first search over complementary bases with principal pivot updates.
class Engine {
 public:
  /// `reliable_data`: false when (M, q) span more than double's exponent range (then the
  /// tableau, which is only used for pruning, is not trusted and every leaf is decided from
  /// the data).
  Engine(const EnumerationOptions& opt, SolutionSet& out, Deadline& deadline, bool reliable_data)
      : n_(static_cast<int>(out.q.size())), M_(out.M), q_(out.q), opt_(opt), tol_(opt.tol),
        out_(out), deadline_(deadline), decided_(n_, 0) {
    levels_.resize(n_ + 1);
    for (Level& L : levels_) {
      L.T.resize(size_t(n_) * n_);
      L.qv.resize(n_);
      L.row_label.resize(n_);
      L.col_label.resize(n_);
      L.row_of.resize(2 * n_);
      L.col_of.resize(2 * n_);
      L.row_scale.resize(n_);
      L.qmag.resize(n_);
    }
    Level& L = levels_[0];
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j) L.T[size_t(i) * n_ + j] = M_(i, j);
      L.qv[i] = q_(i);
      L.row_label[i] = n_ + i;  // w_i basic
      L.col_label[i] = i;       // z_i nonbasic
      L.row_of[n_ + i] = i;
      L.row_of[i] = -1;
      L.col_of[i] = i;
      L.col_of[n_ + i] = -1;
    }
    L.pending = 0;
    L.unsafe = !reliable_data;
    make_order();
    for (int i = 0; i < n_; ++i) {
      double sc = 0;
      for (int j = 0; j < n_; ++j) sc = std::max(sc, std::abs(M_(i, j)));
      L.row_scale[i] = sc;
      L.qmag[i] = std::abs(q_(i));
    }
  }

  void run() {
    if (!prune(levels_[0])) visit(0, 0, 0);
    out_.nodes = nodes_;
    out_.leaves = leaves_;
    finish();
    if (deadline_.hit() && out_.message.empty())
      out_.message = "time limit reached after " + std::to_string(nodes_) + " nodes";
    if (unrepresentable_ > 0) out_.unrepresentable += unrepresentable_;
  }

 private:
  struct Level {
    std::vector<double> T;  // row-major n x n: basic_r = qv_r + sum_c T(r,c) nonbasic_c
    std::vector<double> qv;
    std::vector<int> row_label, col_label;  // variable ids: z_j = j, w_j = n + j
    std::vector<int> row_of, col_of;        // inverse maps (-1: not there)
    std::vector<double> row_scale;          // max_c |T(r,c)|, kept by pivot()
    std::vector<double> qmag;               // sum of |q-terms| of qv_r (its round-off scale)
    Mask pending = 0;  // decided in S, z_j still nonbasic (diagonal pivot vanished)
    bool unsafe = false;  // some entry overflowed (or the data are extreme): no pruning below
  };

  double& t(Level& L, int r, int c) { return L.T[size_t(r) * n_ + c]; }

  /// Decision order: natural, except that an index with a vanishing diagonal is followed by
  /// the partner j maximising |M_ij M_ji| (so that the 2x2 block pivot becomes available at
  /// once; for bimatrix games this interleaves the two players' strategies).
  void make_order() {
    std::vector<char> used(n_, 0);
    double mmax = M_.cwiseAbs().maxCoeff();
    for (int i = 0; i < n_; ++i) {
      if (used[i]) continue;
      used[i] = 1;
      order_.push_back(i);
      if (std::abs(M_(i, i)) > kPivotTol * mmax) continue;
      int best = -1;
      double bv = 0;
      for (int j = 0; j < n_; ++j)
        if (!used[j] && std::abs(M_(i, j) * M_(j, i)) > bv) {
          bv = std::abs(M_(i, j) * M_(j, i));
          best = j;
        }
      if (best >= 0) {
        used[best] = 1;
        order_.push_back(best);
      }
    }
  }

  void copy_level(const Level& a, Level& b) {
    std::copy(a.T.begin(), a.T.end(), b.T.begin());
    b.qv = a.qv;
    b.row_label = a.row_label;
    b.col_label = a.col_label;
    b.row_of = a.row_of;
    b.col_of = a.col_of;
    b.row_scale = a.row_scale;
    b.qmag = a.qmag;
    b.pending = a.pending;
    b.unsafe = a.unsafe;
  }

  /// Exchanges the basic variable of row r with the nonbasic variable of column c.
  void pivot(Level& L, int r, int c) {
    double* row = &L.T[size_t(r) * n_];
    const double p = row[c];
    const double ip = 1.0 / p;
    L.qv[r] = -L.qv[r] * ip;
    L.qmag[r] *= std::abs(ip);
    double sr = 0;
    for (int k = 0; k < n_; ++k) {
      row[k] = -row[k] * ip;
      sr = std::max(sr, std::abs(row[k]));
    }
    row[c] = ip;
    L.row_scale[r] = std::max(sr, std::abs(ip));
    for (int i = 0; i < n_; ++i) {
      if (i == r) continue;
      double* ri = &L.T[size_t(i) * n_];
      const double f = ri[c];
      if (f == 0) continue;
      L.qv[i] += f * L.qv[r];
      // f itself carries round-off from earlier pivots, up to a small multiple of eps times
      // the row's magnitude: a coefficient that should be 0 (paired columns c, -c) comes out
      // as 1e-17 and moves q'_i by f q'_r. The magnitude must cover that, or the prune test
      // below would read the noise as a proof of infeasibility (a missed solution).
      L.qmag[i] += std::max(std::abs(f), kCoefNoise * L.row_scale[i]) * L.qmag[r];
      double si = 0;
      for (int k = 0; k < n_; ++k) {
        ri[k] += f * row[k];
        si = std::max(si, std::abs(ri[k]));
      }
      ri[c] = f * ip;
      L.row_scale[i] = std::max(si, std::abs(ri[c]));
    }
    for (int i = 0; i < n_; ++i)
      L.unsafe = L.unsafe || !(L.row_scale[i] <= kHuge) || !(L.qmag[i] <= kHuge) || !finite(L.qv[i]);
    const int br = L.row_label[r], nc = L.col_label[c];
    L.row_label[r] = nc;
    L.col_label[c] = br;
    L.row_of[nc] = r;
    L.row_of[br] = -1;
    L.col_of[br] = c;
    L.col_of[nc] = -1;
  }

  bool pivot_ok(Level& L, int r, int c, double value) {
    double s = 0;
    for (int k = 0; k < n_; ++k) s = std::max(s, std::abs(t(L, r, k)));
    for (int k = 0; k < n_; ++k) s = std::max(s, std::abs(t(L, k, c)));
    return std::abs(value) > kPivotTol * s;
  }

  /// Pivots pending indices in whenever a 1x1 or 2x2 principal block allows it.
  void resolve_pending(Level& L) {
    bool progress = true;
    while (progress && L.pending) {
      progress = false;
      for (int p = 0; p < n_; ++p) {
        if (!((L.pending >> p) & 1u)) continue;
        const int r = L.row_of[n_ + p], c = L.col_of[p];
        if (pivot_ok(L, r, c, t(L, r, c))) {
          pivot(L, r, c);
          L.pending &= ~(Mask(1) << p);
          progress = true;
        }
      }
      if (progress) continue;
      for (int a = 0; a < n_ && !progress; ++a) {
        if (!((L.pending >> a) & 1u)) continue;
        for (int b = a + 1; b < n_ && !progress; ++b) {
          if (!((L.pending >> b) & 1u)) continue;
          const int r1 = L.row_of[n_ + a], c1 = L.col_of[a];
          const int r2 = L.row_of[n_ + b], c2 = L.col_of[b];
          const double t12 = t(L, r1, c2);
          if (!pivot_ok(L, r1, c2, t12)) continue;
          const double t21 = t(L, r2, c1) - t(L, r2, c2) * t(L, r1, c1) / t12;
          if (!pivot_ok(L, r2, c1, t21)) continue;
          pivot(L, r1, c2);  // w_a <-> z_b
          pivot(L, r2, c1);  // w_b <-> z_a
          L.pending &= ~((Mask(1) << a) | (Mask(1) << b));
          progress = true;
        }
      }
    }
  }

  bool free_col(const Level& L, int c) const {
    const int lab = L.col_label[c];
    return lab < n_ && (!decided_[lab] || ((L.pending >> lab) & 1u));
  }

  /// True when some row proves that no completion of the current decisions is feasible.
  /// With only_col >= 0, only the rows in which that column could raise the basic variable
  /// are examined (the column has just stopped being free).
  bool prune(Level& L, int only_col = -1) {
    if (L.unsafe) return false;  // overflowed tableau: prove nothing from it
    int nf = 0;
    for (int c = 0; c < n_; ++c)
      if (free_col(L, c)) free_[nf++] = c;
    for (int r = 0; r < n_; ++r) {
      const double qr = L.qv[r];
      const double* row = &L.T[size_t(r) * n_];
      const double s = L.row_scale[r], sq = L.qmag[r];
      if (only_col >= 0) {
        const double v = row[only_col];
        if (!(qr < -kPruneTol * sq && v > tol_ * s) && !(qr > kPruneTol * sq && v < -tol_ * s))
          continue;
      }
      const int lab = L.row_label[r];
      const bool must_vanish = lab >= n_ && ((L.pending >> (lab - n_)) & 1u);
      if (qr < -kPruneTol * sq) {
        bool can_rise = false;
        for (int f = 0; f < nf && !can_rise; ++f) can_rise = row[free_[f]] > tol_ * s;
        if (!can_rise) return true;
      } else if (must_vanish && qr > kPruneTol * sq) {
        bool can_fall = false;
        for (int f = 0; f < nf && !can_fall; ++f) can_fall = row[free_[f]] < -tol_ * s;
        if (!can_fall) return true;
      }
    }
    return false;
  }

  void visit(int d, int cur, Mask S) {
    if (stopped_) return;
    ++nodes_;
    if (deadline_.passed(1024)) {
      stopped_ = true;
      return;
    }
    if (d == n_) {
      leaf(levels_[cur], S);
      return;
    }
    const int i = order_[d];
    decided_[i] = 1;
    // branch A: i not in S (z_i = 0, w_i basic): only column z_i stopped being free
    const int ci = levels_[cur].col_of[i];
    if (!prune(levels_[cur], ci >= 0 ? ci : -1)) visit(d + 1, cur, S);
    // branch B: i in S (w_i = 0, z_i basic)
    Level& nb = levels_[d + 1];
    copy_level(levels_[cur], nb);
    const int r = nb.row_of[n_ + i], c = nb.col_of[i];
    if (r >= 0 && c >= 0 && pivot_ok(nb, r, c, t(nb, r, c))) {
      pivot(nb, r, c);
    } else {
      nb.pending |= Mask(1) << i;
    }
    resolve_pending(nb);
    if (!prune(nb)) visit(d + 1, d + 1, S | (Mask(1) << i));
    decided_[i] = 0;
  }

  void leaf(Level& L, Mask S) {
    ++leaves_;
    if (L.pending || L.unsafe) {  // a block the 1x1 / 2x2 pivots could not resolve: decide from the data
      piece(S);
      return;
    }
    for (int r = 0; r < n_; ++r)
      if (L.qv[r] < -kLeafTol * L.qmag[r]) return;
    piece(S);
  }

  /// Solutions of piece S decided from the original data: a point when M_SS is nonsingular,
  /// otherwise vertices and rays in the null space of M_SS.
  void piece(Mask S) {
    if (deadline_.passed(16)) {  // a leaf may cost C(n, m) solves: the limit holds here too
      stopped_ = true;
      return;
    }
    const std::vector<int> idx = indices_of(S, n_);
    const int k = static_cast<int>(idx.size());
    Vec z = Vec::Zero(n_);
    if (k == 0) {
      add_point(S, z);
      return;
    }
    // rows equilibrated: each equation w_i = 0 has its own scale, so the rank decision must
    // not compare the rows with each other (diag(1e-320, 1) is regular); x is unchanged
    Mat A(k, k);
    Vec b(k);
    for (int r = 0; r < k; ++r) {
      double rm = 0;
      for (int c = 0; c < k; ++c) rm = std::max(rm, std::abs(M_(idx[r], idx[c])));
      if (!(rm > 0)) rm = 1;
      for (int c = 0; c < k; ++c) A(r, c) = M_(idx[r], idx[c]) / rm;
      b(r) = -q_(idx[r]) / rm;
    }
    Eigen::FullPivLU<Mat> lu(A);
    lu.setThreshold(tol_);
    const Vec x = lu.solve(b);
    for (int c = 0; c < k; ++c) z(idx[c]) = x(c);
    const int m = k - static_cast<int>(lu.rank());
    if (m == 0) {
      add_point(S, z);
      return;
    }
    if (!z.allFinite()) {  // overflow: nothing below can be decided
      ++unrepresentable_;
      return;
    }
    // consistency: -q_S in the range of M_SS (backward-error scale |q_i| + ||M_i.||_1 ||z0||_inf:
    // entries of z0 that should vanish carry round-off of the size of the whole z0)
    const double z0n = z.cwiseAbs().maxCoeff();
    for (int c = 0; c < k; ++c) {
      const int i = idx[c];
      double v = q_(i), sc = std::abs(q_(i));
      for (int j = 0; j < n_; ++j) {
        v += M_(i, j) * z(j);
        sc += std::abs(M_(i, j)) * z0n;
      }
      if (!finite(sc) || !finite(v)) {
        ++unrepresentable_;
        return;
      }
      if (std::abs(v) > kGray * tol_ * sc) return;  // empty piece
      if (std::abs(v) > tol_ * sc) {
        ++out_.ambiguous;
        return;
      }
    }
    if (m > opt_.max_piece_dim) {
      if (!incomplete_piece_) {
        incomplete_piece_ = true;
        out_.message = "a piece with a " + std::to_string(m) +
                       "-dimensional null space exceeds max_piece_dim";
      }
      return;
    }
    singular_.push_back(S);
    const Mat K = lu.kernel();  // k x m
    if (!K.allFinite()) {
      ++unrepresentable_;
      return;
    }
    Mat N = Mat::Zero(n_, m);
    for (int c = 0; c < k; ++c) N.row(idx[c]) = K.row(c);
    // constraints g_i(t) = b_i + G_i t >= 0: z_i on S, w_i off S
    Mat G(n_, m);
    Vec g0(n_);
    const Vec w0 = M_ * z + q_;
    const Mat MN = M_ * N;
    // entries at round-off level of their own terms are zero (a constraint that is constant
    // on the piece must not produce a "vertex" from noise / noise)
    const double nmax = N.cwiseAbs().maxCoeff();
    for (int i = 0; i < n_; ++i) {
      if ((S >> i) & 1u) {
        G.row(i) = N.row(i);
        g0(i) = z(i);
        for (int f = 0; f < m; ++f)
          if (std::abs(G(i, f)) <= tol_ * nmax) G(i, f) = 0;
        if (std::abs(g0(i)) <= tol_ * z0n) g0(i) = 0;
      } else {
        G.row(i) = MN.row(i);
        g0(i) = w0(i);
        double sz = std::abs(q_(i));
        for (int j = 0; j < n_; ++j) sz += std::abs(M_(i, j)) * z0n;
        for (int f = 0; f < m; ++f) {
          double sf = 0;
          for (int j = 0; j < n_; ++j) sf += std::abs(M_(i, j) * N(j, f));
          if (std::abs(G(i, f)) <= tol_ * sf) G(i, f) = 0;
        }
        if (std::abs(g0(i)) <= tol_ * sz) g0(i) = 0;
      }
    }
    if (!G.allFinite() || !g0.allFinite()) {
      ++unrepresentable_;
      return;
    }
    // each row of G has the units of its own z_i or w_i: the systems below are row-equilibrated
    // so that their rank decisions are invariant under (M, q) -> b (M, q)
    Vec gmax(n_);
    for (int i = 0; i < n_; ++i) gmax(i) = G.row(i).cwiseAbs().maxCoeff();
    // vertices: m active constraints; rays: m - 1
    std::vector<int> comb;
    auto for_each_subset = [&](int size, auto&& fn) {
      comb.resize(size);
      for (int j = 0; j < size; ++j) comb[j] = j;
      while (true) {
        if (deadline_.passed(64)) {
          stopped_ = true;
          return;
        }
        fn();
        int j = size - 1;
        while (j >= 0 && comb[j] == n_ - size + j) --j;
        if (j < 0) break;
        ++comb[j];
        for (int l = j + 1; l < size; ++l) comb[l] = comb[l - 1] + 1;
      }
    };
    for_each_subset(m, [&] {
      Mat E(m, m);
      Vec e(m);
      for (int r = 0; r < m; ++r) {
        const double gm = gmax(comb[r]);
        if (gm == 0) return;  // constant on the piece
        E.row(r) = G.row(comb[r]) / gm;
        e(r) = -g0(comb[r]) / gm;
      }
      Eigen::FullPivLU<Mat> l2(E);
      l2.setThreshold(tol_);
      if (l2.rank() < m) return;
      Vec zz = z + N * l2.solve(e);
      add_point(S, zz);
    });
    if (m == 1) {
      Vec d = N.col(0);
      add_ray(S, d);
      d = -N.col(0);
      add_ray(S, d);
      return;
    }
    for_each_subset(m - 1, [&] {
      Mat E(m - 1, m);
      for (int r = 0; r < m - 1; ++r) {
        const double gm = gmax(comb[r]);
        if (gm == 0) return;  // a zero row: rank < m - 1
        E.row(r) = G.row(comb[r]) / gm;
      }
      Eigen::FullPivLU<Mat> l2(E);
      l2.setThreshold(tol_);
      if (l2.rank() < m - 1) return;
      const Vec tt = l2.kernel().col(0);
      Vec d = N * tt;
      add_ray(S, d);
      d = -d;
      add_ray(S, d);
    });
  }

  /// Judges the candidate z of piece S (z_i = 0 off S, w_i = 0 on S by construction) from the
  /// data and stores it when feasible and new; the same tests as SmallEnumerator::add_point
  /// (enumerate_small.hpp): relative to ||z||_inf and W_i = |q_i| + sum_j |M_ij z_j|.
  void add_point(Mask S, Vec& z) {
    double zs = 0;
    bool ok = true;
    for (int j = 0; j < n_; ++j) {
      if (!((S >> j) & 1u)) {
        z(j) = 0;
        continue;
      }
      if (!finite(z(j))) {
        if (z(j) < 0) return;  // -inf: clearly negative
        ok = false;            // +inf or NaN: not representable
      }
      zs = std::max(zs, std::abs(z(j)));
    }
    if (!ok) {
      ++unrepresentable_;
      return;
    }
    int verdict = 0;
    Mask zz = 0, zw = 0, tiny = 0;
    for (int j = 0; j < n_; ++j) {
      if (!((S >> j) & 1u)) {
        zz |= Mask(1) << j;
        continue;
      }
      if (z(j) < -kGray * tol_ * zs) return;         // clearly negative against ||z||
      if (z(j) <= tol_ * zs) tiny |= Mask(1) << j;  // tiny, or in the gray band
    }
    if (tiny && !settle_tiny(S, tiny, z, zz)) return;
    Vec w(n_);
    for (int i = 0; i < n_; ++i) {
      double v = q_(i), sc = std::abs(q_(i));
      for (int j = 0; j < n_; ++j)
        if (z(j) != 0) {
          v += M_(i, j) * z(j);
          sc += std::abs(M_(i, j) * z(j));
        }
      if (!finite(sc) || !finite(v)) {
        ++unrepresentable_;
        return;
      }
      if ((S >> i) & 1u) {  // w_i = 0 by construction; a solve that missed it cannot be trusted
        if (!(std::abs(v) <= kGray * tol_ * sc)) verdict = 1;
        w(i) = 0;
        zw |= Mask(1) << i;
        continue;
      }
      if (v < -kGray * tol_ * sc) return;
      if (v < -tol_ * sc) verdict = 1;
      if (std::abs(v) <= tol_ * sc) {
        w(i) = 0;
        zw |= Mask(1) << i;
      } else {
        w(i) = v;
      }
    }
    if (verdict == 1) {
      ++out_.ambiguous;
      return;
    }
    for (size_t p = 0; p < out_.solutions.size(); ++p) {
      const Vec& y = out_.solutions[p].z;
      const double s2 = std::max(zs, y.cwiseAbs().maxCoeff());
      if ((y - z).cwiseAbs().maxCoeff() <= kGray * tol_ * s2 && merge_ok(p, zz, zw)) {
        zero_z_[p] |= zz;
        zero_w_[p] |= zw;
        return;
      }
    }
    ExtremeSolution e;
    e.z = z;
    e.w = w;
    out_.solutions.push_back(std::move(e));
    zero_z_.push_back(zz);
    zero_w_.push_back(zw);
  }

  /// Entries tiny against ||z||_inf or in the gray band below zero (mask `tiny`; a unit-free
  /// backward-error decision rather than a comparison with ||z|| alone) are zero when setting
  /// them all to zero keeps every equation w_i = 0 (i in S, to 1e4 tol W_i) and the
  /// feasibility of every other w_i; else each one is zero only when negligible in every row
  /// (|M_ij z_j| <= tol W_i), and one that is not negligible keeps its value, its sign deciding
  /// (e.g. M = diag(1e200, 1): z_0 = -1e-200 moves w_0 by 1, so the candidate is infeasible).
  /// False when the candidate is infeasible.
  /// The same rule as SmallEnumerator::settle_tiny (enumerate_small.hpp).
  bool settle_tiny(Mask S, Mask tiny, Vec& z, Mask& zz) const {
    const Vec W = row_scales(z);
    Vec zt = z;
    for (int j = 0; j < n_; ++j)
      if ((tiny >> j) & 1u) zt(j) = 0;
    bool consistent = true;
    for (int i = 0; i < n_ && consistent; ++i) {
      const double vt = q_(i) + M_.row(i).dot(zt);
      if ((S >> i) & 1u) {
        consistent = std::abs(vt) <= kGray * tol_ * W(i);
      } else {
        consistent = (vt >= -tol_ * W(i)) == (q_(i) + M_.row(i).dot(z) >= -tol_ * W(i));
      }
    }
    if (consistent) {
      z = zt;
      zz |= tiny;
      return true;
    }
    for (int j = 0; j < n_; ++j) {
      if (!((tiny >> j) & 1u)) continue;
      bool negligible = true;
      for (int i = 0; i < n_ && negligible; ++i)
        negligible = std::abs(M_(i, j) * z(j)) <= tol_ * W(i);
      if (negligible) {
        z(j) = 0;
        zz |= Mask(1) << j;
      } else if (z(j) < 0) {
        return false;
      }
    }
    return true;
  }

  /// W_i = |q_i| + sum_j |M_ij z_j|: the size of the terms of w_i.
  Vec row_scales(const Vec& z) const {
    Vec W(n_);
    for (int i = 0; i < n_; ++i) {
      double sc = std::abs(q_(i));
      for (int j = 0; j < n_; ++j) sc += std::abs(M_(i, j) * z(j));
      W(i) = sc;
    }
    return W;
  }

  /// True when stored solution p satisfies the new zero claims zz, zw of a candidate found
  /// equal to it (close in z is not close in w when M has large entries).
  bool merge_ok(size_t p, Mask zz, Mask zw) const {
    const Mask nz = zz & ~zero_z_[p], nw = zw & ~zero_w_[p];
    if (!nz && !nw) return true;
    const ExtremeSolution& e = out_.solutions[p];
    const Vec W = row_scales(e.z);
    for (int j = 0; j < n_; ++j) {
      if (!((nz >> j) & 1u)) continue;
      for (int i = 0; i < n_; ++i)
        if (!(std::abs(M_(i, j) * e.z(j)) <= tol_ * W(i))) return false;
    }
    for (int i = 0; i < n_; ++i)
      if (((nw >> i) & 1u) && !(std::abs(e.w(i)) <= tol_ * W(i))) return false;
    return true;
  }

  void add_ray(Mask S, Vec& d) {
    if (!d.allFinite()) {
      ++unrepresentable_;
      return;
    }
    Eigen::Index arg = 0;
    const double big = d.cwiseAbs().maxCoeff(&arg);
    if (!(big > 0) || d(arg) < 0) return;
    d /= big;
    int verdict = 0;
    Mask zd = 0, zmd = 0;
    for (int j = 0; j < n_; ++j) {
      if (!((S >> j) & 1u)) {
        d(j) = 0;
        zd |= Mask(1) << j;
        continue;
      }
      if (d(j) < -kGray * tol_) return;
      if (d(j) < -tol_) verdict = 1;
      if (std::abs(d(j)) <= tol_) {
        d(j) = 0;
        zd |= Mask(1) << j;
      }
    }
    for (int i = 0; i < n_; ++i) {
      if ((S >> i) & 1u) {
        zmd |= Mask(1) << i;
        continue;
      }
      double v = 0, sc = 0;
      for (int j = 0; j < n_; ++j)
        if (d(j) != 0) {
          v += M_(i, j) * d(j);
          sc += std::abs(M_(i, j) * d(j));
        }
      if (!finite(sc) || !finite(v)) {
        ++unrepresentable_;
        return;
      }
      if (v < -kGray * tol_ * sc) return;
      if (v < -tol_ * sc) verdict = 1;
      if (std::abs(v) <= tol_ * sc) zmd |= Mask(1) << i;
    }
    if (verdict == 1) {
      ++out_.ambiguous;
      return;
    }
    for (size_t p = 0; p < rays_.size(); ++p)
      if ((rays_[p] - d).cwiseAbs().maxCoeff() <= kGray * tol_) {
        ray_zero_d_[p] |= zd;
        ray_zero_md_[p] |= zmd;
        return;
      }
    rays_.push_back(d);
    ray_zero_d_.push_back(zd);
    ray_zero_md_.push_back(zmd);
  }

  void finish() {
    const Mask all = n_ == 64 ? ~Mask(0) : (Mask(1) << n_) - 1;
    for (size_t p = 0; p < out_.solutions.size(); ++p) {
      ExtremeSolution& e = out_.solutions[p];
      for (int j = 0; j < n_; ++j) {
        if ((zero_z_[p] >> j) & 1u) e.z(j) = 0;
        if ((zero_w_[p] >> j) & 1u) e.w(j) = 0;
      }
      e.basis = basis_of(~zero_z_[p] & all, n_);
    }
    std::sort(singular_.begin(), singular_.end());
    singular_.erase(std::unique(singular_.begin(), singular_.end()), singular_.end());
    struct Cand {
      Mask S;
      std::vector<char> v, r;
      int nv = 0, nr = 0;
    };
    std::vector<Cand> cands;
    for (Mask S : singular_) {
      if (deadline_.passed()) break;
      const Mask off = ~S & all;
      Cand c;
      c.S = S;
      c.v.assign(out_.solutions.size(), 0);
      c.r.assign(rays_.size(), 0);
      for (size_t p = 0; p < out_.solutions.size(); ++p)
        if ((zero_z_[p] & off) == off && (zero_w_[p] & S) == S) { c.v[p] = 1; ++c.nv; }
      for (size_t p = 0; p < rays_.size(); ++p)
        if ((ray_zero_d_[p] & off) == off && (ray_zero_md_[p] & S) == S) { c.r[p] = 1; ++c.nr; }
      if (c.nv == 0 || (c.nv < 2 && c.nr == 0)) continue;
      cands.push_back(std::move(c));
    }
    auto subset = [](const std::vector<char>& a, const std::vector<char>& b) {
      for (size_t i = 0; i < a.size(); ++i)
        if (a[i] && !b[i]) return false;
      return true;
    };
    for (size_t a = 0; a < cands.size(); ++a) {
      if (deadline_.passed()) break;
      bool maximal = true;
      for (size_t b = 0; b < cands.size() && maximal; ++b) {
        if (a == b) continue;
        const bool sub = subset(cands[a].v, cands[b].v) && subset(cands[a].r, cands[b].r);
        const bool equal = sub && cands[a].nv == cands[b].nv && cands[a].nr == cands[b].nr;
        if (sub && (!equal || b < a)) maximal = false;
      }
      if (!maximal) continue;
      SolutionPiece pc;
      pc.support = indices_of(cands[a].S, n_);
      for (size_t p = 0; p < cands[a].v.size(); ++p)
        if (cands[a].v[p]) pc.vertices.push_back(static_cast<int>(p));
      for (size_t p = 0; p < cands[a].r.size(); ++p)
        if (cands[a].r[p]) pc.rays.push_back(rays_[p]);
      out_.pieces.push_back(std::move(pc));
    }
    out_.infinite = !out_.pieces.empty();
    out_.complete = !stopped_ && !incomplete_piece_ && !deadline_.hit();
  }

  int n_;
  const Mat& M_;
  const Vec& q_;
  const EnumerationOptions& opt_;
  double tol_;
  SolutionSet& out_;
  Deadline& deadline_;
  std::vector<char> decided_;
  std::vector<int> order_;
  std::vector<int> free_ = std::vector<int>(kMaxEnumerationSize);
  std::vector<Level> levels_;
  std::vector<Mask> zero_z_, zero_w_;
  std::vector<Vec> rays_;
  std::vector<Mask> ray_zero_d_, ray_zero_md_;
  std::vector<Mask> singular_;
  bool stopped_ = false;
  bool incomplete_piece_ = false;
  int unrepresentable_ = 0;
  long long nodes_ = 0, leaves_ = 0;
};

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

/// Why the structured path did not answer: the general engine then decides (kUndecided), or,
/// on a budget, the answer is incomplete and says so.
enum class Structured { kAnswered, kUndecided, kTimeLimit, kMemory };

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
  // (D, b) come from enumerate_all's equilibrated data: each row and each column of D in a unit
  // of its own, so the column maxima below compare numbers of one unit.
  const int m = static_cast<int>(D.rows()), d = static_cast<int>(D.cols());
  const int w = m + 1;  // columns of the right-hand side: beta, then the perturbation P
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
  const size_t open_bytes = sizeof(Open) + sizeof(int) * size_t(m + d) + 64;
  const size_t dict_bytes = sizeof(double) * size_t(m) * size_t(d + w);
  constexpr size_t kStackDictBytes = size_t(64) << 20;
  size_t stack_dicts = 0;  // bytes of the dictionaries on the stack
  // Pivot entries: a candidate below -kTie times its column's largest entry, too small to call
  // between kZero and kTie. A basic value
  // above kGrayHi times the largest is positive on an updated dictionary (smaller ones are
  // decided on a fresh one, see classify).
  constexpr double kZero = 1e-10, kGrayHi = 1e-7, kTie = 1e-9;
  // Ties of ratios and of perturbation entries: at the rounding level of a dictionary fresh
  // from the data (rounding_ties.hpp; a fresh LU's backward error is at the rounding floor),
  // relative to the size of the terms of each number; an updated dictionary only decides what
  // is clear beyond kTieWindow, anything nearer is decided on a dictionary fresh from the data.
  const double tau = detail::tie_level(m + 1, 0.0);
  double b_l1 = 0;
  for (int r = 0; r < m; ++r) b_l1 += std::abs(b(r));
  // The system s - D v = b + (perturbation): A x = P0 with A = [-D | I], P0 = [b | I]; the
  // column of a variable in A by its label.
  Mat A(m, d + m), P0 = Mat::Zero(m, w);
  A.leftCols(d) = -D;
  A.rightCols(m).setIdentity();
  P0.col(0) = b;
  P0.rightCols(m).setIdentity();
  std::vector<int> col_of(static_cast<size_t>(n), -1);
  for (int c = 0; c < d; ++c) col_of[size_t(var_label[c])] = c;
  for (int r = 0; r < m; ++r) col_of[size_t(row_label[r])] = d + r;
  Mat AB(m, m), AN(m, d);
  // the dictionary of basis s.bl from the data: x_B = A_B^-1 P0 - A_B^-1 A_N x_N
  auto refactor = [&](State& s) {
    for (int r = 0; r < m; ++r) AB.col(r) = A.col(col_of[size_t(s.bl[r])]);
    for (int c = 0; c < d; ++c) AN.col(c) = A.col(col_of[size_t(s.nl[c])]);
    const Eigen::PartialPivLU<Mat> lu(AB);
    const Mat Rm = lu.solve(P0), Tm = -lu.solve(AN);
    if (!Rm.allFinite() || !Tm.allFinite()) return false;
    s.T.resize(size_t(m) * d);
    s.R.resize(size_t(m) * w);
    for (int r = 0; r < m; ++r) {
      for (int c = 0; c < d; ++c) s.T[size_t(r) * d + c] = Tm(r, c);
      for (int k = 0; k < w; ++k) s.R[size_t(r) * w + k] = Rm(r, k);
    }
    return true;
  };
  // pivot in place: nonbasic c enters, basic r0 leaves
  auto pivot = [&](State& s, int r0, int c) {
    const double p = s.T[size_t(r0) * d + c];
    double* tp = &s.T[size_t(r0) * d];
    double* rp = &s.R[size_t(r0) * w];
    for (int cc = 0; cc < d; ++cc) tp[cc] = cc == c ? 1.0 / p : -tp[cc] / p;
    for (int k = 0; k < w; ++k) rp[k] = -rp[k] / p;
    for (int r = 0; r < m; ++r) {
      if (r == r0) continue;
      double* tr = &s.T[size_t(r) * d];
      const double f = tr[c];
      if (f == 0) continue;
      double* rr = &s.R[size_t(r) * w];
      for (int cc = 0; cc < d; ++cc) tr[cc] = cc == c ? f * tp[cc] : tr[cc] + f * tp[cc];
      for (int k = 0; k < w; ++k) rr[k] += f * rp[k];
    }
    std::swap(s.bl[size_t(r0)], s.nl[size_t(c)]);
  };
  // The basic values of a dictionary: positive, or zero (a degenerate vertex: the label is
  // added to `lab`, and the row must be lexicographically positive). A value that is small
  // against the largest (<= kGrayHi of it) is judged against the componentwise forward error
  // bound of a fresh solve, |dx_r| <= gamma sum_j |A_B^-1|_rj (|A_B| |x_B| + |b|)_j
  // [Higham 2002, Thm. 7.4] (A_B^-1 is the perturbation block of R): zero within 10 bounds,
  // positive beyond 1e4 bounds, too close to call between. A fixed fraction of the largest value
  // was not scale-aware: an 18 x 18 game with payoffs up to 1000 has a vertex with a genuine
  // basic value 8e-8 times the largest (fresh and pivoted dictionaries agree to 1e-15).
  enum { kDecided, kNeedsFresh, kCannotDecide };
  const double gamma = 4.0 * (m + 1) * std::numeric_limits<double>::epsilon();
  // Scales of the current dictionary s, computed when first needed (-1: not yet): pmax[r] =
  // max_j |A_B^-1(r, j)| (the row's perturbation part), and on a fresh dictionary u = |A_B|
  // |x_B| + |b| and terms[r] = sum_j |A_B^-1|_rj u_j, the forward-error scale of beta_r.
  std::vector<double> u(m), pmax(m), terms(m);
  bool u_ready = false;
  State s;
  auto reset_scales = [&] {
    std::fill(pmax.begin(), pmax.end(), -1.0);
    std::fill(terms.begin(), terms.end(), -1.0);
    u_ready = false;
  };
  auto row_pmax = [&](int r) {
    if (pmax[size_t(r)] < 0) {
      double x = 0;
      for (int k = 1; k < w; ++k) x = std::max(x, std::abs(s.R[size_t(r) * w + k]));
      pmax[size_t(r)] = x;
    }
    return pmax[size_t(r)];
  };
  auto ensure_u = [&] {
    if (u_ready) return;
    for (int j = 0; j < m; ++j) {
      double sum = std::abs(b(j));
      for (int k = 0; k < m; ++k)
        sum += std::abs(A(j, col_of[size_t(s.bl[k])])) * std::abs(s.R[size_t(k) * w]);
      u[size_t(j)] = sum;
    }
    u_ready = true;
  };
  auto row_terms = [&](int r) {
    if (terms[size_t(r)] < 0) {
      ensure_u();
      double x = 0;
      for (int j = 0; j < m; ++j) x += std::abs(s.R[size_t(r) * w + 1 + j]) * u[size_t(j)];
      terms[size_t(r)] = x;
    }
    return terms[size_t(r)];
  };
  auto classify = [&](bool is_fresh, IndexSet& labels) {
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
  };
  // Lexicographic order of rows r and t for the entering column (pivot entries -a_r, -a_t > 0):
  // -1 when r's row / a_r comes first, 1 when t's does, 0 when they are equal at the rounding
  // level in every column (not for independent rows: the path gives up), 2 when the updated
  // dictionary is too close to call (it is then recomputed from the data).
  auto lex_order = [&](int r, double ar, int t, double at, bool is_fresh) {
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
  };
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
      int best = -1;
      for (bool again = true; again;) {  // twice at most: a near tie is decided on fresh data
        again = false;
        double tmax = 0;
        for (int r = 0; r < m; ++r) tmax = std::max(tmax, std::abs(s.T[size_t(r) * d + c]));
        best = -1;
        for (int r = 0; r < m; ++r) {
          const double a = s.T[size_t(r) * d + c];
          if (!(a < -kTie * tmax)) {
            if (a < -kZero * tmax) return Structured::kUndecided;  // pivot too small to call
            continue;
          }
          if (best < 0) {
            best = r;
            continue;
          }
          const int order = lex_order(r, -a, best, -s.T[size_t(best) * d + c], fresh);
          if (order == 2) {
            if (!refactor(s)) return Structured::kUndecided;
            fresh = again = true;
            reset_scales();
            break;
          }
          if (order == 0) return Structured::kUndecided;  // not for independent perturbations
          if (order < 0) best = r;
        }
      }
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

}  // namespace

bool SolutionSet::contains(const Vec& z, double ctol) const {
  const Eigen::Index n = q.size();
  if (z.size() != n || !z.allFinite()) return false;
  // The acceptance test's own units (residuals.hpp): a point finalize() accepts at tolerance
  // ctol is judged here by the same numbers, whatever the problem's units.
  Vec w;
  const UnitFreePoint u = unit_free_point(LcpProblem(M, q), z, w);
  if (!u.finite) return false;
  for (Eigen::Index i = 0; i < n; ++i)
    if (u.to_lower[i] < -ctol || u.w[i] < -ctol) return false;
  const double zn = n ? z.cwiseAbs().maxCoeff() : 0.0;
  for (const ExtremeSolution& e : solutions)
    if (n == 0 || (e.z - z).cwiseAbs().maxCoeff() <=
                      ctol * std::max(zn, e.z.cwiseAbs().maxCoeff()))
      return true;
  // Row i "free in z" must have w_i ~ 0, otherwise z_i ~ 0: the complementarity pattern of a
  // listed basis or piece, met within ctol in the test's units.
  auto fits = [&](auto z_free) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (z_free(i) ? !(std::abs(u.w[i]) <= ctol) : !(std::abs(u.z[i]) <= ctol)) return false;
    return true;
  };
  for (const ExtremeSolution& e : solutions)
    if (static_cast<Eigen::Index>(e.basis.size()) == n &&
        fits([&](Eigen::Index i) { return e.basis[static_cast<size_t>(i)] >= 0; }))
      return true;
  for (const SolutionPiece& p : pieces) {
    std::vector<char> in(static_cast<size_t>(n), 0);
    for (int i : p.support) in[static_cast<size_t>(i)] = 1;
    if (fits([&](Eigen::Index i) { return in[static_cast<size_t>(i)] != 0; })) return true;
  }
  return false;
}

namespace {

/// Power-of-two scale 2^e with x / 2^e in [0.5, 1) (e = 0 for x = 0).
int scale_exponent(double x) {
  if (!(x > 0)) return 0;
  int e = 0;
  std::frexp(x, &e);
  return e;
}

/// Powers of two that put the data in one unit per row, per column and for q: M~_ij =
/// M_ij 2^-(r_i + c_j) (every row, then every column, of largest entry in [0.5, 1)), q~_i =
/// q_i 2^-(r_i + e) (largest in [0.5, 1)). LCP(M~, q~) has the solutions z~_j = z_j 2^(c_j - e),
/// w~_i = w_i 2^-(r_i + e): the same problem with each z_j and each w_i in its own unit.
struct Equilibration {
  std::vector<int> r, c;
  int e = 0;
  bool exact = true;  // false: an entry would lose bits (subnormal); the data are used as given
};

Equilibration equilibrate(const Mat& M, const Vec& q, Mat& Mn, Vec& qn) {
  const Eigen::Index n = q.size();
  Equilibration s;
  s.r.assign(size_t(n), 0);
  s.c.assign(size_t(n), 0);
  Mn = M;
  qn = q;
  auto scale = [&](double& x, int e) {
    const double y = std::ldexp(x, -e);
    s.exact = s.exact && std::ldexp(y, e) == x;
    x = y;
  };
  for (Eigen::Index i = 0; i < n; ++i) {
    s.r[size_t(i)] = scale_exponent(Mn.row(i).cwiseAbs().maxCoeff());
    for (Eigen::Index j = 0; j < n; ++j) scale(Mn(i, j), s.r[size_t(i)]);
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    s.c[size_t(j)] = scale_exponent(Mn.col(j).cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < n; ++i) scale(Mn(i, j), s.c[size_t(j)]);
  }
  // q_i 2^-(r_i + e) in one step (q_i 2^-r_i alone may overflow): e from the exponents
  bool any = false;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (q(i) == 0) continue;
    const int x = scale_exponent(std::abs(q(i))) - s.r[size_t(i)];
    s.e = any ? std::max(s.e, x) : x;
    any = true;
  }
  for (Eigen::Index i = 0; i < n; ++i) scale(qn(i), s.r[size_t(i)] + s.e);
  if (!s.exact) {
    Mn = M;
    qn = q;
    std::fill(s.r.begin(), s.r.end(), 0);
    std::fill(s.c.begin(), s.c.end(), 0);
    s.e = 0;
  }
  return s;
}

/// The final check of every listed solution against the original data (M, q), with the
/// unit-free componentwise test: z finite and >= 0, w = M z + q finite; with
/// W_i = |q_i| + sum_j |M_ij z_j|, every listed w_i = 0 has |w_i| <= 1e4 tol W_i and every
/// other w_i > 0 agrees with the data to 1e4 tol W_i, and z_i w_i = 0 as listed. Solutions
/// that fail (values double cannot represent, e.g. z = 1e320 after scaling back) are removed.
/// Returns the number removed.
int recheck(SolutionSet& out) {
  const Mat& M = out.M;
  const Vec& q = out.q;
  const int n = static_cast<int>(q.size());
  const double band = kGray * out.tol;
  std::vector<int> new_index(out.solutions.size(), -1);
  std::vector<ExtremeSolution> kept;
  for (size_t p = 0; p < out.solutions.size(); ++p) {
    const ExtremeSolution& e = out.solutions[p];
    bool ok = e.z.allFinite() && e.w.allFinite() && (n == 0 || e.z.minCoeff() >= 0);
    for (int i = 0; i < n && ok; ++i) {
      double v = q(i), sc = std::abs(q(i));
      for (int j = 0; j < n; ++j) {
        v += M(i, j) * e.z(j);
        sc += std::abs(M(i, j) * e.z(j));
      }
      ok = finite(v) && finite(sc) && (e.z(i) == 0 || e.w(i) == 0);
      if (!ok) break;
      ok = e.w(i) == 0 ? std::abs(v) <= band * sc
                       : e.w(i) > 0 && std::abs(v - e.w(i)) <= band * sc;
    }
    if (!ok) continue;
    new_index[p] = static_cast<int>(kept.size());
    kept.push_back(e);
  }
  const int removed = static_cast<int>(out.solutions.size() - kept.size());
  if (removed == 0) return 0;
  out.solutions = std::move(kept);
  for (SolutionPiece& pc : out.pieces) {
    std::vector<int> v;
    for (int k : pc.vertices)
      if (new_index[k] >= 0) v.push_back(new_index[k]);
    pc.vertices = std::move(v);
  }
  return removed;
}

}  // namespace

SolutionSet enumerate_all(const LcpProblem& problem, const EnumerationOptions& options) {
  throw_if_invalid(problem.validate(), "enumerate_all");
  throw_if_invalid(options.validate(), "enumerate_all");
  const Eigen::Index n = problem.size();
  Stopwatch clock;
  Deadline deadline(options.time_limit_s);
  SolutionSet out;
  out.M = problem.dense_M();
  out.q = problem.q;
  out.tol = options.tol;
  if (n == 0) {
    out.complete = true;
    out.solutions.push_back({Vec(), Vec(), {}});
    out.seconds = clock.seconds();
    return out;
  }
  // Every decision is made on the equilibrated data (equilibrate(): each row w_i, each z_j and
  // q in a unit of their own, by powers of two): the same problem in other units (q -> a q,
  // (M, q) -> b (M, q), any row or column scaling) then takes the same decisions, bit for bit
  // when the factors are powers of two. With only one scale for M and one for q, a problem
  // whose rows were in units 1e-10..1e10 of each other (a bimatrix game, each w_i in its own
  // unit) lost solutions in the search and said complete (issue 24, item 7 class). The results
  // are scaled back exactly unless they overflow or underflow, which the final check catches.
  SolutionSet work;
  work.tol = options.tol;
  const Equilibration eq = equilibrate(out.M, out.q, work.M, work.q);
  const bool exact = eq.exact;
  switch (n) {
    case 1: run_small<1>(work); break;
    case 2: run_small<2>(work); break;
    case 3: run_small<3>(work); break;
    case 4: run_small<4>(work); break;
    default: {
      if (options.use_structure && try_bipartite(options, work, deadline) != Structured::kUndecided)
        break;
      if (n > options.max_size) {  // beyond the general engine's supports: say so, not throw
        work.complete = false;
        work.message = "n = " + std::to_string(n) + " exceeds the general engine's limit " +
                       std::to_string(options.max_size) +
                       " (max_size, the CLI's --max-size, at most " +
                       std::to_string(kMaxEnumerationSize) +
                       "); only bimatrix games (block-bipartite LCPs) are enumerated beyond it";
        break;
      }
      Engine engine(options, work, deadline, exact);
      engine.run();
    }
  }
  out.solutions = std::move(work.solutions);
  out.pieces = std::move(work.pieces);
  out.complete = work.complete;
  out.infinite = work.infinite;
  out.ambiguous = work.ambiguous;
  out.unrepresentable = work.unrepresentable;
  out.nodes = work.nodes;
  // a candidate whose sign test was too close to call was left out: the list may lack it
  // (issue 24: the DART 12-D LCP printed ambiguous: 1 with complete: true)
  if (work.ambiguous > 0) {
    out.complete = false;
    const std::string msg = std::to_string(work.ambiguous) +
                            " candidate(s) with a sign test too close to call: not listed";
    work.message = work.message.empty() ? msg : work.message + "; " + msg;
  }
  out.leaves = work.leaves;
  out.structured = work.structured;
  out.message = work.message;
  for (ExtremeSolution& e : out.solutions) {
    for (Eigen::Index j = 0; j < n; ++j) {
      e.z(j) = std::ldexp(e.z(j), eq.e - eq.c[size_t(j)]);
      e.w(j) = std::ldexp(e.w(j), eq.e + eq.r[size_t(j)]);
    }
  }
  for (SolutionPiece& pc : out.pieces)
    for (Vec& d : pc.rays) {  // directions of z: per column, then ||d||_inf = 1 again
      for (Eigen::Index j = 0; j < n; ++j) d(j) = std::ldexp(d(j), -eq.c[size_t(j)]);
      const double big = d.cwiseAbs().maxCoeff();
      if (big > 0 && std::isfinite(big)) d /= big;
    }
  out.unrepresentable += recheck(out);
  if (out.unrepresentable > 0) {
    out.complete = false;
    const std::string msg = std::to_string(out.unrepresentable) +
                            " candidate(s) not representable in double precision (a value of z or "
                            "w = M z + q overflows or underflows, e.g. z = 1e320): not listed";
    out.message = out.message.empty() ? msg : out.message + "; " + msg;
  }
  if (!fill_directions(out, deadline)) out.complete = false;
  if (deadline.hit()) {
    out.complete = false;
    if (out.message.find("time limit") == std::string::npos) {
      const std::string msg = "time limit of " + std::to_string(options.time_limit_s) +
                              " s reached (the lists may be partial)";
      out.message = out.message.empty() ? msg : out.message + "; " + msg;
    }
  }
  out.seconds = clock.seconds();
  return out;
}

}  // namespace cpkit::lcp
