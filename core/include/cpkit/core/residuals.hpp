#pragma once
/// \file residuals.hpp
/// Residuals of a candidate solution, computed from the problem data only, in units that do
/// not depend on the problem's units (docs/conventions.md, "What within tolerance means").
///
/// For LCP(M, q) and a candidate z (w = M z + q recomputed), row i is judged in its own units:
///   z_ref = ||q||_inf / ||M||_max      the data's own size of z (none when q = 0 or M = 0)
///   Z     = max(||z||_inf, z_ref)      the unit of every z_i (||z||_inf without z_ref)
///   s_i   = |q_i| + ||M_i,:||_1 min(||z||_inf, z_ref)
///           the unit of w_i: what row i can err by when q_i is perturbed relative to itself and
///           z within its own size (componentwise in q, normwise in z), capped at the size row i
///           has when z has the data's own size, so that it never grows with a diverging z
///   a_i   = gamma_{n+1} ((|M| |z|)_i + |q_i|)   the worst-case rounding error of computing w_i
///           in double precision [Higham 2002, Sec. 3.1]; |w_i| <= a_i counts as 0, and a
///           larger |w_i| is reduced by a_i before it is divided by s_i
///   z+   = z projected onto its bounds (z+ = max(z, 0) for an LCP); w is judged at z+, and
///          the distance of z from z+ counts as a violation of its own, ||z - z+||_inf / Z
///   zn_i = z_i / Z,  wn_i = (w_i(z+) reduced by a_i) / s_i   (units taken at z+)
///   r_i  = violation of the complementarity rule by (zn_i, wn_i): |min(zn_i, wn_i)| for an LCP
///   natural = max_i r_i                 the one acceptance number
/// Every quantity is invariant under q -> a q (z -> a z) and (M, q) -> b (M, q) (z unchanged),
/// for all a, b > 0 (exactly when a and b are powers of two, up to rounding otherwise).
/// finalize(), SolutionSet::contains() and cross_verify() all use this one definition.
/// - A diverging iterate (|z| -> inf with min(z, w) = O(1)) is never accepted: s_i is capped.
/// - z = 0 is never accepted when q has a negative entry: at z = 0, s_i = |q_i| and wn_i = -1.
/// - One large row excuses nothing in another: every unit is per row.
#include <Eigen/Core>

#include "cpkit/core/problem.hpp"

namespace cpkit {

struct Residuals {
  double natural = 0;         ///< unit-free residual max_i r_i (the test; rounding deducted)
  double natural_abs = 0;     ///< ||min(z, w)||_inf in the problem's units (information only)
  double complementarity = 0; ///< max_i |z_i w_i|
  double min_z = 0;           ///< min_i z_i (negative = infeasible); for MCPs min distance to box
  double min_w = 0;           ///< min_i w_i (negative = infeasible); for MCPs the sign error
  Eigen::Index worst_index = -1;  ///< index attaining `natural` (-1 when n = 0)
  double scale = 0;           ///< largest w-unit s_i (units of w; information only)
  double z_scale = 0;         ///< the z-unit Z (units of z; information only)
  double rounding = 0;        ///< largest per-row rounding allowance a_i (unit-free)
  bool finite = true;         ///< false when z, w or a scale is NaN/Inf (never acceptable)
};

/// A candidate in the units of the acceptance test, row by row: zn_i = z_i / Z, wn_i = w_i / s_i
/// with w taken at the projection z+ (rounding allowance deducted), and the distances of z
/// itself to the bounds (z_i - l_i) / Z and
/// (u_i - z_i) / Z (+inf for infinite bounds; an LCP has l = 0, u = +inf).
struct UnitFreePoint {
  Vec z, w, to_lower, to_upper;
  bool finite = true;  ///< false when some value or unit is NaN/Inf
};

/// Violation of one row of the box rule by unit-free values: the largest bound violation, or
/// else the smallest violation among "z at l and w >= 0", "z at u and w <= 0", "w = 0".
/// Zero exactly when the row holds; |min(zn, wn)| for an LCP row (to_lower = zn, to_upper = inf).
double row_violation(double wn, double to_lower, double to_upper) noexcept;

/// The data's part of the units, computed once per problem.
struct DataSizes {
  double q_norm = 0;  ///< ||q||_inf
  double m_max = 0;   ///< ||M||_max
  Vec row_sums;       ///< ||M_i,:||_1
};
DataSizes data_sizes(const LcpProblem& p);
/// Z of the header comment for a candidate with ||z||_inf = z_norm.
double z_unit(const DataSizes& d, double z_norm);
/// s of the header comment for a candidate with ||z||_inf = z_norm; allocation-free when s
/// already has size n.
void w_units(const DataSizes& d, const Vec& q, double z_norm, Vec& s);
/// |M| |z| (without q).
Vec abs_product(const LcpProblem& p, const Vec& z);
/// max_i r_i from raw values z, w = M z + q, R = |M||z| + |q|, s (w_units), Z (z_unit), bounds
/// (nullptr: 0 and +inf, the LCP). The one acceptance number; allocation-free, for solvers'
/// stopping tests. Non-finite inputs give +inf. `worst` receives the index of the maximum.
double unit_free_residual(const Vec& z, const Vec& w, const Vec& R, const Vec& s, double Z,
                          const Vec* lower, const Vec* upper, Eigen::Index* worst = nullptr);

/// max_i of the distance of z_i outside [l_i, u_i], divided by Z (nullptr bounds: 0, +inf).
double bound_violation(const Vec& z, double Z, const Vec* lower, const Vec* upper,
                       Eigen::Index* worst = nullptr);

/// z, w of an LCP candidate in unit-free form; w = M z + q is returned in `w`.
UnitFreePoint unit_free_point(const LcpProblem& p, const Vec& z, Vec& w);
/// The same for a box LCP (bounds divided by Z as z is).
UnitFreePoint unit_free_point(const BoxLcpProblem& p, const Vec& z, Vec& w);

/// LCP residuals of z; also returns w = M z + q computed from the data.
Residuals lcp_residuals(const LcpProblem& p, const Vec& z, Vec& w);
/// The largest n small_lcp_natural() takes.
constexpr int kSmallLcpMax = 4;
/// lcp_residuals(p, z, w).natural for a dense problem of size 1 <= n <= kSmallLcpMax given as
/// raw arrays (M column-major n x n, q, z; w receives M z + q), without allocating: the C API's
/// per-call path. The same number bit for bit (tests/core/test_residuals.cpp); +inf for another n.
double small_lcp_natural(int n, const double* M, const double* q, const double* z, double* w);
/// Box-LCP residuals (box rule per row).
Residuals box_lcp_residuals(const BoxLcpProblem& p, const Vec& z, Vec& w);
/// MCP residuals with F evaluated at x (F given). The units come from the linearisation
/// F(y) ~ J y + (F(x) - J x) at x, i.e. the LCP rule with M = J and q = F(x) - J x; J from the
/// problem's Jacobian callback, else forward differences (when those leave F's domain, the
/// units fall back to |F_i(x)| + ||F(x)||_inf). For lcp_as_mcp() this is exactly the LCP test.
Residuals mcp_residuals(const McpProblem& p, const Vec& x, const Vec& F);

}  // namespace cpkit
