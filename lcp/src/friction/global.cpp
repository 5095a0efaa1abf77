// Global frictional contact problems by condensation (global.hpp).
#include "cpkit/lcp/friction/global.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

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

// What M is, with the words of a refusal: positive definite (no words) when symmetric to 1e2 eps
// of ||M||_max and every pivot of LDL^T is positive and above m eps of the largest (a smaller one
// is rounding of a zero: M singular, e.g. a free rigid body without mass on some degree of
// freedom).
std::pair<MassMatrix, std::string> factorize(const Sparse& M, Ldlt& ldlt) {
  const double big = max_abs(M);
  if (big == 0) return {MassMatrix::kZero, "M is zero"};
  const Sparse asym = Sparse(M.transpose()) - M;
  if (max_abs(asym) > 1e2 * kEps * big)
    return {MassMatrix::kNotSymmetric,
            "M is not symmetric (max |M - M^T| = " + short_number(max_abs(asym)) + ")"};
  ldlt.compute(M);
  if (ldlt.info() != Eigen::Success)
    return {MassMatrix::kSingular, "M is singular (its LDL^T factorization met a zero pivot)"};
  const Eigen::VectorXd d = ldlt.vectorD();
  const double dmax = d.cwiseAbs().maxCoeff();
  const double floor = static_cast<double>(M.rows()) * kEps * dmax;
  for (Eigen::Index i = 0; i < d.size(); ++i)
    if (!(d[i] > floor))
      return d[i] < -floor
                 ? std::pair{MassMatrix::kIndefinite,
                             std::string("M is not positive semidefinite (an LDL^T pivot is negative)")}
                 : std::pair{MassMatrix::kSingular,
                             std::string("M is singular (an LDL^T pivot is zero to rounding)")};
  return {MassMatrix::kPositiveDefinite, {}};
}

// gamma_k = k u / (1 - k u), u = eps / 2 [Higham 2002, Lemma 3.1].
double gamma_bound(double k) {
  const double ku = k * kEps / 2;
  return ku < 0.5 ? ku / (1 - ku) : std::numeric_limits<double>::infinity();
}

// The local number of (r, u = H^T v + w) in the global problem's own units (global.hpp). u is
// w + H^T M^-1 (H r + f): its row k has the unit s_k = |w_k| + (|H^T| v_size)_k, with
// v_size_j = (|f_j| + (|H| rc)_j) / M_jj the size the balance's terms give v_j on a degree of
// freedom with mass (rc: r entry by entry, capped at the condensed problem's cap_i, so that a
// diverging r gains nothing), never v itself (v = 0 at a stick by cancellation). A rounded
// rank-deficient M (a rigid mode) makes the condensed W and v huge along the mode; these units
// stay at the data's size, so a penetration u_N = -7782 next to |f| ~ 3 is seen
// (hostile-friction F4-02). u_k is formed in twice the working precision (Dot2) where some |v_j|
// exceeds v_size_j, as the local verdict does where r exceeds its cap.
double local_in_global_units(const GlobalFrictionContactProblem& g,
                             const FrictionContactProblem& condensed, const Eigen::VectorXd& v,
                             const Eigen::VectorXd& r) {
  const Eigen::Index m = g.dofs(), nc = g.contacts();
  const FrictionUnits cond = friction_units(condensed);
  Eigen::VectorXd rc = r.cwiseAbs();
  if (cond.r_cap.size() == nc)
    for (Eigen::Index i = 0; i < 3 * nc; ++i) rc[i] = std::min(rc[i], cond.r_cap[i / 3]);
  const Eigen::VectorXd force = g.f.cwiseAbs() + g.H.cwiseAbs() * rc;
  const Eigen::VectorXd diag = g.M.diagonal();
  Eigen::VectorXd v_size(m);
  for (Eigen::Index j = 0; j < m; ++j)  // no mass on j: v_j's own size is all there is
    v_size[j] = diag[j] > 0 ? force[j] / diag[j] : std::abs(v[j]);
  // d_i: the largest entry of contact i's block of the condensed W (u per r), when there is one.
  Eigen::VectorXd block = Eigen::VectorXd::Zero(nc);
  if (condensed.W.rows() == 3 * nc)
    for (Eigen::Index k = 0; k < condensed.W.outerSize(); ++k)
      for (Sparse::InnerIterator it(condensed.W, k); it; ++it)
        if (it.row() / 3 == it.col() / 3)
          block[k / 3] = std::max(block[k / 3], std::abs(it.value()));
  double worst = 0;
  for (Eigen::Index i = 0; i < nc; ++i) {
    Vec3 u_reduced;
    ContactUnits3 units;
    double c_max = 0;
    bool verifiable = true;
    for (int jr = 0; jr < 3; ++jr) {
      const Eigen::Index k = 3 * i + jr;  // column k of H is row k of H^T
      double c = 0, full = 0, plain = g.w[k], s = g.w[k], comp = 0, count = 1;  // c: (|H^T| v_size)_k
      for (Sparse::InnerIterator it(g.H, k); it; ++it) {
        const double h = it.value(), x = v[it.row()];
        c += std::abs(h) * v_size[it.row()];
        full += std::abs(h * x);
        plain += h * x;
        const double p = h * x, e = std::fma(h, x, -p), t = s + p, z = t - s;  // Dot2
        comp += ((s - (t - z)) + (p - z)) + e;
        s = t;
        count += 1;
      }
      const double wk = std::abs(g.w[k]), gk = gamma_bound(count);
      double a = gk * (c + wk), uk = plain;
      if (full > c) {  // some |v_j| beyond v_size_j
        uk = s + comp;
        if (gk * gk * (full + wk) > a) verifiable = false;
        a += 2 * kEps * std::abs(uk) + gk * gk * (full + wk);
      }
      c_max = std::max(c_max, c);
      if (jr == 0) units.s_N = wk + c;
      u_reduced[jr] = std::copysign(std::max(0.0, std::abs(uk) - a), uk);
    }
    units.S = g.w.segment<3>(3 * i).norm() + c_max;
    const double r_own = r.segment<3>(3 * i).lpNorm<Eigen::Infinity>();
    units.R = block[i] > 0 ? std::max(r_own, units.S / block[i]) : r_own;
    const double e = judge_contact(r.segment<3>(3 * i), u_reduced, units, g.mu[i]).error;
    worst = std::max(worst, verifiable ? e : std::numeric_limits<double>::infinity());
  }
  return worst;
}

}  // namespace

CondensedProblem condense(const GlobalFrictionContactProblem& g) {
  throw_if_invalid(g.validate(), "global friction problem" + (g.name.empty() ? "" : " '" + g.name + "'"));
  CondensedProblem c;
  c.local.name = g.name;
  c.local.note = g.note;
  c.local.mu = g.mu;
  Ldlt ldlt;
  std::tie(c.mass, c.message) = factorize(g.M, ldlt);
  if (c.mass != MassMatrix::kPositiveDefinite) {
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
  e.local = local_in_global_units(g, condensed, v, r);
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
  lo.time_limit_s = o.time_limit_s - clock.seconds();  // read once: a solver refuses <= 0
  if (!(lo.time_limit_s > 0)) {
    out.result.status = Status::kTimeLimit;
    out.result.message = "time limit reached before the local solve";
    out.result.seconds = clock.seconds();
    return out;
  }
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
    // The time left, read once (read twice it could pass 0 in between, and a solver refuses a
    // time limit <= 0 as bad input).
    const double left = o.time_limit_s - clock.seconds();
    if (!(left > 0)) {
      stop = Status::kTimeLimit;
      break;
    }
    reg.M = g.M + rho * I;
    reg.f = g.f + rho * v;
    CommonOptions io = o;
    io.max_iterations = 0;  // the inner solver's own default
    io.time_limit_s = left;
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
