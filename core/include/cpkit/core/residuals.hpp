#pragma once
/// \file residuals.hpp
/// Residuals of a candidate solution, computed from the problem data only.
///
/// Scale and rounding allowance (documented tolerance convention, docs/conventions.md):
///   scale    = 1 + ||q||_inf                                   (the data's own size)
///   natural  = ||min(z, w)||_inf / scale                       (the reported residual)
///   rounding = 2 n eps max_i ( |M| |z| + |q| )_i / scale        (bound on the error of
///              computing w = M z + q in double precision)
/// finalize() accepts  natural <= tol + rounding. The allowance lets a genuine solution with a
/// huge z verify, while a diverging iterate (min(z, w) = O(1) as |z| grows) is rejected until
/// |M||z| reaches ~1 / (n eps) times that error, i.e. until z itself is meaningless in doubles.
#include <Eigen/Core>

#include "cpkit/core/problem.hpp"

namespace cpkit {

struct Residuals {
  double natural = 0;        ///< scaled natural residual ||min(z, w)||_inf / scale (the test)
  double natural_abs = 0;    ///< unscaled ||min(z, w)||_inf
  double complementarity = 0;///< max_i |z_i w_i|
  double min_z = 0;          ///< min_i z_i (negative = infeasible); for MCPs min distance to box
  double min_w = 0;          ///< min_i w_i (negative = infeasible); for MCPs the sign error
  Eigen::Index worst_index = -1;  ///< index attaining natural_abs (-1 when n = 0)
  double scale = 1;          ///< the scale used (1 + ||q||_inf; MCP: 1 + ||F(x)||_inf)
  double rounding = 0;       ///< rounding allowance of w, on the same scale as `natural`
};

/// LCP residuals of z; also returns w = M z + q recomputed from the data.
Residuals lcp_residuals(const LcpProblem& p, const Vec& z, Vec& w);
/// Box-LCP residuals: natural = ||z - mid(l, u, z - w)||_inf / scale.
Residuals box_lcp_residuals(const BoxLcpProblem& p, const Vec& z, Vec& w);
/// MCP residuals with F evaluated at x (F given). scale = 1 + ||F(x)||_inf, rounding = 0
/// (F's own rounding is unknown).
Residuals mcp_residuals(const McpProblem& p, const Vec& x, const Vec& F);

}  // namespace cpkit
