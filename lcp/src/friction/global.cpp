// Global frictional contact problems by condensation (global.hpp).
#include "cpkit/lcp/friction/global.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp::friction {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Ldlt = Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kRhoShrink = 10;    // global proximal route: rho_{k+1} = rho_k / 10 ...
constexpr double kRhoFloor = 1e-6;   // ... but at least 1e-6 max|M_ii|
constexpr int kRhoStagnation = 20;   // outer steps without halving the verdict's number

double max_abs(const Sparse& A) {
  double m = 0;
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (Sparse::InnerIterator it(A, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

// Empty when M is symmetric positive definite to rounding: symmetric to 1e2 eps of ||M||_max,
// every pivot of LDL^T positive and above m eps of the largest (a smaller one is rounding of a
// zero: M singular, e.g. a free rigid body without mass on some degree of freedom).
std::string factorize(const Sparse& M, Ldlt& ldlt) {
  const double big = max_abs(M);
  if (big == 0) return "M is zero";
  const Sparse asym = Sparse(M.transpose()) - M;
  if (max_abs(asym) > 1e2 * kEps * big)
    return "M is not symmetric (max |M - M^T| = " + short_number(max_abs(asym)) + ")";
  ldlt.compute(M);
  if (ldlt.info() != Eigen::Success) return "M is singular (its LDL^T factorization met a zero pivot)";
  const Eigen::VectorXd d = ldlt.vectorD();
  const double dmax = d.cwiseAbs().maxCoeff();
  const double floor = static_cast<double>(M.rows()) * kEps * dmax;
  for (Eigen::Index i = 0; i < d.size(); ++i)
    if (!(d[i] > floor))
      return d[i] < -floor ? "M is not positive semidefinite (an LDL^T pivot is negative)"
                           : "M is singular (an LDL^T pivot is zero to rounding)";
  return {};
}

}  // namespace

CondensedProblem condense(const GlobalFrictionContactProblem& g) {
  throw_if_invalid(g.validate(), "global friction problem" + (g.name.empty() ? "" : " '" + g.name + "'"));
  CondensedProblem c;
  c.local.name = g.name;
  c.local.note = g.note;
  c.local.mu = g.mu;
  Ldlt ldlt;
  c.message = factorize(g.M, ldlt);
  if (!c.message.empty()) {
    c.message += ": not condensed (no solver in the global variables yet)";
    return c;
  }
  const Sparse X = ldlt.solve(g.H);  // M^-1 H by sparse solves
  Sparse W = Sparse(g.H.transpose()) * X;
  W = 0.5 * (W + Sparse(W.transpose()));  // symmetric as H^T M^-1 H is, to rounding
  W.prune(0.0);
  c.local.W = W;
  const Eigen::VectorXd Mf = ldlt.solve(g.f);
  c.local.q = g.H.transpose() * Mf + g.w;
  c.ok = true;
  return c;
}

GlobalErrors global_errors(const GlobalFrictionContactProblem& g,
                           const FrictionContactProblem& condensed, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& r) {
  if (v.size() != g.dofs() || r.size() != g.H.cols())
    throw InputError("global friction verdict: v needs " + std::to_string(g.dofs()) +
                     " entries and r " + std::to_string(g.H.cols()));
  GlobalErrors e;
  if (!v.allFinite() || !r.allFinite()) {
    e.balance = e.local = std::numeric_limits<double>::infinity();
    return e;
  }
  const Eigen::VectorXd res = g.M * v - g.H * r - g.f;
  const Eigen::VectorXd size = g.M.cwiseAbs() * v.cwiseAbs() + g.H.cwiseAbs() * r.cwiseAbs() +
                               g.f.cwiseAbs();
  for (Eigen::Index k = 0; k < res.size(); ++k)
    if (res[k] != 0) e.balance = std::max(e.balance, std::abs(res[k]) / size[k]);
  const Eigen::VectorXd u = g.H.transpose() * v + g.w;
  e.local = friction_residuals(condensed, friction_units(condensed), r, u).natural;
  return e;
}

GlobalSolveResult solve_global(const GlobalFrictionContactProblem& g, const std::string& solver,
                               const CommonOptions& o) {
  const Stopwatch clock;
  throw_if_invalid(o.validate(), "solver options");
  const SolverEntry* entry = lcp::solvers().find(solver);
  if (entry == nullptr || !entry->accepts(ProblemKind::kFrictionContact))
    throw InputError("unknown friction solver '" + solver + "'");
  GlobalSolveResult out;
  out.condensed = condense(g);
  const CondensedProblem& c = out.condensed;
  out.result.solver = entry->info.name;
  if (!c.ok) {
    out.result.status = Status::kNotRun;
    out.result.message = c.message;
    out.result.seconds = clock.seconds();
    return out;
  }
  CommonOptions lo = o;
  lo.time_limit_s = o.time_limit_s - clock.seconds();
  SolveResult local = entry->solve_fc(c.local, lo);
  if (local.solver.empty()) local.solver = entry->info.name;
  out.result = std::move(local);
  if (out.result.z.size() != g.H.cols()) {
    out.result.seconds = clock.seconds();
    return out;  // no candidate: the local status says why
  }
  Ldlt ldlt;
  ldlt.compute(g.M);  // factorize() accepted M above
  const Eigen::VectorXd& r = out.result.z;
  out.v = ldlt.solve(g.H * r + g.f);
  out.v += ldlt.solve(g.H * r + g.f - g.M * out.v);  // one step of refinement
  out.errors = global_errors(g, c.local, out.v, r);
  out.result.w = g.H.transpose() * out.v + g.w;
  const double worst = std::max(out.errors.balance, out.errors.local);
  const Status local_status = out.result.status;
  if (worst <= o.tol) {
    out.result.status = Status::kSolved;
  } else if (worst <= o.tol_acceptable) {
    out.result.status = Status::kSolvedInaccurate;
  } else if (is_solution(local_status)) {
    out.result.status = Status::kNumericalFailure;
    out.result.message = "the condensed solution fails the global verdict (balance " +
                         short_number(out.errors.balance) + ", local " +
                         short_number(out.errors.local) + ")";
  }
  out.result.seconds = clock.seconds();
  return out;
}

GlobalSolveResult solve_global_proximal(const GlobalFrictionContactProblem& g,
                                        const std::string& solver, const CommonOptions& o,
                                        double rho_factor) {
  const Stopwatch clock;
  throw_if_invalid(g.validate(),
                   "global friction problem" + (g.name.empty() ? "" : " '" + g.name + "'"));
  throw_if_invalid(o.validate(), "solver options");
  if (!(rho_factor > 0) || !std::isfinite(rho_factor))
    throw InputError("rho_factor must be positive and finite");
  GlobalSolveResult out;
  out.result.solver = solver;
  const double big = max_abs(g.M);
  const double asym = max_abs(Sparse(g.M.transpose()) - g.M);
  double diag = 0;
  for (Eigen::Index i = 0; i < g.M.rows(); ++i) diag = std::max(diag, std::abs(g.M.coeff(i, i)));
  if (big == 0 || asym > 1e2 * kEps * big || diag == 0) {
    out.result.status = Status::kNotRun;
    out.result.message = big == 0    ? "M is zero: no scale for the proximal term"
                         : diag == 0 ? "M has a zero diagonal: no scale for the proximal term"
                                     : "M is not symmetric";
    out.result.seconds = clock.seconds();
    return out;
  }
  double rho = rho_factor * diag;
  Sparse I(g.M.rows(), g.M.cols());
  I.setIdentity();
  GlobalFrictionContactProblem reg = g;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(g.dofs());
  const int max_outer = o.max_iterations > 0 ? o.max_iterations : 200;
  int k = 0, progress_k = 0;
  double progress = std::numeric_limits<double>::infinity();
  Status stop = Status::kIterationLimit;
  for (; k < max_outer; ++k) {
    if (clock.exceeded(o.time_limit_s)) {
      stop = Status::kTimeLimit;
      break;
    }
    reg.M = g.M + rho * I;
    reg.f = g.f + rho * v;
    CommonOptions io = o;
    io.max_iterations = 0;  // the inner solver's own default
    io.time_limit_s = o.time_limit_s - clock.seconds();
    GlobalSolveResult in = solve_global(reg, solver, io);
    if (!in.condensed.ok || in.v.size() != g.dofs() || in.result.z.size() != g.H.cols()) {
      out = std::move(in);
      stop = Status::kNumericalFailure;
      out.result.message = "regularized problem " + std::to_string(k) + ": " + out.result.message;
      break;
    }
    v = in.v;
    out = std::move(in);
    // rho falls geometrically (as prox's alpha, prox.hpp) down to a floor that keeps M + rho I
    // clear of the condensation's singularity test (pivots above m eps of the largest).
    rho = std::max(rho / kRhoShrink, kRhoFloor * diag);
    out.errors = global_errors(g, out.condensed.local, v, out.result.z);
    const double worst = std::max(out.errors.balance, out.errors.local);
    if (worst <= o.tol) {
      stop = Status::kSolved;
      ++k;
      break;
    }
    // Stagnation: no halving of the verdict's number in kRhoStagnation outer steps (a problem
    // without solution: v grows and each regularized problem gets harder to solve).
    if (worst <= 0.5 * progress) {
      progress = worst;
      progress_k = k;
    } else if (k - progress_k >= kRhoStagnation) {
      stop = Status::kStalled;
      ++k;
      break;
    }
  }
  if (out.v.size() == g.dofs()) out.result.w = g.H.transpose() * out.v + g.w;
  const double worst = std::max(out.errors.balance, out.errors.local);
  if (stop == Status::kSolved) {
    out.result.status = Status::kSolved;
  } else if (out.v.size() == g.dofs() && worst <= o.tol_acceptable) {
    out.result.status = Status::kSolvedInaccurate;
  } else {
    out.result.status = stop;
  }
  out.result.iterations = k;
  out.result.message = "global proximal point (rho = " + short_number(rho_factor) +
                       " max|M_ii|): " + std::to_string(k) + " outer iterations, balance " +
                       short_number(out.errors.balance) + ", local " +
                       short_number(out.errors.local) +
                       (out.result.message.empty() ? "" : "; last inner: " + out.result.message);
  out.result.seconds = clock.seconds();
  return out;
}

}  // namespace cpkit::lcp::friction
