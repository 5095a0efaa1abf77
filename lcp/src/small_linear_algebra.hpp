#pragma once
/// \file small_linear_algebra.hpp
/// Internal (lcp/src) kernels of enumerate_small and its prepared variant SmallPreparedLcp
/// (enumerate_small.cpp): sign tests with the gray band, determinants and their "permanents",
/// complete-pivoting elimination with a replayable record (detail::SmallElimRecord, declared
/// with the prepared data in cpkit/lcp/enumerate_small_prepared.hpp), null vectors, square
/// solves and Cramer's rule for blocks of at most 4 x 4. Tolerances as documented in
/// cpkit/lcp/enumerate_small.hpp ("Tolerance").
#include <cmath>
#include <utility>

#include "cpkit/lcp/enumerate_small_prepared.hpp"

namespace cpkit::lcp::detail {

inline constexpr double kSmallGray = 1e4;  ///< gray band factor of the sign tests

// Rare paths (degenerate or extreme candidates) are kept out of line so that the hot
// add_point stays small enough to be inlined (bench/bench_enumerate.cpp, section 1).
#if defined(__GNUC__) || defined(__clang__)
#define CPKIT_SMALL_COLD __attribute__((noinline, cold))
#define CPKIT_SMALL_HOT __attribute__((always_inline))
#define CPKIT_SMALL_NOINLINE __attribute__((noinline))
#else
#define CPKIT_SMALL_COLD
#define CPKIT_SMALL_HOT
#define CPKIT_SMALL_NOINLINE
#endif

constexpr int small_popcount(unsigned x) noexcept {
  int c = 0;
  for (; x; x &= x - 1) ++c;
  return c;
}
inline double small_abs(double x) noexcept { return std::fabs(x); }
inline double small_max(double a, double b) noexcept { return a < b ? b : a; }

/// Outcome of a sign test v >= 0 at scale s: 0 pass, 1 ambiguous, 2 fail.
inline int small_sign(double v, double s, double tol) noexcept {
  if (v >= -tol * s) return 0;
  if (v >= -kSmallGray * tol * s) return 1;
  return 2;
}

/// True when x is finite (not inf, not NaN).
inline bool small_finite(double x) noexcept { return small_abs(x) <= 1.7976931348623157e308; }

/// The Cramer path may be used for a principal block with determinant det and "permanent" perm
/// (small_det): the block is clearly nonsingular (|det| > 1e4 tol perm, a test invariant under
/// any scaling of M) and perm is a normal finite number (no overflow or underflow in the products
/// of the determinant). Otherwise the block goes to the elimination path (singular_piece).
inline bool small_det_ok(double det, double perm, double tol) noexcept {
  return small_abs(det) > kSmallGray * tol * perm && perm >= 2.2250738585072014e-308 &&
         perm <= 1.7976931348623157e308;
}

/// det and "permanent" (sum of the absolute values of the determinant's terms) of a k x k
/// block, k <= 3, taken from rows r[] and columns c[] of M.
template <typename Mat>
inline void small_det(const Mat& M, const int* r, const int* c, int k, double& det,
                      double& perm) noexcept {
  if (k == 1) {
    det = M(r[0], c[0]);
    perm = small_abs(det);
  } else if (k == 2) {
    const double t1 = M(r[0], c[0]) * M(r[1], c[1]), t2 = M(r[0], c[1]) * M(r[1], c[0]);
    det = t1 - t2;
    perm = small_abs(t1) + small_abs(t2);
  } else {
    det = 0;
    perm = 0;
    constexpr int p[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
    for (int t = 0; t < 6; ++t) {
      const double v = M(r[0], c[p[t][0]]) * M(r[1], c[p[t][1]]) * M(r[2], c[p[t][2]]);
      det += t < 3 ? v : -v;
      perm += small_abs(v);
    }
  }
}

/// Complete-pivoting elimination of the k x c block a (c <= k + 1 columns, column 4 is a
/// right-hand side) in place. Returns the rank found (pivots > piv_tol); perm receives the
/// column order; `gray` is set when an accepted pivot lies within kSmallGray of the threshold.
/// With `rec`, the matrix part only is eliminated (column 4 is left alone) and the row
/// operations are recorded in *rec (then perm must be rec->perm).
inline int small_eliminate(double (&a)[4][5], int k, int c, int (&perm)[5], double piv_tol,
                           bool& gray, SmallElimRecord* rec = nullptr) noexcept {
  for (int j = 0; j < c; ++j) perm[j] = j;
  int rank = 0;
  for (int p = 0; p < k && p < c; ++p) {
    int br = p, bc = p;
    double best = -1;
    for (int r = p; r < k; ++r)
      for (int cc = p; cc < c; ++cc) {
        const double v = small_abs(a[r][perm[cc]]);
        if (v > best) { best = v; br = r; bc = cc; }
      }
    if (!(best > piv_tol)) break;
    if (best <= kSmallGray * piv_tol) gray = true;
    if (rec) rec->swap[p] = br;
    if (br != p)
      for (int cc = 0; cc < 5; ++cc) std::swap(a[p][cc], a[br][cc]);
    std::swap(perm[p], perm[bc]);
    const double piv = a[p][perm[p]];
    for (int r = p + 1; r < k; ++r) {
      const double f = a[r][perm[p]] / piv;
      if (rec) rec->f[p][r] = f;
      if (f == 0) continue;
      for (int cc = p; cc < c; ++cc) a[r][perm[cc]] -= f * a[p][perm[cc]];
      if (!rec) a[r][4] -= f * a[p][4];
    }
    ++rank;
  }
  if (rec) {
    rec->rank = rank;
    for (int r = 0; r < 4; ++r)
      for (int cc = 0; cc < 5; ++cc) rec->a[r][cc] = a[r][cc];
  }
  return rank;
}

/// Back substitution on the first r rows of a block eliminated by small_eliminate with column
/// order perm: x[perm[p]] for p < r from the eliminated right-hand side rhs(p) (a column of
/// the block itself or a separate vector). The entries x[perm[c]], c >= r, are left as they
/// are: zero for a basic solution, the free value for a null vector.
template <typename Rhs>
inline void small_back_substitute(const double (&u)[4][5], int r, const int (&perm)[5],
                                  const Rhs& rhs, double* x) noexcept {
  for (int p = r - 1; p >= 0; --p) {
    double s = rhs(p);
    for (int c = p + 1; c < r; ++c) s -= u[p][perm[c]] * x[perm[c]];
    x[perm[p]] = s / u[p][perm[p]];
  }
}

/// Null vector y of a block of rank r eliminated by small_eliminate (column order perm): the
/// free column perm[free] (free >= r) set to 1, the other free columns 0. y must be zeroed.
inline void small_null_column(const double (&u)[4][5], int r, const int (&perm)[5], int free,
                              double* y) noexcept {
  const int col = perm[free];
  y[col] = 1;
  small_back_substitute(u, r, perm, [&](int p) { return -u[p][col]; }, y);
}

/// Null vector x (m entries, x[pm[m-1]] = 1) of an m x m block whose first m - 1 rows were
/// eliminated by small_eliminate with column order pm (rank m - 1).
inline void small_null_vector(const double (&e)[4][5], int m, const int (&pm)[5],
                              double* x) noexcept {
  small_null_column(e, m - 1, pm, m - 1, x);
}

/// Replays the row operations recorded by small_eliminate on the right-hand side b (k rows).
inline void small_replay_rhs(const SmallElimRecord& rec, int k, double (&b)[4]) noexcept {
  for (int p = 0; p < rec.rank; ++p) {
    if (rec.swap[p] != p) std::swap(b[p], b[rec.swap[p]]);
    for (int r = p + 1; r < k; ++r) {
      const double f = rec.f[p][r];
      if (f == 0) continue;
      b[r] -= f * b[p];
    }
  }
}

/// Cramer's rule for M[R,C] x = -q[R] (k = |R| = |C| <= 3) given inv = 1 / det M[R,C]; writes
/// x[out[c]] for the c-th column. Always inlined: the per-call path of every nonsingular support.
template <typename Mat, typename Vq>
CPKIT_SMALL_HOT inline void small_cramer_inv(const Mat& M, const Vq& q, const int* rows,
                                             const int* cols, int k, double inv, const int* out,
                                             double* x) noexcept {
  if (k == 1) {
    x[out[0]] = -q(rows[0]) * inv;
  } else if (k == 2) {
    const double b0 = -q(rows[0]), b1 = -q(rows[1]);
    x[out[0]] = (b0 * M(rows[1], cols[1]) - M(rows[0], cols[1]) * b1) * inv;
    x[out[1]] = (M(rows[0], cols[0]) * b1 - b0 * M(rows[1], cols[0])) * inv;
  } else {
    // cofactors of the 3x3 block
    const double a00 = M(rows[0], cols[0]), a01 = M(rows[0], cols[1]), a02 = M(rows[0], cols[2]);
    const double a10 = M(rows[1], cols[0]), a11 = M(rows[1], cols[1]), a12 = M(rows[1], cols[2]);
    const double a20 = M(rows[2], cols[0]), a21 = M(rows[2], cols[1]), a22 = M(rows[2], cols[2]);
    const double b0 = -q(rows[0]), b1 = -q(rows[1]), b2 = -q(rows[2]);
    x[out[0]] = (b0 * (a11 * a22 - a12 * a21) - a01 * (b1 * a22 - a12 * b2) +
                 a02 * (b1 * a21 - a11 * b2)) * inv;
    x[out[1]] = (a00 * (b1 * a22 - a12 * b2) - b0 * (a10 * a22 - a12 * a20) +
                 a02 * (a10 * b2 - b1 * a20)) * inv;
    x[out[2]] = (a00 * (a11 * b2 - b1 * a21) - a01 * (a10 * b2 - b1 * a20) +
                 b0 * (a10 * a21 - a11 * a20)) * inv;
  }
}

/// Cramer's rule for the principal block M[S,S] z_S = -q_S (k = |S| <= 3) whose determinant
/// det (nonzero, from small_det) is already known; writes z[idx[c]].
template <typename Mat, typename Vq>
inline void small_cramer(const Mat& M, const Vq& q, const int* idx, int k, double det,
                         double* z) noexcept {
  small_cramer_inv(M, q, idx, idx, k, 1.0 / det, idx, z);
}

}  // namespace cpkit::lcp::detail
