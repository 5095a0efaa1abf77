// The rate problem's entry points: validation, dispatch to the three routes, result assembly.
#include "cpkit/rate_problem/rate/point_rate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "rate_detail.hpp"

namespace cpkit::rate {

std::string_view to_string(RateMethod m) noexcept {
  switch (m) {
    case RateMethod::kEnumerate:
      return "enumerate";
    case RateMethod::kAnalytic:
      return "analytic";
    case RateMethod::kLemke:
      return "lemke";
    case RateMethod::kFbNewton:
      return "fb-newton";
    case RateMethod::kIpopt:
      return "ipopt";
  }
  return "unknown";
}

std::optional<RateMethod> rate_method_from_string(std::string_view s) noexcept {
  if (s == "enumerate") return RateMethod::kEnumerate;
  if (s == "analytic") return RateMethod::kAnalytic;
  if (s == "lemke") return RateMethod::kLemke;
  if (s == "fb-newton") return RateMethod::kFbNewton;
  if (s == "ipopt") return RateMethod::kIpopt;
  return std::nullopt;
}

unsigned RateSolutionSet::type_mask() const noexcept {
  unsigned m = 0;
  for (const auto& s : solutions) m |= 1u << static_cast<unsigned>(s.type);
  return m;
}

namespace detail {

void validate_inputs(const ContactParameters& params, const ContactState& state,
                     const LoadRate& load) {
  throw_if_invalid(params.validate(), "contact parameters");
  throw_if_invalid(state.validate(params), "contact state");
  if (!std::isfinite(load.dF_T) || !std::isfinite(load.dF_N)) {
    std::ostringstream msg;
    msg << "load rate: (dF_T, dF_N) = (" << load.dF_T << ", " << load.dF_N << ") is not finite";
    throw InputError(msg.str());
  }
}

void canonicalize(std::vector<RateSolution>& sols) {
  for (auto& s : sols) {
    if (s.kind == RateSolution::Kind::kSegment && std::abs(s.end.dw_Ti) < std::abs(s.start.dw_Ti)) {
      std::swap(s.start, s.end);
      std::swap(s.start_closed, s.end_closed);
    }
  }
  std::stable_sort(sols.begin(), sols.end(), [](const RateSolution& a, const RateSolution& b) {
    if (a.type != b.type) return a.type < b.type;
    if (a.kind != b.kind) return a.kind < b.kind;
    return a.start.dP_N < b.start.dP_N;
  });
}

RateSolutionSet make_solution_set(const ContactParameters& params, const ContactState& state,
                                  const LoadRate& load, const RateSolution* pieces, int n,
                                  bool infinite, bool complete) {
  RateSolutionSet out;
  out.solutions.assign(pieces, pieces + n);
  canonicalize(out.solutions);
  out.infinite = infinite;
  for (const auto& s : out.solutions)
    if (s.kind != RateSolution::Kind::kPoint) out.infinite = true;
  out.complete = complete;
  const RateIndicators ind = rate_indicators(params, state);
  out.Lambda = ind.Lambda;
  out.D_plus = ind.D_plus;
  out.D_minus = ind.D_minus;
  out.unique_for_all_directions = ind.unique_for_all_directions;
  out.scale = rate_scale(params, load);
  return out;
}

}  // namespace detail

namespace {
int exponent_of_(double v) noexcept {  // 2^e <= v < 2^(e+1) for finite v > 0
  int e = 0;
  std::frexp(v, &e);
  return e - 1;
}
}  // namespace

namespace detail {

/// The exact power-of-two normalisation of solve_rate_problem: A / 2^eA, C_T 2^eA, load / 2^eF.
void normalise(const ContactParameters& params, const LoadRate& load, ContactParameters& pn,
               LoadRate& fn, int& eA, int& eF) noexcept {
  eA = exponent_of_(std::max(params.a11, params.a22));
  normalise_load(load, fn, eF);
  pn = params;
  pn.a11 = std::ldexp(params.a11, -eA);
  pn.a12 = std::ldexp(params.a12, -eA);
  pn.a22 = std::ldexp(params.a22, -eA);
  pn.C_T = std::ldexp(params.C_T, eA);
}

void normalise_load(const LoadRate& load, LoadRate& fn, int& eF) noexcept {
  const double fmax = std::max(std::abs(load.dF_T), std::abs(load.dF_N));
  eF = fmax > 0 && std::isfinite(fmax) ? exponent_of_(fmax) : 0;
  // x 2^-eF rounds as ldexp does (both are the correctly rounded product); one ldexp instead
  // of two matters in the maps' inner loop. 2^-eF overflows only for subnormal loads.
  const double scale = std::ldexp(1.0, -eF);
  if (std::isfinite(scale))
    fn = LoadRate{load.dF_T * scale, load.dF_N * scale};
  else
    fn = LoadRate{std::ldexp(load.dF_T, -eF), std::ldexp(load.dF_N, -eF)};
}

}  // namespace detail

namespace {

Rates scaled_rates(const Rates& r, int eF, int eL) noexcept {
  Rates s;
  s.dP_T = std::ldexp(r.dP_T, eF);
  s.dP_N = std::ldexp(r.dP_N, eF);
  s.dw_T = std::ldexp(r.dw_T, eL);
  s.dw_N = std::ldexp(r.dw_N, eL);
  s.dw_Ti = std::ldexp(r.dw_Ti, eL);
  s.dw_w = std::ldexp(r.dw_w, eL);
  return s;
}

bool finite_rates(const Rates& r) noexcept {
  return std::isfinite(r.dP_T) && std::isfinite(r.dP_N) && std::isfinite(r.dw_T) &&
         std::isfinite(r.dw_N) && std::isfinite(r.dw_Ti) && std::isfinite(r.dw_w);
}

RateSolutionSet dispatch(const ContactParameters& params, const ContactState& state,
                         const LoadRate& load, RateMethod method) {
  switch (method) {
    case RateMethod::kEnumerate:
      return solve_rate_enumerate(params, state, load);
    case RateMethod::kAnalytic:
      return solve_rate_analytic(params, state, load);
    case RateMethod::kLemke:
    case RateMethod::kFbNewton:
    case RateMethod::kIpopt:
      break;
  }
  return solve_rate_single(params, state, load, std::string(to_string(method)));
}

}  // namespace

RateSolutionSet solve_rate_problem(const ContactParameters& params, const ContactState& state,
                                   const LoadRate& load, RateMethod method) {
  detail::validate_inputs(params, state, load);
  // Every route runs in normalised units: stiffnesses divided by 2^eA (eA from max(a11, a22)),
  // the load rate by 2^eF (the rates are linear in it), lengths then in units of 2^(eF - eA).
  // Powers of two make this exact: the answer does not depend on the units of A or of the
  // load, and loads near 1e308 or subnormal ones are solved like loads of order 1 (issue 24).
  // The state (P_N) and the wear and softening constants keep their units: with forces
  // unscaled, kappa = k_a P_N / (3 P_s) is unchanged.
  int eA = 0, eF = 0;
  ContactParameters pn;
  LoadRate fn;
  detail::normalise(params, load, pn, fn, eA, eF);
  RateSolutionSet out = dispatch(pn, state, fn, method);
  const int eL = eF - eA;
  for (auto& s : out.solutions) {
    s.start = scaled_rates(s.start, eF, eL);
    s.end = scaled_rates(s.end, eF, eL);
    s.direction = scaled_rates(s.direction, 0, -eA);  // a direction: any positive factor
    const bool fits = finite_rates(s.start) &&
                      (s.kind != RateSolution::Kind::kSegment || finite_rates(s.end)) &&
                      (s.kind != RateSolution::Kind::kRay || finite_rates(s.direction));
    if (!fits)
      throw InputError("rate problem: a solution is not representable in double precision "
                       "(its rates overflow in these units)");
  }
  const RateIndicators ind = rate_indicators(params, state);
  out.Lambda = ind.Lambda;
  out.D_plus = ind.D_plus;
  out.D_minus = ind.D_minus;
  out.scale = detail::rate_scale(params, load);
  return out;
}

RateSummary summarize_rate_problem(const ContactParameters& params, const ContactState& state,
                                   const LoadRate& load, RateMethod method) noexcept {
  // judged in the normalised units of solve_rate_problem (exact; the count and types do not
  // depend on the units of A or of the load)
  int eA = 0, eF = 0;
  ContactParameters pn;
  LoadRate fn;
  detail::normalise(params, load, pn, fn, eA, eF);
  switch (method) {
    case RateMethod::kEnumerate:
      return summarize_rate_enumerate(pn, state, fn);
    case RateMethod::kAnalytic:
      return summarize_rate_analytic(pn, state, fn);
    case RateMethod::kLemke:
    case RateMethod::kFbNewton:
    case RateMethod::kIpopt:
      break;
  }
  // Single solvers: at most one solution; not allocation-free (they build an LcpProblem).
  RateSummary sum;
  try {
    const RateSolutionSet s = solve_rate_problem(params, state, load, method);
    sum.count = s.count();
    sum.types = s.type_mask();
  } catch (...) {
    sum.reliable = false;
  }
  return sum;
}

}  // namespace cpkit::rate

namespace cpkit::rate {
namespace {

using detail::as_array;

bool close_rates(const Rates& x, const Rates& y, const Rates& sc, double tol) noexcept {
  const auto xs = as_array(x), ys = as_array(y), ss = as_array(sc);
  for (int c = 0; c < 6; ++c) {
    const double n = std::max({ss[c] > 0 ? ss[c] : 1.0, std::abs(xs[c]), std::abs(ys[c])});
    if (std::abs(xs[c] - ys[c]) > tol * n) return false;
  }
  return true;
}

bool same_piece(const RateSolution& a, const RateSolution& b, const Rates& sc, double tol) {
  if (a.type != b.type || a.kind != b.kind) return false;
  switch (a.kind) {
    case RateSolution::Kind::kPoint:
      return close_rates(a.start, b.start, sc, tol);
    case RateSolution::Kind::kSegment:
      return (close_rates(a.start, b.start, sc, tol) && close_rates(a.end, b.end, sc, tol) &&
              a.start_closed == b.start_closed && a.end_closed == b.end_closed) ||
             (close_rates(a.start, b.end, sc, tol) && close_rates(a.end, b.start, sc, tol) &&
              a.start_closed == b.end_closed && a.end_closed == b.start_closed);
    case RateSolution::Kind::kRay: {
      if (!close_rates(a.start, b.start, sc, tol) || a.start_closed != b.start_closed) return false;
      // directions agree up to a positive factor: compare normalised by dw_T^i or the largest
      const auto da = as_array(a.direction), db = as_array(b.direction), ss = as_array(sc);
      double na = 0, nb = 0;
      for (int c = 0; c < 6; ++c) {
        const double s = ss[c] > 0 ? ss[c] : 1.0;
        na = std::max(na, std::abs(da[c]) / s);
        nb = std::max(nb, std::abs(db[c]) / s);
      }
      if (!(na > 0) || !(nb > 0)) return false;
      for (int c = 0; c < 6; ++c) {
        const double s = ss[c] > 0 ? ss[c] : 1.0;
        if (std::abs(da[c] / (s * na) - db[c] / (s * nb)) > tol) return false;
      }
      return true;
    }
  }
  return false;
}

}  // namespace

bool same_solution_sets(const RateSolutionSet& a, const RateSolutionSet& b, double rel_tol,
                        std::string* why) {
  auto fail = [&](const std::string& m) {
    if (why != nullptr) *why = m;
    return false;
  };
  if (a.count() != b.count())
    return fail("counts differ: " + std::to_string(a.count()) + " vs " + std::to_string(b.count()));
  if (a.solutions.size() != b.solutions.size())
    return fail("number of pieces differs: " + std::to_string(a.solutions.size()) + " vs " +
                std::to_string(b.solutions.size()));
  std::vector<bool> used(b.solutions.size(), false);
  for (const auto& s : a.solutions) {
    bool found = false;
    for (std::size_t k = 0; k < b.solutions.size() && !found; ++k) {
      if (used[k]) continue;
      if (same_piece(s, b.solutions[k], a.scale, rel_tol)) {
        used[k] = true;
        found = true;
      }
    }
    if (!found)
      return fail(std::string("no match for the ") + std::string(to_string(s.type)) + " " +
                  std::string(to_string(s.kind)) + " starting at dP_N = " +
                  std::to_string(s.start.dP_N) + ", dw_T^i = " + std::to_string(s.start.dw_Ti));
  }
  return true;
}

namespace {

/// Whether the enumeration's set of (params, state, load) rests on certified signs only
/// (detail::enumeration_certified, in the normalised units the routes use).
bool enumeration_certified(const ContactParameters& params, const ContactState& state,
                           const LoadRate& load) noexcept {
  int eA = 0, eF = 0;
  ContactParameters pn;
  LoadRate fn;
  detail::normalise(params, load, pn, fn, eA, eF);
  return detail::enumeration_certified(pn, state, fn);
}

}  // namespace

CheckedRateSolution solve_rate_problem_checked(const ContactParameters& params,
                                               const ContactState& state, const LoadRate& load,
                                               RateMethod method) {
  CheckedRateSolution out;
  out.set = solve_rate_problem(params, state, load, method);
  const RateSolutionSet& s = out.set;
  if (method == RateMethod::kEnumerate) {
    const RateSolutionSet analytic = solve_rate_problem(params, state, load, RateMethod::kAnalytic);
    std::string why;
    if (!s.complete) {
      out.problem = "the enumeration is not conclusive: " + s.message;
      out.inconclusive = true;
    } else if (!analytic.complete && enumeration_certified(params, state, load)) {
      // a cross-check that cannot decide does not undo a certified answer (issue 34): every
      // sign of the enumeration's set was decided exactly or beyond its rounding bound
    } else if (!analytic.complete) {
      out.problem = "the analytic route cannot decide a sign: " + analytic.message;
      out.inconclusive = true;
    } else if (!same_solution_sets(s, analytic, 1e-7, &why)) {
      out.problem = "enumeration and analytic routes disagree: " + why;
    }
    return out;
  }
  if (method == RateMethod::kAnalytic) {
    if (!s.complete) {
      out.problem = "the analytic route cannot decide a sign: " + s.message;
      out.inconclusive = true;
    }
    return out;
  }
  out.reference = solve_rate_problem(params, state, load, RateMethod::kEnumerate);
  if (s.solutions.empty()) return out;
  // the solver's point is accurate to its residual (solved_inaccurate allows up to 1e-6)
  const double tol = std::max(1e-6, 1e3 * s.residual);
  const std::string name(to_string(method));
  if (!contains(*out.reference, s.solutions.front().start, tol))
    out.problem = name + "'s solution is not in the enumerated solution set";
  else if (out.reference->solutions[find_piece(*out.reference, s.solutions.front().start, tol)]
               .type != s.solutions.front().type)
    out.problem = name + "'s solution has another type than the enumerated set's piece";
  return out;
}

}  // namespace cpkit::rate
