#pragma once
// Small helpers shared by h16's friction solvers (prox, faceted Lemke, Ipopt, solutions).
#include <Eigen/SparseCore>
#include <cstdio>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/friction_verdict.hpp"

namespace cpkit::lcp::friction::helpers {

inline void check_problem(const FrictionContactProblem& p) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
}

/// The 3x3 diagonal blocks W_ii.
inline std::vector<Mat3> diagonal_blocks(const Eigen::SparseMatrix<double>& W) {
  const Eigen::Index nc = W.cols() / 3;
  std::vector<Mat3> D(static_cast<std::size_t>(nc), Mat3::Zero());
  for (Eigen::Index c = 0; c < W.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W, c); it; ++it)
      if (it.row() / 3 == c / 3) D[c / 3](it.row() % 3, c % 3) = it.value();
  return D;
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

inline std::string short_number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

}  // namespace cpkit::lcp::friction::helpers
