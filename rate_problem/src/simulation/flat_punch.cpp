#include "cpkit/rate_problem/simulation/flat_punch.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

ContactSystem flat_punch_system(const FlatPunch& p) {
  if (p.n_points < 2) throw InputError("flat punch: n_points must be >= 2");
  if (!(p.width > 0) || !std::isfinite(p.width)) throw InputError("flat punch: width must be > 0");
  if (!(p.modulus > 0) || !std::isfinite(p.modulus))
    throw InputError("flat punch: modulus must be > 0");
  ContactParameters cp;
  static_cast<InterfaceParameters&>(cp) = p;
  throw_if_invalid(cp.validate(), "flat punch");
  const int N = p.n_points;
  const double h = p.width / N, c = 2 / (std::acos(-1.0) * p.modulus);
  const double L0 = std::log(p.width) + 2;
  Eigen::MatrixXd C(N, N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      C(i, j) = i == j ? c * (L0 - std::log(h / 2) + 1) : c * (L0 - std::log(std::abs(i - j) * h));
  Eigen::LLT<Eigen::MatrixXd> llt(C);
  if (llt.info() != Eigen::Success)
    throw InputError("flat punch: the strip compliance is not positive definite");
  // The stiffness K = C^-1 by solving C K = I with the Cholesky factors.
  const Eigen::MatrixXd K = llt.solve(Eigen::MatrixXd::Identity(N, N));
  ContactSystem s;
  s.name = "flat punch, " + std::to_string(N) + " points";
  s.A = Eigen::MatrixXd::Zero(2 * N, 2 * N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const double k = 0.5 * (K(i, j) + K(j, i));
      s.A(2 * i, 2 * j) = k;
      s.A(2 * i + 1, 2 * j + 1) = k;
    }
  const Eigen::VectorXd rigid = K * Eigen::VectorXd::Ones(N);
  Eigen::VectorXd e1 = Eigen::VectorXd::Zero(2 * N), e2 = Eigen::VectorXd::Zero(2 * N);
  for (int i = 0; i < N; ++i) {
    e1[2 * i] = rigid[i] / rigid.sum();
    e2[2 * i + 1] = 1.0 / N;
  }
  s.pattern1 = e1;
  s.pattern2 = e2;
  for (int i = 0; i < N; ++i) {
    SystemPoint q;
    static_cast<InterfaceParameters&>(q) = p;
    q.state.label = StateLabel::kB;
    s.points.push_back(q);
  }
  return s;
}

}  // namespace cpkit::rate
