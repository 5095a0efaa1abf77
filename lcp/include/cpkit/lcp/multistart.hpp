#pragma once
/// \file multistart.hpp
/// Multistart search for additional solutions of an NCP/MCP where complete enumeration does
/// not apply (nonlinear F). Local solves from a documented, seeded set of points; distinct
/// verified solutions are collected and deduplicated. THE RESULT NEVER CLAIMS COMPLETENESS: a
/// solution no start led to is simply not found.
///
/// Problem: MCP(F, l, u) as in cpkit/core/problem.hpp (an NCP is l = 0, u = +inf).
///
/// Starting points: for k = 0 .. starts-1, s_k is drawn uniformly from the sampling box
/// [sample_lower, sample_upper] with std::mt19937_64(seed) (53-bit uniforms, so the sequence is
/// the same on every platform). Default box, per index: lower = l_i - 1 when l_i is finite,
/// else -10; upper = u_i + 1 when u_i is finite, else max(lower, 0) + 10.
/// At each s_k:
///   1. every solver of `local_solvers` (registry names, looked up in cpkit::lcp::solvers();
///      unknown names are skipped) is started from x0 = proj_[l,u](s_k);
///   2. when `selection` is set, the MPCC with the selection objective 1/2 ||x - s_k||^2 is
///      solved by Ipopt (solve_mcp_mpcc with reference s_k): it finds the solution nearest s_k
///      (locally), which reaches the ends and corners of solution continua that plain local
///      solvers rarely land on.
/// Every answer goes through finalize() (inside each solver); only kSolved points are kept.
/// Two points are the same solution when ||a - b||_inf <= dedup_tol max(||a||_inf, ||b||_inf)
/// (relative: the same in any units); the first one found is kept and its `hits` counted.
#include <cstdint>
#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"

namespace cpkit::lcp {

struct MultistartOptions {
  CommonOptions common;  ///< passed to every local solve (time_limit_s: for the whole search)
  int starts = 20;
  std::uint64_t seed = 1;
  Vec sample_lower;      ///< empty: the default box above
  Vec sample_upper;
  std::vector<std::string> local_solvers = {"fb-newton"};
  bool selection = true;  ///< also run the Ipopt MPCC with the selection objective
  double dedup_tol = 1e-6;
  std::string validate(Eigen::Index n) const;
};

struct MultistartSolution {
  Vec x;
  double residual = 0;   ///< scaled natural residual (finalize())
  std::string solver;    ///< who found it first ("fb-newton", "ipopt-selection", ...)
  int first_start = 0;   ///< index k of the start that found it first
  int hits = 0;          ///< how many local solves ended at it
};

struct MultistartResult {
  std::vector<MultistartSolution> solutions;  ///< distinct verified solutions, in order found
  int starts_run = 0;
  int local_solves = 0;
  int failed_solves = 0;  ///< local solves that ended without a verified solution
  double seconds = 0;
  std::string message;    ///< always states that the list may be incomplete
};

/// Throws InputError for an invalid problem or options.
MultistartResult multistart_ncp(const McpProblem& problem, const MultistartOptions& options = {});

}  // namespace cpkit::lcp
