#include "cpkit/rate_problem/report/json.hpp"

#include <string>
#include <vector>

#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/report/step_outcome.hpp"
#include "piece_report.hpp"

namespace cpkit::rate {

nlohmann::json step_values_json(const StepValues& v) {
  return {{"DP_T", v.DP_T},   {"DP_N", v.DP_N}, {"Dw_T", v.Dw_T}, {"Dw_N", v.Dw_N},
          {"Dw_Ti", v.Dw_Ti}, {"Dw_w", v.Dw_w}, {"P_T1", v.P_T1}, {"P_N1", v.P_N1},
          {"g1", v.g1}};
}

nlohmann::json step_set_json(const StepSolutionSet& s) {
  nlohmann::json j;
  j["count"] = report_detail::count_json(s.count());
  j["types"] = report_detail::type_names(s.solutions);
  j["continuous_count"] = s.continuous_count;
  j["complete"] = s.complete;
  if (!s.complete) j["message"] = s.message;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& sol : s.solutions) {
    nlohmann::json e;
    e["type"] = std::string(to_string(sol.type));
    report_detail::add_piece(e, sol, "values",
                             [](const StepValues& v) { return step_values_json(v); });
    e["jump"] = sol.jump;
    e["residual"] = sol.residual;
    sols.push_back(e);
  }
  j["solutions"] = sols;
  return j;
}

nlohmann::json step_result_json(const StepSolveResult& r, const StepSolutionSet* all) {
  nlohmann::json j;
  j["status"] = std::string(to_string(r.status));
  j["solver"] = r.solver;
  if (is_solution(r.status)) {
    j["type"] = std::string(to_string(r.solution.type));
    j["values"] = step_values_json(r.solution.values);
  }
  j["residual"] = r.residuals.natural;
  nlohmann::json at = nlohmann::json::array();
  for (const auto& a : r.attempts)
    at.push_back({{"solver", a.solver}, {"status", std::string(to_string(a.status))},
                  {"residual", a.residual}, {"seconds", a.seconds}, {"message", a.message}});
  j["attempts"] = at;
  j["message"] = r.message;
  if (all) {
    j["solutions_found"] = report_detail::count_json(all->count());
    j["listed"] = 1;
    j["enumeration_complete"] = all->complete;
  }
  return j;
}

nlohmann::json contact_system_json(const ContactSystem& system) {
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& q : system.points)
    pts.push_back({{"mu", q.mu}, {"C_T", q.C_T}, {"k_a", q.k_a}, {"P_s", q.P_s},
                   {"P_T", q.P_T}, {"P_N", q.P_N}, {"g", q.g}});
  nlohmann::json A = nlohmann::json::array();
  for (Eigen::Index r = 0; r < system.A.rows(); ++r) {
    std::vector<double> row(static_cast<std::size_t>(system.A.cols()));
    for (Eigen::Index c = 0; c < system.A.cols(); ++c) row[static_cast<std::size_t>(c)] = system.A(r, c);
    A.push_back(row);
  }
  return {{"name", system.name}, {"A", A}, {"points", pts}};
}

nlohmann::json system_step_set_json(const SystemStepSolutionSet& s) {
  nlohmann::json j;
  j["count"] = s.solutions.size();
  j["complete"] = s.complete;
  j["notes"] = s.notes;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& sol : s.solutions) {
    std::vector<std::string> types;
    for (auto t : sol.types) types.emplace_back(to_string(t));
    // One array per field, one number per point.
    nlohmann::json vals = {{"DP_T", nlohmann::json::array()}, {"DP_N", nlohmann::json::array()},
                           {"Dw_T", nlohmann::json::array()}, {"Dw_N", nlohmann::json::array()},
                           {"Dw_Ti", nlohmann::json::array()}, {"Dw_w", nlohmann::json::array()},
                           {"P_T1", nlohmann::json::array()}, {"P_N1", nlohmann::json::array()},
                           {"g1", nlohmann::json::array()}};
    for (const auto& v : sol.values) {
      const nlohmann::json point = step_values_json(v);
      for (auto it = point.begin(); it != point.end(); ++it) vals[it.key()].push_back(*it);
    }
    sols.push_back({{"types", types}, {"values", vals}, {"residual", sol.residual}});
  }
  j["solutions"] = sols;
  return j;
}

namespace {

/// The echo of a 3-D request: the file, its points' start states (numbers for one point, arrays
/// with one entry per point for N points), the load, the wear law and the mode's options.
nlohmann::json step_3d_input_json(const StepOutcome& oc) {
  const Step3dOutcome& o = oc.step_3d;
  const int N = o.n_points();
  nlohmann::json state = nlohmann::json::array(), P_T0 = nlohmann::json::array(),
                 P_N0 = nlohmann::json::array(), g0 = nlohmann::json::array();
  for (int i = 0; i < N; ++i) {
    const Step3dState& st = o.states[static_cast<std::size_t>(i)];
    state.push_back(std::string(1, o.system.points[static_cast<std::size_t>(i)].state.state));
    P_T0.push_back(std::vector<double>{st.P_T0(0), st.P_T0(1)});
    P_N0.push_back(st.P_N0);
    g0.push_back(st.g0);
  }
  nlohmann::json in = {{"system", oc.system}, {"name", o.system.name}, {"DF", oc.DF},
                       {"wear_law", std::string(to_string(o.wear.law))}, {"mode", o.mode}};
  if (N == 1) {
    in.update({{"state", state[0]}, {"P_T0", P_T0[0]}, {"P_N0", P_N0[0]}, {"g0", g0[0]}});
  } else {
    in.update({{"n_points", N}, {"state", state}, {"P_T0", P_T0}, {"P_N0", P_N0}, {"g0", g0}});
  }
  if (o.wear.law == WearLaw::kMrozStupkiewicz) in["k_M"] = o.wear.k_M;
  if (o.mode == "facets") in["facets"] = oc.facets;
  if (o.mode == "multistart") in["multistart"] = oc.multistart;
  if (o.mode == "chain") in["chain"] = o.chain;
  return in;
}

nlohmann::json step_3d_json(const StepOutcome& oc, const std::string& cpkit_version) {
  const Step3dOutcome& o = oc.step_3d;
  const bool chain = o.mode == "chain";
  nlohmann::json j;
  j["cpkit_version"] = cpkit_version;
  j["input"] = step_3d_input_json(oc);
  j["dim"] = 3;
  j["mode"] = o.mode;
  if (o.n_points() == 1) {
    j.update(step_3d_set_json(o.set, !chain));
  } else {
    j["n_points"] = o.n_points();
    j.update(system_step_3d_set_json(o.system_set, !chain));
  }
  if (chain) {
    j["status"] = o.status == Status::kSolved ? "solved" : "no_solution";
    j["solver"] = o.solver;
    j["attempts"] = attempts_json(o.attempts);
  }
  if (o.mode == "facets") j["facets"] = oc.facets;
  return j;
}

}  // namespace

nlohmann::json step_outcome_json(const StepOutcome& outcome, const std::string& cpkit_version) {
  switch (outcome.route) {
    case StepRoute::kPointAll:
      return step_set_json(outcome.set);
    case StepRoute::kPointChain:
      return step_result_json(outcome.one, outcome.has_enumeration ? &outcome.set : nullptr);
    case StepRoute::kSystem: {
      nlohmann::json j;
      j["cpkit_version"] = cpkit_version;
      j["input"] = contact_system_json(outcome.system_problem.system);
      j["input"]["system"] = outcome.system;
      j["input"]["DF"] = outcome.DF;
      j["n_points"] = outcome.system_problem.system.n_points();
      j.update(system_step_set_json(outcome.system_set));
      return j;
    }
    case StepRoute::kPoint3d:
    case StepRoute::kSystem3d:
      break;
  }
  return step_3d_json(outcome, cpkit_version);
}

}  // namespace cpkit::rate
