#pragma once
/// \file enumerate_small.hpp
/// All solutions of a tiny LCP (1 <= N <= 4) on a fixed-size, allocation-free path.
///
/// Problem: z >= 0, w = M z + q >= 0, z . w = 0 (cpkit's sign convention everywhere).
/// The solution set is the finite union of the polyhedral pieces
///   P_S = { z : z_i = 0 (i not in S), w_i = 0 (i in S), z >= 0, w >= 0 },  S subset of {0..N-1}
/// [Cottle-Pang-Stone 1992, Sec. 3.9 (the solution set of an LCP)]. Singular principal blocks are
/// normal input: the rate LCPs of the contact model [Stromberg et al. 1996, Sec. 4.2] always have
/// a singular 2x2 block, and every physical solution with dP_N = 0 is a whole ray of z.
///
/// Algorithm (docs/enumeration.md):
/// - vertices: a point z is a vertex of some piece iff it is complementary and feasible and
///   n linearly independent equations of the family {z_i = 0, w_j = 0} hold at it. Every such
///   point is the basic solution of one square subsystem: choose a row set R and a column set C of
///   equal size, set z_i = 0 for i not in C and w_r = 0 for r in R, i.e. solve M[R,C] z_C = -q_R.
///   All sum_k C(N,k)^2 = C(2N,N) pairs are tried (20 for N = 3) - these are all bases of
///   [I, -M], not only the 2^N complementary ones, which is what keeps vertices whose
///   complementary bases are all singular.
/// - rays: an extreme ray of the recession cone of a piece is the null vector of M[R,C] with
///   |C| = |R| + 1 and rank |R| (C(2N,N-1) pairs, 15 for N = 3), normalised to ||d||_inf = 1.
/// - pieces: P_S contains exactly the vertices z with z_i = 0 off S and w_i = 0 on S, and its
///   recession cone exactly the rays d with d_i = 0 off S and (M d)_i = 0 on S. A piece has
///   positive dimension iff it has two vertices or a ray; only inclusion-maximal pieces of
///   positive dimension are listed.
///
/// Tolerance (unit-free, `tol` relative; docs/enumeration.md, "Tolerance"): a value v of z_i is
/// judged against ||z||_inf, a value of w_i against W_i = |q_i| + sum_j |M_ij| |z_j| (the size of
/// the terms that make up w_i); a sign test fails clearly below -1e4 tol * scale, and w values in
/// the band between are counted in `ambiguous` (and rejected). Entries of z tiny against ||z||
/// (or in that band) are zero only when the data allow it: setting them to zero must keep the
/// piece's equations w_i = 0 (to 1e4 tol W_i) and the feasibility of the other w_i, else each one
/// is zero only when |M_ij z_j| <= tol W_i in every row, and a negative one that is not makes the
/// candidate infeasible (M = diag(1e200, 1): z_0 = -1e-200 moves w_0 by 1). A square block is
/// singular when a complete-pivoting elimination meets a pivot <= tol * max|block| (or
/// |det| <= 1e4 tol * sum |terms of det|); the vertex and ray systems of a singular piece are
/// row-equilibrated first (their rows have the units of z_i or of w_i); pivots within 1e4 x of
/// the threshold are counted as ambiguous. Two vertices are the same when they differ by
/// <= 1e4 tol ||z||_inf and the stored one satisfies the other's zero claims. All these tests are
/// invariant under q -> a q and (M, q) -> b (M, q).
/// Values double cannot represent (a non-finite z, w or scale, e.g. z = 1e320 for M = [[1e-320]],
/// q = [-1]) are never stored: they are counted in `unrepresentable` and `dropped`.
/// Sizes: N = 1, 2, 3, 4 only (the library holds the compiled enumeration for these four; any
/// other N is a compile-time error). The implementation is in lcp/src (enumerate_small.cpp and
/// its private headers), not in this header: the call is one out-of-line call per problem.
#include <Eigen/Core>
#include <array>

#include "cpkit/core/errors.hpp"  // InputError (thrown on bad input)

namespace cpkit::lcp {

/// All solutions of a tiny LCP (1 <= N <= 4) on a fixed-size, allocation-free path.
template <int N>
struct SmallSolutionSet {
  static_assert(N >= 1 && N <= 4,
                "enumerate_small / SmallPreparedLcp: only N = 1, 2, 3, 4 are compiled into "
                "cpkit_lcp");
  static constexpr int kMax = 1 << N;
  using V = Eigen::Matrix<double, N, 1>;
  struct Piece {                 ///< one complementary piece of positive dimension
    unsigned support = 0;        ///< bit i set: w_i = 0 on the piece (z_i free >= 0); clear: z_i = 0
    unsigned vertex_mask = 0;    ///< bit k set: z[k] (an extreme solution) belongs to the piece
    int num_rays = 0;            ///< extreme rays of the piece's recession cone (unbounded piece)
    std::array<V, kMax> rays;    ///< unit rays (||d||_inf = 1), d >= 0, M d >= 0, d.(M d) = 0
  };
  int num_points = 0;            ///< distinct extreme solutions (vertices of the solution set)
  std::array<V, kMax> z;         ///< the extreme solutions (w = M z + q)
  std::array<V, kMax> w;         ///< w = M z + q of each extreme solution (entries judged zero are 0)
  /// Support of each extreme solution: bit i set iff z_i > 0 (the smallest support S whose
  /// piece P_S holds the point; for a nondegenerate solution, the basic z-variables).
  std::array<unsigned, kMax> support;
  int num_pieces = 0;
  std::array<Piece, kMax> pieces;
  bool infinite = false;         ///< some piece has positive dimension
  int ambiguous = 0;             ///< sign tests too close to call (see docs/enumeration.md)
  /// Candidates (vertices, rays, pieces) that double precision cannot represent or verify: a
  /// non-finite value of z, of w = M z + q or of their scales, e.g. the solution z = 1e320 of
  /// M = [[1e-320]], q = [-1]. Such a candidate is never listed; each one is also counted in
  /// `dropped`.
  int unrepresentable = 0;
  /// Vertices or rays the lists lack: beyond the fixed capacity kMax (never observed) or not
  /// representable (see `unrepresentable`). Nonzero means the lists are incomplete and the
  /// caller must not rely on them.
  int dropped = 0;
};

/// Enumerates every extreme solution, every positive-dimensional piece (with its vertices and
/// extreme rays) and whether the solution set is infinite. `tol` is relative to the data scale
/// (see the file comment). Throws InputError on non-finite data or tol outside (0, 1e-3].
/// Allocation-free; `out` is overwritten (its counts are reset).
/// Compiled into cpkit_lcp for N = 1, 2, 3, 4 (lcp/src/enumerate_small.cpp); SmallSolutionSet
/// rejects any other N at compile time.
template <int N>
void enumerate_small(const Eigen::Matrix<double, N, N>& M, const Eigen::Matrix<double, N, 1>& q,
                     SmallSolutionSet<N>& out, double tol = 1e-12);

extern template void enumerate_small<1>(const Eigen::Matrix<double, 1, 1>&,
                                        const Eigen::Matrix<double, 1, 1>&, SmallSolutionSet<1>&,
                                        double);
extern template void enumerate_small<2>(const Eigen::Matrix<double, 2, 2>&,
                                        const Eigen::Matrix<double, 2, 1>&, SmallSolutionSet<2>&,
                                        double);
extern template void enumerate_small<3>(const Eigen::Matrix<double, 3, 3>&,
                                        const Eigen::Matrix<double, 3, 1>&, SmallSolutionSet<3>&,
                                        double);
extern template void enumerate_small<4>(const Eigen::Matrix<double, 4, 4>&,
                                        const Eigen::Matrix<double, 4, 1>&, SmallSolutionSet<4>&,
                                        double);

}  // namespace cpkit::lcp
