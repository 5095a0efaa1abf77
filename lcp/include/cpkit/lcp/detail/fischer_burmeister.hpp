#pragma once
// Internal (not part of the documented API): the scalar and second-order-cone Fischer-Burmeister
// functions with an element of their generalized Jacobians (docs/contact_3d.md, (3D.28)-(3D.29)),
// shared by the one-point and N-point 3-D step solvers (rate_problem/src/step/) and the
// friction solver fb-soc (lcp/src/friction/fb_soc.cpp). Lives in lcp so that both can use it.
#include <Eigen/Core>

#include <cmath>

namespace cpkit::lcp::detail {

const double kFbZero = 1.0 - 1.0 / std::sqrt(2.0);  // FB derivative element at (0, 0)

/// Scalar FB: fb(a, b) = a + b - sqrt(a^2 + b^2), with (da, db) an element of its generalized
/// gradient ((1 - 1/sqrt2, 1 - 1/sqrt2) at the kink (0, 0)).
inline double fb_scalar(double a, double b, double& da, double& db) noexcept {
  const double r = std::hypot(a, b);
  if (r == 0) {
    da = db = kFbZero;
    return 0;
  }
  da = 1 - a / r;
  db = 1 - b / r;
  // a, b > 0: the cancellation-free form 2ab / (a + b + r)
  if (a > 0 && b > 0) return 2 * a * b / (a + b + r);
  return a + b - r;
}

/// SOC FB phi(x, y) = x + y - sqrt(x o x + y o y) on K = {(x0, xb) : x0 >= |xb|} in R^3, with an
/// element (Jx, Jy) of its generalized Jacobian. Spectral decomposition of w = x o x + y o y:
/// lambda_{1,2} = w0 -+ |wb|, u_{1,2} = (1, -+ wh) / 2, sqrt(w) = s1 u1 + s2 u2. Loewner's
/// formula for the derivative of sqrt (Fukushima, Luo & Tseng 2001) with dw = 2 L_x dx + 2 L_y dy
/// and e_{1,2} = (1, -+ wh), v a unit vector orthogonal to wh:
///   Jx = I - e1 (x o e1)^T / (2 s1) - e2 (x o e2)^T / (2 s2) - 2/(s1 + s2) (0, v)(L_x (0, v))^T.
/// Since lambda1 = |xb - x0 wh|^2 + |yb - y0 wh|^2 and x o e1 = (-d_x . wh, d_x) with
/// d_x = xb - x0 wh, the first term is bounded (|d_x| <= s1). On bd K (lambda1 = 0, w != 0) the
/// limit along (xb, yb) + t (rho_x v, rho_y v), rho_x^2 + rho_y^2 = 1, is taken with
/// (rho_x, rho_y) = (x0, y0) / |(x0, y0)|: x o e1 / (2 s1) -> (0, rho_x v) / 2. At w = 0 the
/// Jacobian at the point (e, e) (e = (1, 0, 0); phi is positively homogeneous, so it is a limit
/// of Jacobians at t (e, e), t -> 0): Jx = Jy = (1 - 1/sqrt2) I.
inline void fb_soc(const Eigen::Vector3d& x, const Eigen::Vector3d& y, Eigen::Vector3d& phi,
            Eigen::Matrix3d& Jx, Eigen::Matrix3d& Jy) noexcept {
  const Eigen::Vector2d xb = x.tail<2>(), yb = y.tail<2>();
  const double w0 = x.squaredNorm() + y.squaredNorm();
  if (w0 == 0) {
    phi.setZero();
    Jx = kFbZero * Eigen::Matrix3d::Identity();
    Jy = Jx;
    return;
  }
  const Eigen::Vector2d wb = 2 * (x(0) * xb + y(0) * yb);
  const double nw = wb.norm();
  const Eigen::Vector2d wh = nw > 0 ? Eigen::Vector2d(wb / nw) : Eigen::Vector2d(1, 0);
  const Eigen::Vector2d v(-wh(1), wh(0));
  const Eigen::Vector2d dx = xb - x(0) * wh, dy = yb - y(0) * wh;
  const double lam1 = dx.squaredNorm() + dy.squaredNorm();  // = w0 - |wb|, cancellation-free
  const double lam2 = w0 + nw;
  const double s1 = std::sqrt(lam1), s2 = std::sqrt(lam2);
  // sqrt(w) = s1 u1 + s2 u2
  Eigen::Vector3d sq;
  sq(0) = 0.5 * (s1 + s2);
  sq.tail<2>() = 0.5 * (s2 - s1) * wh;
  phi = x + y - sq;
  const Eigen::Vector3d e1(1, -wh(0), -wh(1)), e2(1, wh(0), wh(1));
  const Eigen::Vector3d V(0, v(0), v(1));
  const double a = 1 / (s1 + s2);
  auto one = [&](const Eigen::Vector3d& z, const Eigen::Vector2d& d, double rho,
                 Eigen::Matrix3d& J) {
    Eigen::Vector3d r1;  // (z o e1) f'(lambda1) = (z o e1) / (2 s1)
    if (s1 > 1e-150 * s2) {
      r1(0) = -d.dot(wh) / (2 * s1);
      r1.tail<2>() = d / (2 * s1);
    } else {
      r1(0) = 0;
      r1.tail<2>() = 0.5 * rho * v;
    }
    Eigen::Vector3d ze2;  // z o e2
    ze2(0) = z(0) + z.tail<2>().dot(wh);
    ze2.tail<2>() = z.tail<2>() + z(0) * wh;
    Eigen::Vector3d LzV;  // L_z (0, v)
    LzV(0) = z.tail<2>().dot(v);
    LzV.tail<2>() = z(0) * v;
    J = Eigen::Matrix3d::Identity() - e1 * r1.transpose() - e2 * ze2.transpose() / (2 * s2) -
        2 * a * V * LzV.transpose();
  };
  const double r = std::hypot(x(0), y(0));
  const double rho_x = r > 0 ? x(0) / r : 1 / std::sqrt(2.0);
  const double rho_y = r > 0 ? y(0) / r : 1 / std::sqrt(2.0);
  one(x, dx, rho_x, Jx);
  one(y, dy, rho_y, Jy);
}

/// The power of two 2^e with 2^e <= v < 2^(e+1) (v > 0 finite), else 1: exact scale factors
/// for the solvers' unit normalisation.
inline double pow2_below(double v) {
  if (!(v > 0) || !std::isfinite(v)) return 1.0;
  int e;
  std::frexp(v, &e);
  return std::ldexp(1.0, e - 1);
}

}  // namespace cpkit::lcp::detail
