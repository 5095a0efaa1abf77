#pragma once
/// \file enumerate_small_prepared.hpp
/// All solutions of many tiny LCPs (1 <= N <= 4) that share one matrix M: the prepared-matrix
/// path of enumerate_small (enumerate_small.hpp).
///
/// Problem: z >= 0, w = M z + q >= 0, z . w = 0 (cpkit's sign convention); the solution set is
/// the union of the pieces P_S [Cottle-Pang-Stone 1992, Sec. 3.9]. The typical use is a map of
/// the one-point rate problem [Stromberg et al. 1996, Sec. 4.2, Eqs. (4.5)-(4.8)]: one parameter
/// set fixes M, thousands of load directions dF change only q.
///
/// SmallPreparedLcp does, once in its constructor, everything of enumerate_small that depends
/// on M only: for every support S the determinant of M_SS and the singularity decision (same
/// scale-aware test, same tolerance), 1/det for the Cramer solves of nonsingular blocks, and for
/// singular blocks the complete-pivoting elimination (same pivots and rank decision), the
/// operator P with z0 = P q of the particular solution, the null basis, the constraint
/// directions of the piece, the eliminations that locate its vertices (recorded row operations,
/// replayed on q) and the candidate rays with add_ray's tests already applied (they depend on M
/// only). enumerate(q) then runs the q-dependent part on the kernel of enumerate_small
/// (detail::SmallEnumerator: add_point, piece_consistent, constraint_offsets, vertex_from,
/// store_ray; detail::small_finish) with the M-only geometry of detail/small_piece.hpp computed
/// once: only the way a basic solution is obtained differs (replay of the recorded elimination).
///
/// Agreement with enumerate_small(M, q, out, tol): every M-only decision is identical, and the
/// nonsingular supports use the very same operations. On singular blocks z0 = P q and the line
/// parameter t = -b_i * (1 / A_i0) are computed by a different (cheaper) order of operations, so
/// those values agree to round-off (relative ~1e-15) rather than bit for bit; the q-dependent
/// decisions (signs, zero tests, deduplication) therefore agree except for a value within
/// round-off of a tolerance threshold - a case where enumerate_small's own verdict is decided
/// by round-off. tests/lcp/test_enumerate_small_prepared.cpp checks counts, supports, masks,
/// flags and the ambiguous count for equality and values to 1e-12 relative, on random integer
/// matrices (frequent singular blocks) and on the state-b rate LCP incl. a11 = mu |a12|.
/// Supports whose M-only values overflow, a Cramer solve or a z0 = P q that overflows, are
/// decided per call from the data by SmallEnumerator::singular_piece, exactly as
/// enumerate_small decides them (values double cannot represent: `unrepresentable`).
/// Allocation-free, fixed-size; enumerate() is const and thread-safe.
#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"

namespace cpkit::lcp {

namespace detail {

/// Everything of one support S that depends on M only.
template <int N>
struct SmallPreparedSupport {
  static constexpr int kActs = 6;   ///< max C(N, m) active sets of a vertex
  static constexpr int kRays = 12;  ///< max candidate directions 2 C(N, m - 1)
  int k = 0;                        ///< |S|
  int idx[4] = {};                  ///< the members of S, ascending
  /// 0: S empty, 1: nonsingular block (Cramer), 2: singular path, 3: M-only values that double
  /// cannot hold (overflow): enumerate() runs SmallEnumerator::singular_piece from the data
  int kind = 0;
  double det = 0;                   ///< det M_SS (kind 1)
  double inv = 0;                   ///< 1 / det, as small_cramer computes it
  // ---- kind 2 ----
  int pre_ambiguous = 0;            ///< gray pivot of the block elimination (always counted)
  int post_ambiguous = 0;           ///< gray pivots of vertex / ray eliminations (counted if P_S != {})
  int r = 0, m = 0;                 ///< rank of M_SS and dimension of its null space
  SmallElimRecord el;               ///< elimination of M_SS
  double P[N][N] = {};              ///< z0 = P q: the basic solution of M_SS z_S = -q_S (free vars 0)
  double inv_a[N] = {};             ///< m == 1: 1 / A_i0 for the constraints in line_mask
  double nb[4][N] = {};             ///< null basis (one row per free variable)
  double A[N][4] = {};              ///< constraint directions g_i(t) = b_i + sum_f A_if t_f
  unsigned line_mask = 0;           ///< m == 1: constraints not parallel to the line
  int num_acts = 0;                 ///< m != 1: active sets whose system is regular
  unsigned acts[kActs] = {};
  SmallElimRecord act_el[kActs];
  double act_rmax[kActs][4] = {};   ///< row scales of the equilibrated vertex systems
  bool overflow = false;            ///< an M-only value is not finite (then kind becomes 3)
  int num_rays = 0;                 ///< candidate rays that pass add_ray's (M-only) tests
  double rays[kRays][N] = {};       ///< normalised as add_ray stores them
  unsigned ray_zero_d[kRays] = {};  ///< their zero patterns (as add_ray records them)
  unsigned ray_zero_md[kRays] = {};
  int ray_ambiguous = 0;            ///< candidates add_ray counts as ambiguous
};

}  // namespace detail

/// A matrix M prepared for the enumeration of all solutions of LCP(M, q) for many q.
/// enumerate(q, out, tol) gives exactly what enumerate_small(M, q, out, tol) gives; with a tol
/// other than the one of the constructor it simply calls enumerate_small.
template <int N>
class SmallPreparedLcp {
 public:
  using Mat = Eigen::Matrix<double, N, N>;
  using Vec = Eigen::Matrix<double, N, 1>;
  static constexpr int kSupports = 1 << N;
  static constexpr unsigned kAll = (1u << N) - 1;

  /// Does all M-only work. Throws InputError on non-finite M or tol outside (0, 1e-3].
  explicit SmallPreparedLcp(const Mat& M, double tol = 1e-12) : M_(M), tol_(tol) {
    if (!M.allFinite()) throw InputError("SmallPreparedLcp: M has a non-finite entry");
    detail::small_check_tol("SmallPreparedLcp", tol);
    for (unsigned S = 0; S <= kAll; ++S) {
      Sup& s = sup_[S];
      prepare(S, s);
      if (s.overflow) {  // decided per call from the data, exactly as enumerate_small does
        Sup t;
        t.k = s.k;
        for (int c = 0; c < 4; ++c) t.idx[c] = s.idx[c];
        t.kind = 3;
        s = t;
      }
    }
  }

  const Mat& matrix() const noexcept { return M_; }
  double tolerance() const noexcept { return tol_; }

  /// All solutions of LCP(M, q) (see enumerate_small). Throws InputError on non-finite q or
  /// tol outside (0, 1e-3]. Allocation-free; `out` is overwritten.
  void enumerate(const Vec& q, SmallSolutionSet<N>& out, double tol = 1e-12) const {
    if (!q.allFinite()) throw InputError("SmallPreparedLcp::enumerate: q has a non-finite entry");
    detail::small_check_tol("SmallPreparedLcp::enumerate", tol);
    if (tol != tol_) {  // the preparation holds for tol_ only
      enumerate_small<N>(M_, q, out, tol);
      return;
    }
    detail::SmallEnumerator<N> en(M_, q, out, tol);
    for (unsigned S = 0; S <= kAll; ++S) {
      const auto& s = sup_[S];
      if (s.kind == 2) {
        singular_piece(en, S, s, q, out);
        continue;
      }
      if (s.kind == 3) {
        en.singular_piece_cold(S, s.idx, s.k);
        continue;
      }
      double z[N] = {};
      if (s.kind == 1) {
        detail::small_cramer_inv(M_, q, s.idx, s.idx, s.k, s.inv, s.idx, z);
        if (!en.all_finite(z)) {  // as enumerate_small: overflow in Cramer's products
          en.singular_piece_cold(S, s.idx, s.k);
          continue;
        }
      }
      en.add_point(S, z);
    }
    detail::small_finish<N>(en, out);
  }

 private:
  using Sup = detail::SmallPreparedSupport<N>;

  void prepare(unsigned S, Sup& s) {
    using detail::small_abs;
    using detail::small_max;
    const double tol = tol_;
    const auto& M = M_;
    s.k = 0;
    for (int j = 0; j < N; ++j)
      if (S & (1u << j)) s.idx[s.k++] = j;
    const int k = s.k;
    if (k == 0) { s.kind = 0; return; }
    if (k <= 3) {
      double det, perm;
      detail::small_det(M, s.idx, s.idx, k, det, perm);
      if (detail::small_det_ok(det, perm, tol)) {
        s.kind = 1;
        s.det = det;
        s.inv = 1.0 / det;
        return;
      }
    }
    s.kind = 2;
    const int* idx = s.idx;
    double a[4][5] = {};
    double amax = 0;
    for (int r = 0; r < k; ++r)
      for (int c = 0; c < k; ++c) {
        a[r][c] = M(idx[r], idx[c]);
        amax = small_max(amax, small_abs(a[r][c]));
      }
    bool gray = false;
    const int r = detail::small_eliminate(a, k, k, s.el.perm, tol * amax, gray, &s.el);
    s.pre_ambiguous = gray ? 1 : 0;
    s.r = r;
    const int m = k - r;
    s.m = m;
    detail::small_null_basis<N>(s.el.a, r, k, s.el.perm, idx, s.nb);
    // z0 is linear in q: its operator P is the recorded elimination applied to -e_i
    for (int ii = 0; ii < N; ++ii) {
      double rhs[4] = {};
      for (int c = 0; c < k; ++c) rhs[c] = idx[c] == ii ? -1.0 : 0.0;
      detail::small_replay_rhs(s.el, k, rhs);
      double x[4] = {};
      detail::small_back_substitute(s.el.a, r, s.el.perm, [&](int p) { return rhs[p]; }, x);
      for (int c = 0; c < k; ++c) s.P[idx[c]][ii] = x[c];
    }
    for (int j = 0; j < N; ++j) {
      for (int f = 0; f < m; ++f) s.overflow = s.overflow || !detail::small_finite(s.nb[f][j]);
      for (int i = 0; i < N; ++i) s.overflow = s.overflow || !detail::small_finite(s.P[j][i]);
    }
    if (s.overflow) return;
    if (!detail::small_constraint_dirs<N>(M, S, s.nb, m, tol, s.A)) { s.overflow = true; return; }
    if (m == 1) {
      for (int i = 0; i < N; ++i) {
        if (small_abs(s.A[i][0]) > tol * detail::small_line_scale<N>(M, S, i, s.nb)) {
          s.line_mask |= 1u << i;
          s.inv_a[i] = 1.0 / s.A[i][0];
        }
      }
    } else {  // vertices: m active constraints
      for (unsigned act = 0; act <= kAll; ++act) {
        if (detail::small_popcount(act) != m) continue;
        if (m == 0) {
          s.acts[s.num_acts++] = act;
          continue;
        }
        double e[4][5] = {};
        if (!detail::small_equilibrated_rows<N>(s.A, nullptr, act, m, e, s.act_rmax[s.num_acts]))
          continue;
        bool g2 = false;
        detail::SmallElimRecord& rec = s.act_el[s.num_acts];
        if (detail::small_eliminate(e, m, m, rec.perm, tol, g2, &rec) < m) {
          rec = detail::SmallElimRecord{};
          continue;
        }
        if (g2) ++s.post_ambiguous;
        s.acts[s.num_acts++] = act;
      }
    }
    if (m == 0) return;
    // rays: add_ray's tests depend on M only
    detail::small_ray_candidates<N>(s.A, s.nb, m, tol, s.post_ambiguous, [&](double (&d)[N]) {
      unsigned zd = 0, zmd = 0;
      switch (detail::small_judge_ray<N>(M, S, d, tol, zd, zmd)) {
        case detail::kRayAccepted:
          for (int j = 0; j < N; ++j) s.rays[s.num_rays][j] = d[j];
          s.ray_zero_d[s.num_rays] = zd;
          s.ray_zero_md[s.num_rays] = zmd;
          ++s.num_rays;
          return;
        case detail::kRayAmbiguous: ++s.ray_ambiguous; return;
        case detail::kRayNotFinite: s.overflow = true; return;
        default: return;
      }
    });
  }

  /// The q-dependent part of SmallEnumerator::singular_piece, same operations in the same order.
  void singular_piece(detail::SmallEnumerator<N>& en, unsigned S, const Sup& s, const Vec& q,
                      SmallSolutionSet<N>& out) const {
    using detail::small_abs;
    using detail::small_max;
    const int k = s.k, m = s.m;
    const int* idx = s.idx;
    double z0[N];
    for (int j = 0; j < N; ++j) {
      double v = 0;
      for (int i = 0; i < N; ++i) v += s.P[j][i] * q(i);
      z0[j] = v;
    }
    if (!en.all_finite(z0)) {  // overflow of P q: decide from the data as enumerate_small does
      en.singular_piece_cold(S, idx, k);
      return;
    }
    out.ambiguous += s.pre_ambiguous;
    double z0n = 0;
    for (int j = 0; j < N; ++j) z0n = small_max(z0n, small_abs(z0[j]));
    if (!en.piece_consistent(idx, k, z0, z0n)) return;
    out.ambiguous += s.post_ambiguous;
    double b[N];
    if (!en.constraint_offsets(S, z0, z0n, b)) { en.unrepresentable(); return; }
    const auto& nb = s.nb;
    if (m == 1) {
      for (int i = 0; i < N; ++i) {
        if (!(s.line_mask & (1u << i))) continue;
        const double t = -b[i] * s.inv_a[i];
        double z[N];
        for (int j = 0; j < N; ++j) z[j] = z0[j] + t * nb[0][j];
        en.add_point(S, z);
      }
    } else {
      for (int a = 0; a < s.num_acts; ++a) {
        double z[N];
        for (int j = 0; j < N; ++j) z[j] = z0[j];
        if (m > 0) {  // the vertex system's elimination replayed on its right-hand side
          const detail::SmallElimRecord& rec = s.act_el[a];
          double e4[4] = {};
          int t = 0;
          for (int i = 0; i < N; ++i)
            if (s.acts[a] & (1u << i)) { e4[t] = -b[i] / s.act_rmax[a][t]; ++t; }
          detail::small_replay_rhs(rec, m, e4);
          en.vertex_from(rec.a, rec.perm, m, [&](int p) { return e4[p]; }, nb, z);
        }
        en.add_point(S, z);
      }
    }
    out.ambiguous += s.ray_ambiguous;
    for (int c = 0; c < s.num_rays; ++c)
      en.store_ray(s.rays[c], s.ray_zero_d[c], s.ray_zero_md[c]);
  }

  Mat M_;
  double tol_;
  std::array<Sup, kSupports> sup_;
};

}  // namespace cpkit::lcp
