// Multistart search for additional NCP/MCP solutions (see multistart.hpp).
#include "cpkit/lcp/multistart.hpp"

#include <cmath>
#include <random>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/mpcc_solvers.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "uniform01.hpp"

namespace cpkit::lcp {

std::string MultistartOptions::validate(Eigen::Index n) const {
  if (auto msg = common.validate(); !msg.empty()) return msg;
  if (starts < 1) return "starts = " + std::to_string(starts) + " must be >= 1";
  if (!(dedup_tol > 0) || !std::isfinite(dedup_tol)) return "dedup_tol must be positive";
  if (sample_lower.size() != sample_upper.size())
    return "sample_lower and sample_upper must both be empty or both have size n";
  if (sample_lower.size() != 0) {
    if (sample_lower.size() != n) return "sample box has size " +
                                         std::to_string(sample_lower.size()) + ", expected " +
                                         std::to_string(n);
    if (!sample_lower.allFinite() || !sample_upper.allFinite())
      return "sample box has non-finite entries";
    for (Eigen::Index i = 0; i < n; ++i)
      if (sample_lower(i) > sample_upper(i))
        return "sample_lower[" + std::to_string(i) + "] > sample_upper[" + std::to_string(i) + "]";
  }
  if (local_solvers.empty() && !selection) return "no local solver and selection off";
  return {};
}

namespace {

using detail::uniform01;

// Relative to the points' own size (no absolute floor: the same in any units; two zero vectors
// are the same).
bool same(const Vec& a, const Vec& b, double tol) {
  const double s = std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>());
  return (a - b).lpNorm<Eigen::Infinity>() <= tol * s;
}

}  // namespace

MultistartResult multistart_ncp(const McpProblem& problem, const MultistartOptions& options) {
  throw_if_invalid(problem.validate(), "multistart problem");
  throw_if_invalid(options.validate(problem.n), "multistart options");
  Stopwatch timer;
  const Eigen::Index n = problem.n;
  const Vec l = problem.lower.size() == n ? problem.lower : Vec::Zero(n);
  const Vec u = problem.upper.size() == n
                    ? problem.upper
                    : Vec::Constant(n, std::numeric_limits<double>::infinity());
  Vec lo = options.sample_lower, hi = options.sample_upper;
  if (lo.size() == 0) {
    lo.resize(n);
    hi.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      lo(i) = std::isfinite(l(i)) ? l(i) - 1 : -10.0;
      hi(i) = std::isfinite(u(i)) ? u(i) + 1 : std::max(lo(i), 0.0) + 10.0;
    }
  }
  MultistartResult out;
  std::mt19937_64 rng(options.seed);
  auto record = [&](const SolveResult& r, const std::string& who, int k) {
    ++out.local_solves;
    if (r.status != Status::kSolved) {
      ++out.failed_solves;
      return;
    }
    for (auto& s : out.solutions)
      if (same(s.x, r.z, options.dedup_tol)) {
        ++s.hits;
        return;
      }
    out.solutions.push_back({r.z, r.residuals.natural, who, k, 1});
  };
  bool timed_out = false;
  for (int k = 0; k < options.starts; ++k) {
    Vec s(n);
    for (Eigen::Index i = 0; i < n; ++i) s(i) = lo(i) + uniform01(rng) * (hi(i) - lo(i));
    CommonOptions common = options.common;
    common.time_limit_s = options.common.time_limit_s - timer.seconds();
    if (!(common.time_limit_s > 0)) {
      timed_out = true;
      break;
    }
    ++out.starts_run;
    McpProblem local = problem;
    local.x0 = s.cwiseMax(l).cwiseMin(u);
    for (const auto& name : options.local_solvers) {
      const SolverEntry* e = solvers().find(name);
      if (e == nullptr || !e->solve_mcp) continue;
      SolveResult r;
      try {
        r = e->solve_mcp(local, common);
      } catch (const InputError&) {
        throw;
      } catch (const std::exception& ex) {
        r.status = Status::kNumericalFailure;
        r.message = ex.what();
      }
      record(r, name, k);
    }
    if (options.selection) {
      ComplementarityMpccOptions o;
      o.mpcc.common = common;
      o.reference = s;
      o.restarts = 0;
      McpProblem sel = problem;
      sel.x0 = local.x0;
      record(solve_mcp_mpcc(sel, o), "ipopt-selection", k);
    }
  }
  out.seconds = timer.seconds();
  std::ostringstream msg;
  msg << out.solutions.size() << " distinct solution(s) from " << out.starts_run << " start(s), "
      << out.local_solves << " local solve(s) (" << out.failed_solves
      << " without a verified solution)";
  if (timed_out) msg << "; time limit reached";
  msg << "; a multistart search cannot prove that no other solution exists";
  out.message = msg.str();
  return out;
}

}  // namespace cpkit::lcp
