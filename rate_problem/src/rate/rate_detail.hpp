#pragma once
// Internal helpers shared by the routes of the rate problem (not installed).
#include <array>
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit {
struct SolverEntry;
struct SolveResult;
}  // namespace cpkit

namespace cpkit::rate::detail {

/// The registered LCP solver of a single-solver route, one point or N points ("ipopt" also
/// under the MPCC route's longer names); nullptr when there is none.
const SolverEntry* find_lcp_solver(const std::string& name);
/// What a single solver's answer says: "<solver>: <status>" and " (<its message>)" if any.
std::string solver_message(const SolverEntry& entry, const SolveResult& r);

/// Fixed-capacity list of solution pieces (allocation-free). The analytic route needs at most
/// 4 pieces (one per type in b); the enumeration route's conversion uses the larger capacity.
template <int Cap>
struct PieceListN {
  static constexpr int kCapacity = Cap;
  std::array<RateSolution, kCapacity> p;
  int n = 0;
  bool infinite = false;
  bool overflow = false;  ///< more pieces than kCapacity (never expected; reported as an error)
  /// some piece's existence hangs on a sign within the rounding error of its expression: the
  /// list is not complete (analytic route; issue 24)
  bool undecided = false;
  void push(const RateSolution& s) noexcept {
    if (n < kCapacity) {
      p[n++] = s;
    } else {
      overflow = true;
    }
  }
};

using PieceList = PieceListN<16>;
using SmallPieceList = PieceListN<4>;

/// The six rates (dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w) as an array, for componentwise tests.
inline std::array<double, 6> as_array(const Rates& r) noexcept {
  return {r.dP_T, r.dP_N, r.dw_T, r.dw_N, r.dw_Ti, r.dw_w};
}

/// Throws InputError naming the first problem of params, state or load.
void validate_inputs(const ContactParameters& params, const ContactState& state,
                     const LoadRate& load);

/// The exact power-of-two normalisation in which every route and summary judges: A / 2^eA
/// (eA from max(a11, a22)), C_T 2^eA, the load / 2^eF (eF from its largest component).
void normalise(const ContactParameters& params, const LoadRate& load, ContactParameters& pn,
               LoadRate& fn, int& eA, int& eF) noexcept;
/// The load's half of normalise: fn = load 2^-eF.
void normalise_load(const LoadRate& load, LoadRate& fn, int& eF) noexcept;

/// Route 1 into a PieceList (analytic.cpp).
void analytic_pieces(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                     SmallPieceList& out,
                     bool exact = true) noexcept;

/// Sorted (type, kind, dP_N) RateSolutionSet with the indicators of (params, state).
RateSolutionSet make_solution_set(const ContactParameters& params, const ContactState& state,
                                  const LoadRate& load, const RateSolution* pieces, int n,
                                  bool infinite, bool complete);
template <int Cap>
RateSolutionSet make_solution_set(const ContactParameters& params, const ContactState& state,
                                  const LoadRate& load, const PieceListN<Cap>& list,
                                  bool complete) {
  return make_solution_set(params, state, load, list.p.data(), list.n, list.infinite,
                           complete && !list.overflow && !list.undecided);
}

/// States a and c (no LCP): the unique rates by a numerical solve of the linear system.
Rates linear_state_rates(const ContactParameters& p, const ContactState& st,
                         const LoadRate& f) noexcept;

/// Componentwise magnitudes for tolerance comparisons: forces |dF_T| + |dF_N| (1 when zero),
/// displacement rates that force times (C_T + 1/a11 + 1/a22).
Rates rate_scale(const ContactParameters& p, const LoadRate& f) noexcept;

/// Whether solve_rate_enumerate's set of (p, st, f) (normalised units) rests on certified signs
/// only: states a and c (no sign), b through its support enumeration (certified_b.hpp), d through
/// the exact signs of L_s and Lambda (exact_signs.hpp). A cross-check that cannot decide a sign
/// does not undo such a set (issue 34).
bool enumeration_certified(const ContactParameters& p, const ContactState& st,
                           const LoadRate& f) noexcept;

/// Puts the solutions in canonical order: by type, kind, then start.dP_N; segments oriented so
/// that |dw_T^i| does not decrease from start to end.
void canonicalize(std::vector<RateSolution>& solutions);

template <int Cap>
RateSummary summarize(const PieceListN<Cap>& list) noexcept {
  RateSummary s;
  for (int i = 0; i < list.n; ++i) s.types |= 1u << static_cast<unsigned>(list.p[i].type);
  s.count = list.infinite ? -1 : list.n;
  s.reliable = !list.undecided && !list.overflow;
  return s;
}

}  // namespace cpkit::rate::detail
