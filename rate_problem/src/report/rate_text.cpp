// The text of `cpkit rate` (docs/cli.md): what users read and the docs show, so every character
// is kept as it was when the program printed it.
#include "cpkit/rate_problem/report/rate_text.hpp"

#include <sstream>

#include "cpkit/rate_problem/report/json_3d.hpp"
#include "piece_report.hpp"

namespace cpkit::rate {
namespace {

std::string rates_text(const Rates& r) {
  std::ostringstream o;
  o.precision(10);
  o << "dP_T=" << r.dP_T << " dP_N=" << r.dP_N << " dw_T=" << r.dw_T << " dw_N=" << r.dw_N
    << " dw_Ti=" << r.dw_Ti << " dw_w=" << r.dw_w;
  return o.str();
}

std::string system_values_text(const SystemRates& r) {
  std::ostringstream o;
  o.precision(10);
  auto vec = [&](const char* name, const Eigen::VectorXd& v) {
    o << ' ' << name << "=[";
    for (Eigen::Index i = 0; i < v.size(); ++i) o << (i ? ", " : "") << v(i);
    o << ']';
  };
  vec("dP_T", r.dP_T);
  vec("dP_N", r.dP_N);
  vec("dw_T", r.dw_T);
  vec("dw_N", r.dw_N);
  vec("dw_Ti", r.dw_Ti);
  vec("dw_w", r.dw_w);
  return o.str();
}

std::string values_3d_text(const std::vector<Rates3d>& rs) {
  std::ostringstream o;
  o.precision(10);
  auto pairs = [&](const char* name, auto get) {
    o << ' ' << name << "=[";
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const Eigen::Vector2d v = get(rs[i]);
      o << (i ? ", " : "") << '[' << v(0) << ", " << v(1) << ']';
    }
    o << ']';
  };
  auto scalars = [&](const char* name, auto get) {
    o << ' ' << name << "=[";
    for (std::size_t i = 0; i < rs.size(); ++i) o << (i ? ", " : "") << get(rs[i]);
    o << ']';
  };
  pairs("dP_T", [](const Rates3d& r) { return r.dP_T; });
  scalars("dP_N", [](const Rates3d& r) { return r.dP_N; });
  pairs("dw_T", [](const Rates3d& r) { return r.dw_T; });
  scalars("dw_N", [](const Rates3d& r) { return r.dw_N; });
  pairs("dw_Ti", [](const Rates3d& r) { return r.dw_Ti; });
  scalars("dw_w", [](const Rates3d& r) { return r.dw_w; });
  return o.str();
}

std::string count_text(int count) { return count < 0 ? std::string("inf") : std::to_string(count); }

void one_point_text(std::ostream& o, const RateOutcome& out) {
  const RateSolutionSet& s = out.one_point->set;
  const RateSolutionSet* reference = out.one_point->reference ? &*out.one_point->reference : nullptr;
  o << "rate problem, state " << out.state << ", method " << out.method << "\n";
  if (s.complete) {
    o << "count: " << count_text(s.count()) << "   types:";
  } else if (!reference) {
    o << "solutions found: " << s.solutions.size()
      << " (the enumeration is INCOMPLETE: not a count)   types:";
  } else if (!s.solutions.empty()) {
    o << "a solution (found by " << out.method
      << "; one solver finds one solution, the set may hold more: not a count)"
      << "   type:";
  } else {
    o << "no solution found by " << out.method << " (incomplete: not a proof)   types:";
  }
  for (const auto& t : report_detail::type_names(s.solutions)) o << ' ' << t;
  o << "\nLambda: " << s.Lambda << "   D_+: " << s.D_plus << "   D_-: " << s.D_minus
    << "   unique for all directions: " << (s.unique_for_all_directions ? "yes" : "no") << "\n";
  for (const auto& p : s.solutions) {
    o << "  " << to_string(p.type) << ' ' << to_string(p.kind) << ": ";
    report_detail::piece_text(o, p, "from ", " ", rates_text);
  }
  if (!s.message.empty()) o << "note: " << s.message << "\n";
  if (reference && reference->complete)
    o << "complete enumeration (--method enumerate): " << count_text(reference->count())
      << " solution(s)\n";
}

void system_text(std::ostream& o, const RateOutcome& out) {
  const SystemRateSolutionSet& s = *out.system;
  const bool single = out.method != "enumerate";
  o << "rate problem, system " << (out.name.empty() ? out.path : out.name) << " ("
    << out.n_points << " points), method " << out.method << "\n";
  if (s.complete)
    o << "count: " << count_text(s.count()) << "\n";
  else if (single)
    o << (s.solutions.empty() ? "no solution found" : "a solution") << " (found by "
      << out.method << "; not a count)\n";
  else
    o << "solutions found: " << s.solutions.size() << " (INCOMPLETE: not a count)\n";
  for (const auto& p : s.solutions) {
    o << "  " << types_string(p.types) << ' ' << to_string(p.kind) << ":";
    report_detail::piece_text(o, p, " from", "", system_values_text);
  }
  if (!s.message.empty()) o << "note: " << s.message << "\n";
}

void system_3d_text(std::ostream& o, const RateOutcome& out) {
  const SystemRateRoute3d& s = *out.system_3d;
  const int N = out.n_points;
  o << "rate problem, 3-D system " << (out.name.empty() ? out.path : out.name) << " (" << N
    << (N == 1 ? " point, state " + std::string(1, out.first_state) : std::string(" points"))
    << "), "
    << (out.facets != 0 ? "faceted with " + std::to_string(out.facets) + " facets" : "exact")
    << "\n";
  if (s.complete)
    o << "count: " << count_text(s.infinite() ? -1 : s.count()) << "\n";
  else
    o << "solutions found: " << s.count() << " (INCOMPLETE: not a count)\n";
  for (const auto& r : s.solutions) {
    o << "  " << types_string(r.types) << (r.ray ? " ray from" : " point:")
      << values_3d_text(r.rates);
    nlohmann::json e;
    add_slip_json(e, r.types, r.ray ? r.direction : r.rates);
    if (e.contains("slip_angle")) {
      o << " slip_angle=[";
      for (std::size_t i = 0; i < r.types.size(); ++i) {
        const auto& x = e["slip_angle"][i];
        o << (i ? ", " : "");
        if (x.is_null()) o << '-'; else o << x.get<double>();
      }
      o << ']';
    }
    o << "\n";
    if (r.ray) o << "      direction" << values_3d_text(r.direction) << "\n";
  }
  if (!s.message.empty()) o << "note: " << s.message << "\n";
}

}  // namespace

std::string rate_outcome_text(const RateOutcome& outcome) {
  std::ostringstream o;
  switch (outcome.route) {
    case RateOutcome::Route::kOnePoint: one_point_text(o, outcome); break;
    case RateOutcome::Route::kSystem: system_text(o, outcome); break;
    case RateOutcome::Route::kSystem3d: system_3d_text(o, outcome); break;
  }
  return o.str();
}

}  // namespace cpkit::rate
