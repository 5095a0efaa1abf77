#pragma once
// Test helper (not a test): an independent check of a frictional contact solution, written
// without cpkit's cone code: u = W r + q recomputed here, then per contact the three conditions
// of De Saxce's form directly (r in K_mu, u_hat in K*_mu, r . u_hat = 0), each relative to the
// contact's own sizes. Returns the largest violation.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

namespace cpkit::test {

inline double friction_violation(const Eigen::SparseMatrix<double>& W, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& mu, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = Eigen::MatrixXd(W) * r + q;  // dense product: a different route
  const double r_size = std::max(r.lpNorm<Eigen::Infinity>(), 1e-300);
  double worst = 0;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    const double rN = r[3 * i], rT = std::sqrt(r[3 * i + 1] * r[3 * i + 1] + r[3 * i + 2] * r[3 * i + 2]);
    const double uN = u[3 * i], uT = std::sqrt(u[3 * i + 1] * u[3 * i + 1] + u[3 * i + 2] * u[3 * i + 2]);
    const double m = mu[i];
    const double u_size = std::max({q.segment(3 * i, 3).norm(),
                                    Eigen::MatrixXd(W).middleRows(3 * i, 3).cwiseAbs().maxCoeff() * r_size, 1e-300});
    const double hatN = uN + m * uT;
    double v = std::max(0.0, -rN) / r_size;                        // r_N >= 0
    v = std::max(v, std::max(0.0, rT - m * rN) / r_size);          // |r_T| <= mu r_N
    v = std::max(v, std::max(0.0, -uN) / u_size);                  // u_hat in K*: u_N >= 0
    const double dot = rN * hatN + r[3 * i + 1] * u[3 * i + 1] + r[3 * i + 2] * u[3 * i + 2];
    v = std::max(v, std::abs(dot) / (r_size * u_size));            // r . u_hat = 0
    // Signorini on the normal: r_N u_N = 0
    v = std::max(v, std::abs(rN * uN) / (r_size * u_size));
    // Coulomb: when sliding (u_T != 0), r_T = -mu r_N u_T / |u_T|
    if (uT > 1e-6 * u_size)
      for (int j = 1; j < 3; ++j)
        v = std::max(v, std::abs(r[3 * i + j] + m * rN * u[3 * i + j] / uT) / r_size);
    worst = std::max(worst, v);
  }
  return worst;
}

}  // namespace cpkit::test
