#pragma once
// Internal: the units of a 3-D step and the per-point terms of the step residual
// (step_3d_residual, docs/contact_3d.md section 7) and a point's type and slip direction,
// shared by the one-point step (step_3d.cpp) and the N-point step (system_step_3d.cpp), which
// adds its own equilibrium over all points.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "cpkit/rate_problem/step/step_3d.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate::detail {

/// The units of a 3-D step of n points (states[0..n)): stiffness max |A_ij|; force the largest
/// of |DF|, |P_T0|, |P_N0| and |g0| max|A_ij| (a product beyond double's range left out);
/// length force / stiffness; each 1 when it would be 0 or not finite.
template <class MatrixA, class VectorDF>
Units step_3d_units(const Eigen::MatrixBase<MatrixA>& A, const Eigen::MatrixBase<VectorDF>& DF,
                    const Step3dState* states, std::size_t n) noexcept {
  Units u;
  u.stiffness = A.size() > 0 ? A.cwiseAbs().maxCoeff() : 1.0;
  if (!(u.stiffness > 0) || !std::isfinite(u.stiffness)) u.stiffness = 1;
  double f = DF.size() > 0 ? DF.cwiseAbs().maxCoeff() : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double g = std::abs(states[i].g0) * u.stiffness;
    f = std::max({f, states[i].P_T0.cwiseAbs().maxCoeff(), std::abs(states[i].P_N0),
                  std::isfinite(g) ? g : 0.0});
  }
  u.force = (f > 0 && std::isfinite(f)) ? f : 1.0;
  u.length = u.force / u.stiffness;
  return u;
}

/// One point's step in the units `u` (stiffness / u.stiffness, forces / u.force, lengths /
/// u.length) with its friction ellipse in its own unit (normalize_ellipse).
inline Step3dProblem normalized_step_3d(Step3dProblem n, const Units& u) noexcept {
  n.params.A /= u.stiffness;
  n.params.C_T *= u.stiffness;
  // c_w P_N lambda is a length: c_w scales as 1/force. Archard's k = k_a/(3 P_s) through k_a.
  n.params.k_a *= u.force;
  n.wear.k_M *= u.force;
  // The ellipse in its own unit (alpha / c, mu c, k_a c; lambda / c); validate() has made sure
  // that these fit a double.
  normalize_ellipse(n.params);
  n.state.P_T0 /= u.force;
  n.state.P_N0 /= u.force;
  n.state.g0 /= u.length;
  n.DF /= u.force;
  return n;
}

/// A step's values with its forces times `force`, its lengths times `length` and its plastic
/// multiplier times `multiplier`: into or out of a problem's units (each caller passes its own
/// factors, computed as it always has, so that its rounding stays what it was).
inline Step3dValues scaled_values(Step3dValues v, double force, double length,
                                  double multiplier) noexcept {
  v.DP_T *= force;
  v.P_T1 *= force;
  v.DP_N *= force;
  v.P_N1 *= force;
  v.Dw_T *= length;
  v.Dw_Ti *= length;
  v.Dw_N *= length;
  v.Dw_w *= length;
  v.g1 *= length;
  v.lambda *= multiplier;
  return v;
}

/// The type of a point's solution from its values in normalized units (classify_step_3d): P_N1
/// = 0 is separation (open when the step started open, g0 < 0), else stick or slip.
inline SolutionType classify_normalized_step_3d(const Step3dValues& v, double g0) noexcept {
  if (v.P_N1 <= 1e-9) return g0 < 0 ? SolutionType::kOpen : SolutionType::kSeparation;
  if (v.lambda <= 1e-9 * (1 + v.Dw_T.cwiseAbs().maxCoeff())) return SolutionType::kStick;
  return SolutionType::kSlip;
}

/// A slip solution's direction (the unit vector of Dw_T^i) and its angle.
inline void set_slip_direction(Step3dSolution& s) noexcept {
  if (s.type == SolutionType::kSlip && s.values.Dw_Ti.stableNorm() > 0) {
    s.slip_direction = s.values.Dw_Ti.stableNormalized();  // no overflow near 1e308
    s.slip_angle = std::atan2(s.slip_direction(1), s.slip_direction(0));
  }
}

/// Projection onto the second-order cone {(x0, x1): x0 >= |x1|}.
inline Eigen::Vector3d project_soc(const Eigen::Vector3d& v) noexcept {
  const double r = v.tail<2>().stableNorm();
  if (r <= v(0)) return v;
  if (r <= -v(0)) return Eigen::Vector3d::Zero();
  const double a = (v(0) + r) / 2;
  Eigen::Vector3d out;
  out << a, a * v.tail<2>() / r;
  return out;
}

/// Every term of step_3d_residual except equilibrium: consistency of the values, the contact
/// pair, the SOC natural residual of (3D.22) and the complementarity products. `p` and `v` are
/// in normalized units (forces / F0, stiffness / K0, lengths / (F0 / K0)); p.params.A is not
/// used (equilibrium is the caller's). INFINITY when a term is not finite.
inline double local_step_3d_residual(const Step3dProblem& p, const Step3dValues& v) noexcept {
  const Eigen::Vector3d P0(p.state.P_T0(0), p.state.P_T0(1), p.state.P_N0);
  const Eigen::Vector3d DP(v.DP_T(0), v.DP_T(1), v.DP_N);
  const Eigen::Vector3d P1(v.P_T1(0), v.P_T1(1), v.P_N1);
  const Eigen::Vector3d Dw(v.Dw_T(0), v.Dw_T(1), v.Dw_N);
  const double c_w = p.wear_coefficient();
  const double big = 1 + P0.cwiseAbs().maxCoeff() + P1.cwiseAbs().maxCoeff();
  double res = 0;
  auto worse = [&res](double r) { res = std::isfinite(r) ? std::max(res, r) : INFINITY; };
  // The values must be consistent with one another (a solver may fill them in any way).
  worse((P1 - P0 - DP).cwiseAbs().maxCoeff() / big);
  const double dscale = 1 + Dw.cwiseAbs().maxCoeff() + std::abs(p.state.g0) +
                        p.params.C_T * DP.cwiseAbs().maxCoeff() + std::abs(v.Dw_w);
  worse((v.Dw_T - p.params.C_T * v.DP_T - v.Dw_Ti).cwiseAbs().maxCoeff() / dscale);
  worse(std::abs(v.Dw_w - c_w * std::max(v.P_N1, 0.0) * v.lambda) / dscale);
  worse(std::abs(v.g1 - (p.state.g0 + v.Dw_N - v.Dw_w)) / dscale);
  // Contact: P_N1 >= 0, g1 <= 0, P_N1 g1 = 0.
  worse(std::abs(std::min(v.P_N1 / big, -v.g1 / dscale)));
  // Friction over the second-order cone (3D.22).
  const Eigen::Vector2d alpha = p.params.alpha;
  Eigen::Vector3d x, y;
  x << p.params.mu * v.P_N1, v.P_T1.cwiseQuotient(alpha);
  y << v.lambda, -alpha.cwiseProduct(v.Dw_Ti);
  const Eigen::Vector3d nat = x - project_soc(x - y);
  worse(nat.cwiseAbs().maxCoeff() / (1 + x.cwiseAbs().maxCoeff() + y.cwiseAbs().maxCoeff()));
  // The natural residual is relative to |x| + |y|: a huge multiplier over a tiny force could
  // pass it. The complementarity products relative to (1 + |x|)(1 + |y|) close that gap (and
  // are of the natural residual's order where one factor is small).
  worse(std::abs(x.dot(y)) / ((1 + x.norm()) * (1 + y.norm())));
  worse(std::abs(v.P_N1 * v.g1) / ((1 + std::abs(v.P_N1)) * (1 + std::abs(v.g1))));
  return res;
}

}  // namespace cpkit::rate::detail
