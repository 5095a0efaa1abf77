// Semismooth Newton on the Fischer-Burmeister reformulation (see fb_newton.hpp and
// docs/fb_newton.md). One generic driver (FbDriver) over two linear-algebra back ends
// (dense LU, sparse LU: fb_newton_algebra.hpp) and two function sources (affine M z + q, or the
// MCP callbacks).
#include "cpkit/lcp/fb_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/units.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/core/short_number.hpp"
#include "fb_newton_algebra.hpp"

namespace cpkit::lcp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kDefaultMaxIterations = 200;
/// An accepted step with Psi_new > (1 - kWeakDecrease) Psi_old makes little progress;
/// kWeakLimit of them in a row count as stagnation (watchdog trigger).
constexpr double kWeakDecrease = 1e-4;
constexpr int kWeakLimit = 3;

// ---- the scalar NCP functions ------------------------------------------------------------------

/// How the bounds of component i enter Phi_i.
enum class BoundKind : unsigned char { kLower, kUpper, kBoth, kFree };

BoundKind bound_kind(double l, double u) {
  const bool lf = std::isfinite(l), uf = std::isfinite(u);
  if (lf && uf) return BoundKind::kBoth;
  if (lf) return BoundKind::kLower;
  if (uf) return BoundKind::kUpper;
  return BoundKind::kFree;
}

// sqrt(a^2 + b^2) without spurious overflow/underflow and without the cost of hypot when safe.
inline double norm2(double a, double b) {
  const double s = a * a + b * b;
  if (s > 1e-290 && s < 1e290) return std::sqrt(s);
  return std::hypot(a, b);
}

/// phi(a, b) = lambda (a + b - r) + (1 - lambda) a+ b+,  r = sqrt(a^2 + b^2); the FB part is
/// evaluated as 2ab / (a + b + r) when a + b > 0 (no cancellation).
inline double phi(double a, double b, double r, double lambda) {
  const double s = a + b;
  const double fb = s > 0 ? 2.0 * a * b / (s + r) : s - r;
  if (lambda == 1.0) return fb;
  return lambda * fb + (1.0 - lambda) * std::max(a, 0.0) * std::max(b, 0.0);
}

/// Gradient (ga, gb) of phi at (a, b). At r = 0 the limiting gradient along the direction
/// (da, db) (De Luca-Facchinei-Kanzow); returns false when r = 0 and the direction is zero
/// (the caller then supplies a direction).
inline bool phi_grad(double a, double b, double r, double da, double db, double lambda, double& ga,
                     double& gb) {
  if (r > 0) {
    ga = 1.0 - a / r;
    gb = 1.0 - b / r;
  } else {
    const double rd = norm2(da, db);
    if (!(rd > 0)) return false;
    ga = 1.0 - da / rd;
    gb = 1.0 - db / rd;
  }
  if (lambda != 1.0) {
    ga *= lambda;
    gb *= lambda;
    if (a > 0 && b > 0) {
      ga += (1.0 - lambda) * b;
      gb += (1.0 - lambda) * a;
    }
  }
  return true;
}

/// Phi_i only (line-search evaluations).
inline double component_value(BoundKind k, double x, double f, double l, double u, double lambda) {
  switch (k) {
    case BoundKind::kLower: {
      const double a = x - l;
      return phi(a, f, norm2(a, f), lambda);
    }
    case BoundKind::kUpper: {
      const double c = u - x;
      return -phi(c, -f, norm2(c, f), lambda);
    }
    case BoundKind::kBoth: {
      const double c = u - x, a = x - l;
      const double g = -phi(c, -f, norm2(c, f), lambda);
      return phi(a, g, norm2(a, g), lambda);
    }
    case BoundKind::kFree:
      return f;
  }
  return f;
}

/// Phi_i and the row coefficients (Da_i, Db_i) of H = diag(Da) + diag(Db) F'. (zi, jzi) is the
/// direction (z_i, (F' z)_i) used at degenerate pairs; returns false when a degenerate pair was
/// met and zi = 0 (no direction yet).
inline bool component_grad(BoundKind k, double x, double f, double l, double u, double lambda,
                           double zi, double jzi, double& da, double& db) {
  switch (k) {
    case BoundKind::kLower: {
      const double a = x - l;
      return phi_grad(a, f, norm2(a, f), zi, jzi, lambda, da, db);
    }
    case BoundKind::kUpper: {
      // Phi = g = -phi(c, e), c = u - x, e = -f: dPhi/dx = pc, dPhi/df = pe.
      const double c = u - x, e = -f;
      return phi_grad(c, e, norm2(c, e), -zi, -jzi, lambda, da, db);
    }
    case BoundKind::kBoth: {
      const double c = u - x, e = -f, a = x - l;
      const double rin = norm2(c, e);
      double pc, pe;
      if (!phi_grad(c, e, rin, -zi, -jzi, lambda, pc, pe)) return false;
      const double g = -phi(c, e, rin, lambda);
      double oa, og;
      // Direction of (a, g) along x + t z: (z_i, pc z_i + pe (F'z)_i).
      if (!phi_grad(a, g, norm2(a, g), zi, pc * zi + pe * jzi, lambda, oa, og)) return false;
      da = oa + og * pc;
      db = og * pe;
      return true;
    }
    case BoundKind::kFree:
      da = 0.0;
      db = 1.0;
      return true;
  }
  return true;
}

// ---- function sources --------------------------------------------------------------------------

/// F(x) = M x + q with dense or sparse M (the Jacobian is M, evaluated once).
struct AffineSource {
  const LcpProblem* lcp = nullptr;
  DataSizes sizes;    // the data's part of the acceptance test's units (residuals.hpp)
  Mat absM;
  SparseMat absMs;
  mutable Vec R, s, xp, Fp;  // workspaces: |M||x| + |q|, the w-units, the projected point

  explicit AffineSource(const LcpProblem& p) : lcp(&p), sizes(data_sizes(p)) {
    if (p.is_sparse())
      absMs = p.M_sparse.cwiseAbs();
    else
      absM = p.M.cwiseAbs();
    R.resize(p.size());
    s.resize(p.size());
    xp.resize(p.size());
    Fp.resize(p.size());
  }
  bool eval(const Vec& x, Vec& F) const {
    if (lcp->is_sparse())
      F.noalias() = lcp->M_sparse * x;
    else
      F.noalias() = lcp->M * x;
    F += lcp->q;
    return true;
  }
  /// The acceptance number of finalize() (residuals.hpp), so that the iteration stops exactly
  /// when the answer will verify: unit-free, per row, never growing with |x| (a diverging
  /// sequence of an infeasible problem is never "converged").
  double residual(const Vec& x, const Vec& F, const Vec& l, const Vec& u) const {
    // As finalize(): w is judged at the projection xp of x onto [l, u].
    xp.noalias() = x.cwiseMax(l).cwiseMin(u);
    const bool inside = xp == x;
    if (!inside) eval(xp, Fp);
    if (lcp->is_sparse())
      R.noalias() = absMs * xp.cwiseAbs();
    else
      R.noalias() = absM * xp.cwiseAbs();
    R += lcp->q.cwiseAbs();
    const double x_norm = xp.lpNorm<Eigen::Infinity>();
    w_units(sizes, lcp->q, x_norm, s);
    const double Z = z_unit(sizes, x_norm);
    const double r = unit_free_residual(xp, inside ? F : Fp, R, s, Z, &l, &u);
    return inside ? r : std::max(r, bound_violation(x, Z, &l, &u));
  }
};

/// F from the McpProblem callback; stopping scale 1 + ||F||_inf (the final word is finalize()'s
/// unit-free test, which linearises F at the answer: residuals.hpp).
struct CallbackSource {
  const McpProblem* p = nullptr;
  bool eval(const Vec& x, Vec& F) const {
    if (!p->F(x, F)) return false;
    return F.size() == x.size() && F.allFinite();
  }
  double residual(const Vec& x, const Vec& F, const Vec& l, const Vec& u) const {
    double m = 0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double q = std::min(std::max(x[i] - F[i], l[i]), u[i]);
      m = std::max(m, std::abs(x[i] - q));
    }
    return m / (1.0 + F.lpNorm<Eigen::Infinity>());
  }
};

// ---- the driver --------------------------------------------------------------------------------

struct Bounds {
  const Vec* lower;
  const Vec* upper;
};

/// Jacobian provider for the callback source (dense: analytic or forward differences; sparse:
/// the sparse callback). The affine source sets the algebra's J once and never calls these.
bool eval_dense_jacobian(const McpProblem& p, const Vec& x, const Vec& F, double fd_step,
                         DenseAlgebra& la, int& fevals) {
  const Eigen::Index n = x.size();
  if (p.jacobian) {
    if (!p.jacobian(x, la.J_own)) return false;
    return la.J_own.rows() == n && la.J_own.cols() == n && la.J_own.allFinite();
  }
  // Forward differences, h_j = fd_step max(1, |x_j|); backward when x + h e_j is outside the
  // domain of F.
  if (la.J_own.rows() != n || la.J_own.cols() != n) la.J_own.resize(n, n);
  la.fd_x = x;
  la.fd_F.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = fd_step * std::max(1.0, std::abs(x[j]));
    bool ok = false;
    for (const double sgn : {1.0, -1.0}) {
      la.fd_x[j] = x[j] + sgn * h;
      const double hj = la.fd_x[j] - x[j];  // the step actually represented
      ++fevals;
      if (p.F(la.fd_x, la.fd_F) && la.fd_F.size() == n && la.fd_F.allFinite()) {
        la.J_own.col(j) = (la.fd_F - F) / hj;
        ok = true;
        break;
      }
    }
    la.fd_x[j] = x[j];
    if (!ok) return false;
  }
  return true;
}

bool eval_sparse_jacobian(const McpProblem& p, const Vec& x, SparseAlgebra& la) {
  const Eigen::Index n = x.size();
  if (!p.sparse_jacobian(x, la.J_own)) return false;
  if (la.J_own.rows() != n || la.J_own.cols() != n) return false;
  if (!la.J_own.isCompressed()) la.J_own.makeCompressed();
  for (Eigen::Index k = 0; k < la.J_own.nonZeros(); ++k)
    if (!std::isfinite(la.J_own.valuePtr()[k])) return false;
  return true;
}

/// The Newton loop, generic in the function source and the linear algebra.
template <class Source, class Algebra>
class FbDriver {
 public:
  FbDriver(const Source& src, Algebra& la, Bounds b, const FbNewtonOptions& o, Eigen::Index n)
      : src_(src), la_(la), l_(*b.lower), u_(*b.upper), o_(o), n_(n) {
    kinds_.resize(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) kinds_[static_cast<size_t>(i)] = bound_kind(l_[i], u_[i]);
    for (Vec* v : {&x_, &F_, &Phi_, &Da_, &Db_, &g_, &d_, &rhs_, &xt_, &Ft_, &Phit_, &tmp_, &z_,
                   &jz_, &best_x_, &best_res_x_, &xp_, &Fp_, &Phip_})
      v->resize(n);
    degenerate_.reserve(static_cast<size_t>(n));
    const int m = std::max(1, o.nonmonotone_memory);
    history_.assign(static_cast<size_t>(m), 0.0);
    lambda_ = o.penalty_lambda;
    max_iter_ = o.common.max_iterations > 0 ? o.common.max_iterations : kDefaultMaxIterations;
  }

  /// Jacobian refresh hook: called once per iteration with the current point.
  template <class JacFn>
  SolveResult run(const Vec& x0, JacFn&& refresh_jacobian) {
    SolveResult r;
    r.solver = "fb-newton";
    Stopwatch clock;
    x_ = x0;
    ++r.function_evals;
    if (!src_.eval(x_, F_)) {
      r.status = Status::kNumericalFailure;
      r.z = x_;
      r.message = "F is undefined or non-finite at the starting point";
      r.seconds = clock.seconds();
      return r;
    }
    double psi = merit(x_, F_, Phi_);
    double res = natural_residual(x_, F_);
    std::fill(history_.begin(), history_.end(), psi);
    size_t hist_pos = 0;
    best_x_ = x_;
    double best_psi = psi;
    best_res_x_ = x_;
    double best_res = res;
    if (o_.common.record_trace) r.trace.push_back({0, res, 0.0, "start", -1, -1});
    const bool debug_log = o_.common.log != nullptr && o_.common.verbosity >= 3;
    if (debug_log)
      log(o_.common.log, o_.common.verbosity, LogLevel::kDebug,
          "fb-newton: start, scaled natural residual " + short_number(res));

    Status claim = Status::kIterationLimit;
    std::string why;
    int it = 0;
    int weak = 0;     // consecutive iterations with little decrease of Psi
    int escapes = 0;  // watchdog escapes used
    bool newton_ok = false;
    // Jacobian, row coefficients, gradient and Newton direction at x_ (false: no Jacobian).
    auto prepare = [&]() {
      if (!refresh_jacobian(x_, F_, r)) return false;
      row_coefficients();
      la_.grad(Da_, Db_, Phi_, tmp_, g_);
      rhs_ = -Phi_;
      newton_ok = la_.solve(Da_, Db_, rhs_, d_);
      return true;
    };
    auto accept = [&](double t, double psit, const char* kind) {
      x_.swap(xt_);
      F_.swap(Ft_);
      Phi_.swap(Phit_);
      psi = psit;
      history_[hist_pos] = psi;
      hist_pos = (hist_pos + 1) % history_.size();
      res = natural_residual(x_, F_);
      if (psi < best_psi) {
        best_psi = psi;
        best_x_ = x_;
      }
      if (res < best_res) {
        best_res = res;
        best_res_x_ = x_;
      }
      ++it;
      if (o_.common.record_trace) r.trace.push_back({it, res, t, kind, -1, -1});
      if (debug_log)
        log(o_.common.log, o_.common.verbosity, LogLevel::kDebug,
            "fb-newton: it " + std::to_string(it) + " residual " + short_number(res) + " step " + short_number(t) +
                " " + kind);
    };
    for (;;) {
      if (res <= o_.common.tol) {
        claim = Status::kSolved;
        break;
      }
      if (it >= max_iter_) {
        claim = Status::kIterationLimit;
        why = "iteration limit " + std::to_string(max_iter_) + " reached";
        break;
      }
      if (clock.exceeded(o_.common.time_limit_s)) {
        claim = Status::kTimeLimit;
        why = "time limit reached";
        break;
      }
      if (!prepare()) {
        claim = Status::kNumericalFailure;
        why = "Jacobian undefined or non-finite at iteration " + std::to_string(it);
        break;
      }
      std::string stagnation;
      const double gnorm = g_.template lpNorm<Eigen::Infinity>();
      if (!(gnorm > 0) || !std::isfinite(gnorm)) {
        stagnation = "stationary point of the merit function that is not a solution";
      } else {
        // Newton direction, or the gradient fallback. An exactly solved Newton system gives
        // grad.d = -||Phi||^2 = -2 Psi; a direction achieving at least half of that is accepted
        // even when the (scale-dependent) test grad.d <= -rho ||d||^p fails, which happens on
        // ill-conditioned problems where ||d|| is large although d is an accurate Newton step.
        double gd = newton_ok ? g_.dot(d_) : 0.0;
        bool newton = newton_ok && std::isfinite(gd) &&
                      (gd <= -o_.descent_rho * std::pow(d_.norm(), o_.descent_power) || gd <= -psi);
        const double psi_ref = *std::max_element(history_.begin(), history_.end());
        double t = 0, psit = 0;
        bool ok = newton && line_search(psi_ref, gd, t, psit, r);
        if (!ok) {
          newton = false;
          d_ = -g_;
          gd = -g_.squaredNorm();
          ok = line_search(psi_ref, gd, t, psit, r);
        }
        if (ok) {
          if (!newton) ++r.gradient_steps;
          weak = psit > (1.0 - kWeakDecrease) * psi ? weak + 1 : 0;
          accept(t, psit, newton ? "newton" : "gradient");
          if (weak >= kWeakLimit)
            stagnation = "no progress in " + std::to_string(weak) + " iterations";
        } else {
          stagnation = "line search failed along the gradient at iteration " + std::to_string(it);
        }
      }
      if (stagnation.empty()) continue;
      if (res <= o_.common.tol) continue;  // the last accepted step solved it
      // Watchdog escape: up to watchdog_steps undamped Newton steps from the stagnation point;
      // success when Psi drops below its stagnation value, else back to the best point.
      bool escaped = false;
      if (escapes < o_.max_escapes && o_.watchdog_steps > 0) {
        ++escapes;
        weak = 0;
        const double psi_s = best_psi;
        for (int k = 0; k < o_.watchdog_steps && it < max_iter_; ++k) {
          if (!prepare() || !newton_ok) break;
          double t = 0, psit = 0;
          if (!backstep(psi, t, psit, r)) break;
          accept(t, psit, "watchdog");
          if (res <= o_.common.tol || psi < (1.0 - kWeakDecrease) * psi_s) {
            escaped = true;
            break;
          }
        }
        if (escaped) {
          std::fill(history_.begin(), history_.end(), psi);
          continue;
        }
        // Back to the best point seen.
        if (!(psi <= best_psi)) {
          x_ = best_x_;
          ++r.function_evals;
          if (src_.eval(x_, F_)) {
            psi = merit(x_, F_, Phi_);
            res = natural_residual(x_, F_);
          }
        }
        stagnation += "; watchdog escape failed";
      }
      claim = Status::kStalled;
      why = stagnation;
      break;
    }
    r.iterations = it;
    r.status = claim;
    // A solution is the current point; otherwise the point of smallest stopping residual seen
    // (the earliest on ties), never a point chosen only for its small Psi.
    r.z = claim == Status::kSolved ? x_ : best_res_x_;
    r.message = claim == Status::kSolved ? "natural residual " + short_number(res) + " <= tol" : why;
    r.seconds = clock.seconds();
    return r;
  }

 private:
  // The watchdog's step, Miranda-Fackler's backstepping: halve t while Psi keeps falling along
  // t = 1, 1/2, ...; stop at the first decrease below psi = Psi(x) or at the first rise (then
  // the previous trial is taken, even if psi is exceeded). The trial is left in xt_, Ft_, Phit_;
  // false when no trial was defined.
  bool backstep(double psi, double& t, double& psit, SolveResult& r) {
    double prev_t = 0, prev_psi = kInf;
    auto swap_previous = [&]() {
      xt_.swap(xp_);
      Ft_.swap(Fp_);
      Phit_.swap(Phip_);
    };
    for (t = 1.0; t >= o_.min_step; t *= o_.backtrack) {
      xt_ = x_ + t * d_;
      ++r.function_evals;
      if (!src_.eval(xt_, Ft_) || !std::isfinite(psit = merit(xt_, Ft_, Phit_))) {
        ++r.line_search_steps;  // outside F's domain: too long
        continue;
      }
      if (psit < psi) return true;
      if (psit > prev_psi) break;  // rising again: take the previous trial
      swap_previous();
      prev_t = t;
      prev_psi = psit;
      ++r.line_search_steps;
    }
    if (!(prev_psi < kInf)) return false;
    swap_previous();
    t = prev_t;
    psit = prev_psi;
    return true;
  }

  // Phi(x) and Psi = 0.5 ||Phi||^2.
  double merit(const Vec& x, const Vec& F, Vec& Phi) const {
    for (Eigen::Index i = 0; i < n_; ++i)
      Phi[i] = component_value(kinds_[static_cast<size_t>(i)], x[i], F[i], l_[i], u_[i], lambda_);
    return 0.5 * Phi.squaredNorm();
  }
  // The stopping residual of the source (for LCPs exactly finalize()'s acceptance number).
  double natural_residual(const Vec& x, const Vec& F) { return src_.residual(x, F, l_, u_); }
  // Da, Db at x_; degenerate pairs get the DFK direction z = sum of their unit vectors.
  void row_coefficients() {
    degenerate_.clear();
    for (Eigen::Index i = 0; i < n_; ++i)
      if (!component_grad(kinds_[static_cast<size_t>(i)], x_[i], F_[i], l_[i], u_[i], lambda_, 0.0,
                          0.0, Da_[i], Db_[i]))
        degenerate_.push_back(i);
    if (degenerate_.empty()) return;
    z_.setZero();
    for (const auto i : degenerate_) z_[i] = 1.0;
    la_.jz(z_, jz_);
    for (const auto i : degenerate_)
      component_grad(kinds_[static_cast<size_t>(i)], x_[i], F_[i], l_[i], u_[i], lambda_, 1.0,
                     jz_[i], Da_[i], Db_[i]);
  }
  // Armijo backtracking from t = 1 along d_ (into xt_, Ft_, Phit_); an undefined or non-finite
  // F at a trial point counts as a rejected (too long) step.
  bool line_search(double psi_ref, double gd, double& t, double& psit, SolveResult& r) {
    t = 1.0;
    while (t >= o_.min_step) {
      xt_ = x_ + t * d_;
      ++r.function_evals;
      if (src_.eval(xt_, Ft_)) {
        psit = merit(xt_, Ft_, Phit_);
        if (std::isfinite(psit) && psit <= psi_ref + o_.armijo_sigma * t * gd) return true;
      }
      ++r.line_search_steps;
      t *= o_.backtrack;
    }
    return false;
  }

  const Source& src_;
  Algebra& la_;
  const Vec& l_;
  const Vec& u_;
  const FbNewtonOptions& o_;
  Eigen::Index n_;
  std::vector<BoundKind> kinds_;
  Vec x_, F_, Phi_, Da_, Db_, g_, d_, rhs_, xt_, Ft_, Phit_, tmp_, z_, jz_, best_x_, best_res_x_;
  Vec xp_, Fp_, Phip_;  // previous watchdog trial
  std::vector<Eigen::Index> degenerate_;
  std::vector<double> history_;
  double lambda_ = 1.0;
  int max_iter_ = kDefaultMaxIterations;
};

// Start: options.x0, else the problem's x0, else the origin projected onto [l, u].
Vec start_point(const FbNewtonOptions& o, const Vec& problem_x0, const Vec& l, const Vec& u) {
  if (o.x0.size() > 0) return o.x0;
  if (problem_x0.size() > 0) return problem_x0;
  return Vec::Zero(l.size()).cwiseMax(l).cwiseMin(u);
}

double fd_step_of(const FbNewtonOptions& o) { return o.fd_step > 0 ? o.fd_step : std::sqrt(kEps); }

// Affine problems (LCP / box LCP): F = M z + q, J = M once.
SolveResult solve_affine(const LcpProblem& lcp, const Vec& l, const Vec& u,
                         const FbNewtonOptions& o) {
  const Eigen::Index n = lcp.size();
  AffineSource src(lcp);
  const Vec x0 = start_point(o, Vec(), l, u);
  auto jac_once = [](const Vec&, const Vec&, SolveResult& r) {
    if (r.jacobian_evals == 0) r.jacobian_evals = 1;  // J = M, constant
    return true;
  };
  if (lcp.is_sparse()) {
    SparseAlgebra la(n);
    la.J = &lcp.M_sparse;
    la.symmetric = SparseMat(lcp.M_sparse.transpose()).isApprox(lcp.M_sparse, 0.0);
    FbDriver<AffineSource, SparseAlgebra> drv(src, la, {&l, &u}, o, n);
    return drv.run(x0, jac_once);
  }
  DenseAlgebra la(n);
  la.J = &lcp.M;
  FbDriver<AffineSource, DenseAlgebra> drv(src, la, {&l, &u}, o, n);
  return drv.run(x0, jac_once);
}

}  // namespace

std::string FbNewtonOptions::validate(Eigen::Index n) const {
  std::ostringstream m;
  if (auto c = common.validate(); !c.empty()) return c;
  if (!(armijo_sigma > 0 && armijo_sigma < 0.5))
    m << "armijo_sigma must be in (0, 0.5) (got " << armijo_sigma << ")";
  else if (!(backtrack > 0 && backtrack < 1))
    m << "backtrack must be in (0, 1) (got " << backtrack << ")";
  else if (!(min_step > 0 && min_step < 1))
    m << "min_step must be in (0, 1) (got " << min_step << ")";
  else if (nonmonotone_memory < 1)
    m << "nonmonotone_memory must be >= 1 (got " << nonmonotone_memory << ")";
  else if (!(descent_rho >= 0 && std::isfinite(descent_rho)))
    m << "descent_rho must be finite and >= 0 (got " << descent_rho << ")";
  else if (!(descent_power > 2 && std::isfinite(descent_power)))
    m << "descent_power must be finite and > 2 (got " << descent_power << ")";
  else if (watchdog_steps < 0)
    m << "watchdog_steps must be >= 0 (got " << watchdog_steps << ")";
  else if (max_escapes < 0)
    m << "max_escapes must be >= 0 (got " << max_escapes << ")";
  else if (!(penalty_lambda > 0 && penalty_lambda <= 1))
    m << "penalty_lambda must be in (0, 1] (got " << penalty_lambda << ")";
  else if (!(fd_step >= 0 && fd_step < 1))
    m << "fd_step must be in [0, 1) (got " << fd_step << ")";
  else if (x0.size() != 0 && x0.size() != n)
    m << "x0 has size " << x0.size() << ", expected " << n;
  else if (x0.size() != 0 && !x0.allFinite())
    m << "x0 has a non-finite entry";
  return m.str();
}

SolveResult solve_fb_newton(const LcpProblem& problem, const FbNewtonOptions& options) {
  const std::string what =
      "fb-newton: LCP" + (problem.name.empty() ? "" : " '" + problem.name + "'");
  throw_if_invalid(problem.validate(), what);
  throw_if_invalid(options.validate(problem.size()), what + " options");
  const Eigen::Index n = problem.size();
  const Vec l = Vec::Zero(n), u = Vec::Constant(n, kInf);
  // Iterate on the problem in its natural units (units.hpp), answer in the caller's.
  const LcpUnits units = equilibrated_units(problem);
  FbNewtonOptions o = options;
  if (o.x0.size()) o.x0 = z_to_units(o.x0, units);
  SolveResult r = solve_affine(to_units(problem, units), l, u, o);
  r.z = z_from_units(r.z, units);
  return finalize(problem, std::move(r), options.common);
}

SolveResult solve_fb_newton(const BoxLcpProblem& problem, const FbNewtonOptions& options) {
  const std::string what =
      "fb-newton: box LCP" + (problem.lcp.name.empty() ? "" : " '" + problem.lcp.name + "'");
  throw_if_invalid(problem.validate(), what);
  throw_if_invalid(options.validate(problem.size()), what + " options");
  const LcpUnits units = equilibrated_units(problem.lcp);
  const BoxLcpProblem scaled = to_units(problem, units);
  FbNewtonOptions o = options;
  if (o.x0.size()) o.x0 = z_to_units(o.x0, units);
  SolveResult r = solve_affine(scaled.lcp, scaled.lower, scaled.upper, o);
  r.z = z_from_units(r.z, units);
  return finalize(problem, std::move(r), options.common);
}

SolveResult solve_fb_newton(const McpProblem& problem, const FbNewtonOptions& options) {
  const std::string what =
      "fb-newton: MCP" + (problem.name.empty() ? "" : " '" + problem.name + "'");
  throw_if_invalid(problem.validate(), what);
  throw_if_invalid(options.validate(problem.size()), what + " options");
  const Eigen::Index n = problem.size();
  CallbackSource src;
  src.p = &problem;
  const Vec x0 = start_point(options, problem.x0, problem.lower, problem.upper);
  SolveResult r;
  if (problem.sparse_jacobian) {
    SparseAlgebra la(n);
    la.J = &la.J_own;
    FbDriver<CallbackSource, SparseAlgebra> drv(src, la, {&problem.lower, &problem.upper}, options,
                                                n);
    r = drv.run(x0, [&](const Vec& x, const Vec&, SolveResult& res) {
      ++res.jacobian_evals;
      return eval_sparse_jacobian(problem, x, la);
    });
  } else {
    DenseAlgebra la(n);
    la.J = &la.J_own;
    la.J_own.resize(n, n);
    const double h = fd_step_of(options);
    FbDriver<CallbackSource, DenseAlgebra> drv(src, la, {&problem.lower, &problem.upper}, options,
                                               n);
    r = drv.run(x0, [&](const Vec& x, const Vec& F, SolveResult& res) {
      ++res.jacobian_evals;
      return eval_dense_jacobian(problem, x, F, h, la, res.function_evals);
    });
  }
  return finalize(problem, std::move(r), options.common);
}

SolverEntry fb_newton_entry() {
  SolverEntry e;
  e.info.name = "fb-newton";
  e.info.description =
      "semismooth Newton on the Fischer-Burmeister reformulation, Armijo line search with "
      "gradient fallback; dense LU or sparse LU [De Luca-Facchinei-Kanzow 1996]";
  e.info.dense = true;
  e.info.sparse = true;
  e.solve_lcp = [](const LcpProblem& p, const CommonOptions& c) {
    FbNewtonOptions o;
    o.common = c;
    return solve_fb_newton(p, o);
  };
  e.solve_box_lcp = [](const BoxLcpProblem& p, const CommonOptions& c) {
    FbNewtonOptions o;
    o.common = c;
    return solve_fb_newton(p, o);
  };
  e.solve_mcp = [](const McpProblem& p, const CommonOptions& c) {
    FbNewtonOptions o;
    o.common = c;
    return solve_fb_newton(p, o);
  };
  return e;
}

}  // namespace cpkit::lcp
