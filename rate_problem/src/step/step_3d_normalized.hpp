#pragma once
// Internal: a 3-D step in normalized units and its Fischer-Burmeister residual map, written
// once for one point (step_solvers_3d.cpp) and N points (system_step_3d.cpp).
//
// `Points` is 1 (fixed sizes: z has 4 entries, the 3x3 LDLT solved with unit vectors, no
// allocation in the Newton loop) or Eigen::Dynamic (N points, 4N unknowns). The two keep the
// operation order each had before they were merged (the result digest is bit-identical): the
// one-point affine maps come from solves with unit vectors and its Jacobian's rows are built
// as the derivative rows times the FB derivatives; the N-point ones from one solve with the
// spreading matrix of z and rows accumulated into a zeroed Jacobian. `if constexpr` marks the
// few lines where the two differ.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/detail/fischer_burmeister.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate::detail {

/// The step in normalized units (forces / F0, A / K0, lengths / L0 = F0 / K0; point i's
/// ellipse in its own unit E_i) with the affine maps of the unknowns z (per point
/// (P_TX1, P_TY1, P_N1, lambda)):
///   Dw_T,i^i = ui0_i + Ui_i z,   g1_i = gc_i + gz_i . z - cw_i P_N1,i lambda_i.
template <int Points>
struct Normalized3d {
  static_assert(Points == 1 || Points == Eigen::Dynamic, "one point or N points");
  static constexpr bool kOnePoint = Points == 1;
  static constexpr int kZ = kOnePoint ? 4 : Eigen::Dynamic;  ///< unknowns (4N)
  static constexpr int kF = kOnePoint ? 3 : Eigen::Dynamic;  ///< forces (3N)
  static constexpr int kT = kOnePoint ? 2 : Eigen::Dynamic;  ///< tangential rows (2N)
  using Vector = Eigen::Matrix<double, kZ, 1>;
  using Matrix = Eigen::Matrix<double, kZ, kZ>;
  using PerPoint = Eigen::Matrix<double, Points, 1>;

  int N = 0;
  double K0 = 1, F0 = 1, L0 = 1;
  PerPoint mu, C, cw;  ///< mu E, C_T K0, c_w F0 E
  PerPoint E;          ///< the ellipse's unit: lambda / (L0 E) is normalized
  PerPoint g0;         ///< g0 / L0
  Eigen::Matrix<double, 2, Points> al;  ///< alpha / E
  Eigen::Matrix<double, kF, kF> A;      ///< A / K0
  Eigen::Matrix<double, kF, 1> DF, P0;  ///< load increment and start forces, / F0
  Vector z0;                            ///< the start state (lambda = 0)
  Eigen::Matrix<double, kT, 1> ui0;
  Eigen::Matrix<double, kT, kZ> Ui;
  PerPoint gc;
  Eigen::Matrix<double, Points, kZ> gz;

  int points() const noexcept { return N; }
  /// Dw_T^i of every point (2N) at z.
  Eigen::Matrix<double, kT, 1> slip_rates(const Vector& z) const {
    if constexpr (kOnePoint) {
      const Eigen::Vector3d P1 = z.template head<3>();
      return ui0 + Ui.template leftCols<3>() * P1;
    } else {
      return ui0 + Ui * z;
    }
  }
  /// g1 of every point at z without the wear term.
  PerPoint gaps(const Vector& z) const {
    if constexpr (kOnePoint) {
      const Eigen::Vector3d P1 = z.template head<3>();
      PerPoint g;
      g(0) = gc(0) + gz.template leftCols<3>().dot(P1);
      return g;
    } else {
      return gc + gz * z;
    }
  }
};

/// Normalizes a 3-D step of `points` points with stiffness A (3N x 3N) and load increment DF
/// (3N) in the units `u` (force, stiffness, length); `point(i)` returns point i's one-point
/// problem (parameters, wear, state).
/// Throws InputError when a scale overflows double (with the message the route has always
/// given) or, for N points, when A cannot be factorised.
template <int Points, class MatrixA, class VectorDF, class PointProblem>
Normalized3d<Points> normalize_3d(const Units& u, const Eigen::MatrixBase<MatrixA>& A,
                                  const Eigen::MatrixBase<VectorDF>& DF, int points,
                                  PointProblem&& point) {
  using Nd = Normalized3d<Points>;
  Nd n;
  n.N = points;
  n.K0 = u.stiffness;
  n.F0 = u.force;
  n.L0 = u.length;
  require_representable(n.F0, n.L0, "step");
  const bool length_bad = !std::isfinite(n.L0) || n.L0 == 0;
  if (!Nd::kOnePoint && length_bad)
    throw InputError("step: the step's scales overflow double (F0 / |A|): give the data in units "
                     "of moderate size");
  const int N = points;
  n.mu.resize(N);
  n.C.resize(N);
  n.cw.resize(N);
  n.E.resize(N);
  n.g0.resize(N);
  n.al.resize(2, N);
  n.P0.resize(3 * N);
  n.z0 = Nd::Vector::Zero(4 * N);
  n.A = A / n.K0;
  n.DF = DF / n.F0;
  for (int i = 0; i < N; ++i) {
    const Step3dProblem q = point(i);
    // The ellipse in its own unit: alpha / E, mu E, c_w E (lambda / E).
    const double E = ellipse_unit(q.params.alpha);
    n.E(i) = E;
    n.mu(i) = q.params.mu * E;
    n.C(i) = q.params.C_T * n.K0;
    n.cw(i) = q.wear_coefficient() * n.F0 * E;
    n.al.col(i) = q.params.alpha / E;
    if (!std::isfinite(n.C(i)) || !std::isfinite(n.cw(i)) || length_bad) {
      if constexpr (Nd::kOnePoint)
        throw InputError("the step's scales overflow double (C_T |A|, c_w F0 or F0 / |A|): "
                         "give the data in units of moderate size");
      else
        throw InputError("step: point " + std::to_string(i + 1) + ": C_T |A| or c_w F0 "
                         "overflows double: give the data in units of moderate size");
    }
    n.P0.template segment<3>(3 * i) << q.state.P_T0 / n.F0, q.state.P_N0 / n.F0;
    n.z0.template segment<3>(4 * i) = n.P0.template segment<3>(3 * i);
    n.g0(i) = q.state.g0 / n.L0;
  }
  // Dw = dw0 - A^-1 P1 by the factorisation (no explicit inverse): dw0 by a direct solve, the
  // linear map of z (row 3j + k of A^-1 for the force k of point j) by solves with unit
  // vectors (one point) or with the spreading of z's force part (N points).
  const Eigen::LDLT<Eigen::Matrix<double, Nd::kF, Nd::kF>> ldlt(n.A);
  const Eigen::Matrix<double, Nd::kF, 1> dw0 = ldlt.solve(n.DF + n.P0);
  Eigen::Matrix<double, Nd::kF, Nd::kZ> Az;
  if constexpr (Nd::kOnePoint) {
    Az.setZero();
    for (int k = 0; k < 3; ++k)
      Az.row(k).template head<3>() = ldlt.solve(Eigen::Vector3d::Unit(k)).transpose();
  } else {
    Eigen::MatrixXd Sz = Eigen::MatrixXd::Zero(3 * N, 4 * N);  // column 4j + k <- row 3j + k
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < 3; ++k) Sz(3 * j + k, 4 * j + k) = 1;
    Az = ldlt.solve(Sz);
    if (ldlt.info() != Eigen::Success || !dw0.allFinite() || !Az.allFinite())
      throw InputError("step: A cannot be factorised in double precision");
  }
  n.Ui = decltype(n.Ui)::Zero(2 * N, 4 * N);
  n.ui0.resize(2 * N);
  n.gz.resize(N, 4 * N);
  n.gc.resize(N);
  for (int i = 0; i < N; ++i) {
    n.Ui.middleRows(2 * i, 2) = -Az.middleRows(3 * i, 2);
    n.Ui(2 * i, 4 * i) -= n.C(i);
    n.Ui(2 * i + 1, 4 * i + 1) -= n.C(i);
    n.ui0.template segment<2>(2 * i) =
        dw0.template segment<2>(3 * i) + n.C(i) * n.P0.template segment<2>(3 * i);
    n.gz.row(i) = -Az.row(3 * i + 2);
    n.gc(i) = n.g0(i) + dw0(3 * i + 2);
  }
  return n;
}

/// z of the start points `starts` (one per point) in the units of `n`. Throws InputError when
/// it is not finite.
template <int Points>
typename Normalized3d<Points>::Vector normalized_start_3d(const Normalized3d<Points>& n,
                                                          const Step3dStart* starts) {
  typename Normalized3d<Points>::Vector z = n.z0;
  for (int i = 0; i < n.N; ++i) {
    const Step3dStart& s = starts[i];
    z.template segment<4>(4 * i) << s.P_T1 / n.F0, s.P_N1 / n.F0, s.lambda / (n.L0 * n.E(i));
  }
  if (!z.allFinite()) throw InputError("start point must be finite");
  return z;
}

/// Point i's two FB functions at z (ui, g1: the slip rates and the gaps without wear at z): the
/// normal pair (P_N, -g) and the cone pair x = (mu P_N, P_T / alpha), y = (lambda,
/// -alpha Dw_T^i), with their derivatives.
struct PointFb3d {
  double g = 0, phi_N = 0, da = 0, db = 0;  ///< gap with the wear term; FB value; dFB/d(P_N, -g)
  Eigen::Vector2d al;
  Eigen::Vector3d x, y, phi;
  Eigen::Matrix3d Jx, Jy;
};

template <int Points, class Vector, class Slip, class Gaps>
PointFb3d point_fb_3d(const Normalized3d<Points>& n, const Vector& z, const Slip& ui,
                      const Gaps& g1, int i) {
  PointFb3d f;
  const int r = 4 * i;
  const double PN = z(r + 2), lam = z(r + 3);
  f.g = g1(i) - n.cw(i) * PN * lam;
  f.phi_N = lcp::detail::fb_scalar(PN, -f.g, f.da, f.db);
  f.al = n.al.col(i);
  f.x << n.mu(i) * PN, z(r) / f.al(0), z(r + 1) / f.al(1);
  f.y << lam, -f.al(0) * ui(2 * i), -f.al(1) * ui(2 * i + 1);
  lcp::detail::fb_soc(f.x, f.y, f.phi, f.Jx, f.Jy);
  return f;
}

/// Phi(z) (4N) and an element of its generalized Jacobian (4N x 4N).
template <int Points>
void residual_map_3d(const Normalized3d<Points>& n, const typename Normalized3d<Points>::Vector& z,
                     typename Normalized3d<Points>::Vector& Phi,
                     typename Normalized3d<Points>::Matrix& J) {
  using Nd = Normalized3d<Points>;
  const auto ui = n.slip_rates(z);
  const auto g1 = n.gaps(z);
  if constexpr (!Nd::kOnePoint) J.setZero();
  for (int i = 0; i < n.N; ++i) {
    const int r = 4 * i;
    const PointFb3d f = point_fb_3d(n, z, ui, g1, i);
    const double PN = z(r + 2), lam = z(r + 3);
    const Eigen::Vector2d& al = f.al;
    Phi(r) = f.phi_N;
    Phi.template segment<3>(r + 1) = f.phi;
    // dx/dz: own columns only; dy/dz: lambda_i and the rows of Ui (all points).
    Eigen::Matrix3d dxo = Eigen::Matrix3d::Zero();  // d x / d(P_TX, P_TY, P_N)_i
    dxo(0, 2) = n.mu(i);
    dxo(1, 0) = 1 / al(0);
    dxo(2, 1) = 1 / al(1);
    if constexpr (Nd::kOnePoint) {
      // d(-g1)/dz times dFB/d(-g1), plus dFB/dP_N.
      Eigen::RowVector4d dmg;
      dmg << -n.gz(0), -n.gz(1), -n.gz(2) + n.cw(0) * lam, n.cw(0) * PN;
      J.row(0) = f.db * dmg;
      J(0, 2) += f.da;
      Eigen::Matrix<double, 3, 4> dx = Eigen::Matrix<double, 3, 4>::Zero(), dy = dx;
      dx.leftCols<3>() = dxo;
      dy(0, 3) = 1;
      dy.block<1, 3>(1, 0) = -al(0) * n.Ui.row(0).template head<3>();
      dy.block<1, 3>(2, 0) = -al(1) * n.Ui.row(1).template head<3>();
      J.template bottomRows<3>() = f.Jx * dx + f.Jy * dy;
    } else {
      J.row(r) = -f.db * n.gz.row(i);
      J(r, r + 2) += f.da + f.db * n.cw(i) * lam;
      J(r, r + 3) += f.db * n.cw(i) * PN;
      J.block(r + 1, r, 3, 3) += f.Jx * dxo;
      Eigen::MatrixXd dy = Eigen::MatrixXd::Zero(3, 4 * n.N);
      dy(0, r + 3) = 1;
      dy.row(1) = -al(0) * n.Ui.row(2 * i);
      dy.row(2) = -al(1) * n.Ui.row(2 * i + 1);
      J.middleRows(r + 1, 3) += f.Jy * dy;
    }
  }
}

/// The solvers' own check in normalized units, besides the step residual: each FB function
/// small against its arguments, |fb(a, b)| <= 1e-9 (1 + min(|a|, |b|)) + 1e-13 (|a| + |b|),
/// so that a point with a huge multiplier and a small but nonzero complementarity product
/// (x interior to K, y not zero) is never taken, whatever the scaling of a relative residual.
template <int Points>
bool fb_small_3d(const Normalized3d<Points>& n, const typename Normalized3d<Points>::Vector& z) {
  const auto ui = n.slip_rates(z);
  const auto g1 = n.gaps(z);
  auto ok = [](double f, double a, double b) {
    return std::abs(f) <= 1e-9 * (1 + std::min(a, b)) + 1e-13 * (a + b);
  };
  for (int i = 0; i < n.N; ++i) {
    const PointFb3d f = point_fb_3d(n, z, ui, g1, i);
    if (!ok(f.phi_N, std::abs(z(4 * i + 2)), std::abs(f.g))) return false;
    if (!ok(f.phi.norm(), f.x.norm(), f.y.norm())) return false;
  }
  return true;
}

/// What the shared Newton solve (step_3d_newton.hpp) asks of the normalized problem; a route's
/// kernel adds its residual and verdict (`residual`, `finalize`).
template <int Points>
struct NormalizedKernel3d {
  using Nd = Normalized3d<Points>;
  const Nd& n;
  int points() const noexcept { return n.N; }
  double mu(int i) const noexcept { return n.mu(i); }
  Eigen::Vector2d alpha(int i) const noexcept { return n.al.col(i); }
  auto slip_rates(const typename Nd::Vector& z) const { return n.slip_rates(z); }
  void residual_map(const typename Nd::Vector& z, typename Nd::Vector& Phi,
                    typename Nd::Matrix& J) const {
    residual_map_3d(n, z, Phi, J);
  }
  bool fb_small(const typename Nd::Vector& z) const { return fb_small_3d(n, z); }
};

}  // namespace cpkit::rate::detail
