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
/// only). enumerate(q) then runs the q-dependent part on the kernel of enumerate_small (the
/// same vertex and ray tests, piece consistency, constraint offsets, vertex solves and piece
/// collection, with the M-only piece geometry computed once; lcp/src/enumerate_small.cpp):
/// only the way a basic solution is obtained differs (replay of the recorded elimination).
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
/// Sizes: N = 1, 2, 3, 4 only, compiled into cpkit_lcp (lcp/src/enumerate_small.cpp); any other
/// N is a compile-time error. The data layout of the prepared matrix is below (the object is
/// fixed-size: sizeof ~25 KB for N = 3); the code that fills and reads it is in the library.
#include <Eigen/Core>
#include <array>

#include "cpkit/core/errors.hpp"  // InputError (thrown on bad input)
#include "cpkit/lcp/enumerate_small.hpp"

namespace cpkit::lcp {

namespace detail {

/// The row operations of one complete-pivoting elimination of a block of at most 4 x 4, for
/// replaying them on other right-hand sides.
struct SmallElimRecord {
  int rank = 0;
  int perm[5] = {};     ///< column order
  int swap[4] = {};     ///< row exchanged with row p at step p
  double f[4][4] = {};  ///< f[p][r]: multiple of row p subtracted from row r > p
  double a[4][5] = {};  ///< the eliminated block (column 4 unused)
};

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
  static_assert(N >= 1 && N <= 4,
                "SmallPreparedLcp: only N = 1, 2, 3, 4 are compiled into cpkit_lcp");

 public:
  using Mat = Eigen::Matrix<double, N, N>;
  using Vec = Eigen::Matrix<double, N, 1>;
  static constexpr int kSupports = 1 << N;
  static constexpr unsigned kAll = (1u << N) - 1;

  /// Does all M-only work. Throws InputError on non-finite M or tol outside (0, 1e-3].
  explicit SmallPreparedLcp(const Mat& M, double tol = 1e-12);

  const Mat& matrix() const noexcept { return M_; }
  double tolerance() const noexcept { return tol_; }

  /// All solutions of LCP(M, q) (see enumerate_small). Throws InputError on non-finite q or
  /// tol outside (0, 1e-3]. Allocation-free; `out` is overwritten.
  void enumerate(const Vec& q, SmallSolutionSet<N>& out, double tol = 1e-12) const;

 private:
  using Sup = detail::SmallPreparedSupport<N>;

  Mat M_;
  double tol_;
  std::array<Sup, kSupports> sup_;
};

extern template class SmallPreparedLcp<1>;
extern template class SmallPreparedLcp<2>;
extern template class SmallPreparedLcp<3>;
extern template class SmallPreparedLcp<4>;

}  // namespace cpkit::lcp
