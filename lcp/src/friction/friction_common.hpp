#pragma once
// Internal helpers shared by h13's friction solvers (nsgs.cpp, fb_soc.cpp, auto.cpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_problem.hpp"
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

/// The 3x3 diagonal blocks W_ii.
inline std::vector<Mat3> diagonal_blocks(const Eigen::SparseMatrix<double>& W) {
  std::vector<Mat3> b(static_cast<size_t>(W.rows() / 3), Mat3::Zero());
  for (Eigen::Index k = 0; k < W.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W, k); it; ++it)
      if (it.row() / 3 == it.col() / 3)
        b[static_cast<size_t>(it.row() / 3)](it.row() % 3, it.col() % 3) = it.value();
  return b;
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
