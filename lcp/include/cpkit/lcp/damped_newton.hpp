#pragma once
/// \file damped_newton.hpp
/// cpkit's one damped semismooth Newton loop on Phi(z) = 0 (a Fischer-Burmeister
/// reformulation): Newton direction J d = -Phi by full-pivoting LU, Armijo backtracking on
/// Psi = |Phi|^2 / 2, steepest descent -J^T Phi when the Newton direction is not finite or not a
/// clear descent direction [De Luca, Facchinei, Kanzow 1996]. Used by the SOC solver
/// (cone_complementarity_fb.hpp) and the 3-D step solvers (one point: fixed-size 4; N points: 4N).
///
/// The loop only iterates; it grants nothing. The caller's `done(z, Phi)` says when to stop
/// (typically a cheap test on Phi, then the verdict), and every answer goes through the caller's
/// finalize()-style check. Fixed-size Vector/Matrix types make the loop allocation-free; with
/// dynamic types every buffer (LU included) is sized once before the loop.
#include <Eigen/LU>
#include <cmath>

namespace cpkit::lcp {

struct DampedNewtonOptions {
  int max_iterations = 100;   ///< Newton/gradient iterations
  double sigma = 1e-4;        ///< Armijo: Psi(z + t d) <= Psi(z) + sigma t grad.d
  int max_backtracks = 60;    ///< halvings of t before the line search fails
  /// The Newton direction d is used when grad.d <= -descent_factor |d|^descent_power (a clear
  /// descent direction, scale-free on a normalized problem); else -grad.
  double descent_factor = 1e-12;
  double descent_power = 2.1;
};

/// Why the loop stopped.
enum class DampedNewtonStop {
  kDone,              ///< done(z, Phi) returned true
  kIterationLimit,    ///< max_iterations reached
  kNonFinite,         ///< Phi not finite at the iterate
  kStationary,        ///< grad.d >= 0: a stationary point of Psi that is not a zero
  kLineSearchFailed,  ///< no Armijo step within max_backtracks halvings
  kNoProgress,        ///< the accepted step did not change z
};

struct DampedNewtonStats {
  int iterations = 0;         ///< directions computed
  int line_search_steps = 0;  ///< backtracking halvings
  int gradient_steps = 0;     ///< steepest-descent fallbacks
  int function_evals = 0;     ///< calls of eval
  double merit = 0;           ///< Psi at the returned z
};

/// Runs the loop from z (overwritten with the last accepted iterate).
/// eval(const Vector& z, Vector& Phi, Matrix& J): Phi(z) and an element J of its generalized
/// Jacobian. done(const Vector& z, const Vector& Phi) -> bool: stop here.
template <class Vector, class Matrix, class Eval, class Done>
DampedNewtonStop damped_newton(Vector& z, Eval&& eval, Done&& done, const DampedNewtonOptions& o,
                               DampedNewtonStats& stats) {
  const Eigen::Index n = z.size();
  Vector Phi = z, Phi_t = z, z_t = z, d = z, g = z;
  Matrix J, J_t;
  if constexpr (Matrix::RowsAtCompileTime == Eigen::Dynamic) {
    J.resize(n, n);
    J_t.resize(n, n);
  }
  Eigen::FullPivLU<Matrix> lu(n, n);
  auto merit = [](const Vector& p) { return 0.5 * p.squaredNorm(); };
  eval(z, Phi, J);
  ++stats.function_evals;
  double psi = merit(Phi);
  DampedNewtonStop stop = DampedNewtonStop::kIterationLimit;
  for (int it = 0; it < o.max_iterations; ++it) {
    if (!Phi.allFinite()) {
      stop = DampedNewtonStop::kNonFinite;
      break;
    }
    if (done(static_cast<const Vector&>(z), static_cast<const Vector&>(Phi))) {
      stop = DampedNewtonStop::kDone;
      break;
    }
    ++stats.iterations;
    g.noalias() = J.transpose() * Phi;
    lu.compute(J);
    d = lu.solve(-Phi);
    const double dn = d.norm();
    if (!d.allFinite() || g.dot(d) > -o.descent_factor * std::pow(dn, o.descent_power)) {
      d = -g;
      ++stats.gradient_steps;
    }
    const double slope = g.dot(d);
    if (!(slope < 0)) {
      stop = DampedNewtonStop::kStationary;
      break;
    }
    double t = 1;
    bool accepted = false;
    for (int ls = 0; ls < o.max_backtracks; ++ls) {
      z_t = z + t * d;
      eval(static_cast<const Vector&>(z_t), Phi_t, J_t);
      ++stats.function_evals;
      const double psi_t = merit(Phi_t);
      if (std::isfinite(psi_t) && psi_t <= psi + o.sigma * t * slope) {
        accepted = true;
        break;
      }
      t *= 0.5;
      ++stats.line_search_steps;
    }
    if (!accepted) {
      stop = DampedNewtonStop::kLineSearchFailed;
      break;
    }
    const bool progress = (z_t - z).cwiseAbs().maxCoeff() > 0;
    z.swap(z_t);
    Phi.swap(Phi_t);
    J.swap(J_t);
    psi = merit(Phi);
    if (!progress) {
      stop = DampedNewtonStop::kNoProgress;
      break;
    }
  }
  stats.merit = psi;
  return stop;
}

/// The loop as a solver runs it: max_iterations is the solver's limit in the convention of
/// CommonOptions::max_iterations (0: the loop's default, 100), and the counters of the run go
/// to `result` (a SolveResult or one derived from it: iterations, function_evals,
/// line_search_steps, gradient_steps). `stats` receives the whole statistics (merit included).
template <class Vector, class Matrix, class Eval, class Done, class Result>
DampedNewtonStop damped_newton_counted(Vector& z, Eval&& eval, Done&& done, int max_iterations,
                                       Result& result, DampedNewtonStats& stats) {
  DampedNewtonOptions o;
  o.max_iterations = max_iterations > 0 ? max_iterations : 100;
  const DampedNewtonStop stop = damped_newton<Vector, Matrix>(z, eval, done, o, stats);
  result.iterations = stats.iterations;
  result.function_evals = stats.function_evals;
  result.line_search_steps = stats.line_search_steps;
  result.gradient_steps = stats.gradient_steps;
  return stop;
}

}  // namespace cpkit::lcp
