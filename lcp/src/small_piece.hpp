#pragma once
/// \file small_piece.hpp
/// Internal (lcp/src) M-only geometry of one piece P_S of a tiny LCP, shared by enumerate_small
/// (computed per call) and SmallPreparedLcp (computed once per matrix), both in
/// enumerate_small.cpp: null basis of a singular block, the constraint directions of the piece,
/// the equilibrated systems of its vertices and rays, and the tests of a ray. Tolerances as
/// documented in cpkit/lcp/enumerate_small.hpp ("Tolerance").
#include "small_linear_algebra.hpp"

namespace cpkit::lcp::detail {

/// Null basis of the k x k block eliminated by small_eliminate (rank r, column order perm), one
/// row per free variable, scattered to the members idx[] of S. nb must be zeroed.
template <int N>
inline void small_null_basis(const double (&u)[4][5], int r, int k, const int (&perm)[5],
                             const int* idx, double (&nb)[4][N]) noexcept {
  for (int f = 0; f < k - r; ++f) {
    double y[4] = {};
    small_null_column(u, r, perm, r + f, y);
    for (int c = 0; c < k; ++c) nb[f][idx[c]] = y[c];
  }
}

/// Directions A of the constraints g_i(t) = b_i + sum_f A_if t_f >= 0 of the piece
/// {z0 + nb^T t} (z_i for i in S, w_i off S). Entries at round-off level of their own terms are
/// zero (a constraint constant on the piece must not produce a "vertex" from noise / noise).
/// False when a value overflows.
template <int N, typename Mat>
inline bool small_constraint_dirs(const Mat& M, unsigned S, const double (&nb)[4][N], int m,
                                  double tol, double (&A)[N][4]) noexcept {
  for (int i = 0; i < N; ++i) {
    for (int f = 0; f < m; ++f) {
      if (S & (1u << i)) {
        double nm = 0;
        for (int j = 0; j < N; ++j) nm = small_max(nm, small_abs(nb[f][j]));
        A[i][f] = small_abs(nb[f][i]) <= tol * nm ? 0.0 : nb[f][i];
      } else {
        double u = 0, su = 0;
        for (int j = 0; j < N; ++j) { u += M(i, j) * nb[f][j]; su += small_abs(M(i, j) * nb[f][j]); }
        if (!small_finite(su)) return false;
        A[i][f] = small_abs(u) <= tol * su ? 0.0 : u;
      }
    }
  }
  return true;
}

/// m == 1 (the piece is a line z0 + t nb_0): the scale of constraint i's slope A_i0; the
/// constraint is parallel to the line unless |A_i0| > tol * scale.
template <int N, typename Mat>
inline double small_line_scale(const Mat& M, unsigned S, int i, const double (&nb)[4][N]) noexcept {
  double sa = 0;
  if (S & (1u << i)) {
    for (int j = 0; j < N; ++j) sa = small_max(sa, small_abs(nb[0][j]));
  } else {
    for (int j = 0; j < N; ++j) sa += small_abs(M(i, j) * nb[0][j]);
  }
  return sa;
}

/// The rows i in `act` of A (m columns) divided by their largest entry into e (each row of A
/// has the units of its own z_i or w_i: the rank decision is then invariant under
/// (M, q) -> b (M, q)); rm[t] receives the scale of row t; with b, e[t][4] = -b_i / rm[t].
/// False when a row is zero (the system is singular).
template <int N>
inline bool small_equilibrated_rows(const double (&A)[N][4], const double* b, unsigned act, int m,
                                    double (&e)[4][5], double* rm) noexcept {
  int t = 0;
  for (int i = 0; i < N; ++i) {
    if (!(act & (1u << i))) continue;
    double rmax = 0;
    for (int f = 0; f < m; ++f) rmax = small_max(rmax, small_abs(A[i][f]));
    if (rmax == 0) return false;
    for (int f = 0; f < m; ++f) e[t][f] = A[i][f] / rmax;
    if (b) e[t][4] = -b[i] / rmax;
    rm[t++] = rmax;
  }
  return true;
}

/// Candidate extreme rays of a piece of dimension m >= 1 (null basis nb, constraint directions
/// A): +-nb_0 for a line, else +-(nb^T x) for x spanning the null space of each regular set of
/// m - 1 active constraints. Calls emit(d) for each (d is scratch the callee may change);
/// `gray` counts close rank decisions. Inlined: a line's two rays are on the per-call path of
/// the rate LCPs (bench/bench_enumerate.cpp, section 1).
template <int N, typename Emit>
CPKIT_SMALL_HOT inline void small_ray_candidates(const double (&A)[N][4], const double (&nb)[4][N], int m,
                                 double tol, int& gray, Emit&& emit) {
  constexpr unsigned kAll = (1u << N) - 1;
  double d[N];
  if (m == 1) {
    for (int j = 0; j < N; ++j) d[j] = nb[0][j];
    emit(d);
    for (int j = 0; j < N; ++j) d[j] = -nb[0][j];
    emit(d);
    return;
  }
  if constexpr (N > 1) {
    for (unsigned act = 0; act <= kAll; ++act) {
      if (small_popcount(act) != m - 1) continue;
      double e[4][5] = {}, rm[4];
      if (!small_equilibrated_rows(A, nullptr, act, m, e, rm)) continue;  // rank < m - 1
      int pm[5] = {};
      bool g2 = false;
      if (small_eliminate(e, m - 1, m, pm, tol, g2) < m - 1) continue;
      if (g2) ++gray;
      double x[5] = {};
      small_null_vector(e, m, pm, x);
      for (double sign : {1.0, -1.0}) {
        for (int j = 0; j < N; ++j) d[j] = 0;
        for (int f = 0; f < m; ++f)
          for (int j = 0; j < N; ++j) d[j] += sign * x[f] * nb[f][j];
        emit(d);
      }
    }
  }
}

/// Verdict of small_judge_ray.
enum SmallRayVerdict { kRayRejected = 0, kRayAmbiguous = 1, kRayAccepted = 2, kRayNotFinite = 3 };

/// Judges the direction d (d_i = 0 off S, (M d)_i = 0 on S by construction) of the recession
/// cone of piece S: a ray is >= 0 with M d >= 0 off S. On acceptance d is scaled to
/// ||d||_inf = 1 with its zero entries set, and zd / zmd receive its zero patterns (d_i = 0,
/// (M d)_i = 0). Depends on M only. Always inlined: a line's two rays are judged on every call
/// of enumerate_small for the rate LCPs.
template <int N, typename Mat>
CPKIT_SMALL_HOT inline SmallRayVerdict small_judge_ray(const Mat& M, unsigned S, double (&d)[N],
                                                       double tol, unsigned& zd,
                                                       unsigned& zmd) noexcept {
  constexpr unsigned kAll = (1u << N) - 1;
  double big = 0;
  int arg = 0;
  for (int j = 0; j < N; ++j) {
    if (!small_finite(d[j])) return kRayNotFinite;
    if (small_abs(d[j]) > big) { big = small_abs(d[j]); arg = j; }
  }
  if (!(big > 0) || d[arg] < 0) return kRayRejected;  // a ray is >= 0: its largest entry is positive
  const double f = 1.0 / big;
  int verdict = 0;
  zd = ~S & kAll;
  zmd = S;
  for (int j = 0; j < N; ++j) {
    if (!(S & (1u << j))) { d[j] = 0; continue; }
    d[j] *= f;
    const int sgn = small_sign(d[j], 1.0, tol);
    if (sgn == 2) return kRayRejected;
    verdict = sgn > verdict ? sgn : verdict;
    if (small_abs(d[j]) <= tol) { d[j] = 0; zd |= 1u << j; }
  }
  for (int i = 0; i < N; ++i) {
    if (S & (1u << i)) continue;
    double v = 0, sc = 0;
    for (int j = 0; j < N; ++j)
      if (d[j] != 0) { v += M(i, j) * d[j]; sc += small_abs(M(i, j) * d[j]); }
    if (!small_finite(sc) || !small_finite(v)) return kRayNotFinite;
    const int sgn = small_sign(v, sc, tol);
    if (sgn == 2) return kRayRejected;
    verdict = sgn > verdict ? sgn : verdict;
    if (small_abs(v) <= tol * sc) zmd |= 1u << i;
  }
  return verdict == 1 ? kRayAmbiguous : kRayAccepted;
}

}  // namespace cpkit::lcp::detail
