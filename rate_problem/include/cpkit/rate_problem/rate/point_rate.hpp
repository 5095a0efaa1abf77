#pragma once
/// \file point_rate.hpp
/// The rate problem of the one-point contact problem [Stromberg et al. 1996, Sec. 4.3]:
/// given a contact state and a load rate (dF_T, dF_N), every solution (rates), by one of three
/// independent routes (docs/contact_model.md).
#include <string>
#include <string_view>
#include <optional>
#include <vector>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/rate/detail/state_b_terms.hpp"

namespace cpkit::rate {

enum class RateMethod {
  kEnumerate,  ///< the state's LCP (model.md) + complete enumeration, mapped to physical rates
  kAnalytic,   ///< the paper's closed forms (b.i-b.iii, c, d.i-d.ii, eqn (51))
  kLemke,      ///< one solution by Lemke's method on the state's LCP
  kFbNewton,   ///< one solution by the Fischer-Burmeister Newton method
  kIpopt,      ///< one solution by the Ipopt MPCC route
};
std::string_view to_string(RateMethod m) noexcept;  ///< "enumerate", "analytic", "lemke", "fb-newton", "ipopt"
std::optional<RateMethod> rate_method_from_string(std::string_view s) noexcept;

/// The solution set of a 2-D rate problem, of one point (Piece = RateSolution) or of N points
/// (SystemRateSolution, system_rate.hpp): connected pieces (points, segments, rays, never
/// sampled) whose types partition the set, whether the list is the whole set and why not.
template <class Piece>
struct RatePieceSetOf {
  std::vector<Piece> solutions;  ///< points, segments, rays; types partition the set
  bool infinite = false;         ///< some piece is a segment or a ray
  bool complete = true;          ///< false for single-solution methods (lemke, ...)
  /// Why the set is incomplete or a single solver failed / which one answered (else empty).
  std::string message;
  /// Single solvers: the natural residual ||min(z, w)||_inf of the LCP solution divided by
  /// 1 + ||q||_inf (relative to the data, not to the iterate; 0 otherwise). Checks of such a
  /// point against a complete set should allow an error of order 1e3 x residual.
  double residual = 0;
  /// Number of solutions: -1 when infinite.
  int count() const noexcept { return infinite ? -1 : static_cast<int>(solutions.size()); }
};

/// All solutions of one rate problem, and the quantities that decide them.
struct RateSolutionSet : RatePieceSetOf<RateSolution> {
  double Lambda = 0;                    ///< eqn (51) for state d with s = sgn P_T (else 0)
  double D_plus = 0, D_minus = 0;       ///< D_s = a11 - s mu a12 (state b)
  bool unique_for_all_directions = false;  ///< b: a11 > mu|a12|; c: true; d: Lambda > 0; a: true
  /// Componentwise magnitudes used for tolerance comparisons of rates (see contains()):
  /// forces |dF_T| + |dF_N|, displacement rates that times (C_T + 1/a11 + 1/a22).
  Rates scale;
  /// Bit mask of the types present (bit = static_cast<int>(SolutionType)).
  unsigned type_mask() const noexcept;
};

/// Solves the rate problem. Throws InputError for invalid parameters/state/load (NaN, A not
/// SPD, mu <= 0, P_N <= 0 in c/d, ...) and when a solution is not representable in double.
/// Every route runs in normalised units (A divided by 2^eA ~ max(a11, a22), the load rate by
/// 2^eF ~ its size; exact, undone on the answer): the answer does not depend on the units of A
/// or of the load (issue 24 item 17).
RateSolutionSet solve_rate_problem(const ContactParameters& params, const ContactState& state,
                                   const LoadRate& load,
                                   RateMethod method = RateMethod::kEnumerate);

/// Do two solution sets agree (same pieces: type, kind, ends and their closedness, rates within
/// rel_tol per component relative to a.scale)? Segment ends may be listed in either order.
/// When they differ and `why` is set, it receives a one-line reason.
bool same_solution_sets(const RateSolutionSet& a, const RateSolutionSet& b, double rel_tol = 1e-7,
                        std::string* why = nullptr);

/// The rate problem solved by `method` and checked by a second route, as `cpkit rate` reports
/// it: enumerate against analytic (the same pieces to 1e-7), analytic alone (complete), and a
/// single solver (lemke, fb-newton, ipopt) against the complete enumeration (its point lies in the
/// enumerated set, to max(1e-6, 1e3 x its residual), on a piece of the same type).
struct CheckedRateSolution {
  RateSolutionSet set;                       ///< the method's answer
  std::optional<RateSolutionSet> reference;  ///< single solvers: the complete enumeration
  std::string problem;        ///< empty when the check passed; else why not (one line)
  bool inconclusive = false;  ///< a route could not decide a sign: proves nothing, no disagreement
};
CheckedRateSolution solve_rate_problem_checked(const ContactParameters& params,
                                               const ContactState& state, const LoadRate& load,
                                               RateMethod method);

/// Count (-1: infinite) and type mask only: the allocation-free fast path the maps call
/// millions of times. Inputs must already be valid (no validation here: call
/// params.validate() / state.validate() once per map).
struct RateSummary {
  int count = 0;
  unsigned types = 0;
  /// false when the enumeration met sign tests too close to call (count/types may then be
  /// wrong near a boundary between solution types); always true for the analytic route.
  bool reliable = true;
};
RateSummary summarize_rate_problem(const ContactParameters& params, const ContactState& state,
                                   const LoadRate& load,
                                   RateMethod method = RateMethod::kEnumerate) noexcept;

/// What the enumeration route can compute once per (parameters, state) for maps over many load
/// rates: the parameters in normalised units, state b's load-independent sign terms, state d's
/// LCP matrix and rates per unit load. Built by precompute_rate_problem (which validates); read-only afterwards, so one
/// object can serve many threads.
struct RatePrecomputed {
  ContactParameters params;
  ContactState state;
  ContactParameters params_n;              ///< params in the summaries' normalised units
  detail::BTerms<detail::Mag> b_terms;     ///< state b: the load-independent certified terms
  double M_d = 0;                          ///< state d: the 1x1 LCP matrix (snapped)
  bool d_snapped = false;                  ///< state d: a nonzero M_d was snapped to zero
  double dPN_T = 0, dPN_N = 0, dPT_T = 0, dPT_N = 0;  ///< state d: stick rates per unit load
};
/// Validates (InputError) and precomputes.
RatePrecomputed precompute_rate_problem(const ContactParameters& params, const ContactState& state);
/// Same result as summarize_rate_problem(pre.params, pre.state, load, method); faster for the
/// enumeration route. Allocation-free.
RateSummary summarize_rate_problem(const RatePrecomputed& pre, const LoadRate& load,
                                   RateMethod method = RateMethod::kEnumerate) noexcept;

}  // namespace cpkit::rate
