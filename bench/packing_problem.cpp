// The local frictional contact problem of a packing's time step (packing.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "packing.hpp"

namespace cpkit::bench {

Mat3 contact_frame(const Vec3& normal) {
  Eigen::Index least = 0;
  normal.cwiseAbs().minCoeff(&least);
  const Vec3 t1 = normal.cross(Vec3::Unit(least)).normalized();
  Mat3 f;
  f << normal, t1, normal.cross(t1);
  return f;
}

Eigen::SparseMatrix<double> contact_jacobian(const Packing& p) {
  const Eigen::Index nc = static_cast<Eigen::Index>(p.contacts.size());
  const Eigen::Index nb = static_cast<Eigen::Index>(p.bodies.size());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(p.contacts.size() * 36);
  // Body b's part of contact c: sign * frame^T [I | -[x - x_b]_x] (velocity of the point of b
  // at x: v_b + w_b x (x - x_b) = v_b - [x - x_b]_x w_b).
  auto add_body = [&](Eigen::Index c, int b, double sign) {
    const Contact& k = p.contacts[static_cast<size_t>(c)];
    const Vec3 arm = k.point - p.bodies[static_cast<size_t>(b)].center;
    Mat3 cross;
    cross << 0, -arm.z(), arm.y(), arm.z(), 0, -arm.x(), -arm.y(), arm.x(), 0;
    const Mat3 translation = sign * k.frame.transpose();
    const Mat3 rotation = -translation * cross;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        t.emplace_back(3 * c + i, 6 * b + j, translation(i, j));
        t.emplace_back(3 * c + i, 6 * b + 3 + j, rotation(i, j));
      }
  };
  for (Eigen::Index c = 0; c < nc; ++c) {
    const Contact& k = p.contacts[static_cast<size_t>(c)];
    add_body(c, k.body_b, 1.0);
    if (k.body_a >= 0) add_body(c, k.body_a, -1.0);
  }
  Eigen::SparseMatrix<double> J(3 * nc, 6 * nb);
  J.setFromTriplets(t.begin(), t.end());
  return J;
}

Eigen::VectorXd free_velocity(const Packing& p) {
  Eigen::VectorXd v(6 * static_cast<Eigen::Index>(p.bodies.size()));
  for (size_t b = 0; b < p.bodies.size(); ++b) {
    // M^-1 f_gravity = gravity (no torque: gravity acts at the center of mass).
    v.segment<3>(6 * static_cast<Eigen::Index>(b)) = p.bodies[b].velocity + p.step * p.gravity;
    v.segment<3>(6 * static_cast<Eigen::Index>(b) + 3) = p.bodies[b].spin;
  }
  return v;
}

FrictionContactProblem packing_problem(const Packing& p) {
  const Eigen::Index nc = static_cast<Eigen::Index>(p.contacts.size());
  const Eigen::SparseMatrix<double> J = contact_jacobian(p);
  // G = J M^-1/2, W = G G^T: symmetric positive semidefinite by construction.
  Eigen::VectorXd inv_sqrt_mass(J.cols());
  for (size_t b = 0; b < p.bodies.size(); ++b) {
    const RigidBody& body = p.bodies[b];
    for (int j = 0; j < 3; ++j) {
      inv_sqrt_mass[6 * static_cast<Eigen::Index>(b) + j] = 1 / std::sqrt(body.mass);
      inv_sqrt_mass[6 * static_cast<Eigen::Index>(b) + 3 + j] = 1 / std::sqrt(body.inertia[j]);
    }
  }
  const Eigen::SparseMatrix<double> G = J * inv_sqrt_mass.asDiagonal();
  const Eigen::SparseMatrix<double> GT = G.transpose();
  Eigen::SparseMatrix<double> W = G * GT;
  // Bitwise symmetry (the product's sums need not run in the same order for (a, b) and (b, a)).
  const Eigen::SparseMatrix<double> WT = W.transpose();
  W = 0.5 * (W + WT);
  W.makeCompressed();

  FrictionContactProblem out;
  out.W = std::move(W);
  out.q = J * free_velocity(p);
  out.mu.resize(nc);
  for (Eigen::Index c = 0; c < nc; ++c) {
    const Contact& k = p.contacts[static_cast<size_t>(c)];
    out.q[3 * c] += std::max(k.gap, 0.0) / p.step;  // overlaps: 0 (packing.hpp)
    out.mu[c] = k.mu;
  }
  out.name = p.name;
  return out;
}

}  // namespace cpkit::bench
