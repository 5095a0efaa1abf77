// The one-point rate problem [Stromberg et al. 1996, Sec. 4.3]: every solution for a contact
// state and a load rate (docs/contact_model.md), as plain Python data.
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"

namespace cpkit::py {
namespace {

rate::RateMethod method_from(const std::string& name) {
  const auto m = rate::rate_method_from_string(name);
  if (!m)
    throw InputError("method must be one of enumerate, analytic, lemke, fb-newton, ipopt, got '" +
                     name + "'");
  return *m;
}

pyb::dict solution_to_dict(const rate::RateSolution& s) {
  pyb::dict d;
  d["type"] = std::string(rate::to_string(s.type));
  d["kind"] = std::string(rate::to_string(s.kind));
  d["start"] = to_dict(s.start);
  d["start_closed"] = s.start_closed;
  if (s.kind == rate::RateSolution::Kind::kSegment) {
    d["end"] = to_dict(s.end);
    d["end_closed"] = s.end_closed;
  }
  if (s.kind == rate::RateSolution::Kind::kRay) d["direction"] = to_dict(s.direction);
  return d;
}

pyb::dict solve_rate(const pyb::object& params, const pyb::object& state, double dF_T,
                     double dF_N, const std::string& method) {
  const auto p = parameters_from(params);
  const auto s = state_from(state, p);
  const auto m = method_from(method);
  if (!std::isfinite(dF_T) || !std::isfinite(dF_N))
    throw InputError("dF must be finite, got (" + std::to_string(dF_T) + ", " +
                     std::to_string(dF_N) + ")");
  const rate::LoadRate load{dF_T, dF_N};
  rate::RateSolutionSet set = without_gil([&] { return rate::solve_rate_problem(p, s, load, m); });
  pyb::dict d;
  d["solutions"] = list_of(set.solutions, solution_to_dict);
  d["complete"] = set.complete;
  d["infinite"] = set.infinite;
  d["count"] = set.count();
  d["types"] = type_names(set.type_mask());
  d["Lambda"] = set.Lambda;
  d["D_plus"] = set.D_plus;
  d["D_minus"] = set.D_minus;
  d["unique_for_all_directions"] = set.unique_for_all_directions;
  d["message"] = set.message;
  d["residual"] = set.residual;
  return d;
}

pyb::dict indicators(const pyb::object& params, const pyb::object& state) {
  const auto p = parameters_from(params);
  const auto s = state_from(state, p);
  const auto ind = rate::rate_indicators(p, s);
  pyb::dict d;
  d["detA"] = ind.detA;
  d["D0"] = ind.D0;
  d["kappa"] = ind.kappa;
  d["mu_eff"] = ind.mu_eff;
  d["D_plus"] = ind.D_plus;
  d["D_minus"] = ind.D_minus;
  d["Lambda"] = ind.Lambda;
  d["unique_for_all_directions"] = ind.unique_for_all_directions;
  return d;
}

}  // namespace

void bind_rate(pyb::module_& m) {
  m.def("solve_rate_problem", &solve_rate);
  m.def("rate_indicators", &indicators);
}

}  // namespace cpkit::py
