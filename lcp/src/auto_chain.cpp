// The automatic solver chain (see auto_chain.hpp).
#include "cpkit/lcp/auto_chain.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/mpcc.hpp"
#include "cpkit/lcp/small_lcp.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp {

const std::vector<std::string>& auto_chain_names(ProblemKind kind) {
  // Built once: a tiny LCP's whole solve costs about as much as four strings' allocation.
  static const std::vector<std::string> lcp{"lemke", "fb-newton", "ipopt", "nlopt"};
  static const std::vector<std::string> other{"fb-newton", "ipopt", "nlopt"};
  return kind == ProblemKind::kLcp ? lcp : other;
}

namespace {

const LcpSolveFn* pick(const SolverEntry& e, const LcpProblem& p) {
  return e.accepts(p) ? &e.solve_lcp : nullptr;
}
const BoxLcpSolveFn* pick(const SolverEntry& e, const BoxLcpProblem&) {
  return e.solve_box_lcp ? &e.solve_box_lcp : nullptr;
}
const McpSolveFn* pick(const SolverEntry& e, const McpProblem&) {
  return e.solve_mcp ? &e.solve_mcp : nullptr;
}

/// Lemke and FB Newton: microseconds to milliseconds; the Farkas LP and the MPCC solvers
/// (Ipopt, NLopt) come after them.
bool is_cheap(const std::string& name) { return name == "lemke" || name == "fb-newton"; }

/// Largest LCP the chain enumerates completely before the expensive solvers.
constexpr Eigen::Index kAutoEnumerationSize = 12;

ProblemKind kind_of(const LcpProblem&) { return ProblemKind::kLcp; }
ProblemKind kind_of(const BoxLcpProblem&) { return ProblemKind::kBoxLcp; }
ProblemKind kind_of(const McpProblem&) { return ProblemKind::kMcp; }

/// Searches a Farkas certificate of infeasibility with Ipopt (an LP; see auto_chain.hpp).
std::optional<Certificate> farkas_search(const LcpProblem& p, const CommonOptions& common,
                                         double time_left) {
  const Eigen::Index n = p.size();
  const Mat M = p.dense_M();
  const Vec q = p.q;
  MpccProblem lp;
  lp.name = "farkas";
  lp.n = n;
  lp.lower = Vec::Zero(n);
  lp.upper = Vec::Constant(n, std::numeric_limits<double>::infinity());
  lp.x0 = Vec::Constant(n, 1.0 / static_cast<double>(n));
  lp.objective = [q](const Vec& y, double& f) { f = q.dot(y); return true; };
  lp.gradient = [q](const Vec&, Vec& g) { g = q; return true; };
  lp.m = n + 1;
  lp.constraints = [M](const Vec& y, Vec& c) {
    c.resize(M.cols() + 1);
    c.head(M.cols()) = M.transpose() * y;
    c(M.cols()) = y.sum();
    return true;
  };
  lp.constraint_jacobian = [M](const Vec&, Mat& J) {
    J.resize(M.cols() + 1, M.rows());
    J.topRows(M.cols()) = M.transpose();
    J.row(M.cols()).setOnes();
    return true;
  };
  lp.c_lower = Vec::Constant(n + 1, -std::numeric_limits<double>::infinity());
  lp.c_upper = Vec::Zero(n + 1);
  lp.c_lower(n) = 1;
  lp.c_upper(n) = 1;
  lp.hessian = [n](const Vec&, double, const Vec&, const Vec&, const Vec&, Mat& Hs) {
    Hs.setZero(n, n);
    return true;
  };
  MpccOptions o;
  o.common.time_limit_s = time_left;
  o.common.log = common.log;
  o.common.verbosity = common.verbosity;
  const MpccResult r = solve_mpcc(lp, o);
  if (!(r.objective < 0) || r.x.size() != n) return std::nullopt;
  Certificate cert;
  cert.y = r.x.cwiseMax(0.0);
  if (!check_certificate(p, cert)) return std::nullopt;
  return cert;
}

/// A runaway point: ||z||_inf > 1e10 z_ref for LCPs, with z_ref = ||q||_inf / ||M||_max the
/// data's own size of z (unit-free; residuals.hpp), and 1e10 (1 + ||finite bounds||) for MCPs.
/// Defence in depth only: finalize()'s test already rejects diverging iterates.
bool diverged(const LcpProblem& p, const Vec& z) {
  const double qn = p.q.lpNorm<Eigen::Infinity>();
  const double mn = p.max_abs_entry();
  if (!(qn > 0 && mn > 0)) return false;  // no data size of z (q = 0 or M = 0)
  return z.lpNorm<Eigen::Infinity>() / 1e10 > qn / mn;
}
bool diverged(const BoxLcpProblem& p, const Vec& z) { return diverged(p.lcp, z); }
bool diverged(const McpProblem& p, const Vec& z) {
  double ref = 1 + (p.x0.size() == p.n ? p.x0.lpNorm<Eigen::Infinity>() : 0.0);
  for (Eigen::Index i = 0; i < p.n; ++i) {
    if (p.lower.size() == p.n && std::isfinite(p.lower(i))) ref = std::max(ref, std::abs(p.lower(i)));
    if (p.upper.size() == p.n && std::isfinite(p.upper(i))) ref = std::max(ref, std::abs(p.upper(i)));
  }
  return z.lpNorm<Eigen::Infinity>() > 1e10 * ref;
}

/// A tiny dense LCP (n <= kSmallLcpMax) whose one solution is proved (a P-matrix's
/// complementary basis, or the complete closed enumeration finding exactly one point): that
/// solution is the answer any solver of the chain must give, found at a tenth of Lemke's cost
/// (issue 37: a C, Fortran or Python code calls this every time step). Decided by finalize();
/// nullopt when the route does not apply or does not verify (the chain then runs as always).
std::optional<SolveResult> tiny_unique(const LcpProblem& p, const CommonOptions& o,
                                       const Stopwatch& timer) {
  const Eigen::Index n = p.size();
  // A trace or a log asks to watch a solver iterate: this route has no iterations to show.
  if (o.record_trace || o.log != nullptr) return std::nullopt;
  if (p.is_sparse() || n < 1 || n > kSmallLcpMax) return std::nullopt;
  double z[kSmallLcpMax], w[kSmallLcpMax], natural = 0;
  if (!solve_small_fast(static_cast<int>(n), p.M.data(), p.q.data(), o.tol, z, w, natural))
    return std::nullopt;
  SolveResult r;
  r.status = Status::kSolved;  // a claim: finalize() decides
  r.solver = "enumeration";
  r.z = Eigen::Map<const Vec>(z, n);
  r = finalize(p, std::move(r), o);
  if (r.status != Status::kSolved) return std::nullopt;
  r.seconds = timer.seconds();
  const char* how = "the one solution of this LCP (n <= 4: a P-matrix basis or the complete "
                    "enumeration)";
  r.attempts.push_back({"enumeration", r.status, r.residuals.natural, r.seconds, how});
  r.message = std::string("auto: answer from enumeration after 1 attempt(s); ") + how;
  return r;
}

template <class Problem>
SolveResult run_chain(const Problem& problem, const CommonOptions& options) {
  throw_if_invalid(problem.validate(), "auto");
  throw_if_invalid(options.validate(), "options");
  Stopwatch timer;
  if constexpr (std::is_same_v<Problem, LcpProblem>) {
    if (auto tiny = tiny_unique(problem, options, timer)) return std::move(*tiny);
  }
  std::vector<Attempt> attempts;
  std::optional<SolveResult> chosen, inaccurate, last;
  bool farkas_done = false;
  // The Farkas LP (LCPs only) runs once, after the cheap solvers have failed and before the
  // first expensive one (Ipopt/NLopt MPCC), or at the end: an Ipopt LP costs ~0.1-1 s where
  // Lemke and FB Newton decide most problems in microseconds (issue 11, sec. 4).
  auto try_farkas = [&](const std::string& after) -> bool {
    if constexpr (std::is_same_v<Problem, LcpProblem>) {
      if (farkas_done || inaccurate || attempts.empty() || solvers().find("ipopt") == nullptr)
        return false;
      farkas_done = true;
      const double left = options.time_limit_s - timer.seconds();
      if (!(left > 0)) return false;
      Stopwatch t;
      auto cert = farkas_search(problem, options, left);
      attempts.push_back({"farkas-search", cert ? Status::kInfeasible : Status::kStalled, 0,
                          t.seconds(),
                          cert ? "certificate y >= 0, M^T y <= 0, q^T y < 0 found (LP by Ipopt)"
                               : "no Farkas certificate found"});
      if (!cert) return false;
      SolveResult proof;
      proof.status = Status::kInfeasible;
      proof.solver = "farkas-search";
      proof.certificate = std::move(*cert);
      proof.message = "infeasible: Farkas certificate found by the LP after " + after;
      chosen = std::move(proof);
      return true;
    } else {
      (void)after;
      return false;
    }
  };
  // Small LCPs (n <= kAutoEnumerationSize): after the cheap solvers and before the expensive
  // ones, the complete enumeration (microseconds to milliseconds there) finds a solution that
  // local methods miss, e.g. on bimatrix games where Lemke with covering vector e ends on a ray.
  bool enumeration_done = false;
  auto try_enumeration = [&]() -> bool {
    if constexpr (std::is_same_v<Problem, LcpProblem>) {
      if (enumeration_done || inaccurate || problem.size() > kAutoEnumerationSize) return false;
      enumeration_done = true;
      EnumerationOptions eo;
      eo.time_limit_s = std::min(1.0, options.time_limit_s - timer.seconds());
      if (!(eo.time_limit_s > 0)) return false;
      Stopwatch t;
      const SolutionSet set = enumerate_all(problem, eo);
      SolveResult r;
      r.solver = "enumeration";
      r.status = Status::kStalled;
      r.message = set.solutions.empty()
                      ? (set.complete ? "complete enumeration: no solution" : "no solution found")
                      : "an extreme solution of the complete enumeration";
      if (!set.solutions.empty()) {
        r.z = set.solutions.front().z;
        r.status = Status::kSolved;  // a claim: finalize() decides
        r = finalize(problem, std::move(r), options);
      }
      r.seconds = t.seconds();
      attempts.push_back({"enumeration", r.status, r.residuals.natural, r.seconds, r.message});
      if (r.status != Status::kSolved) return false;
      chosen = std::move(r);
      return true;
    } else {
      return false;
    }
  };
  for (const std::string& name : auto_chain_names(kind_of(problem))) {
    if (!is_cheap(name) && !attempts.empty() && try_enumeration()) break;
    if (!is_cheap(name) && !attempts.empty() && try_farkas(attempts.back().solver)) break;
    const SolverEntry* entry = solvers().find(name);
    const auto* fn = entry ? pick(*entry, problem) : nullptr;
    if (fn == nullptr) {
      attempts.push_back({name, Status::kNotRun, 0, 0,
                          entry ? "skipped: does not accept this problem"
                                : "skipped: not registered"});
      continue;
    }
    CommonOptions o = options;
    o.time_limit_s = options.time_limit_s - timer.seconds();
    if (!(o.time_limit_s > 0)) {
      attempts.push_back({name, Status::kTimeLimit, 0, 0, "skipped: time limit reached"});
      break;
    }
    SolveResult r;
    try {
      r = (*fn)(problem, o);
    } catch (const InputError&) {
      throw;  // misuse is the caller's error, not the solver's outcome
    } catch (const std::exception& e) {
      r.status = Status::kNumericalFailure;
      r.solver = name;
      r.message = std::string("exception: ") + e.what();
    }
    if (r.solver.empty()) r.solver = name;
    if (is_solution(r.status) && diverged(problem, r.z)) {
      // A runaway z is not an answer (defence in depth against a residual scale growing with z).
      r.status = Status::kNumericalFailure;
      r.message += "; rejected by auto: ||z||_inf = " +
                   std::to_string(r.z.lpNorm<Eigen::Infinity>()) + " counts as diverged";
      r.z.resize(0);
    }
    attempts.push_back({name, r.status, r.residuals.natural, r.seconds, r.message});
    if (r.status == Status::kSolved || r.status == Status::kInfeasible) {
      chosen = std::move(r);
      break;
    }
    if (r.status == Status::kSolvedInaccurate && !inaccurate) inaccurate = r;
    last = std::move(r);
  }
  if (!chosen && !attempts.empty() && attempts.back().solver != "farkas-search")
    try_farkas(attempts.back().solver);
  SolveResult result;
  if (chosen) result = std::move(*chosen);
  else if (inaccurate) result = std::move(*inaccurate);
  else if (last) result = std::move(*last);
  else result.message = "no solver of the chain could run";
  // Plain concatenation, not a stream: a stream's set-up is a tenth of a tiny LCP's solve.
  std::string msg = "auto: ";
  if (is_solution(result.status) || result.status == Status::kInfeasible)
    msg += "answer from " + result.solver;
  else
    msg += "no solver succeeded";
  msg += " after " + std::to_string(attempts.size()) + " attempt(s)";
  if (!result.message.empty()) msg += "; " + result.message;
  result.message = std::move(msg);
  result.attempts = std::move(attempts);
  result = finalize(problem, std::move(result), options);
  result.seconds = timer.seconds();
  return result;
}

}  // namespace

SolveResult solve_auto(const LcpProblem& problem, const CommonOptions& options) {
  return run_chain(problem, options);
}
SolveResult solve_auto(const BoxLcpProblem& problem, const CommonOptions& options) {
  return run_chain(problem, options);
}
SolveResult solve_auto(const McpProblem& problem, const CommonOptions& options) {
  return run_chain(problem, options);
}

SolverEntry auto_entry() {
  SolverEntry e;
  e.info.name = "auto";
  e.info.description =
      "automatic chain: lemke, fb-newton, ipopt for LCPs; fb-newton, ipopt for box LCPs and "
      "MCPs; first verified answer (docs/mpcc.md)";
  e.info.dense = true;
  e.info.sparse = true;
  e.info.serialized = false;
  e.solve_lcp = [](const LcpProblem& p, const CommonOptions& o) { return solve_auto(p, o); };
  e.solve_box_lcp = [](const BoxLcpProblem& p, const CommonOptions& o) {
    return solve_auto(p, o);
  };
  e.solve_mcp = [](const McpProblem& p, const CommonOptions& o) { return solve_auto(p, o); };
  return e;
}

}  // namespace cpkit::lcp
