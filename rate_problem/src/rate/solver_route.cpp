// Route 3: one solution by a single registered LCP solver, and membership tests of a rate
// vector in a solution set.
#include <algorithm>
#include <array>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "rate_detail.hpp"

namespace cpkit::rate {

using detail::as_array;

const SolverEntry* detail::find_lcp_solver(const std::string& name) {
  const SolverRegistry& reg = lcp::solvers();
  if (const SolverEntry* e = reg.find(name)) return e;
  if (name == "ipopt") {  // the MPCC route may be registered under a longer name
    for (const char* alt : {"mpcc-ipopt", "mpcc", "ipopt-mpcc"})
      if (const SolverEntry* e = reg.find(alt)) return e;
  }
  return nullptr;
}

std::string detail::solver_message(const SolverEntry& entry, const SolveResult& r) {
  return entry.info.name + ": " + std::string(to_string(r.status)) +
         (r.message.empty() ? "" : " (" + r.message + ")");
}

RateSolutionSet solve_rate_single(const ContactParameters& p, const ContactState& st,
                                  const LoadRate& f, const std::string& solver, SolveResult* raw) {
  detail::validate_inputs(p, st, f);
  const SolverEntry* entry = detail::find_lcp_solver(solver);
  if (entry == nullptr || !entry->solve_lcp) {
    std::string names;
    for (const auto& n : lcp::solvers().names(ProblemKind::kLcp)) names += (names.empty() ? "" : ", ") + n;
    throw InputError("LCP solver '" + solver + "' is not registered in cpkit::lcp::solvers() "
                     "(registered: " + (names.empty() ? std::string("none") : names) + ")");
  }
  detail::PieceList list;
  std::string message;
  double residual = 0;
  if (st.label == StateLabel::kA || st.label == StateLabel::kC) {
    RateSolution s;
    s.type = st.label == StateLabel::kA ? SolutionType::kOpen : SolutionType::kStick;
    s.start = detail::linear_state_rates(p, st, f);
    list.push(s);
    message = "state " + std::string(to_string(st.label)) +
              " has no LCP: its linear rate system was solved directly";
  } else {
    const LcpProblem lcp = rate_lcp_problem(p, st, f);
    SolveResult r = entry->solve_lcp(lcp, CommonOptions{});
    if (is_solution(r.status)) {
      RateSolution s;
      s.start = rates_from_lcp_solution(p, st, f, r.z);
      s.type = classify_rates(p, st, f, s.start);
      list.push(s);
    }
    message = detail::solver_message(*entry, r);
    // finalize()'s unit-free number: its w-units do not grow with z, so a drift to large z
    // along the z-rays of state b does not shrink it (residuals.hpp)
    residual = r.residuals.natural;
    if (raw != nullptr) *raw = std::move(r);
  }
  RateSolutionSet out = detail::make_solution_set(p, st, f, list, false);
  out.message = message;
  out.residual = residual;
  return out;
}

int find_piece(const RateSolutionSet& set, const Rates& r, double rel_tol) noexcept {
  const auto x = as_array(r);
  const auto sc = as_array(set.scale);
  for (std::size_t i = 0; i < set.solutions.size(); ++i) {
    const RateSolution& s = set.solutions[i];
    const auto a = as_array(s.start);
    std::array<double, 6> d{};
    if (s.kind == RateSolution::Kind::kSegment) {
      const auto b = as_array(s.end);
      for (int c = 0; c < 6; ++c) d[c] = b[c] - a[c];
    } else if (s.kind == RateSolution::Kind::kRay) {
      d = as_array(s.direction);
    }
    // normalisation per component
    std::array<double, 6> n{};
    for (int c = 0; c < 6; ++c) {
      n[c] = std::max({sc[c] > 0 ? sc[c] : 1.0, std::abs(a[c]), std::abs(x[c])});
      if (s.kind == RateSolution::Kind::kSegment) n[c] = std::max(n[c], std::abs(a[c] + d[c]));
    }
    double dd = 0, rd = 0;
    for (int c = 0; c < 6; ++c) {
      dd += (d[c] / n[c]) * (d[c] / n[c]);
      rd += ((x[c] - a[c]) / n[c]) * (d[c] / n[c]);
    }
    double t = 0;
    if (s.kind != RateSolution::Kind::kPoint && dd > 0) {
      t = std::max(0.0, rd / dd);
      if (s.kind == RateSolution::Kind::kSegment) t = std::min(1.0, t);
    }
    double dist = 0;
    for (int c = 0; c < 6; ++c) dist = std::max(dist, std::abs(x[c] - a[c] - t * d[c]) / n[c]);
    if (dist > rel_tol) continue;
    if (s.kind != RateSolution::Kind::kPoint) {
      // at an open end? (closeness measured the same way)
      auto near_end = [&](double te) {
        double e = 0;
        for (int c = 0; c < 6; ++c) e = std::max(e, std::abs(x[c] - a[c] - te * d[c]) / n[c]);
        return e <= rel_tol;
      };
      if (!s.start_closed && near_end(0.0)) continue;
      if (s.kind == RateSolution::Kind::kSegment && !s.end_closed && near_end(1.0)) continue;
    }
    return static_cast<int>(i);
  }
  return -1;
}

bool contains(const RateSolutionSet& set, const Rates& r, double rel_tol) noexcept {
  return find_piece(set, r, rel_tol) >= 0;
}

}  // namespace cpkit::rate
