#pragma once
// Test helper (not a test): hand-built frictional contact problems for h16's tests, with the
// closed forms their tests assert.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::test {

/// Block-diagonal problem: contact i has W_i = diag(wn_i, wt_i, wt_i) and q_i. Closed forms
/// (one contact, W = diag(wn, wt, wt)):
///   q_N >= 0                          separation  r = 0
///   q_N < 0, |q_T|/wt <= mu |q_N|/wn  stick       r = (-q_N/wn, -q_T/wt)
///   q_N < 0, |q_T|/wt >  mu |q_N|/wn  slip        r = (-q_N/wn) (1, -mu q_T/|q_T|)
/// (slip: u_N = 0 gives r_N; u_T = wt r_T + q_T must be opposite to r_T, which holds for
/// r_T = -mu r_N q_T/|q_T| exactly when |q_T| > wt mu r_N).
struct DiagContact {
  double wn, wt, mu;
  Eigen::Vector3d q;
};

inline FrictionContactProblem diagonal_problem(const std::vector<DiagContact>& cs) {
  FrictionContactProblem p;
  const int n = 3 * static_cast<int>(cs.size());
  std::vector<Eigen::Triplet<double>> t;
  p.q.resize(n);
  p.mu.resize(static_cast<Eigen::Index>(cs.size()));
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const int k = 3 * static_cast<int>(i);
    t.emplace_back(k, k, cs[i].wn);
    t.emplace_back(k + 1, k + 1, cs[i].wt);
    t.emplace_back(k + 2, k + 2, cs[i].wt);
    p.q.segment<3>(k) = cs[i].q;
    p.mu[static_cast<Eigen::Index>(i)] = cs[i].mu;
  }
  p.W.resize(n, n);
  p.W.setFromTriplets(t.begin(), t.end());
  p.name = "diagonal";
  return p;
}

inline Eigen::Vector3d diagonal_closed_form(const DiagContact& c) {
  const double qn = c.q[0];
  const Eigen::Vector2d qt = c.q.tail<2>();
  if (qn >= 0) return Eigen::Vector3d::Zero();
  const double rn = -qn / c.wn;
  if (qt.norm() / c.wt <= c.mu * rn) return Eigen::Vector3d(rn, -qt[0] / c.wt, -qt[1] / c.wt);
  const Eigen::Vector2d rt = -c.mu * rn * qt / qt.norm();
  return Eigen::Vector3d(rn, rt[0], rt[1]);
}

/// A rigid box (mass m, principal inertias I, half sizes a, b, c) resting on the plane z = 0 on
/// its 4 bottom corners, under gravity for one step h: M v = H r + f, u = H^T v, f = M v_prev
/// + h m (0, 0, -g) + h push (a horizontal force at the centre). Contact frames: normal z,
/// tangents x, y. W = H^T M^-1 H is 12 x 12 of rank 6: more contacts than dofs.
/// Every solution at rest (u = 0, stick) has H r = -f: total normal impulse m g h, total
/// tangential impulse -h push, zero moments about the centre (at height c).
struct Box {
  double m = 2, g = 9.81, h = 0.01, a = 0.5, b = 0.3, c = 0.2, mu = 0.5;
  Eigen::Vector2d push = Eigen::Vector2d::Zero();
};

inline FrictionContactProblem box_problem(const Box& box, Eigen::MatrixXd* H_out = nullptr) {
  const double I[3] = {box.m * (box.b * box.b + box.c * box.c) / 3,
                       box.m * (box.a * box.a + box.c * box.c) / 3,
                       box.m * (box.a * box.a + box.b * box.b) / 3};
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(6, 12);
  const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d p(sx[i] * box.a, sy[i] * box.b, -box.c);  // corner from the centre
    const Eigen::Vector3d dir[3] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                    Eigen::Vector3d::UnitY()};
    for (int j = 0; j < 3; ++j) {
      // u_j = dir . (v + w x p) = dir . v + (p x dir) . w
      H.block<3, 1>(0, 3 * i + j) = dir[j];
      H.block<3, 1>(3, 3 * i + j) = p.cross(dir[j]);
    }
  }
  Eigen::VectorXd Minv(6);
  Minv << 1 / box.m, 1 / box.m, 1 / box.m, 1 / I[0], 1 / I[1], 1 / I[2];
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f[0] = box.h * box.push[0];
  f[1] = box.h * box.push[1];
  f[2] = -box.h * box.m * box.g;
  FrictionContactProblem p;
  const Eigen::MatrixXd W = H.transpose() * Minv.asDiagonal() * H;
  p.W = W.sparseView();
  p.q = H.transpose() * (Minv.asDiagonal() * f);
  p.mu = Eigen::VectorXd::Constant(4, box.mu);
  p.name = "box on 4 corners";
  if (H_out) *H_out = H;
  return p;
}

/// An independent check of a frictional contact solution (written here, no cpkit cone code):
/// per contact r in K_mu, u_N >= 0, u_hat . r = 0, Signorini r_N u_N = 0, and Coulomb's
/// direction r_T = -mu r_N u_T/|u_T| when sliding; forces relative to
/// R = max(||r||_inf, ||q||_inf/||W||_max) (so that r = 0 plus rounding is judged at the data's
/// size), velocities to the contact's |q_i| + ||W_i,:||_max R. Returns the largest violation.
inline double violation(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  const Eigen::MatrixXd W(p.W);
  const Eigen::VectorXd u = W * r + p.q;
  const double wmax = W.cwiseAbs().maxCoeff();
  const double R =
      std::max(r.lpNorm<Eigen::Infinity>(), wmax > 0 ? p.q.lpNorm<Eigen::Infinity>() / wmax : 0.0);
  double worst = 0;
  for (Eigen::Index i = 0; i < p.mu.size(); ++i) {
    const Eigen::Vector3d ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
    const double m = p.mu[i], rT = ri.tail<2>().norm(), uT = ui.tail<2>().norm();
    const double S =
        p.q.segment<3>(3 * i).norm() + W.middleRows(3 * i, 3).cwiseAbs().maxCoeff() * R;
    if (!(R > 0) || !(S > 0)) continue;
    double v = std::max({0.0, -ri[0] / R, (rT - m * ri[0]) / R, -ui[0] / S});
    v = std::max(v, std::abs(ri[0] * ui[0]) / (R * S));
    v = std::max(v, std::abs(ri[0] * (ui[0] + m * uT) + ri.tail<2>().dot(ui.tail<2>())) / (R * S));
    if (uT > 1e-6 * S) v = std::max(v, (ri.tail<2>() + m * ri[0] * ui.tail<2>() / uT).norm() / R);
    worst = std::max(worst, v);
  }
  return worst;
}

}  // namespace cpkit::test
