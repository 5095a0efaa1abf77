#pragma once
// The kernel of enumerate_small and SmallPreparedLcp (private to cpkit_lcp; compiled once in
// enumerate_small.cpp for N = 1..4): SmallEnumerator judges and stores the candidate vertices
// and rays of one call, small_finish collects the pieces. The algorithm, the tolerances and
// their invariances are documented in cpkit/lcp/enumerate_small.hpp.
#include <Eigen/Core>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "small_piece.hpp"

namespace cpkit::lcp::detail {

/// Working state of one enumerate_small call (all on the stack).
template <int N>
struct SmallEnumerator {
  static constexpr int kMax = SmallSolutionSet<N>::kMax;
  static constexpr unsigned kAll = (1u << N) - 1;
  static constexpr int kRayCap = 4 * kMax;  // distinct extreme rays of all pieces
  const Eigen::Matrix<double, N, N>& M;
  const Eigen::Matrix<double, N, 1>& q;
  SmallSolutionSet<N>& out;
  double tol;
  // Written before they are read (entry p when vertex / ray p is stored): deliberately not
  // zero-initialised, which would cost more than the whole enumeration of a 3x3 problem.
  unsigned zero_z[kMax], zero_w[kMax];  // zero patterns of the stored vertices
  double rays[kRayCap][N];
  unsigned ray_zero_d[kRayCap], ray_zero_md[kRayCap];
  int num_rays = 0;

  SmallEnumerator(const Eigen::Matrix<double, N, N>& m, const Eigen::Matrix<double, N, 1>& qq,
                  SmallSolutionSet<N>& o, double t)
      : M(m), q(qq), out(o), tol(t) {  // out is overwritten: its counts are reset
    out.num_points = 0;
    out.num_pieces = 0;
    out.infinite = false;
    out.ambiguous = 0;
    out.unrepresentable = 0;
    out.dropped = 0;
  }

  /// A candidate that double precision cannot represent or verify (never listed).
  CPKIT_SMALL_COLD void unrepresentable() noexcept {
    ++out.unrepresentable;
    ++out.dropped;
  }

  /// A candidate with a non-finite entry: -inf is clearly negative (infeasible); +inf or NaN
  /// is a value double cannot represent.
  CPKIT_SMALL_COLD void non_finite_point(const double (&z)[N]) noexcept {
    for (int j = 0; j < N; ++j)
      if (z[j] < 0 && !small_finite(z[j])) return;
    unrepresentable();
  }

  /// Judges the candidate z (z_i = 0 off S, w_i = 0 on S by construction) of piece S and
  /// stores it when feasible and new. Every test is relative to the scale of its own terms
  /// (||z||_inf for z, W_i = |q_i| + sum_j |M_ij z_j| for w_i), hence invariant under
  /// q -> a q and (M, q) -> b (M, q).
  CPKIT_SMALL_HOT void add_point(unsigned S, double (&z)[N]) {
    double zs = 0, nf = 0;  // nf stays 0 when every z_j is finite (z_j - z_j is NaN otherwise)
    for (int j = 0; j < N; ++j) {  // (z_j = 0 off S by construction)
      zs = small_max(zs, small_abs(z[j]));
      nf += z[j] - z[j];
    }
    if (nf != 0) { non_finite_point(z); return; }
    int verdict = 0;
    unsigned zz = ~S & kAll, zw = S, tiny = 0;
    for (int j = 0; j < N; ++j) {
      if (!(S & (1u << j))) continue;
      if (small_sign(z[j], zs, tol) == 2) return;       // clearly negative against ||z||
      if (z[j] <= tol * zs) tiny |= 1u << j;              // tiny, or in the gray band
    }
    if (tiny && !settle_tiny(S, tiny, z, zz)) return;
    double w[N];
    for (int i = 0; i < N; ++i) {
      if (S & (1u << i)) { w[i] = 0; continue; }
      double v = q(i), sc = small_abs(q(i));
      for (int j = 0; j < N; ++j)
        if (z[j] != 0) { v += M(i, j) * z[j]; sc += small_abs(M(i, j) * z[j]); }
      // sc >= |every term of v|: a finite sc means a finite v (M and z are finite)
      if (!(sc <= 1.7976931348623157e308)) { unrepresentable(); return; }
      const int sgn = small_sign(v, sc, tol);
      if (sgn == 2) return;
      verdict = sgn > verdict ? sgn : verdict;
      if (small_abs(v) <= tol * sc) { w[i] = 0; zw |= 1u << i; } else { w[i] = v; }
    }
    if (verdict == 1) { ++out.ambiguous; return; }
    for (int p = 0; p < out.num_points; ++p) {
      double d = 0, s2 = zs;
      for (int j = 0; j < N; ++j) {
        d = small_max(d, small_abs(out.z[p](j) - z[j]));
        s2 = small_max(s2, small_abs(out.z[p](j)));
      }
      // the same point from another piece or basis; its zero pattern is merged only when the
      // stored point satisfies it too (close in z does not mean close in w when M is large)
      if (d <= kSmallGray * tol * s2 && merge_ok(p, zz, zw)) {
        zero_z[p] |= zz;
        zero_w[p] |= zw;
        return;
      }
    }
    // a new point: its own equations w_i = 0 (i in S) re-checked from the data (the solve of
    // an ill-conditioned block may miss them; such a candidate is too close to call)
    for (int i = 0; i < N; ++i) {
      if (!(S & (1u << i))) continue;
      double v = q(i), sc = small_abs(q(i));
      for (int j = 0; j < N; ++j) {
        const double t = M(i, j) * z[j];
        v += t;
        sc += small_abs(t);
      }
      if (!(small_abs(v) <= kSmallGray * tol * sc)) {  // (fails for inf and NaN too)
        if (small_finite(sc) && small_finite(v)) ++out.ambiguous; else unrepresentable();
        return;
      }
    }
    if (out.num_points == kMax) { ++out.dropped; return; }
    const int p = out.num_points++;
    for (int j = 0; j < N; ++j) { out.z[p](j) = z[j]; out.w[p](j) = w[j]; }
    zero_z[p] = zz;
    zero_w[p] = zw;
  }

  /// Entries tiny against ||z||_inf or in the gray band below zero (mask `tiny`; a unit-free
  /// backward-error decision rather than a comparison with ||z|| alone) are zero when setting
  /// them all to zero keeps every equation w_i = 0 (i in S, to 1e4 tol W_i) and the
  /// feasibility of every other w_i; else each one is zero only when negligible in every row
  /// (|M_ij z_j| <= tol W_i), and one that is not negligible keeps its value, its sign deciding
  /// (e.g. M = diag(1e200, 1): z_0 = -1e-200 moves w_0 by 1, so the candidate is infeasible).
  /// False when the candidate is infeasible.
  CPKIT_SMALL_COLD bool settle_tiny(unsigned S, unsigned tiny, double (&z)[N], unsigned& zz) const {
    unsigned nonzero = 0;
    for (int j = 0; j < N; ++j)
      if ((tiny & (1u << j)) && z[j] != 0) nonzero |= 1u << j;
    if (!nonzero) {  // exact zeros: nothing changes
      zz |= tiny;
      return true;
    }
    double W[N];
    bool consistent = true;
    for (int i = 0; i < N; ++i) {  // one pass: W_i, w_i at z, and w_i with the tiny entries zeroed
      double sc = small_abs(q(i)), v = q(i), dv = 0;
      for (int j = 0; j < N; ++j) {
        const double t = M(i, j) * z[j];
        sc += small_abs(t);
        v += t;
        if (nonzero & (1u << j)) dv += t;
      }
      W[i] = sc;
      const double vt = v - dv;
      consistent = consistent && ((S & (1u << i)) ? small_abs(vt) <= kSmallGray * tol * sc
                                                  : (vt >= -tol * sc) == (v >= -tol * sc));
    }
    if (consistent) {
      for (int j = 0; j < N; ++j)
        if (tiny & (1u << j)) z[j] = 0;
      zz |= tiny;
      return true;
    }
    for (int j = 0; j < N; ++j) {
      if (!(tiny & (1u << j))) continue;
      bool negligible = true;
      for (int i = 0; i < N && negligible; ++i)
        negligible = small_abs(M(i, j) * z[j]) <= tol * W[i];
      if (negligible) {
        z[j] = 0;
        zz |= 1u << j;
      } else if (z[j] < 0) {
        return false;
      }
    }
    return true;
  }

  /// True when stored point p satisfies the zero claims zz (z_j = 0) and zw (w_i = 0) of a
  /// candidate found equal to it: the new claims hold at p within tol of their row scales.
  CPKIT_SMALL_COLD bool merge_ok(int p, unsigned zz, unsigned zw) const {
    const unsigned nz = zz & ~zero_z[p], nw = zw & ~zero_w[p];
    if (!nz && !nw) return true;
    double W[N];
    for (int i = 0; i < N; ++i) {
      double sc = small_abs(q(i));
      for (int j = 0; j < N; ++j) sc += small_abs(M(i, j) * out.z[p](j));
      W[i] = sc;
    }
    for (int j = 0; j < N; ++j) {
      if (!(nz & (1u << j))) continue;
      for (int i = 0; i < N; ++i)
        if (!(small_abs(M(i, j) * out.z[p](j)) <= tol * W[i])) return false;
    }
    for (int i = 0; i < N; ++i)
      if ((nw & (1u << i)) && !(small_abs(out.w[p](i)) <= tol * W[i])) return false;
    return true;
  }

  /// Judges the direction d (d_i = 0 off S, (M d)_i = 0 on S by construction) of the
  /// recession cone of piece S; stores it (scaled to ||d||_inf = 1) when it is a new ray.
  void add_ray(unsigned S, double (&d)[N]) {
    unsigned zd = 0, zmd = 0;
    switch (small_judge_ray<N>(M, S, d, tol, zd, zmd)) {
      case kRayAccepted: store_ray(d, zd, zmd); return;
      case kRayAmbiguous: ++out.ambiguous; return;
      case kRayNotFinite: unrepresentable(); return;
      default: return;
    }
  }

  /// Stores an accepted ray d (zero patterns zd, zmd) unless it is already listed; then its
  /// zero patterns are merged into the listed one.
  void store_ray(const double* d, unsigned zd, unsigned zmd) {
    for (int p = 0; p < num_rays; ++p) {
      double dd = 0;
      for (int j = 0; j < N; ++j) dd = small_max(dd, small_abs(rays[p][j] - d[j]));
      if (dd <= kSmallGray * tol) {
        ray_zero_d[p] |= zd;
        ray_zero_md[p] |= zmd;
        return;
      }
    }
    if (num_rays == kRayCap) { ++out.dropped; return; }
    for (int j = 0; j < N; ++j) rays[num_rays][j] = d[j];
    ray_zero_d[num_rays] = zd;
    ray_zero_md[num_rays] = zmd;
    ++num_rays;
  }

  /// Consistency of the basic solution z0 (||z0||_inf = z0n) of the block M_SS (members idx,
  /// k of them): -q_S must lie in the range of M_SS (backward-error scale
  /// |q_i| + ||M_i.||_1 ||z0||_inf: entries of z0 that should vanish carry round-off of the size
  /// of the whole z0). False when the piece is empty, too close to call (counted in ambiguous)
  /// or not representable (counted).
  bool piece_consistent(const int* idx, int k, const double (&z0)[N], double z0n) {
    for (int c = 0; c < k; ++c) {
      const int i = idx[c];
      double v = q(i), sc = small_abs(q(i));
      for (int j = 0; j < N; ++j) {
        v += M(i, j) * z0[j];
        sc += small_abs(M(i, j)) * z0n;
      }
      if (!small_finite(sc) || !small_finite(v)) { unrepresentable(); return false; }
      if (small_abs(v) > kSmallGray * tol * sc) return false;  // empty piece
      if (small_abs(v) > tol * sc) { ++out.ambiguous; return false; }
    }
    return true;
  }

  /// Offsets b_i = g_i(0) of the constraints of piece S at z0 (z_i on S, w_i off S; values at
  /// round-off level of their own terms are zero). False when a value overflows.
  bool constraint_offsets(unsigned S, const double (&z0)[N], double z0n, double (&b)[N]) const {
    for (int i = 0; i < N; ++i) {
      if (S & (1u << i)) {
        b[i] = small_abs(z0[i]) <= tol * z0n ? 0.0 : z0[i];
      } else {
        double v = q(i), sv = small_abs(q(i));
        for (int j = 0; j < N; ++j) { v += M(i, j) * z0[j]; sv += small_abs(M(i, j)) * z0n; }
        if (!small_finite(sv) || !small_finite(v)) return false;
        b[i] = small_abs(v) <= tol * sv ? 0.0 : v;
      }
    }
    return true;
  }

  /// Vertex z += nb^T x of a piece of dimension m, x solving the regular m x m system
  /// eliminated by small_eliminate (u, column order perm) with eliminated right-hand side
  /// rhs(t).
  template <typename Rhs>
  static void vertex_from(const double (&u)[4][5], const int (&perm)[5], int m, const Rhs& rhs,
                          const double (&nb)[4][N], double (&z)[N]) noexcept {
    double x[4] = {};
    small_back_substitute(u, m, perm, rhs, x);
    for (int f = 0; f < m; ++f)
      for (int j = 0; j < N; ++j) z[j] += x[f] * nb[f][j];
  }

  /// Piece S with a singular (or 4x4) block M_SS: P_S = {z0 + N t} cut by the n inequalities
  /// z_i >= 0 (i in S), w_j >= 0 (j not in S); vertices have m = dim t of them active,
  /// extreme rays m - 1.
  void singular_piece(unsigned S, const int* idx, int k) {
    double a[4][5] = {};
    double amax = 0;
    for (int r = 0; r < k; ++r) {
      for (int c = 0; c < k; ++c) {
        a[r][c] = M(idx[r], idx[c]);
        amax = small_max(amax, small_abs(a[r][c]));
      }
      a[r][4] = -q(idx[r]);
    }
    int perm[5] = {};
    bool gray = false;
    const int r = small_eliminate(a, k, k, perm, tol * amax, gray);
    if (gray) ++out.ambiguous;
    const int m = k - r;
    // particular solution (free variables 0) and null basis (one row per free variable)
    double z0[N] = {}, nb[4][N] = {};
    {
      double x[4] = {};
      small_back_substitute(a, r, perm, [&](int p) { return a[p][4]; }, x);
      for (int c = 0; c < k; ++c) z0[idx[c]] = x[c];
    }
    small_null_basis<N>(a, r, k, perm, idx, nb);
    // overflow (e.g. a pivot 1e-320 against q = 1): values double cannot hold
    bool ok = all_finite(z0);
    for (int f = 0; f < m; ++f) ok = ok && all_finite(nb[f]);
    if (!ok) { unrepresentable(); return; }
    double z0n = 0;
    for (int j = 0; j < N; ++j) z0n = small_max(z0n, small_abs(z0[j]));
    if (!piece_consistent(idx, k, z0, z0n)) return;
    double A[N][4] = {}, b[N];
    if (!constraint_offsets(S, z0, z0n, b) || !small_constraint_dirs<N>(M, S, nb, m, tol, A)) {
      unrepresentable();
      return;
    }
    if (m == 1) {  // a line: vertices where one constraint is active
      for (int i = 0; i < N; ++i) {
        if (!(small_abs(A[i][0]) > tol * small_line_scale<N>(M, S, i, nb))) continue;  // parallel
        const double t = -b[i] / A[i][0];
        double z[N];
        for (int j = 0; j < N; ++j) z[j] = z0[j] + t * nb[0][j];
        add_point(S, z);
      }
    } else {  // vertices: m active constraints
      for (unsigned act = 0; act <= kAll; ++act) {
        if (small_popcount(act) != m) continue;
        double z[N];
        for (int j = 0; j < N; ++j) z[j] = z0[j];
        if (m > 0) {
          double e[4][5] = {}, rm[4];
          if (!small_equilibrated_rows<N>(A, b, act, m, e, rm)) continue;
          int pm[5] = {};
          bool g2 = false;
          if (small_eliminate(e, m, m, pm, tol, g2) < m) continue;
          if (g2) ++out.ambiguous;
          vertex_from(e, pm, m, [&](int t) { return e[t][4]; }, nb, z);
        }
        add_point(S, z);
      }
    }
    if (m == 0) return;
    int g = 0;
    small_ray_candidates<N>(A, nb, m, tol, g, [&](double (&d)[N]) { add_ray(S, d); });
    out.ambiguous += g;
  }

  /// True when every entry is finite (z_j - z_j is 0 for finite z_j, NaN otherwise).
  static bool all_finite(const double (&z)[N]) noexcept {
    double s = 0;
    for (int j = 0; j < N; ++j) s += z[j] - z[j];
    return s == 0;
  }

  /// singular_piece, kept out of line for the callers' hot paths (SmallPreparedLcp).
  CPKIT_SMALL_COLD void singular_piece_cold(unsigned S, const int* idx, int k) {
    singular_piece(S, idx, k);
  }

  void run() {
    for (unsigned S = 0; S <= kAll; ++S) {
      int idx[4], k = 0;
      for (int j = 0; j < N; ++j)
        if (S & (1u << j)) idx[k++] = j;
      if (k <= 3) {
        double z[N] = {};
        if (k > 0) {
          double det, perm;
          small_det(M, idx, idx, k, det, perm);
          if (!small_det_ok(det, perm, tol)) {  // singular, close, or extreme: the general path
            singular_piece(S, idx, k);
            continue;
          }
          small_cramer(M, q, idx, k, det, z);
          if (!all_finite(z)) {  // overflow in Cramer's products: elimination instead
            singular_piece(S, idx, k);
            continue;
          }
        }
        add_point(S, z);
      } else {
        singular_piece(S, idx, k);
      }
    }
  }
};

/// Throws InputError unless tol lies in (0, 1e-3] (`who` names the caller).
/// The test stays inline (it is on every call); the throw is out of line.
[[noreturn]] CPKIT_SMALL_COLD inline void small_bad_tol(const char* who, double tol) {
  throw InputError(std::string(who) + ": tol must lie in (0, 1e-3], got " + std::to_string(tol));
}
CPKIT_SMALL_HOT inline void small_check_tol(const char* who, double tol) {
  if (!(tol > 0 && tol <= 1e-3)) small_bad_tol(who, tol);
}

/// Final pass shared by enumerate_small and SmallPreparedLcp: applies the zero patterns to the
/// stored vertices, sets their supports and collects the inclusion-maximal pieces of positive
/// dimension with their vertices and rays.
template <int N>
void small_finish(const SmallEnumerator<N>& en, SmallSolutionSet<N>& out) {
  constexpr int kMax = SmallSolutionSet<N>::kMax;
  constexpr unsigned kAll = (1u << N) - 1;
  const unsigned* zero_z = en.zero_z;
  const unsigned* zero_w = en.zero_w;
  const unsigned* ray_zero_d = en.ray_zero_d;
  const unsigned* ray_zero_md = en.ray_zero_md;
  const int num_rays = en.num_rays;
  const auto& rays = en.rays;
  for (int p = 0; p < out.num_points; ++p) {
    for (int j = 0; j < N; ++j) {
      if (zero_z[p] & (1u << j)) out.z[p](j) = 0;
      if (zero_w[p] & (1u << j)) out.w[p](j) = 0;
    }
    out.support[p] = ~zero_z[p] & kAll;
  }

  // ---- pieces ----
  if (out.num_points < 2 && num_rays == 0) return;  // finite: no piece of positive dimension
  unsigned vmask[kMax];
  unsigned long long rmask[kMax];
  unsigned cand_support[kMax];
  int cand = 0;
  for (unsigned S = 0; S <= kAll; ++S) {
    const unsigned off = ~S & kAll;
    unsigned vm = 0;
    for (int p = 0; p < out.num_points; ++p)
      if ((zero_z[p] & off) == off && (zero_w[p] & S) == S) vm |= 1u << p;
    if (vm == 0) continue;  // empty piece
    unsigned long long rm = 0;
    for (int r = 0; r < num_rays; ++r)
      if ((ray_zero_d[r] & off) == off && (ray_zero_md[r] & S) == S) rm |= 1ull << r;
    if (rm == 0 && (vm & (vm - 1)) == 0) continue;  // a single point
    vmask[cand] = vm;
    rmask[cand] = rm;
    cand_support[cand] = S;
    ++cand;
  }
  for (int a = 0; a < cand; ++a) {
    bool maximal = true;
    for (int b = 0; b < cand && maximal; ++b) {
      if (b == a) continue;
      const bool sub = (vmask[a] & ~vmask[b]) == 0 && (rmask[a] & ~rmask[b]) == 0;
      const bool equal = vmask[a] == vmask[b] && rmask[a] == rmask[b];
      if (sub && (!equal || b < a)) maximal = false;
    }
    if (!maximal) continue;
    auto& piece = out.pieces[out.num_pieces++];
    piece.support = cand_support[a];
    piece.vertex_mask = vmask[a];
    piece.num_rays = 0;
    for (int r = 0; r < num_rays; ++r) {
      if (!(rmask[a] & (1ull << r))) continue;
      if (piece.num_rays == kMax) { ++out.dropped; continue; }
      for (int j = 0; j < N; ++j) piece.rays[piece.num_rays](j) = rays[r][j];
      ++piece.num_rays;
    }
  }
  out.infinite = out.num_pieces > 0;
}

}  // namespace cpkit::lcp::detail
