#pragma once
/// \file mpcc_solvers.hpp
/// Complementarity problems solved as MPCCs (mpcc.hpp) by Ipopt or NLopt, optionally selecting
/// a particular solution by an objective [Luo, Pang & Ralph 1996; Leyffer 2006 for NCP-as-MPCC].
///
/// LCP(M, q):  z >= 0, w = M z + q >= 0, z . w = 0  becomes the MPCC
///   minimize  phi(z)  s.t.  0 <= z  _|_  M z + q >= 0,
/// NCP(F) likewise with F(z); an MCP with bounds l <= x <= u uses, per index,
///   l finite, u infinite:  0 <= x_i - l_i _|_ F_i(x) >= 0;
///   l infinite, u finite:  0 <= u_i - x_i _|_ -F_i(x) >= 0;
///   both infinite:         F_i(x) = 0 (an equality constraint);
///   both finite:           F_i(x) = a_k - b_k with extra variables a_k, b_k >= 0 and
///                          0 <= x_i - l_i _|_ a_k >= 0, 0 <= u_i - x_i _|_ b_k >= 0.
/// The selection objective is phi = 0 (any solution) or phi = 1/2 ||z - reference||^2 (the
/// solution nearest the reference, locally). For LCPs and box LCPs the exact Hessian is used;
/// for nonlinear MCPs (no second derivatives in McpProblem) Ipopt's limited-memory Hessian.
///
/// The MPCC's point is then polished by an active-set Newton step (free set from the natural
/// map, Jacobian of F on it; for an LCP one linear solve) when that lowers the natural residual,
/// and the answer goes through cpkit::finalize() on the ORIGINAL problem: an MPCC point that is
/// not complementary to tolerance is never "solved". Never kInfeasible (no certificate).
#include <cstdint>

#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/mpcc.hpp"

namespace cpkit::lcp {

struct ComplementarityMpccOptions {
  /// mpcc.common is the CommonOptions of the complementarity solve (tol, tol_acceptable decide
  /// through finalize(); max_iterations and time_limit_s bound the NLPs). mpcc.polish (the
  /// MPCC piece polish) is off by default here: the active-set Newton polish replaces it.
  MpccOptions mpcc = [] {
    MpccOptions o;
    o.polish = false;
    return o;
  }();
  Vec reference;             ///< empty: no selection objective; else size n
  bool newton_polish = true; ///< the active-set Newton polish described above
  /// When the answer does not verify, restart the whole MPCC solve up to this many times from
  /// pseudo-random points (deterministic for a given seed): x_i uniform in [l_i, u_i] for a
  /// finite box, in [l_i, l_i + 1 + |x0_i|] (or [u_i - 1 - |x0_i|, u_i]) for one finite bound,
  /// in [-1 - |x0_i|, 1 + |x0_i|] for a free variable; odd restarts switch to the other
  /// reformulation (Scholtes <-> penalty). 0: no restart.
  int restarts = 8;
  std::uint64_t seed = 1;    ///< seed of the restart points
  std::string validate(Eigen::Index n) const;
};

/// Each throws InputError for invalid problems or options. `details` (optional) receives the
/// MPCC record of the attempt returned (subproblems and how each ended; the message counts
/// restarts). result.solver is "ipopt" or "nlopt" (the
/// backend); result.iterations sums NLP iterations; with common.record_trace every NLP is one
/// trace entry (kind "scholtes t=...", "penalty rho=...", residual = its complementarity).
SolveResult solve_lcp_mpcc(const LcpProblem& problem, const ComplementarityMpccOptions& options,
                           MpccResult* details = nullptr);
SolveResult solve_box_lcp_mpcc(const BoxLcpProblem& problem,
                               const ComplementarityMpccOptions& options,
                               MpccResult* details = nullptr);
SolveResult solve_mcp_mpcc(const McpProblem& problem, const ComplementarityMpccOptions& options,
                           MpccResult* details = nullptr);

/// Convenience: Ipopt / NLopt with default MPCC settings and the given common options.
SolveResult solve_lcp_ipopt(const LcpProblem& problem, const CommonOptions& common = {});
SolveResult solve_mcp_ipopt(const McpProblem& problem, const CommonOptions& common = {});
SolveResult solve_lcp_nlopt(const LcpProblem& problem, const CommonOptions& common = {});
SolveResult solve_mcp_nlopt(const McpProblem& problem, const CommonOptions& common = {});

/// Registry entries "ipopt" and "nlopt" (LCP dense and sparse storage via a dense copy, box
/// LCP, MCP); Ipopt's entry is marked serialized.
SolverEntry ipopt_entry();
SolverEntry nlopt_entry();

}  // namespace cpkit::lcp
