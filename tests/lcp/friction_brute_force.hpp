#pragma once
// Every solution of ONE 3-D frictional contact (u = W r + q, W 3 x 3 symmetric positive definite)
// by brute force, independent of cpkit's solvers and verdict: each state of the law is written
// out and solved by closed forms or a scan.
//   separated  r = 0, needs q_N >= 0;
//   stick      u = 0: r = -W^-1 q, needs r in K_mu;
//   slip       r = r_N d(phi), d = (1, -mu cos phi, -mu sin phi), u_N = 0 gives
//              r_N = -q_N / (W d)_N > 0, and u_T = r_N (W d)_T + q_T must be lambda (cos phi,
//              sin phi) with lambda > 0: the roots of g(phi) = u_T x (cos phi, sin phi),
//              found by scanning phi over 7200 points and bisecting each sign change.
#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace cpkit::test {

inline std::vector<Eigen::Vector3d> brute_force_one_contact(const Eigen::Matrix3d& W,
                                                            const Eigen::Vector3d& q, double mu) {
  std::vector<Eigen::Vector3d> out;
  auto add = [&](const Eigen::Vector3d& r) {
    for (const auto& s : out)
      if ((s - r).norm() <= 1e-8 * std::max(s.norm(), r.norm())) return;
    out.push_back(r);
  };
  if (q[0] >= 0) add(Eigen::Vector3d::Zero());
  const Eigen::Vector3d stick = -W.ldlt().solve(q);
  if (stick[0] > 0 && stick.tail<2>().norm() <= mu * stick[0]) add(stick);
  if (mu > 0) {
    struct Slip {
      double g, rn, lambda;
      Eigen::Vector3d r;
    };
    auto at = [&](double phi) {
      const Eigen::Vector3d d(1, -mu * std::cos(phi), -mu * std::sin(phi));
      const Eigen::Vector3d Wd = W * d;
      Slip s;
      s.rn = -q[0] / Wd[0];
      s.r = s.rn * d;
      const Eigen::Vector2d uT = s.rn * Wd.tail<2>() + q.tail<2>();
      s.g = uT[0] * std::sin(phi) - uT[1] * std::cos(phi);
      s.lambda = uT[0] * std::cos(phi) + uT[1] * std::sin(phi);
      return s;
    };
    const int n = 7200;
    const double step = 2 * M_PI / n;
    Slip prev = at(0);
    for (int k = 1; k <= n; ++k) {
      double a = (k - 1) * step, b = k * step;
      const Slip cur = at(b);
      if (std::isfinite(prev.g) && std::isfinite(cur.g) && (prev.g <= 0) != (cur.g <= 0)) {
        double ga = prev.g;
        for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
          const double m = 0.5 * (a + b);
          const double gm = at(m).g;
          if ((gm <= 0) == (ga <= 0)) {
            a = m;
            ga = gm;
          } else {
            b = m;
          }
        }
        const Slip s = at(0.5 * (a + b));
        // A root of g, not a pole of r_N, with a force and a sliding velocity along phi.
        const Eigen::Vector3d u = W * s.r + q;
        if (s.rn > 0 && s.lambda > 0 && std::isfinite(s.rn) &&
            std::abs(u[0]) <= 1e-9 * (W.cwiseAbs() * s.r.cwiseAbs() + q.cwiseAbs())[0] + 1e-300 &&
            std::abs(s.g) <= 1e-8 * std::abs(s.lambda))
          add(s.r);
      }
      prev = cur;
    }
  }
  return out;
}

}  // namespace cpkit::test
