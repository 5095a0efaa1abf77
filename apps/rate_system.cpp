// `cpkit rate --system FILE`: the rate problem of N contact points (docs/contact_model.md,
// "N points"): every solution by complete enumeration, or one by a single LCP solver checked
// against the enumerated set. Exit codes as for one point: 0 at least one solution, 1 none,
// 2 bad input, 3 a single solver's answer is not in the enumerated set, 5 the enumeration is
// not conclusive (e.g. a 2-dimensional piece of solutions; message on stderr).
#include <iostream>
#include <sstream>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::cli {
namespace {

std::vector<double> as_list(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

nlohmann::json values_json(const rate::SystemRates& r) {
  nlohmann::json j;
  j["dP_T"] = as_list(r.dP_T);
  j["dP_N"] = as_list(r.dP_N);
  j["dw_T"] = as_list(r.dw_T);
  j["dw_N"] = as_list(r.dw_N);
  j["dw_Ti"] = as_list(r.dw_Ti);
  j["dw_w"] = as_list(r.dw_w);
  return j;
}

std::string values_text(const rate::SystemRates& r) {
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

nlohmann::json types_json(const std::vector<rate::SolutionType>& t) {
  nlohmann::json j = nlohmann::json::array();
  for (auto x : t) j.push_back(std::string(rate::to_string(x)));
  return j;
}

}  // namespace

/// `cpkit rate --system FILE` with "dim": 3 (rate_system_3d.cpp).
int run_rate_system_3d(const rate::SystemFile& file, const std::vector<double>& dF,
                       const std::string& method, int facets, bool json,
                       std::optional<double> time_limit);

int run_rate_system(const std::string& path, const std::vector<double>& dF_arg,
                    const std::string& method_name, int facets, bool json,
                    std::optional<double> time_limit) {
  // read once (a pipe can be read only once), then by its dimension
  const rate::SystemFile file = rate::read_system_file(path);
  if (file.dim == 3) return run_rate_system_3d(file, dF_arg, method_name, facets, json, time_limit);
  if (time_limit)
    throw InputError("--time-limit applies to the faceted 3-D rate problems (\"dim\": 3 and "
                     "--facets K); " + path + " is a 2-D system");
  if (facets != 0)
    throw InputError("--facets applies to 3-D points (\"dim\": 3 in the system file, "
                     "docs/contact_3d.md); " + path + " is a 2-D system");
  const rate::ContactSystem sys = rate::parse_contact_system(file);
  const int N = sys.n_points();
  Eigen::VectorXd dF;
  if (!dF_arg.empty()) {
    if (static_cast<int>(dF_arg.size()) != 2 * N)
      throw InputError("--dF needs 2N = " + std::to_string(2 * N) + " numbers (T_1 N_1 T_2 N_2 ...) for the " +
                       std::to_string(N) + " points of " + path + ", got " + std::to_string(dF_arg.size()));
    dF = Eigen::Map<const Eigen::VectorXd>(dF_arg.data(), 2 * N);
  } else if (sys.dF) {
    dF = *sys.dF;
  } else {
    throw InputError("no load rate: give --dF (2N numbers) or \"dF\" in " + path);
  }
  const auto method = rate::rate_method_from_string(method_name);
  if (!method || *method == rate::RateMethod::kAnalytic)
    throw InputError("--method with --system must be enumerate, lemke, fb-newton or ipopt, got '" +
                     method_name + "'");
  // A limit that depends on N and the states, checked before the N^3 precomputation (a
  // 1000-point system was refused only after minutes; issue 24, item 12).
  if (const int m = rate::system_map_lcp_size(sys);
      *method == rate::RateMethod::kEnumerate && m > lcp::kMaxEnumerationSize)
    throw InputError(path + ": the rate LCP has size " + std::to_string(m) +
                     " (3 per point in state b, 1 per point in state d); the complete "
                     "enumeration takes at most " + std::to_string(lcp::kMaxEnumerationSize) +
                     " (--method lemke, fb-newton or ipopt find one verified solution)");
  const rate::SystemRateSolutionSet s = rate::solve_rate_problem(sys, dF, *method);
  const bool single = *method != rate::RateMethod::kEnumerate;
  int code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  std::string problem;
  if (single && s.disagreement) {
    problem = method_name + "'s solution is not in the enumerated solution set";
    code = kExitDisagreement;
  } else if (!single && !s.complete) {
    problem = "the enumeration is not conclusive: " + s.message;
    code = kExitInconclusive;
  }
  const std::string count = s.count() < 0 ? std::string("inf") : std::to_string(s.count());
  if (json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    j["input"] = {{"system", path}, {"name", sys.name}, {"dF", as_list(dF)}, {"method", method_name}};
    j["n_points"] = N;
    j["complete"] = s.complete;
    if (s.complete) {
      if (s.count() < 0) j["count"] = "inf"; else j["count"] = s.count();
    } else {
      j["found"] = s.solutions.size();
    }
    if (!s.message.empty()) j["message"] = s.message;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& p : s.solutions) {
      nlohmann::json e;
      e["types"] = types_json(p.types);
      e["kind"] = std::string(rate::to_string(p.kind));
      switch (p.kind) {
        case rate::RateSolution::Kind::kPoint:
          e["values"] = values_json(p.start);
          break;
        case rate::RateSolution::Kind::kSegment:
          e["start"] = values_json(p.start);
          e["start_closed"] = p.start_closed;
          e["end"] = values_json(p.end);
          e["end_closed"] = p.end_closed;
          break;
        case rate::RateSolution::Kind::kRay:
          e["start"] = values_json(p.start);
          e["start_closed"] = p.start_closed;
          e["direction"] = values_json(p.direction);
          break;
      }
      sols.push_back(e);
    }
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "rate problem, system " << (sys.name.empty() ? path : sys.name) << " (" << N
              << " points), method " << method_name << "\n";
    if (s.complete) std::cout << "count: " << count << "\n";
    else if (single) std::cout << (s.solutions.empty() ? "no solution found" : "a solution") << " (found by " << method_name << "; not a count)\n";
    else std::cout << "solutions found: " << s.solutions.size() << " (INCOMPLETE: not a count)\n";
    for (const auto& p : s.solutions) {
      std::cout << "  " << rate::types_string(p.types) << ' ' << rate::to_string(p.kind) << ":";
      switch (p.kind) {
        case rate::RateSolution::Kind::kPoint:
          std::cout << values_text(p.start) << "\n";
          break;
        case rate::RateSolution::Kind::kSegment:
          std::cout << " from" << values_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                    << "\n      to" << values_text(p.end) << (p.end_closed ? " (closed)" : " (open)") << "\n";
          break;
        case rate::RateSolution::Kind::kRay:
          std::cout << " from" << values_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                    << "\n      direction" << values_text(p.direction) << "\n";
          break;
      }
    }
    if (!s.message.empty()) std::cout << "note: " << s.message << "\n";
  }
  if (!problem.empty()) std::cerr << "cpkit rate: " << problem << '\n';
  return code;
}

}  // namespace cpkit::cli
