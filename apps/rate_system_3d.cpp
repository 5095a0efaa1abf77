// `cpkit rate --system FILE` for a "dim": 3 system (docs/contact_3d.md): every solution of the
// rate problem; one point exactly (the slip directions of state b from the roots of a
// trigonometric quadratic) or with --facets K as the faceted LCP; N coupled points with
// --facets K (faceted grazing points). Exit codes as for 2-D: 0 at least one solution, 1 none,
// 2 bad input, 5 not proved complete (message on stderr).
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::cli {
namespace {

using Pair = std::vector<double>;

/// One listed solution: per point its type and rates (a ray: the one-point state-d case).
struct Row {
  std::vector<rate3d::Type3d> types;
  std::vector<rate3d::Rates3d> rates, direction;
  bool ray = false, origin_included = true;
};

nlohmann::json values_json(const std::vector<rate3d::Rates3d>& rs) {
  // as the 2-D N-point output, one entry per point; tangential quantities as [x, y] pairs
  nlohmann::json j = {{"dP_T", nlohmann::json::array()}, {"dP_N", nlohmann::json::array()},
                      {"dw_T", nlohmann::json::array()}, {"dw_N", nlohmann::json::array()},
                      {"dw_Ti", nlohmann::json::array()}, {"dw_w", nlohmann::json::array()}};
  for (const auto& r : rs) {
    j["dP_T"].push_back(Pair{r.dP_T(0), r.dP_T(1)});
    j["dP_N"].push_back(r.dP_N);
    j["dw_T"].push_back(Pair{r.dw_T(0), r.dw_T(1)});
    j["dw_N"].push_back(r.dw_N);
    j["dw_Ti"].push_back(Pair{r.dw_Ti(0), r.dw_Ti(1)});
    j["dw_w"].push_back(r.dw_w);
  }
  return j;
}

std::string values_text(const std::vector<rate3d::Rates3d>& rs) {
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
  pairs("dP_T", [](const rate3d::Rates3d& r) { return r.dP_T; });
  scalars("dP_N", [](const rate3d::Rates3d& r) { return r.dP_N; });
  pairs("dw_T", [](const rate3d::Rates3d& r) { return r.dw_T; });
  scalars("dw_N", [](const rate3d::Rates3d& r) { return r.dw_N; });
  pairs("dw_Ti", [](const rate3d::Rates3d& r) { return r.dw_Ti; });
  scalars("dw_w", [](const rate3d::Rates3d& r) { return r.dw_w; });
  return o.str();
}

std::string types_text(const std::vector<rate3d::Type3d>& t) {
  std::string s;
  for (std::size_t i = 0; i < t.size(); ++i) s += (i ? "/" : "") + std::string(rate3d::to_string(t[i]));
  return s;
}

/// Unit slip directions and angles per point (null where the point does not slip).
void slip_json(const Row& r, nlohmann::json& e) {
  nlohmann::json dir = nlohmann::json::array(), ang = nlohmann::json::array();
  bool any = false;
  for (std::size_t i = 0; i < r.types.size(); ++i) {
    const Eigen::Vector2d v = r.ray ? r.direction[i].dw_Ti : r.rates[i].dw_Ti;
    if (r.types[i] == rate3d::Type3d::kSlip && v.cwiseAbs().maxCoeff() > 0) {
      const Eigen::Vector2d u = v.normalized();
      dir.push_back(Pair{u(0), u(1)});
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

}  // namespace

int run_rate_system_3d(const rate::SystemFile& file, const std::vector<double>& dF_arg,
                       const std::string& method, int facets, bool json,
                       std::optional<double> time_limit_arg) {
  if (time_limit_arg && !(*time_limit_arg > 0 && *time_limit_arg <= 1e9))
    throw InputError("--time-limit must be a positive number of seconds (at most 1e9), got " +
                     num_text(*time_limit_arg));
  if (time_limit_arg && facets == 0)
    throw InputError("--time-limit applies with --facets K (the faceted enumeration); the exact "
                     "one-point route is solved in bounded time");
  // One budget for the whole solve (every separation case of the N-point problem).
  const double time_limit = time_limit_arg.value_or(60.0);
  const std::string& path = file.source;
  const rate3d::ContactSystem3d sys = rate3d::parse_contact_system_3d(file);
  const int N = sys.n_points();
  if (method != "enumerate")
    throw InputError("--method " + method + " is not available for 3-D points: the solution set "
                     "is computed exactly (or with --facets K as a faceted LCP by enumeration)");
  if (N > 1 && facets == 0)
    throw InputError(path + ": " + std::to_string(N) + " coupled 3-D points are solved with the "
                     "faceted friction ellipses: give --facets K (e.g. 16; docs/contact_3d.md)");
  Eigen::VectorXd dF;
  if (!dF_arg.empty()) {
    if (static_cast<int>(dF_arg.size()) != 3 * N)
      throw InputError("--dF needs 3N = " + std::to_string(3 * N) + " numbers (T_X T_Y N per point) for the " +
                       std::to_string(N) + " point(s) of " + path + ", got " + std::to_string(dF_arg.size()));
    dF = Eigen::Map<const Eigen::VectorXd>(dF_arg.data(), 3 * N);
  } else if (sys.dF) {
    dF = *sys.dF;
  } else {
    throw InputError("no load rate: give --dF (3N numbers: T_X T_Y N per point) or \"dF\" in " + path);
  }
  std::vector<Row> rows;
  bool complete = true, timed_out = false;
  std::string message;
  if (N == 1) {
    const rate3d::Point3dParameters p = sys.point_parameters(0);
    const rate3d::Point3dState& st = sys.points[0].state;
    if (facets != 0 && st.state != 'b')
      throw InputError(std::string("--facets applies to state b (grazing); state ") + st.state +
                       " has a linear rate problem, solved exactly without it");
    const rate3d::RateSolutionSet3d s =
        facets != 0 ? rate3d::solve_rate_3d_faceted(p, dF, facets, time_limit).set
                    : rate3d::solve_rate_3d(p, st, dF);
    complete = s.complete;
    message = s.message;
    for (const auto& x : s.solutions)
      rows.push_back({{x.type}, {x.at}, {x.direction}, x.ray, x.origin_included});
  } else {
    const rate3d::SystemRateSet3d s =
        rate3d::solve_system_rate_3d_faceted(sys, dF, facets, time_limit);
    complete = s.complete;
    message = s.message;
    timed_out = s.timed_out;
    for (const auto& x : s.solutions) rows.push_back({x.types, x.rates, {}, false, true});
  }
  const int count = static_cast<int>(rows.size());
  bool infinite = false;
  for (const auto& r : rows) infinite = infinite || r.ray;
  int code = rows.empty() ? kExitNoSolution : kExitOk;
  if (!complete) code = kExitInconclusive;
  const std::string route = facets != 0 ? "faceted" : "exact";
  if (json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    j["input"] = {{"system", path}, {"name", sys.name}, {"dF", std::vector<double>(dF.data(), dF.data() + dF.size())},
                  {"method", method}, {"facets", facets}};
    j["dim"] = 3;
    j["n_points"] = N;
    j["route"] = route;
    j["complete"] = complete;
    if (timed_out) j["time_limit_reached"] = true;
    if (complete) {
      if (infinite) j["count"] = "inf"; else j["count"] = count;
    } else {
      j["found"] = count;
    }
    if (!message.empty()) j["message"] = message;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& r : rows) {
      nlohmann::json e;
      e["types"] = nlohmann::json::array();
      for (auto t : r.types) e["types"].push_back(std::string(rate3d::to_string(t)));
      e["kind"] = r.ray ? "ray" : "point";
      if (r.ray) {
        e["start"] = values_json(r.rates);
        e["start_closed"] = r.origin_included;
        e["direction"] = values_json(r.direction);
      } else {
        e["values"] = values_json(r.rates);
      }
      slip_json(r, e);
      sols.push_back(e);
    }
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "rate problem, 3-D system " << (sys.name.empty() ? path : sys.name) << " (" << N
              << (N == 1 ? " point, state " + std::string(1, sys.points[0].state.state) : std::string(" points"))
              << "), " << route << (facets != 0 ? " with " + std::to_string(facets) + " facets" : "")
              << "\n";
    if (complete) std::cout << "count: " << (infinite ? std::string("inf") : std::to_string(count)) << "\n";
    else std::cout << "solutions found: " << count << " (INCOMPLETE: not a count)\n";
    for (const auto& r : rows) {
      std::cout << "  " << types_text(r.types) << (r.ray ? " ray from" : " point:") << values_text(r.rates);
      nlohmann::json e;
      slip_json(r, e);
      if (e.contains("slip_angle")) {
        std::cout << " slip_angle=[";
        for (std::size_t i = 0; i < r.types.size(); ++i) {
          const auto& x = e["slip_angle"][i];
          std::cout << (i ? ", " : "");
          if (x.is_null()) std::cout << '-'; else std::cout << x.get<double>();
        }
        std::cout << ']';
      }
      std::cout << "\n";
      if (r.ray) std::cout << "      direction" << values_text(r.direction) << "\n";
    }
    if (!message.empty()) std::cout << "note: " << message << "\n";
  }
  if (!complete) std::cerr << "cpkit rate: not proved complete: " << message << '\n';
  return code;
}

}  // namespace cpkit::cli
