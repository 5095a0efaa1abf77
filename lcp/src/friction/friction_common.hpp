#pragma once
// Internal helpers of the friction solvers (lcp/src/friction/*.cpp): input checks, W's blocks and
// size, the registry adapter.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"

namespace cpkit::lcp::friction::detail {

/// Throws InputError for an invalid problem, options or warm start (size 3 n_c, finite).
inline void check_input(const FrictionContactProblem& p, const CommonOptions& o,
                        const Eigen::VectorXd& r0) {
  const std::string ctx = "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'");
  throw_if_invalid(p.validate(), ctx);
  throw_if_invalid(o.validate(), "solver options");
  if (r0.size() != 0 && (r0.size() != p.q.size() || !r0.allFinite()))
    throw InputError("warm start r0 must have " + std::to_string(p.q.size()) +
                     " finite entries (3 per contact), got " + std::to_string(r0.size()));
}

/// Throws InputError for an invalid problem.
inline void check_problem(const FrictionContactProblem& p) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
}

/// The 3x3 diagonal blocks W_ii.
inline std::vector<Mat3> diagonal_blocks(const Eigen::SparseMatrix<double>& W) {
  std::vector<Mat3> b(static_cast<size_t>(W.rows() / 3), Mat3::Zero());
  for (Eigen::Index k = 0; k < W.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W, k); it; ++it)
      if (it.row() / 3 == it.col() / 3)
        b[static_cast<size_t>(it.row() / 3)](it.row() % 3, it.col() % 3) = it.value();
  return b;
}

/// W's own size: largest |W_kk|, else ||W||_max, else 1 (W = 0).
inline double w_scale(const Eigen::SparseMatrix<double>& W, const FrictionUnits& units) {
  double s = 0;
  for (Eigen::Index k = 0; k < W.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W, k); it; ++it)
      if (it.row() == it.col()) s = std::max(s, std::abs(it.value()));
  if (!(s > 0)) s = units.w_max;
  return s > 0 ? s : 1.0;
}

/// u += W(:, c0..c0+2) d, allocation-free.
inline void add_columns(const Eigen::SparseMatrix<double>& W, Eigen::Index c0, const Vec3& d,
                        Eigen::VectorXd& u) {
  for (int j = 0; j < 3; ++j) {
    if (d[j] == 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(W, c0 + j); it; ++it)
      u[it.row()] += it.value() * d[j];
  }
}

/// The registry's solve_fc for a solver whose options are {common, ...}: the defaults with the
/// caller's CommonOptions (one adapter instead of one lambda per solver).
template <class Options, class Solve>
FrictionSolveFn with_common_options(Solve solve) {
  return [solve](const FrictionContactProblem& p, const CommonOptions& c) {
    Options o;
    o.common = c;
    return solve(p, o);
  };
}

}  // namespace cpkit::lcp::friction::detail
