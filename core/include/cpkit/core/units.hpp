#pragma once
/// \file units.hpp
/// A change of units that brings an LCP to unit size, for iterative solvers whose internal
/// tolerances and merit functions mix z and w (FB Newton, the MPCC NLPs).
///
/// With z = z_unit * z~ and w = w_unit * w~, LCP(M, q) becomes LCP(M~, q~) with
///   M~ = M z_unit / w_unit,   q~ = q / w_unit,
/// w_unit ~ ||q||_inf and z_unit ~ ||q||_inf / ||M||_max (the data's own sizes of w and z), both
/// powers of two so that the change is exact (no rounding) and a problem given in other units
/// (q -> a q, or (M, q) -> b (M, q)) is solved by the same iterations on the same scaled data when
/// a and b are powers of two, and on data equal up to rounding otherwise.
/// Solutions map back as z = z_unit z~; certificates y are unchanged (positive scaling keeps
/// the signs of M^T y and q^T y).
#include "cpkit/core/problem.hpp"

namespace cpkit {

struct LcpUnits {
  int z_exponent = 0;  ///< z_unit = 2^z_exponent
  int w_exponent = 0;  ///< w_unit = 2^w_exponent
  /// Optional per-variable refinements (equilibrated_units): z_j's unit is
  /// 2^(z_exponent + z_columns[j]), w_i's unit 2^(w_exponent + w_rows[i]). Empty: uniform.
  Eigen::VectorXi z_columns, w_rows;
};

/// The units of the header comment. q = 0: w_unit from ||M||_max and z_unit = 1 (the solution
/// set is a cone; its size is arbitrary). M = 0 or q and M both 0: unit 1.
LcpUnits natural_units(const LcpProblem& p);
/// natural_units() refined by one pass of power-of-two column and row equilibration
/// [Ruiz 2001]: columns of M~ and then rows of [M~ q~] get largest entries in [1, 2). For badly
/// scaled data (M = diag(1e11, 1)) it brings every solution entry near 1 where the uniform
/// units cannot; still exact, and invariant under uniform power-of-two changes of units.
LcpUnits equilibrated_units(const LcpProblem& p);
/// LCP(M~, q~) in those units (dense or sparse as given; name and note kept).
LcpProblem to_units(const LcpProblem& p, const LcpUnits& u);
/// Box LCP in those units (bounds scale as z).
BoxLcpProblem to_units(const BoxLcpProblem& p, const LcpUnits& u);
/// z = z_unit z~ (entries that overflow become inf: finalize() then rejects them).
Vec z_from_units(const Vec& z_scaled, const LcpUnits& u);
/// z~ = z / z_unit (e.g. a warm start).
Vec z_to_units(const Vec& z, const LcpUnits& u);

}  // namespace cpkit
