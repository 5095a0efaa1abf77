// The general engine of enumerate_all (enumerate.hpp): depth-first search over complementary
// bases with principal pivot updates.
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
  /// (small_enumerator.hpp): relative to ||z||_inf and W_i = |q_i| + sum_j |M_ij z_j|.
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
  /// The same rule as SmallEnumerator::settle_tiny (small_enumerator.hpp).
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

}  // namespace

void run_engine(const EnumerationOptions& opt, SolutionSet& work, Deadline& deadline, bool exact) {
  Engine engine(opt, work, deadline, exact);
  engine.run();
}

}  // namespace cpkit::lcp::detail
