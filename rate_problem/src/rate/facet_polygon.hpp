#pragma once
// Internal: the polygon of k facets inscribed in a friction ellipse, the one-point faceted route
// (faceted_rate_3d.cpp) and the N-point one (system_rate_3d.cpp) both use.
#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace cpkit::rate::detail {

/// Vertices v_i = D (cos theta_i, sin theta_i), theta_i = 2 pi i / k (counter-clockwise), facet
/// j from v_j to v_j+1 with outward unit normal N.col(j) and support h(j) = n_j . v_j > 0: the
/// friction set n_j . dP_T <= mu h_j dP_N, the flow dw_T^i = sum lambda_j n_j.
struct FacetPolygon {
  Eigen::Matrix<double, 2, Eigen::Dynamic> N;
  Eigen::VectorXd h;
};

inline FacetPolygon facet_polygon(const Eigen::Vector2d& alpha, int k) {
  constexpr double kPi = 3.14159265358979323846;
  FacetPolygon p;
  p.N.resize(2, k);
  p.h.resize(k);
  std::vector<Eigen::Vector2d> v(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) {
    const double th = 2 * kPi * i / k;
    v[i] = alpha.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th));
  }
  for (int j = 0; j < k; ++j) {
    const Eigen::Vector2d e = v[(j + 1) % k] - v[j];
    p.N.col(j) = Eigen::Vector2d(e(1), -e(0)).normalized();
    p.h(j) = p.N.col(j).dot(v[j]);
  }
  return p;
}

}  // namespace cpkit::rate::detail
