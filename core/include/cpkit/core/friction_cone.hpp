#pragma once
/// \file friction_cone.hpp
/// The closed forms of one contact of a 3-D frictional contact problem (friction_problem.hpp),
/// written once for the verdict and the solvers. Vectors are (normal, tangent 1, tangent 2).
///   K_mu  = {x : ||x_T|| <= mu x_N}                      (the Coulomb cone, r lives there)
///   K*_mu = K_{1/mu} = {y : mu ||y_T|| <= y_N}          (its dual cone, u_hat lives there)
#include <Eigen/Core>
#include <cmath>

namespace cpkit {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Euclidean projection onto K_mu (mu >= 0; mu = 0 is the ray {x_T = 0, x_N >= 0}):
/// x itself when in K_mu, 0 when in the polar cone -K*_mu, else the nearest point of the
/// boundary, ((x_N + mu |x_T|) / (1 + mu^2)) (1, mu x_T / |x_T|).
inline Vec3 project_on_cone(const Vec3& x, double mu) {
  const double nt = std::hypot(x[1], x[2]);
  if (mu * nt <= -x[0]) return Vec3::Zero();
  if (nt <= mu * x[0]) return x;
  if (mu <= 1) {
    const double n = (x[0] + mu * nt) / (1 + mu * mu);
    return Vec3(n, mu * n * x[1] / nt, mu * n * x[2] / nt);
  }
  // The same point written with t = 1/mu, so that a huge mu (1e13 models "no slip"; mu^2
  // overflows beyond 1e154) neither overflows nor loses the normal part.
  const double t = 1 / mu, tangential = (t * x[0] + nt) / (1 + t * t);  // = mu n
  return Vec3(tangential * t, tangential * x[1] / nt, tangential * x[2] / nt);
}

/// De Saxce's modified velocity u_hat = u + (mu |u_T|, 0, 0).
inline Vec3 de_saxce(const Vec3& u, double mu) {
  return Vec3(u[0] + mu * std::hypot(u[1], u[2]), u[1], u[2]);
}

/// The natural map of one contact, r - P_K(r - u_hat): zero exactly when
/// r in K_mu, u_hat in K*_mu and r . u_hat = 0 (the contact's Signorini-Coulomb law).
inline Vec3 natural_map(const Vec3& r, const Vec3& u, double mu) {
  return r - project_on_cone(r - de_saxce(u, mu), mu);
}

}  // namespace cpkit
