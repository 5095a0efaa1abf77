#pragma once
/// \file rate_lcp.hpp
/// Routes 2 and 3 of the rate problem: the state's rate problem as an LCP (docs/model.md,
/// "The rate problem as an LCP"), z >= 0, w = M z + q >= 0, z . w = 0.
///
/// State b: z = (dP_N, l+, l-), dw_T^i = l+ - l-, w = D0 (-dw_N, mu dP_N - dP_T, mu dP_N + dP_T)
/// with M, q of docs/model.md (M is never a P-matrix: its {1,2} principal minor is 0, and every
/// physical solution with dP_N = 0 is a whole ray of z).
/// State d: z = lambda (the plastic multiplier), w = (1 + a11 C_T)(mu_eff dP_N - s dP_T). Here
/// the 1x1 LCP is built by solving the rate equations (50) numerically for lambda = 0 and 1, not
/// from eqn (51), so that route 2 stays independent of route 1; tests check M = [Lambda] and
/// q = [-L_s].
/// States a and c have no LCP (their rate problem is a linear system, solved numerically here).
/// [Stromberg et al. 1996, Sec. 4.3]
#include <Eigen/Core>
#include <string>

#include "cpkit/core/problem.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

/// State b's LCP (docs/model.md), fixed size.
struct StateBLcp {
  Eigen::Matrix3d M;
  Eigen::Vector3d q;
};
StateBLcp state_b_lcp(const ContactParameters& p, const LoadRate& f) noexcept;
/// Physical rates of the state-b LCP point z = (dP_N, l+, l-) (docs/model.md back-substitution).
Rates state_b_rates(const ContactParameters& p, const LoadRate& f, const Eigen::Vector3d& z) noexcept;

/// State d's 1x1 LCP, built numerically from the rate equations (50).
struct StateDLcp {
  double M = 0, q = 0;
  /// A nonzero q (the load's L_s), or an M (Lambda) above its rounding, within the snapping
  /// band was set to zero: this route cannot tell its sign from zero, so an answer built on it
  /// is not proved complete (issue 24).
  bool snapped = false;
};
StateDLcp state_d_lcp(const ContactParameters& p, const ContactState& st, const LoadRate& f) noexcept;
/// Physical rates of state d for the multiplier lambda (slip if lambda > 0, stick if 0), by a
/// numerical solve of (50) with dw_T = C_T dP_T + s lambda and dw_N = kappa lambda.
Rates state_d_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                    double lambda) noexcept;

/// The state's LCP as a dynamic LcpProblem (for the single solvers of route 3).
/// Throws InputError for invalid input and for states a and c (no LCP).
LcpProblem rate_lcp_problem(const ContactParameters& p, const ContactState& st, const LoadRate& f);
/// Physical rates of an LCP solution z of rate_lcp_problem (size 3 in b, 1 in d).
Rates rates_from_lcp_solution(const ContactParameters& p, const ContactState& st,
                              const LoadRate& f, const Vec& z);

/// Type of a physical rate vector in the given state, judged with the relative tolerance of the
/// enumeration route: separation (b: dw_N < 0), stick (dw_T^i = 0), slip+/slip- (sign of
/// dw_T^i), open (state a).
SolutionType classify_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                            const Rates& r) noexcept;

/// Route 2: every solution by complete enumeration of the state's LCP
/// (cpkit::lcp::enumerate_small), mapped to physical rates and deduplicated there. Throws
/// InputError for invalid input. `complete` is false (and `message` says why) when the
/// enumeration reported sign tests too close to call.
RateSolutionSet solve_rate_enumerate(const ContactParameters& p, const ContactState& st,
                                     const LoadRate& f);
/// Route 2's count and types only; inputs must be valid; allocation-free.
RateSummary summarize_rate_enumerate(const ContactParameters& p, const ContactState& st,
                                     const LoadRate& f) noexcept;

/// Route 3: one solution by the registered single LCP solver `solver` (e.g. "lemke",
/// "fb-newton", "ipopt"), looked up in cpkit::lcp::solvers(). In states a and c (no LCP) the
/// linear system is solved instead. The set has complete = false and holds at most one point
/// (none when the solver did not return a verified solution; `message` then gives its status).
/// Throws InputError for invalid input or an unregistered solver name.
RateSolutionSet solve_rate_single(const ContactParameters& p, const ContactState& st,
                                  const LoadRate& f, const std::string& solver,
                                  SolveResult* raw = nullptr);

/// Is `r` (within a relative tolerance) a member of the solution set (points, segments and rays
/// with their open/closed ends)? Used to check route 3 against routes 1 and 2.
/// Distances are measured per component relative to max(set.scale, |piece coordinates|).
bool contains(const RateSolutionSet& set, const Rates& r, double rel_tol = 1e-7) noexcept;
/// Index of the piece of `set` that holds `r` (-1 when none); a point at an open end of a
/// piece is attributed to the piece that holds it (of another type), never to the open one.
int find_piece(const RateSolutionSet& set, const Rates& r, double rel_tol = 1e-7) noexcept;

}  // namespace cpkit::rate
