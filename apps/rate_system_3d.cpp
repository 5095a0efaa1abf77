// `cpkit rate --system FILE` for a "dim": 3 system (docs/contact_3d.md): one 3-D point, every
// solution of its rate problem, exactly (the slip directions of state b from the roots of a
// trigonometric quadratic) or with --facets K as the faceted LCP. Exit codes as for 2-D: 0 at
// least one solution, 1 none, 2 bad input, 5 not proved complete (message on stderr).
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/three_d/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/three_d/system_3d.hpp"

namespace cpkit::cli {
namespace {

using Pair = std::vector<double>;

nlohmann::json values_json(const rate3d::Rates3d& r) {
  // per point, as the 2-D N-point output: tangential quantities as [x, y] pairs
  return {{"dP_T", {Pair{r.dP_T(0), r.dP_T(1)}}}, {"dP_N", {r.dP_N}},
          {"dw_T", {Pair{r.dw_T(0), r.dw_T(1)}}}, {"dw_N", {r.dw_N}},
          {"dw_Ti", {Pair{r.dw_Ti(0), r.dw_Ti(1)}}}, {"dw_w", {r.dw_w}}};
}

std::string values_text(const rate3d::Rates3d& r) {
  std::ostringstream o;
  o.precision(10);
  o << " dP_T=[" << r.dP_T(0) << ", " << r.dP_T(1) << "] dP_N=" << r.dP_N << " dw_T=["
    << r.dw_T(0) << ", " << r.dw_T(1) << "] dw_N=" << r.dw_N << " dw_Ti=[" << r.dw_Ti(0) << ", "
    << r.dw_Ti(1) << "] dw_w=" << r.dw_w;
  return o.str();
}

}  // namespace

int run_rate_system_3d(const std::string& path, const std::vector<double>& dF_arg,
                       const std::string& method, int facets, bool json) {
  const rate3d::ContactSystem3d sys = rate3d::read_contact_system_3d(path);
  const int N = sys.n_points();
  if (N != 1)
    throw InputError(path + ": 3-D systems of " + std::to_string(N) +
                     " points are not solved yet (one 3-D point only: the exact and faceted "
                     "one-point rate problem, docs/contact_3d.md)");
  if (method != "enumerate")
    throw InputError("--method " + method + " is not available for 3-D points: the solution set "
                     "is computed exactly (or with --facets K as a faceted LCP by enumeration)");
  Eigen::Vector3d dF;
  if (!dF_arg.empty()) {
    if (dF_arg.size() != 3)
      throw InputError("--dF needs 3N = 3 numbers (T_X T_Y N) for the 3-D point of " +
                       path + ", got " + std::to_string(dF_arg.size()));
    dF = Eigen::Vector3d(dF_arg[0], dF_arg[1], dF_arg[2]);
  } else if (sys.dF) {
    dF = *sys.dF;
  } else {
    throw InputError("no load rate: give --dF (3 numbers: T_X T_Y N) or \"dF\" in " + path);
  }
  const rate3d::Point3dParameters p = sys.point_parameters(0);
  const rate3d::Point3dState& st = sys.points[0].state;
  if (facets != 0 && st.state != 'b')
    throw InputError(std::string("--facets applies to state b (grazing); state ") + st.state +
                     " has a linear rate problem, solved exactly without it");
  rate3d::RateSolutionSet3d s;
  if (facets != 0) {
    s = rate3d::solve_rate_3d_faceted(p, dF, facets).set;
  } else {
    s = rate3d::solve_rate_3d(p, st, dF);
  }
  int code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  if (!s.complete) code = kExitInconclusive;
  const std::string route = facets != 0 ? "faceted" : "exact";
  if (json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    j["input"] = {{"system", path}, {"name", sys.name}, {"dF", {dF(0), dF(1), dF(2)}},
                  {"method", method}, {"facets", facets}};
    j["dim"] = 3;
    j["n_points"] = N;
    j["route"] = route;
    j["complete"] = s.complete;
    if (s.complete) {
      if (s.infinite()) j["count"] = "inf"; else j["count"] = s.count();
    } else {
      j["found"] = s.count();
    }
    if (!s.message.empty()) j["message"] = s.message;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& x : s.solutions) {
      nlohmann::json e;
      e["types"] = {std::string(rate3d::to_string(x.type))};
      e["kind"] = x.ray ? "ray" : "point";
      if (x.ray) {
        e["start"] = values_json(x.at);
        e["start_closed"] = x.origin_included;
        e["direction"] = values_json(x.direction);
      } else {
        e["values"] = values_json(x.at);
      }
      if (x.type == rate3d::Type3d::kSlip) {
        e["slip_direction"] = {Pair{x.slip_direction(0), x.slip_direction(1)}};
        e["slip_angle"] = {x.slip_angle};
      }
      sols.push_back(e);
    }
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "rate problem, 3-D system " << (sys.name.empty() ? path : sys.name) << " (1 point, state "
              << st.state << "), " << route << (facets != 0 ? " with " + std::to_string(facets) + " facets" : "")
              << "\n";
    if (s.complete) std::cout << "count: " << (s.infinite() ? std::string("inf") : std::to_string(s.count())) << "\n";
    else std::cout << "solutions found: " << s.count() << " (INCOMPLETE: not a count)\n";
    for (const auto& x : s.solutions) {
      std::cout << "  " << rate3d::to_string(x.type) << (x.ray ? " ray from" : " point:") << values_text(x.at);
      if (x.type == rate3d::Type3d::kSlip) std::cout << " slip_angle=" << x.slip_angle;
      std::cout << "\n";
      if (x.ray) std::cout << "      direction" << values_text(x.direction) << "\n";
    }
    if (!s.message.empty()) std::cout << "note: " << s.message << "\n";
  }
  if (!s.complete) std::cerr << "cpkit rate: not proved complete: " << s.message << '\n';
  return code;
}

}  // namespace cpkit::cli
