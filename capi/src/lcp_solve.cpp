// cpkit_lcp_solve and cpkit_lcp_solve_batch: for n <= 4 ("auto", "lemke") the closed enumeration
// on the stack when it proves a unique solution that the verdict accepts (cpkit/lcp/small_lcp.hpp);
// otherwise the problem mapped into the library's LcpProblem and solved by the registered
// solver. Every answer is decided by finalize()'s verdict (the fast path computes the same
// number and accepts only what finalize() would call solved).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "c_boundary.hpp"
#include "finite_check.hpp"
#include "cpkit/lcp/small_lcp.hpp"
#include "cpkit/core/errors.hpp"

namespace cpkit::capi {
namespace {

/// A thread's problem and result, reused from call to call so that a small solve allocates
/// nothing for its data; problems larger than this are not kept alive after their call.
constexpr int kKeptSize = 64;
struct LcpWorkspace {
  LcpProblem problem;
  SolveResult result;
};

/// What a caller of solve_one reports: the code, and for cpkit_info the iterations and the
/// unit-free residual.
struct Outcome {
  int code = 0;
  int iterations = 0;
  double residual = 0;
};

/// Solves problem (M, q) of size n into z, w through the library's types, with `ws.result`
/// holding the decision (its message explains a code != 0).
Outcome solve_general(int n, const double* M, const double* q, const SolverEntry& entry,
                      const CommonOptions& o, double* z, double* w, LcpWorkspace& ws) {
  Outcome out;
  LcpProblem& p = ws.problem;
  p.M = Eigen::Map<const Mat>(M, n, n);
  p.q = Eigen::Map<const Vec>(q, n);
  SolveResult& r = ws.result;
  if (!lcp::solve_small_unique(p, entry, o, r)) {
    if (!entry.accepts(p))
      throw InputError("solver '" + entry.info.name + "' does not accept dense LCPs");
    r = entry.solve_lcp(p, o);  // through finalize(), as every registered solver
  }
  const bool full = r.z.size() == n && r.w.size() == n;
  for (int i = 0; i < n; ++i) {
    z[i] = full ? r.z[i] : NAN;
    w[i] = full ? r.w[i] : NAN;
  }
  out.code = lcp_code(r.status);
  out.iterations = r.iterations;
  out.residual = r.residuals.natural;
  return out;
}

std::string outcome_message(const SolveResult& r) {
  return "cpkit: " + std::string(to_string(r.status)) + (r.message.empty() ? "" : ": " + r.message);
}

LcpWorkspace& workspace(int n, std::optional<LcpWorkspace>& large) {
  thread_local LcpWorkspace kept;
  return n <= kKeptSize ? kept : large.emplace();
}

}  // namespace
}  // namespace cpkit::capi

using namespace cpkit;
using namespace cpkit::capi;
using cpkit::lcp::small_lcp_route;
using cpkit::lcp::solve_small_fast;

extern "C" int cpkit_lcp_solve(int n, const double* M, const double* q, const char* solver,
                               const cpkit_options* options, double* z, double* w,
                               cpkit_info* info) {
  return guarded(info, [&](cpkit_info& out) {
    check_positive(n, "n");
    require(M, "M");
    require(q, "q");
    require(z, "z");
    require(w, "w");
    const CommonOptions o = common_options(options);
    const SolverEntry& entry = solver_entry(solver, ProblemKind::kLcp);
    check_finite(M, static_cast<long long>(n) * n, "M");
    check_finite(q, n, "q");
    // A tiny problem with one solution: the allocation-free path (solve_small_fast).
    if (small_lcp_route(n, entry) && solve_small_fast(n, M, q, o.tol, z, w, out.residual))
      return 0;
    std::optional<LcpWorkspace> large;
    LcpWorkspace& ws = workspace(n, large);
    const Outcome one = solve_general(n, M, q, entry, o, z, w, ws);
    out.iterations = one.iterations;
    out.residual = one.residual;
    if (one.code != 0) set_message(out, outcome_message(ws.result));
    return one.code;
  });
}

extern "C" int cpkit_lcp_solve_batch(int count, int n, const double* M, const double* q,
                                     const char* solver, const cpkit_options* options, double* z,
                                     double* w, int* status, cpkit_info* info) {
  return guarded(info, [&](cpkit_info& out) {
    if (count < 0) throw InputError("count must be >= 0, got " + std::to_string(count));
    check_positive(n, "n");
    if (count == 0) return 0;
    require(M, "M");
    require(q, "q");
    require(z, "z");
    require(w, "w");
    const CommonOptions o = common_options(options);
    const SolverEntry& entry = solver_entry(solver, ProblemKind::kLcp);
    const long long nn = static_cast<long long>(n) * n;
    // Every problem checked first: a NaN in problem 900 must not leave 899 answers written.
    for (int k = 0; k < count; ++k) {
      const double* q_k = q + static_cast<long long>(k) * n;
      if (all_finite(M + k * nn, nn) && all_finite(q_k, n)) continue;
      check_finite(M + k * nn, nn, "M of problem " + std::to_string(k));
      check_finite(q_k, n, "q of problem " + std::to_string(k));
    }
    std::optional<LcpWorkspace> large;
    LcpWorkspace& ws = workspace(n, large);
    int first = 0;
    const bool small = small_lcp_route(n, entry);
    for (int k = 0; k < count; ++k) {
      const long long at = static_cast<long long>(k) * n;
      Outcome one;
      if (!small || !solve_small_fast(n, M + k * nn, q + at, o.tol, z + at, w + at, one.residual))
        one = solve_general(n, M + k * nn, q + at, entry, o, z + at, w + at, ws);
      if (status != nullptr) status[k] = one.code;
      out.iterations += one.iterations;
      out.residual = std::max(out.residual, one.residual);
      if (one.code != 0 && first == 0) {
        first = one.code;
        set_message(out, "problem " + std::to_string(k) + ": " + outcome_message(ws.result));
      }
    }
    return first;
  });
}
