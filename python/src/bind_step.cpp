// One incremental step (all solutions, or one by the solver chain; docs/simulation.md). The
// quasi-static simulation is bound in bind_simulation.cpp.
#include <cmath>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"

namespace cpkit::py {
namespace {

rate::StepProblem step_problem(const pyb::object& params, double P_T0, double P_N0, double g0,
                               double DF_T, double DF_N, const std::string& wear_law,
                               double k_M) {
  rate::StepProblem p;
  p.params = parameters_from(params);
  p.wear = wear_from(wear_law, k_M);
  p.state = {P_T0, P_N0, g0};
  p.load = {DF_T, DF_N};
  throw_if_invalid(p.validate(), "step");
  return p;
}

pyb::dict values_dict(const rate::StepValues& v) {
  pyb::dict d;
  d["DP_T"] = v.DP_T;
  d["DP_N"] = v.DP_N;
  d["Dw_T"] = v.Dw_T;
  d["Dw_N"] = v.Dw_N;
  d["Dw_Ti"] = v.Dw_Ti;
  d["Dw_w"] = v.Dw_w;
  d["P_T1"] = v.P_T1;
  d["P_N1"] = v.P_N1;
  d["g1"] = v.g1;
  return d;
}

pyb::dict enumerate_step(const pyb::object& params, double P_T0, double P_N0, double g0,
                         double DF_T, double DF_N, const std::string& wear_law, double k_M,
                         bool detect_jumps) {
  const auto p = step_problem(params, P_T0, P_N0, g0, DF_T, DF_N, wear_law, k_M);
  rate::StepEnumerationOptions o;
  o.detect_jumps = detect_jumps;
  rate::StepSolutionSet set = without_gil([&] { return rate::enumerate_step(p, o); });
  pyb::dict d;
  d["solutions"] = list_of(set.solutions, [](const auto& s) {
    pyb::dict sd;
    sd["type"] = std::string(rate::to_string(s.type));
    sd["kind"] = std::string(rate::to_string(s.kind));
    sd["start"] = values_dict(s.start);
    sd["start_closed"] = s.start_closed;
    if (s.kind == rate::RateSolution::Kind::kSegment) {
      sd["end"] = values_dict(s.end);
      sd["end_closed"] = s.end_closed;
    }
    if (s.kind == rate::RateSolution::Kind::kRay) sd["direction"] = values_dict(s.direction);
    sd["residual"] = s.residual;
    sd["jump"] = s.jump;
    return sd;
  });
  d["infinite"] = set.infinite;
  d["count"] = set.count();
  d["continuous_count"] = set.continuous_count;
  d["complete"] = set.complete;  // false: a candidate neither verified nor rejected
  d["message"] = set.message;
  d["types"] = type_names(set.type_mask());
  return d;
}

pyb::dict solve_step(const pyb::object& params, double P_T0, double P_N0, double g0, double DF_T,
                     double DF_N, const std::string& wear_law, double k_M,
                     const std::vector<std::string>& chain) {
  const auto p = step_problem(params, P_T0, P_N0, g0, DF_T, DF_N, wear_law, k_M);
  rate::StepSolveOptions o;
  if (!chain.empty()) o.chain = chain;
  throw_if_invalid(o.validate(), "step options");
  rate::StepSolveResult r = without_gil([&] { return rate::solve_step(p, o); });
  pyb::dict d;
  d["result"] = to_dict(static_cast<const SolveResult&>(r));
  d["values"] = values_dict(r.solution.values);
  d["type"] = std::string(rate::to_string(r.solution.type));
  return d;
}

}  // namespace

void bind_step(pyb::module_& m) {
  m.def("enumerate_step", &enumerate_step);
  m.def("solve_step", &solve_step);
}

}  // namespace cpkit::py
