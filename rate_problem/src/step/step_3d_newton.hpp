#pragma once
// Internal: what the semismooth Newton solve of a 3-D step does the same way for one point
// (step_solvers_3d.cpp, fixed-size 4) and N points (system_step_3d.cpp, 4N): the one damped
// Newton loop run with the step's iteration limit (and the status an unverified stop claims),
// the Newton solve with its verification and canonical form, the multistart's random starts and
// its test of a repeated solution (and the list of distinct ones), and the message of a result the verdict did not accept.
//
// The unknowns z, normalized, are per point (P_TX, P_TY, P_N, lambda). What differs between one
// point and N points is the kernel (the normalized problem and its FB residual map, whose
// fixed-size arithmetic for one point is kept as it is); it is passed as `Kernel` with:
//   int points() const;                        the number of points N
//   double mu(int i) const;                    point i's mu in the ellipse's unit
//   Eigen::Vector2d alpha(int i) const;        point i's alpha in the ellipse's unit
//   slip_rates(const Vector& z) const;         Dw_T^i of every point (2N), D = diag(alpha)
//   void residual_map(const Vector& z, Vector& Phi, Matrix& J) const;
//   double residual(const Vector& z) const;    the residual of the physical values of z
//   bool fb_small(const Vector& z) const;      each FB function small against its arguments
//   void finalize(const Vector& z, Result& out, const CommonOptions& o) const;
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/damped_newton.hpp"

namespace cpkit::rate::detail {

/// Runs lcp::damped_newton_counted from z (normalized; overwritten with the last iterate) with
/// the limit o.max_iterations (0: 100), its counters and final merit recorded in `out`.
/// Returns what the stop claims should the caller's check not verify z: kIterationLimit at the
/// limit, kNumericalFailure for a non-finite Phi, else kStalled.
template <class Vector, class Matrix, class Eval, class Done, class Result>
Status run_newton_3d(Vector& z, Eval&& eval, Done&& done, const CommonOptions& o, Result& out) {
  lcp::DampedNewtonStats st;
  const lcp::DampedNewtonStop stop =
      lcp::damped_newton_counted<Vector, Matrix>(z, eval, done, o.max_iterations, out, st);
  out.merit = st.merit;
  switch (stop) {
    case lcp::DampedNewtonStop::kIterationLimit: return Status::kIterationLimit;
    case lcp::DampedNewtonStop::kNonFinite: return Status::kNumericalFailure;
    default: return Status::kStalled;
  }
}

/// After the verdict: a result that is not kSolved says why (its residual, the iterations and
/// the final merit).
template <class Result>
void explain_unverified(Result& out) {
  if (out.status != Status::kSolved)
    out.message = "no verified solution: residual " + std::to_string(out.solution.residual) +
                  " after " + std::to_string(out.iterations) + " iterations (merit " +
                  std::to_string(out.merit) + ")";
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// z verified: the residual of its physical values within tol and every FB function small.
template <class Kernel, class Vector>
bool verified_3d(const Kernel& k, const Vector& z, double tol) {
  return k.residual(z) <= tol && k.fb_small(z);
}

/// Snaps each point of a verified iterate to its canonical form when the whole stays verified:
/// separation (x_i = 0: P1_i = 0, lambda_i = |D Dw_T^i|, the smallest admissible multiplier)
/// and stick (y_i = 0: lambda_i = 0).
template <class Kernel, class Vector>
Vector canonical_3d(const Kernel& k, Vector z, double tol) {
  for (int i = 0; i < k.points(); ++i) {
    const int r = 4 * i;
    const Eigen::Vector2d al = k.alpha(i);
    const Eigen::Vector2d u = k.slip_rates(z).template segment<2>(2 * i);
    const double xs = std::max(std::abs(k.mu(i) * z(r + 2)),
                               (z.template segment<2>(r).array() / al.array()).abs().maxCoeff());
    const double ys = std::max(std::abs(z(r + 3)), (u.array() * al.array()).abs().maxCoeff());
    if (xs <= 1e-10 * std::max(1.0, ys)) {
      Vector c = z;
      c.template segment<3>(r).setZero();
      const Eigen::Vector2d uc = k.slip_rates(c).template segment<2>(2 * i);
      c(r + 3) = (uc.array() * al.array()).matrix().norm();
      if (verified_3d(k, c, tol)) {
        z = c;
        continue;
      }
    }
    if (std::abs(z(r + 3)) <= 1e-10 * std::max(1.0, xs)) {
      Vector c = z;
      c(r + 3) = 0;
      if (verified_3d(k, c, tol)) z = c;
    }
  }
  return z;
}

/// The semismooth Newton iteration from z (normalized) by the one damped Newton loop; a
/// verified end is put in canonical form; fills `out` through the kernel's finalize (the
/// verdict) but not `seconds`.
template <class Vector, class Matrix, class Kernel, class Result>
void newton_3d(const Kernel& k, Vector z, const CommonOptions& o, Result& out) {
  auto eval = [&k](const Vector& x, Vector& Phi, Matrix& J) { k.residual_map(x, Phi, J); };
  auto done = [&](const Vector& x, const Vector& Phi) {
    return Phi.cwiseAbs().maxCoeff() <= 1e-15 && k.residual(x) <= o.tol;
  };
  const Status unverified = run_newton_3d<Vector, Matrix>(z, eval, done, o, out);
  const bool claim = verified_3d(k, z, o.tol);
  if (claim) z = canonical_3d(k, z, o.tol);
  out.status = claim ? Status::kSolved : unverified;
  k.finalize(z, out, o);
  explain_unverified(out);
}

/// A deterministic pseudo-random start of the multistart (normalized), per point: P_N zero or
/// log-uniform in [e^-4, e^1.5], P_T inside the friction ellipse, lambda zero or log-uniform.
template <class Vector, class Kernel>
Vector random_start_3d(const Kernel& k, std::mt19937_64& rng) {
  constexpr double kPi = 3.14159265358979323846;
  std::uniform_real_distribution<double> U(0, 1);
  Vector z = Vector::Zero(4 * k.points());
  for (int i = 0; i < k.points(); ++i) {
    const double PN = U(rng) < 0.15 ? 0.0 : std::exp(-4 + 5.5 * U(rng));
    const double th = 2 * kPi * U(rng), r = U(rng) < 0.3 ? 1.0 : U(rng);
    const double lam = U(rng) < 0.3 ? 0.0 : std::exp(-4 + 5.5 * U(rng));
    const Eigen::Vector2d al = k.alpha(i);
    const double mu = k.mu(i);
    z.template segment<4>(4 * i) << mu * PN * r * al(0) * std::cos(th),
        mu * PN * r * al(1) * std::sin(th), PN, lam;
  }
  return z;
}

/// Two solutions of a point are one when their forces agree to 1e-7 of the force scale F0.
template <class Values>
bool same_point_solution_3d(const Values& u, const Values& v, double F0) {
  const double d =
      std::max((u.P_T1 - v.P_T1).cwiseAbs().maxCoeff(), std::abs(u.P_N1 - v.P_N1));
  return d <= 1e-7 * F0;
}

/// Adds s to the distinct solutions `out` unless `same` finds it there; a repeated solution
/// replaces each one it repeats when its residual is smaller.
template <class Solution, class Same>
void add_distinct(std::vector<Solution>& out, const Solution& s, Same&& same) {
  bool dup = false;
  for (auto& o : out)
    if (same(o, s)) {
      dup = true;
      if (s.residual < o.residual) o = s;
    }
  if (!dup) out.push_back(s);
}

}  // namespace cpkit::rate::detail
