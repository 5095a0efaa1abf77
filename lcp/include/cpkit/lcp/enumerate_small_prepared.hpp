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
/// only). enumerate(q) then runs the q-dependent part with the same vertex tests
/// (SmallEnumerator::add_point), the same deduplication and the same piece collection
/// (detail::small_finish).
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

/// small_eliminate (same arithmetic, same decisions) on the matrix part only, recording the row
/// operations in rec (enumerate_small.hpp).
inline int small_eliminate_recorded(double (&a)[4][5], int k, int c, SmallElimRecord& rec,
                                    double piv_tol, bool& gray) noexcept {
  return small_eliminate(a, k, c, rec.perm, piv_tol, gray, &rec);
}

/// Replays the recorded row operations on the right-hand side b (k rows).
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
    if (!(tol > 0 && tol <= 1e-3))
      throw InputError("SmallPreparedLcp: tol must lie in (0, 1e-3], got " + std::to_string(tol));
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
    if (!(tol > 0 && tol <= 1e-3))
      throw InputError("SmallPreparedLcp::enumerate: tol must lie in (0, 1e-3], got " +
                       std::to_string(tol));
    if (tol != tol_) {  // the preparation holds for tol_ only
      enumerate_small<N>(M_, q, out, tol);
      return;
    }
    out.num_points = 0;
    out.num_pieces = 0;
    out.infinite = false;
    out.ambiguous = 0;
    out.unrepresentable = 0;
    out.dropped = 0;
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
        cramer(s, q, z);
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
    const int r = detail::small_eliminate_recorded(a, k, k, s.el, tol * amax, gray);
    s.pre_ambiguous = gray ? 1 : 0;
    s.r = r;
    const int m = k - r;
    s.m = m;
    const auto& U = s.el.a;
    const int* perm = s.el.perm;
    for (int f = 0; f < m; ++f) {
      double y[4] = {};
      y[perm[r + f]] = 1;
      for (int p = r - 1; p >= 0; --p) {
        double sum = -U[p][perm[r + f]];
        for (int c = p + 1; c < r; ++c) sum -= U[p][perm[c]] * y[perm[c]];
        y[perm[p]] = sum / U[p][perm[p]];
      }
      for (int c = 0; c < k; ++c) s.nb[f][idx[c]] = y[c];
    }
    // z0 is linear in q: its operator P is the recorded elimination applied to -e_i
    for (int ii = 0; ii < N; ++ii) {
      double rhs[4] = {};
      for (int c = 0; c < k; ++c) rhs[c] = idx[c] == ii ? -1.0 : 0.0;
      detail::small_replay_rhs(s.el, k, rhs);
      double x[4] = {};
      for (int p = r - 1; p >= 0; --p) {
        double sum = rhs[p];
        for (int c = p + 1; c < r; ++c) sum -= U[p][perm[c]] * x[perm[c]];
        x[perm[p]] = sum / U[p][perm[p]];
      }
      for (int c = 0; c < k; ++c) s.P[idx[c]][ii] = x[c];
    }
    for (int j = 0; j < N; ++j) {
      for (int f = 0; f < m; ++f) s.overflow = s.overflow || !detail::small_finite(s.nb[f][j]);
      for (int i = 0; i < N; ++i) s.overflow = s.overflow || !detail::small_finite(s.P[j][i]);
    }
    if (s.overflow) return;
    const auto& nb = s.nb;
    for (int i = 0; i < N; ++i) {
      if (S & (1u << i)) {
        for (int f = 0; f < m; ++f) {
          double nm = 0;
          for (int j = 0; j < N; ++j) nm = small_max(nm, small_abs(nb[f][j]));
          s.A[i][f] = small_abs(nb[f][i]) <= tol * nm ? 0.0 : nb[f][i];
        }
      } else {
        for (int f = 0; f < m; ++f) {
          double u = 0, su = 0;
          for (int j = 0; j < N; ++j) { u += M(i, j) * nb[f][j]; su += small_abs(M(i, j) * nb[f][j]); }
          if (!detail::small_finite(su)) { s.overflow = true; return; }
          s.A[i][f] = small_abs(u) <= tol * su ? 0.0 : u;
        }
      }
    }
    const auto& A = s.A;
    if (m == 1) {
      for (int i = 0; i < N; ++i) {
        double sa = 0;
        if (S & (1u << i)) {
          for (int j = 0; j < N; ++j) sa = small_max(sa, small_abs(nb[0][j]));
        } else {
          for (int j = 0; j < N; ++j) sa += small_abs(M(i, j) * nb[0][j]);
        }
        if (small_abs(A[i][0]) > tol * sa) {
          s.line_mask |= 1u << i;
          s.inv_a[i] = 1.0 / A[i][0];
        }
      }
      double d[N];
      for (int j = 0; j < N; ++j) d[j] = nb[0][j];
      judge_ray(S, s, d);
      for (int j = 0; j < N; ++j) d[j] = -nb[0][j];
      judge_ray(S, s, d);
      return;
    }
    // vertices: m active constraints
    for (unsigned act = 0; act <= kAll; ++act) {
      if (detail::small_popcount(act) != m) continue;
      if (m == 0) {
        s.acts[s.num_acts++] = act;
        continue;
      }
      double e[4][5] = {};
      double rm[4] = {};
      int t = 0;
      bool constant_row = false;
      for (int i = 0; i < N; ++i) {
        if (!(act & (1u << i))) continue;
        double rmax = 0;
        for (int f = 0; f < m; ++f) rmax = small_max(rmax, small_abs(A[i][f]));
        constant_row = constant_row || rmax == 0;
        if (constant_row) break;
        for (int f = 0; f < m; ++f) e[t][f] = A[i][f] / rmax;  // equilibrated (enumerate_small)
        rm[t] = rmax;
        ++t;
      }
      if (constant_row) continue;
      bool g2 = false;
      detail::SmallElimRecord& rec = s.act_el[s.num_acts];
      if (detail::small_eliminate_recorded(e, m, m, rec, tol, g2) < m) {
        rec = detail::SmallElimRecord{};
        continue;
      }
      for (int r2 = 0; r2 < m; ++r2) s.act_rmax[s.num_acts][r2] = rm[r2];
      if (g2) ++s.post_ambiguous;
      s.acts[s.num_acts++] = act;
    }
    if (m == 0) return;
    // rays: m - 1 active constraints
    for (unsigned act = 0; act <= kAll; ++act) {
      if (detail::small_popcount(act) != m - 1) continue;
      double x[5] = {};
      double e[4][5] = {};
      int t = 0;
      bool constant_row = false;
      for (int i = 0; i < N; ++i) {
        if (!(act & (1u << i))) continue;
        double rmax = 0;
        for (int f = 0; f < m; ++f) rmax = small_max(rmax, small_abs(A[i][f]));
        constant_row = constant_row || rmax == 0;
        if (constant_row) break;
        for (int f = 0; f < m; ++f) e[t][f] = A[i][f] / rmax;
        e[t][4] = 0;
        ++t;
      }
      if (constant_row) continue;
      int pm[5] = {};
      bool g2 = false;
      if (detail::small_eliminate(e, m - 1, m, pm, tol, g2) < m - 1) continue;
      if (g2) ++s.post_ambiguous;
      detail::small_null_vector(e, m, pm, x);
      for (double sign : {1.0, -1.0}) {
        double d[N] = {};
        for (int f = 0; f < m; ++f)
          for (int j = 0; j < N; ++j) d[j] += sign * x[f] * nb[f][j];
        judge_ray(S, s, d);
      }
    }
  }

  /// detail::small_cramer with the reciprocal of the determinant taken from the preparation
  /// (the same operations, hence the same result).
  void cramer(const Sup& s, const Vec& q, double (&z)[N]) const {
    const auto& M = M_;
    const double inv = s.inv;
    const int k = s.k;
    if (k == 1) {
      z[s.idx[0]] = -q(s.idx[0]) * inv;
    } else if (k == 2) {
      const int i0 = s.idx[0], i1 = s.idx[1];
      const double b0 = -q(i0), b1 = -q(i1);
      z[i0] = (b0 * M(i1, i1) - M(i0, i1) * b1) * inv;
      z[i1] = (M(i0, i0) * b1 - b0 * M(i1, i0)) * inv;
    } else {
      const int i0 = s.idx[0], i1 = s.idx[1], i2 = s.idx[2];
      const double a00 = M(i0, i0), a01 = M(i0, i1), a02 = M(i0, i2);
      const double a10 = M(i1, i0), a11 = M(i1, i1), a12 = M(i1, i2);
      const double a20 = M(i2, i0), a21 = M(i2, i1), a22 = M(i2, i2);
      const double b0 = -q(i0), b1 = -q(i1), b2 = -q(i2);
      z[i0] = (b0 * (a11 * a22 - a12 * a21) - a01 * (b1 * a22 - a12 * b2) +
               a02 * (b1 * a21 - a11 * b2)) * inv;
      z[i1] = (a00 * (b1 * a22 - a12 * b2) - b0 * (a10 * a22 - a12 * a20) +
               a02 * (a10 * b2 - b1 * a20)) * inv;
      z[i2] = (a00 * (a11 * b2 - b1 * a21) - a01 * (a10 * b2 - b1 * a20) +
               b0 * (a10 * a21 - a11 * a20)) * inv;
    }
  }

  /// The M-only tests of SmallEnumerator::add_ray (same operations): stores the normalised
  /// direction with its zero patterns when it passes, counts it when ambiguous.
  void judge_ray(unsigned S, Sup& s, double (&d)[N]) const {
    using detail::small_abs;
    const double tol = tol_;
    const auto& M = M_;
    double big = 0;
    int arg = 0;
    for (int j = 0; j < N; ++j) {
      if (!detail::small_finite(d[j])) { s.overflow = true; return; }
      if (small_abs(d[j]) > big) { big = small_abs(d[j]); arg = j; }
    }
    if (!(big > 0) || d[arg] < 0) return;
    const double f = 1.0 / big;
    int verdict = 0;
    unsigned zd = ~S & kAll, zmd = S;
    for (int j = 0; j < N; ++j) {
      if (!(S & (1u << j))) { d[j] = 0; continue; }
      d[j] *= f;
      const int sgn = detail::small_sign(d[j], 1.0, tol);
      if (sgn == 2) return;
      verdict = sgn > verdict ? sgn : verdict;
      if (small_abs(d[j]) <= tol) { d[j] = 0; zd |= 1u << j; }
    }
    for (int i = 0; i < N; ++i) {
      if (S & (1u << i)) continue;
      double v = 0, sc = 0;
      for (int j = 0; j < N; ++j)
        if (d[j] != 0) { v += M(i, j) * d[j]; sc += small_abs(M(i, j) * d[j]); }
      if (!detail::small_finite(sc) || !detail::small_finite(v)) { s.overflow = true; return; }
      const int sgn = detail::small_sign(v, sc, tol);
      if (sgn == 2) return;
      verdict = sgn > verdict ? sgn : verdict;
      if (small_abs(v) <= tol * sc) zmd |= 1u << i;
    }
    if (verdict == 1) { ++s.ray_ambiguous; return; }
    for (int j = 0; j < N; ++j) s.rays[s.num_rays][j] = d[j];
    s.ray_zero_d[s.num_rays] = zd;
    s.ray_zero_md[s.num_rays] = zmd;
    ++s.num_rays;
  }

  /// The dedup / store part of SmallEnumerator::add_ray for a ray judged by judge_ray.
  static void store_ray(detail::SmallEnumerator<N>& en, SmallSolutionSet<N>& out, const Sup& s,
                        int c) {
    const double* d = s.rays[c];
    for (int p = 0; p < en.num_rays; ++p) {
      double dd = 0;
      for (int j = 0; j < N; ++j) dd = detail::small_max(dd, detail::small_abs(en.rays[p][j] - d[j]));
      if (dd <= detail::kSmallGray * en.tol) {
        en.ray_zero_d[p] |= s.ray_zero_d[c];
        en.ray_zero_md[p] |= s.ray_zero_md[c];
        return;
      }
    }
    if (en.num_rays == detail::SmallEnumerator<N>::kRayCap) { ++out.dropped; return; }
    for (int j = 0; j < N; ++j) en.rays[en.num_rays][j] = d[j];
    en.ray_zero_d[en.num_rays] = s.ray_zero_d[c];
    en.ray_zero_md[en.num_rays] = s.ray_zero_md[c];
    ++en.num_rays;
  }

  /// The q-dependent part of SmallEnumerator::singular_piece, same operations in the same order.
  void singular_piece(detail::SmallEnumerator<N>& en, unsigned S, const Sup& s, const Vec& q,
                      SmallSolutionSet<N>& out) const {
    using detail::small_abs;
    using detail::small_max;
    const double tol = tol_;
    const auto& M = M_;
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
    for (int c = 0; c < k; ++c) {
      const int i = idx[c];
      double v = q(i), sc = small_abs(q(i));
      for (int j = 0; j < N; ++j) {
        v += M(i, j) * z0[j];
        sc += small_abs(M(i, j)) * z0n;
      }
      if (!detail::small_finite(sc) || !detail::small_finite(v)) { en.unrepresentable(); return; }
      if (small_abs(v) > detail::kSmallGray * tol * sc) return;  // empty piece
      if (small_abs(v) > tol * sc) { ++out.ambiguous; return; }
    }
    out.ambiguous += s.post_ambiguous;
    double b[N];
    for (int i = 0; i < N; ++i) {
      if (S & (1u << i)) {
        b[i] = small_abs(z0[i]) <= tol * z0n ? 0.0 : z0[i];
      } else {
        double v = q(i), sv = small_abs(q(i));
        for (int j = 0; j < N; ++j) { v += M(i, j) * z0[j]; sv += small_abs(M(i, j)) * z0n; }
        if (!detail::small_finite(sv) || !detail::small_finite(v)) { en.unrepresentable(); return; }
        b[i] = small_abs(v) <= tol * sv ? 0.0 : v;
      }
    }
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
        if (m > 0) {
          const unsigned act = s.acts[a];
          const detail::SmallElimRecord& rec = s.act_el[a];
          double e4[4] = {};
          int t = 0;
          for (int i = 0; i < N; ++i)
            if (act & (1u << i)) { e4[t] = -b[i] / s.act_rmax[a][t]; ++t; }
          detail::small_replay_rhs(rec, m, e4);
          double x[4] = {};
          const int* pm = rec.perm;
          for (int p = m - 1; p >= 0; --p) {
            double sum = e4[p];
            for (int c = p + 1; c < m; ++c) sum -= rec.a[p][pm[c]] * x[pm[c]];
            x[pm[p]] = sum / rec.a[p][pm[p]];
          }
          for (int f = 0; f < m; ++f)
            for (int j = 0; j < N; ++j) z[j] += x[f] * nb[f][j];
        }
        en.add_point(S, z);
      }
    }
    out.ambiguous += s.ray_ambiguous;
    for (int c = 0; c < s.num_rays; ++c) store_ray(en, out, s, c);
  }

  Mat M_;
  double tol_;
  std::array<Sup, kSupports> sup_;
};

}  // namespace cpkit::lcp
