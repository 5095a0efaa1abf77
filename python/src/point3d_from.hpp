#pragma once
// Reading a 3-D point (cpkit.Point3d) and small vectors from Python objects, shared by
// bind_three_d.cpp and bind_three_d_more.cpp. Errors are InputError (ValueError in Python)
// naming the field.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/three_d/point_rate_3d.hpp"

namespace cpkit::py {

inline Eigen::Vector2d vec2(const pyb::handle& o, const char* what) {
  const auto v = o.cast<std::vector<double>>();
  if (v.size() != 2) throw InputError(std::string(what) + " must hold 2 numbers, got " + std::to_string(v.size()));
  return {v[0], v[1]};
}

inline Eigen::Vector3d vec3(const pyb::handle& o, const char* what) {
  const auto v = o.cast<std::vector<double>>();
  if (v.size() != 3) throw InputError(std::string(what) + " must hold 3 numbers, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

/// Point3dParameters from an object with A (3x3), mu, C_T, k_a, P_s, alpha (cpkit.Point3d).
inline rate3d::Point3dParameters params_from(const pyb::handle& o) {
  rate3d::Point3dParameters p;
  const auto A = o.attr("A").cast<std::vector<std::vector<double>>>();
  if (A.size() != 3) throw InputError("A must be 3 x 3 (DOFs T_X, T_Y, N)");
  for (int i = 0; i < 3; ++i) {
    if (A[i].size() != 3) throw InputError("A must be 3 x 3 (DOFs T_X, T_Y, N)");
    for (int j = 0; j < 3; ++j) p.A(i, j) = A[i][j];
  }
  p.mu = finite_number(o.attr("mu"), "mu");
  p.C_T = finite_number(o.attr("C_T"), "C_T");
  p.k_a = finite_number(o.attr("k_a"), "k_a");
  p.P_s = finite_number(o.attr("P_s"), "P_s");
  p.alpha = vec2(o.attr("alpha"), "alpha");
  throw_if_invalid(p.validate(), "point");
  return p;
}

}  // namespace cpkit::py
