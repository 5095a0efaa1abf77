#pragma once
/// \file enumerate.hpp
/// All solutions of a dense LCP: z >= 0, w = M z + q >= 0, z . w = 0 (cpkit's sign convention).
///
/// The solution set is the finite union of the pieces
///   P_S = { z : z_i = 0 (i not in S), w_i = 0 (i in S), z >= 0, w >= 0 }
/// [Cottle-Pang-Stone 1992, Sec. 3.9]. enumerate_all() lists every extreme solution (vertex of a
/// piece) once, with z, w and a complementary basis; every piece of positive dimension with its
/// vertices and extreme rays; whether the set is infinite; and whether the enumeration is
/// complete. Singular principal blocks are normal input (docs/enumeration.md).
///
/// Budget: the time limit (default 60 s) holds in every phase (polytope traversal, search,
/// singular pieces, piece collection, directions); when it stops any of them the result has
/// complete = false with a message saying so, never a silent partial answer. The general engine
/// takes n <= EnumerationOptions::max_size (default and at most kMaxEnumerationSize = 64, its
/// supports are 64-bit masks); a larger problem that is not a bimatrix game gets
/// complete = false with a message. Bimatrix games (the structured path) have no size limit:
/// they are bounded by the time limit and a memory bound (docs/enumeration.md).
///
/// Units: every sign and zero test is relative to the size of the terms it compares (unit-free);
/// the decisions are made on (M, q) scaled by powers of two to max entries in [0.5, 1), so the
/// same problem in other units (q -> a q, (M, q) -> b (M, q)) gives the same sets, scaled.
/// Every listed solution is finite and re-checked from the original data; a solution double
/// precision cannot represent (e.g. z = 1e320 for M = [[1e-320]], q = [-1]) is never listed:
/// it is counted in SolutionSet::unrepresentable and leaves complete = false
/// (docs/enumeration.md, "Tolerance" and "Values double cannot represent").
///
/// Algorithm: n <= 4 uses the fixed-size path enumerate_small(); larger n a depth-first search
/// over the complementary bases with principal pivot updates of one tableau per depth (no
/// factorization per basis), 2x2 block pivots where a diagonal pivot vanishes, and pruning of
/// every subtree in which some tableau row proves infeasibility (q'_r < 0 with no free column
/// able to raise it). Candidates are re-solved from the original data before they are accepted.
/// Pieces with a singular principal block are enumerated in the null space of the block.
/// Block-bipartite LCPs (bimatrix games: zero diagonal blocks, q > 0, negative off-diagonal
/// blocks) first try vertex enumeration of the two players' polytopes (lexicographic simplex
/// pivots) and matching of complementary labels [von Stengel 2002, Handbook of Game Theory 3,
/// Ch. 45]; the general engine runs whenever that path cannot decide (docs/enumeration.md).
#include <string>
#include <vector>

#include "cpkit/core/problem.hpp"

namespace cpkit::lcp {

/// Largest n of the general engine (its supports are 64-bit masks). The structured path for
/// bimatrix games has no such ceiling.
inline constexpr int kMaxEnumerationSize = 64;

struct EnumerationOptions {
  /// Relative tolerance of the sign and zero tests (docs/enumeration.md, "Tolerance").
  double tol = 1e-12;
  /// Largest n the general engine attempts (1 <= max_size <= kMaxEnumerationSize); a larger
  /// problem that the structured path cannot answer gets complete = false and a message.
  int max_size = kMaxEnumerationSize;
  /// Wall-clock limit in seconds, honoured by every phase; when hit the result has
  /// complete = false and a message. The default bounds a run on a hostile input (a complete
  /// enumeration may need all 2^n bases).
  double time_limit_s = 60;
  /// Largest null-space dimension of a singular piece that is enumerated; a larger one leaves
  /// complete = false (its vertices need C(n, m) subsystems).
  int max_piece_dim = 3;
  /// Use the structured path for block-bipartite LCPs (bimatrix games: M = [[0, M12], [M21, 0]],
  /// q > 0, M12 < 0, M21 < 0 entrywise): vertex enumeration of the two players' polytopes and
  /// matching of complementary labels. It is taken only when both polytopes are nondegenerate
  /// (otherwise the general engine runs); false forces the general engine (cross-checks).
  bool use_structure = true;
  /// Empty when usable; otherwise names the bad field.
  std::string validate() const;
};

/// One extreme solution (a vertex of a piece of the solution set).
struct ExtremeSolution {
  Vec z;                   ///< z >= 0
  Vec w;                   ///< w = M z + q >= 0, recomputed from the data (entries judged zero are 0)
  /// A complementary basis: entry i is i when z_i is basic, ~i (= -i-1) when w_i is basic
  /// (SolveResult::basis convention). For a vertex whose complementary matrices are all
  /// singular, the basis of its smallest piece {i : z_i > 0}.
  std::vector<int> basis;
};

/// A piece of positive dimension: P_S = conv(vertices) + cone(rays).
struct SolutionPiece {
  std::vector<int> support;   ///< S: indices with w_i = 0 (z_i free >= 0); z_i = 0 elsewhere
  std::vector<int> vertices;  ///< indices into SolutionSet::solutions
  std::vector<Vec> rays;      ///< extreme rays of the recession cone, ||d||_inf = 1
};

struct SolutionSet {
  std::vector<ExtremeSolution> solutions;  ///< every extreme solution, deduplicated
  std::vector<SolutionPiece> pieces;       ///< inclusion-maximal pieces of positive dimension
  /// Directions along which the set continues: every ray of a piece, and the normalised
  /// difference of every pair of vertices of a piece (its edges; for pieces with more than two
  /// vertices some of these pairs cross the piece's interior).
  std::vector<Vec> directions;
  bool complete = false;   ///< every complementary basis was accounted for
  bool infinite = false;   ///< some piece has positive dimension
  int ambiguous = 0;       ///< sign or rank tests too close to call (docs/enumeration.md)
  /// Candidates double precision cannot represent or verify (a non-finite z, w = M z + q or
  /// scale, or a solution that fails the final check from the data after scaling back, e.g.
  /// z = 1e320): never listed; nonzero implies complete = false with a message.
  int unrepresentable = 0;
  long long nodes = 0;     ///< search-tree nodes visited (0 on the small path; polytope
                           ///< vertices visited on the block-bipartite path)
  bool structured = false; ///< answered by the block-bipartite (bimatrix-game) path
  long long leaves = 0;    ///< complementary bases reached (not pruned)
  double seconds = 0;
  std::string message;     ///< why complete is false, if it is
  Mat M;                   ///< the data (for contains())
  Vec q;
  double tol = 1e-12;

  /// "inf" semantics: number of extreme solutions; see `infinite` for continua.
  int count() const { return static_cast<int>(solutions.size()); }
  /// True when z is a solution within `tol` in the units of finalize()'s acceptance test
  /// (residuals.hpp: z_i / ||z||_inf, w_i / s_i, rounding allowance deducted) that this set
  /// accounts for: feasible within tol, and either within relative distance
  /// tol max(||z||, ||e.z||) of an extreme solution e, or matching the complementarity pattern
  /// of a listed basis or piece (w_i ~ 0 where z_i is free, z_i ~ 0 elsewhere). Invariant under
  /// q -> a q and (M, q) -> b (M, q). A verified solution that is not contained in a complete
  /// set proves the set incomplete.
  bool contains(const Vec& z, double tol = 1e-8) const;
};

/// Enumerates the whole solution set of a dense (or sparse, densified) LCP. Throws InputError
/// on invalid problems or options; budgets (time, memory, max_size) end with complete = false.
SolutionSet enumerate_all(const LcpProblem& problem, const EnumerationOptions& options = {});

}  // namespace cpkit::lcp
