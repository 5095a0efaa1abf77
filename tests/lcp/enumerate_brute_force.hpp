#pragma once
// Test helper (not a test): an exact brute-force enumeration of the solution set of a small
// integer LCP, written independently of cpkit's enumerators. Rational arithmetic; vertices are
// the complementary basic feasible solutions of [-M | I] over all C(2n, n) column bases; the
// extreme rays of each piece's recession cone are its nonnegative minimal-support (circuit) null
// vectors [Rockafellar 1970, Sec. 19]. Also: the comparison of a found set against it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <set>
#include <vector>

namespace brute {

// ---------- exact rationals ----------
struct Q {
  std::int64_t n = 0, d = 1;
  Q() = default;
  Q(std::int64_t a, std::int64_t b = 1) : n(a), d(b) { norm(); }
  void norm() {
    if (d < 0) { n = -n; d = -d; }
    const std::int64_t g = std::gcd(n < 0 ? -n : n, d);
    if (g > 1) { n /= g; d /= g; }
  }
  double val() const { return double(n) / double(d); }
};
inline Q operator+(Q a, Q b) { return Q(a.n * b.d + b.n * a.d, a.d * b.d); }
inline Q operator-(Q a, Q b) { return Q(a.n * b.d - b.n * a.d, a.d * b.d); }
inline Q operator*(Q a, Q b) { return Q(a.n * b.n, a.d * b.d); }
inline Q operator/(Q a, Q b) { return Q(a.n * b.d, a.d * b.n); }
inline bool operator==(Q a, Q b) { return a.n == b.n && a.d == b.d; }
inline bool operator<(Q a, Q b) { return a.n * b.d < b.n * a.d; }

using QVec = std::vector<Q>;
using QMat = std::vector<QVec>;

/// Gauss-Jordan over Q: rank and reduced row echelon form (in place), pivot columns.
/// Pivots are searched only in the first `pivot_cols` columns (the rest is a right-hand side).
inline int rref(QMat& a, std::vector<int>& pivots, int pivot_cols) {
  const int rows = int(a.size()), cols = rows ? int(a[0].size()) : 0;
  int r = 0;
  pivots.clear();
  for (int c = 0; c < pivot_cols && r < rows; ++c) {
    int p = -1;
    for (int i = r; i < rows; ++i)
      if (a[i][c].n != 0) { p = i; break; }
    if (p < 0) continue;
    std::swap(a[p], a[r]);
    const Q inv = Q(1) / a[r][c];
    for (auto& x : a[r]) x = x * inv;
    for (int i = 0; i < rows; ++i)
      if (i != r && a[i][c].n != 0) {
        const Q f = a[i][c];
        for (int j = 0; j < cols; ++j) a[i][j] = a[i][j] - f * a[r][j];
      }
    pivots.push_back(c);
    ++r;
  }
  return r;
}

struct Exact {
  int n;
  std::vector<QVec> vertices;  // z of every complementary vertex
  std::vector<QVec> vertex_w;
  // per support S: the extreme rays of its recession cone (normalised to max entry 1)
  std::vector<std::vector<QVec>> rays;
};

inline Exact brute_force(const std::vector<std::vector<int>>& M, const std::vector<int>& q) {
  const int n = int(q.size());
  Exact ex;
  ex.n = n;
  std::set<std::vector<std::pair<std::int64_t, std::int64_t>>> seen;
  // columns 0..n-1: z (coefficient -M), n..2n-1: w (identity); A x = q.
  for (unsigned B = 0; B < (1u << (2 * n)); ++B) {
    if (__builtin_popcount(B) != n) continue;
    std::vector<int> cols;
    for (int j = 0; j < 2 * n; ++j)
      if (B & (1u << j)) cols.push_back(j);
    QMat a(n, QVec(n + 1));
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < n; ++c) {
        const int j = cols[c];
        a[i][c] = j < n ? Q(-M[i][j]) : Q(j - n == i ? 1 : 0);
      }
      a[i][n] = Q(q[i]);
    }
    std::vector<int> piv;
    if (rref(a, piv, n) < n) continue;
    QVec x(2 * n, Q(0));
    for (int c = 0; c < n; ++c) x[cols[c]] = a[c][n];
    bool ok = true;
    for (int j = 0; j < 2 * n; ++j) ok = ok && !(x[j] < Q(0));
    for (int i = 0; i < n; ++i) ok = ok && (x[i].n == 0 || x[n + i].n == 0);
    if (!ok) continue;
    std::vector<std::pair<std::int64_t, std::int64_t>> key;
    for (int j = 0; j < n; ++j) key.emplace_back(x[j].n, x[j].d);
    if (!seen.insert(key).second) continue;
    ex.vertices.emplace_back(x.begin(), x.begin() + n);
    ex.vertex_w.emplace_back(x.begin() + n, x.end());
  }
  // rays of piece S: cone {(d, e) >= 0 : e - M d = 0, d_i = 0 (i not in S), e_i = 0 (i in S)};
  // the allowed variables are d_i (i in S) and e_i (i not in S). Extreme rays are the
  // nonnegative null vectors whose support J is minimal: null space of the J columns is
  // one-dimensional and the null vector has no zero entry.
  ex.rays.resize(1u << n);
  for (unsigned S = 0; S < (1u << n); ++S) {
    std::set<std::vector<std::pair<std::int64_t, std::int64_t>>> rs;
    for (unsigned J = 1; J < (1u << n); ++J) {
      std::vector<int> vars;  // index i: d_i if i in S else e_i
      for (int i = 0; i < n; ++i)
        if (J & (1u << i)) vars.push_back(i);
      const int k = int(vars.size());
      QMat a(n, QVec(k));
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < k; ++c) {
          const int i = vars[c];
          a[r][c] = (S & (1u << i)) ? Q(-M[r][i]) : Q(r == i ? 1 : 0);
        }
      std::vector<int> piv;
      if (rref(a, piv, k) != k - 1) continue;
      int free_c = -1;
      for (int c = 0; c < k; ++c)
        if (std::find(piv.begin(), piv.end(), c) == piv.end()) free_c = c;
      QVec x(k, Q(0));
      x[free_c] = Q(1);
      for (int p = 0; p < int(piv.size()); ++p) x[piv[p]] = Q(0) - a[p][free_c];
      bool all_pos = true, all_neg = true;
      for (const Q& v : x) { all_pos = all_pos && Q(0) < v; all_neg = all_neg && v < Q(0); }
      if (!all_pos && !all_neg) continue;
      // d in z-space
      QVec d(n, Q(0));
      for (int c = 0; c < k; ++c)
        if (S & (1u << vars[c])) d[vars[c]] = all_neg ? Q(0) - x[c] : x[c];
      Q big(0);
      for (const Q& v : d) big = big < v ? v : big;
      if (big.n == 0) continue;  // pure e-direction: impossible (e = M d = 0)
      std::vector<std::pair<std::int64_t, std::int64_t>> key;
      for (Q& v : d) { v = v / big; key.emplace_back(v.n, v.d); }
      rs.insert(key);
    }
    for (const auto& key : rs) {
      QVec d;
      for (auto [a, b] : key) d.emplace_back(a, b);
      ex.rays[S].push_back(d);
    }
  }
  return ex;
}

inline bool in_piece(const Exact& ex, int v, unsigned S) {
  for (int i = 0; i < ex.n; ++i) {
    if ((S & (1u << i)) && ex.vertex_w[v][i].n != 0) return false;
    if (!(S & (1u << i)) && ex.vertices[v][i].n != 0) return false;
  }
  return true;
}


/// A solution set in neutral form (filled from SmallSolutionSet or SolutionSet).
struct Found {
  std::vector<std::vector<double>> z, w;
  struct Piece {
    unsigned support = 0;
    std::vector<int> vertices;
    std::vector<std::vector<double>> rays;
  };
  std::vector<Piece> pieces;
  bool infinite = false;
};

/// REQUIREs that `f` is exactly the solution set of the exact brute force.
inline void check(const std::vector<std::vector<int>>& Mi, const std::vector<int>& qi, const Found& f) {
  const int N = int(qi.size());
  const Exact ex = brute_force(Mi, qi);
  REQUIRE(f.z.size() == ex.vertices.size());
  std::vector<int> to_exact(f.z.size(), -1);
  for (size_t p = 0; p < f.z.size(); ++p) {
    for (int v = 0; v < int(ex.vertices.size()); ++v) {
      double d = 0;
      for (int j = 0; j < N; ++j) d = std::max(d, std::abs(f.z[p][j] - ex.vertices[v][j].val()));
      if (d < 1e-9) to_exact[p] = v;
    }
    REQUIRE(to_exact[p] >= 0);
    for (int i = 0; i < N; ++i) {
      double w = qi[i];
      for (int j = 0; j < N; ++j) w += Mi[i][j] * f.z[p][j];
      REQUIRE(std::abs(f.w[p][i] - w) < 1e-9);
    }
  }
  bool infinite = false;
  for (unsigned S = 0; S < (1u << N); ++S) {
    std::vector<int> members;
    for (int v = 0; v < int(ex.vertices.size()); ++v)
      if (in_piece(ex, v, S)) members.push_back(v);
    if (members.empty()) continue;
    if (members.size() < 2 && ex.rays[S].empty()) continue;
    infinite = true;
    // some listed piece P_T contains P_S: every vertex and ray of P_S satisfies T's equations
    bool covered = false;
    for (size_t k = 0; k < f.pieces.size() && !covered; ++k) {
      const unsigned T = f.pieces[k].support;
      bool ok = true;
      for (int v : members) ok = ok && in_piece(ex, v, T);
      for (const QVec& d : ex.rays[S])
        for (int i = 0; i < N; ++i) {
          Q md(0);
          for (int j = 0; j < N; ++j) md = md + Q(Mi[i][j]) * d[j];
          if ((T & (1u << i)) && md.n != 0) ok = false;
          if (!(T & (1u << i)) && d[i].n != 0) ok = false;
        }
      covered = ok;
    }
    CAPTURE(S);
    REQUIRE(covered);
  }
  REQUIRE(f.infinite == infinite);
  for (size_t k = 0; k < f.pieces.size(); ++k) {
    const auto& pc = f.pieces[k];
    CAPTURE(k, pc.support);
    std::vector<char> listed(f.z.size(), 0);
    for (int v : pc.vertices) listed[v] = 1;
    for (size_t p = 0; p < f.z.size(); ++p)
      REQUIRE(bool(listed[p]) == in_piece(ex, to_exact[p], pc.support));
    REQUIRE(pc.rays.size() == ex.rays[pc.support].size());
    for (const auto& r : pc.rays) {
      bool found = false;
      for (const QVec& e : ex.rays[pc.support]) {
        double d = 0;
        for (int j = 0; j < N; ++j) d = std::max(d, std::abs(r[j] - e[j].val()));
        found = found || d < 1e-9;
      }
      REQUIRE(found);
    }
    REQUIRE(!pc.vertices.empty());
    REQUIRE((!pc.rays.empty() || pc.vertices.size() >= 2));
  }
}

}  // namespace brute
