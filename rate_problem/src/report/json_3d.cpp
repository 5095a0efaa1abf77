#include "cpkit/rate_problem/report/json_3d.hpp"

#include <cmath>
#include <string>

#include "piece_report.hpp"

namespace cpkit::rate {

namespace {

using Pair = std::vector<double>;
Pair pair(const Eigen::Vector2d& v) { return {v(0), v(1)}; }

}  // namespace

nlohmann::json rates_3d_json(const std::vector<Rates3d>& rs) {
  // as the 2-D N-point output, one entry per point; tangential quantities as [x, y] pairs
  nlohmann::json j = {{"dP_T", nlohmann::json::array()}, {"dP_N", nlohmann::json::array()},
                      {"dw_T", nlohmann::json::array()}, {"dw_N", nlohmann::json::array()},
                      {"dw_Ti", nlohmann::json::array()}, {"dw_w", nlohmann::json::array()}};
  for (const auto& r : rs) {
    j["dP_T"].push_back(pair(r.dP_T));
    j["dP_N"].push_back(r.dP_N);
    j["dw_T"].push_back(pair(r.dw_T));
    j["dw_N"].push_back(r.dw_N);
    j["dw_Ti"].push_back(pair(r.dw_Ti));
    j["dw_w"].push_back(r.dw_w);
  }
  return j;
}

void add_slip_json(nlohmann::json& e, const std::vector<SolutionType>& types,
                   const std::vector<Rates3d>& dw_source) {
  nlohmann::json dir = nlohmann::json::array(), ang = nlohmann::json::array();
  bool any = false;
  for (std::size_t i = 0; i < types.size(); ++i) {
    const Eigen::Vector2d v = dw_source[i].dw_Ti;
    if (types[i] == SolutionType::kSlip && v.cwiseAbs().maxCoeff() > 0) {
      const Eigen::Vector2d u = v.normalized();
      dir.push_back(pair(u));
      ang.push_back(std::atan2(u(1), u(0)));
      any = true;
    } else {
      dir.push_back(nullptr);
      ang.push_back(nullptr);
    }
  }
  if (any) {
    e["slip_direction"] = dir;
    e["slip_angle"] = ang;
  }
}

nlohmann::json step_3d_solution_json(const Step3dSolution& s) {
  const Step3dValues& v = s.values;
  nlohmann::json e;
  e["type"] = std::string(to_string(s.type));
  e["P_T1"] = pair(v.P_T1);
  e["P_N1"] = v.P_N1;
  e["DP"] = Pair{v.DP_T(0), v.DP_T(1), v.DP_N};
  e["Dw"] = Pair{v.Dw_T(0), v.Dw_T(1), v.Dw_N};
  e["Dw_Ti"] = pair(v.Dw_Ti);
  e["Dw_w"] = v.Dw_w;
  e["g1"] = v.g1;
  e["lambda"] = v.lambda;
  if (s.type == SolutionType::kSlip) {
    e["slip_direction"] = pair(s.slip_direction);
    e["slip_angle"] = s.slip_angle;
  } else {
    e["slip_direction"] = nullptr;
    e["slip_angle"] = nullptr;
  }
  e["residual"] = s.residual;
  return e;
}

nlohmann::json fretting_3d_sample_json(const Fretting3dSample& s) {
  return {{"step", s.step}, {"t", s.t}, {"F_T", pair(s.F_T)}, {"F_N", s.F_N},
          {"P_T", pair(s.P_T)}, {"P_N", s.P_N}, {"g", s.g}, {"w_T", pair(s.w_T)},
          {"w_N", s.w_N}, {"w_Ti", pair(s.w_Ti)}, {"w_w", s.w_w},
          {"type", std::string(to_string(s.type))}};
}

nlohmann::json system_rate_3d_json(const SystemRateRoute3d& r) {
  nlohmann::json j;
  j["route"] = r.facets != 0 ? "faceted" : "exact";
  report_detail::add_count(j, r.complete, r.infinite() ? -1 : r.count(), r.solutions.size());
  if (r.timed_out) j["time_limit_reached"] = true;
  if (!r.message.empty()) j["message"] = r.message;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& x : r.solutions) {
    nlohmann::json e;
    e["types"] = nlohmann::json::array();
    for (auto t : x.types) e["types"].push_back(std::string(to_string(t)));
    e["kind"] = x.ray ? "ray" : "point";
    if (x.ray) {
      e["start"] = rates_3d_json(x.rates);
      e["start_closed"] = x.origin_included;
      e["direction"] = rates_3d_json(x.direction);
    } else {
      e["values"] = rates_3d_json(x.rates);
    }
    add_slip_json(e, x.types, x.ray ? x.direction : x.rates);
    sols.push_back(e);
  }
  j["solutions"] = sols;
  return j;
}

nlohmann::json attempts_json(const std::vector<Attempt>& attempts) {
  nlohmann::json at = nlohmann::json::array();
  for (const auto& x : attempts)
    at.push_back({{"solver", x.solver},
                  {"solved", x.status == Status::kSolved},
                  {"residual", std::isfinite(x.residual) ? nlohmann::json(x.residual)
                                                         : nlohmann::json(nullptr)},
                  {"iterations", x.iterations},
                  {"seconds", x.seconds},
                  {"message", x.message}});
  return at;
}

nlohmann::json step_3d_set_json(const Step3dSolutionSet& set, bool with_count) {
  nlohmann::json j;
  if (with_count) {
    j["complete"] = set.complete;
    j[set.complete ? "count" : "found"] = set.count();
  }
  if (!set.message.empty()) j["message"] = set.message;
  j["solutions"] = nlohmann::json::array();
  for (const auto& s : set.solutions) j["solutions"].push_back(step_3d_solution_json(s));
  return j;
}

nlohmann::json system_step_3d_set_json(const SystemStep3dSolutionSet& set, bool with_count) {
  nlohmann::json j;
  if (with_count) {
    j["complete"] = false;
    j["found"] = set.count();
  }
  if (!set.message.empty()) j["message"] = set.message;
  j["solutions"] = nlohmann::json::array();
  for (const auto& s : set.solutions) {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& x : s.points) pts.push_back(step_3d_solution_json(x));
    j["solutions"].push_back({{"points", pts}, {"residual", s.residual}});
  }
  return j;
}

}  // namespace cpkit::rate
