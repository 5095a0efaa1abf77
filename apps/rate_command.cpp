// `cpkit rate`: the rate problem of the one-point contact problem [Stromberg et al. 1996,
// Sec. 4.3]: every solution for a contact state and a load rate (docs/contact_model.md).
//
//   cpkit rate --state a|b|c|d --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X
//              --P_N X --sgnPT S] --dF DFT DFN [--method enumerate|analytic|lemke|fb-newton|ipopt]
//              [--criterion 38|35] [--json]
//
// Default method: enumerate, cross-checked against analytic. Single solvers (lemke, fb-newton,
// ipopt) find at most one solution: their output says "a solution" with complete = false and
// no count (the set may hold more; the enumerated count is shown for reference, as
// "enumerated_count" in JSON), and their point is checked against the enumerated set. Exit codes: 0 at least one solution, 1 none
// (or the single solver found none), 2 bad input (also: a solution not representable in
// double), 3 the routes disagree (reason on stderr), 5 the enumeration is inconclusive (sign
// tests too close to call; the routes run in normalised units, so this is conditioning, not
// units).
//
// N points (run_rate_system below; "dim": 3 files: run_rate_system_3d): cpkit rate --system FILE [--dF ... 2N numbers] [--json]
//              [--method enumerate|lemke|fb-newton|ipopt]
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "model_options.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::cli {
namespace {

/// How a system's load rate is described in messages (2-D and 3-D differ).
struct LoadRateWords {
  const char* layout;       ///< the order of the numbers
  const char* points;       ///< "points" or "point(s)"
  const char* none_suffix;  ///< appended to "2N numbers" when there is no load rate
};

/// The load rate of an N-point system: --dF (per_point x N numbers) or else the file's "dF".
Eigen::VectorXd system_load_rate(const std::vector<double>& arg,
                                 const std::optional<Eigen::VectorXd>& from_file, int per_point,
                                 int N, const std::string& path, const LoadRateWords& words) {
  const std::string n = std::to_string(per_point);
  if (arg.empty()) {
    if (from_file) return *from_file;
    throw InputError("no load rate: give --dF (" + n + "N numbers" + words.none_suffix +
                     ") or \"dF\" in " + path);
  }
  if (static_cast<int>(arg.size()) != per_point * N)
    throw InputError("--dF needs " + n + "N = " + std::to_string(per_point * N) + " numbers (" +
                     words.layout + ") for the " + std::to_string(N) + " " + words.points +
                     " of " + path + ", got " + std::to_string(arg.size()));
  return Eigen::Map<const Eigen::VectorXd>(arg.data(), per_point * N);
}



std::string values_3d_text(const std::vector<rate::Rates3d>& rs) {
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
  pairs("dP_T", [](const rate::Rates3d& r) { return r.dP_T; });
  scalars("dP_N", [](const rate::Rates3d& r) { return r.dP_N; });
  pairs("dw_T", [](const rate::Rates3d& r) { return r.dw_T; });
  scalars("dw_N", [](const rate::Rates3d& r) { return r.dw_N; });
  pairs("dw_Ti", [](const rate::Rates3d& r) { return r.dw_Ti; });
  scalars("dw_w", [](const rate::Rates3d& r) { return r.dw_w; });
  return o.str();
}

std::string types_3d_text(const std::vector<rate::SolutionType>& t) {
  std::string s;
  for (std::size_t i = 0; i < t.size(); ++i) s += (i ? "/" : "") + std::string(rate::to_string(t[i]));
  return s;
}

}  // namespace

static int run_rate_system_3d(const rate::SystemFile& file, const std::vector<double>& dF_arg,
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
  const rate::ContactSystem3d sys = rate::parse_contact_system_3d(file);
  const int N = sys.n_points();
  if (method != "enumerate")
    throw InputError("--method " + method + " is not available for 3-D points: the solution set "
                     "is computed exactly (or with --facets K as a faceted LCP by enumeration)");
  if (N > 1 && facets == 0)
    throw InputError(path + ": " + std::to_string(N) + " coupled 3-D points are solved with the "
                     "faceted friction ellipses: give --facets K (e.g. 16; docs/contact_3d.md)");
  const Eigen::VectorXd dF = system_load_rate(dF_arg, sys.dF, 3, N, path, {"T_X T_Y N per point",
                                              "point(s)", ": T_X T_Y N per point"});
  if (N == 1 && facets != 0 && sys.points[0].state.state != 'b')
    throw InputError(std::string("--facets applies to state b (grazing); state ") +
                     sys.points[0].state.state +
                     " has a linear rate problem, solved exactly without it");
  const rate::SystemRateRoute3d s = rate::solve_system_rate_3d(sys, dF, facets, time_limit);
  const bool complete = s.complete;
  const std::string& message = s.message;
  const int code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  if (json) {
    nlohmann::json j = rate::system_rate_3d_json(s);
    j["cpkit_version"] = CPKIT_VERSION;
    j["input"] = {{"system", path}, {"name", sys.name}, {"dF", std::vector<double>(dF.data(), dF.data() + dF.size())},
                  {"method", method}, {"facets", facets}};
    j["dim"] = 3;
    j["n_points"] = N;
    print_json(j);
  } else {
    std::cout << "rate problem, 3-D system " << (sys.name.empty() ? path : sys.name) << " (" << N
              << (N == 1 ? " point, state " + std::string(1, sys.points[0].state.state) : std::string(" points"))
              << "), " << (facets != 0 ? "faceted with " + std::to_string(facets) + " facets" : "exact")
              << "\n";
    if (complete) std::cout << "count: " << (s.infinite() ? std::string("inf") : std::to_string(s.count())) << "\n";
    else std::cout << "solutions found: " << s.count() << " (INCOMPLETE: not a count)\n";
    for (const auto& r : s.solutions) {
      std::cout << "  " << types_3d_text(r.types) << (r.ray ? " ray from" : " point:") << values_3d_text(r.rates);
      nlohmann::json e;
      rate::add_slip_json(e, r.types, r.ray ? r.direction : r.rates);
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
      if (r.ray) std::cout << "      direction" << values_3d_text(r.direction) << "\n";
    }
    if (!message.empty()) std::cout << "note: " << message << "\n";
  }
  if (!complete) std::cerr << "cpkit rate: not proved complete: " << message << '\n';
  return complete ? code : kExitInconclusive;
}

namespace {

std::vector<double> as_list(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::string system_values_text(const rate::SystemRates& r) {
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

}  // namespace

static int run_rate_system(const std::string& path, const std::vector<double>& dF_arg,
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
  const Eigen::VectorXd dF =
      system_load_rate(dF_arg, sys.dF, 2, N, path, {"T_1 N_1 T_2 N_2 ...", "points", ""});
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
    j.update(rate::system_rate_set_json(s));
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
          std::cout << system_values_text(p.start) << "\n";
          break;
        case rate::RateSolution::Kind::kSegment:
          std::cout << " from" << system_values_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                    << "\n      to" << system_values_text(p.end) << (p.end_closed ? " (closed)" : " (open)") << "\n";
          break;
        case rate::RateSolution::Kind::kRay:
          std::cout << " from" << system_values_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                    << "\n      direction" << system_values_text(p.direction) << "\n";
          break;
      }
    }
    if (!s.message.empty()) std::cout << "note: " << s.message << "\n";
  }
  if (!problem.empty()) std::cerr << "cpkit rate: " << problem << '\n';
  return code;
}


namespace {

struct RateArgs {
  std::string state;
  ModelArgs model;
  double P_N = 0;
  int sgn_PT = 1;
  std::vector<double> dF;
  std::string method = "enumerate";
  bool json = false;
  std::string system;  ///< --system FILE: the N-point problem (rate_system.cpp)
  int facets = 0;      ///< --facets K: a 3-D system's faceted route (0: exact)
  std::optional<double> time_limit;  ///< --time-limit S: the faceted 3-D solves' budget
  std::vector<CLI::Option*> one_point_required;  ///< required unless --system is given
};

std::string rates_text(const rate::Rates& r) {
  std::ostringstream o;
  o.precision(10);
  o << "dP_T=" << r.dP_T << " dP_N=" << r.dP_N << " dw_T=" << r.dw_T << " dw_N=" << r.dw_N
    << " dw_Ti=" << r.dw_Ti << " dw_w=" << r.dw_w;
  return o.str();
}

std::vector<std::string> sorted_types(const rate::RateSolutionSet& s) {
  std::set<std::string> t;
  for (const auto& p : s.solutions) t.insert(std::string(rate::to_string(p.type)));
  return {t.begin(), t.end()};
}

/// True for lemke, fb-newton and ipopt: one solver, at most one solution, never a count.
bool single_solver(rate::RateMethod m) {
  return m != rate::RateMethod::kEnumerate && m != rate::RateMethod::kAnalytic;
}

std::string count_text(const rate::RateSolutionSet& s) {
  return s.count() < 0 ? std::string("inf") : std::to_string(s.count());
}

void print_text(const rate::RateSolutionSet& s, const RateArgs& a,
                const rate::RateSolutionSet* reference) {
  std::cout << "rate problem, state " << a.state << ", method " << a.method << "\n";
  if (s.complete) {
    std::cout << "count: " << count_text(s) << "   types:";
  } else if (!single_solver(*rate::rate_method_from_string(a.method))) {
    std::cout << "solutions found: " << s.solutions.size()
              << " (the enumeration is INCOMPLETE: not a count)   types:";
  } else if (!s.solutions.empty()) {
    std::cout << "a solution (found by " << a.method
              << "; one solver finds one solution, the set may hold more: not a count)"
              << "   type:";
  } else {
    std::cout << "no solution found by " << a.method << " (incomplete: not a proof)   types:";
  }
  for (const auto& t : sorted_types(s)) std::cout << ' ' << t;
  std::cout << "\nLambda: " << s.Lambda << "   D_+: " << s.D_plus << "   D_-: " << s.D_minus
            << "   unique for all directions: " << (s.unique_for_all_directions ? "yes" : "no")
            << "\n";
  for (const auto& p : s.solutions) {
    std::cout << "  " << rate::to_string(p.type) << ' ' << rate::to_string(p.kind) << ": ";
    switch (p.kind) {
      case rate::RateSolution::Kind::kPoint:
        std::cout << rates_text(p.start) << "\n";
        break;
      case rate::RateSolution::Kind::kSegment:
        std::cout << "from " << rates_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                  << "\n      to " << rates_text(p.end) << (p.end_closed ? " (closed)" : " (open)")
                  << "\n";
        break;
      case rate::RateSolution::Kind::kRay:
        std::cout << "from " << rates_text(p.start) << (p.start_closed ? " (closed)" : " (open)")
                  << "\n      direction " << rates_text(p.direction) << "\n";
        break;
    }
  }
  if (!s.message.empty()) std::cout << "note: " << s.message << "\n";
  if (reference && reference->complete)
    std::cout << "complete enumeration (--method enumerate): " << count_text(*reference)
              << " solution(s)\n";
}

int run_rate(const RateArgs& a) {
  if (!a.system.empty()) {
    for (const CLI::Option* o : a.one_point_required)
      if (o->count() > 0 && o->get_name() != "--dF")
        throw InputError(o->get_name() + " is a one-point option; with --system the state and "
                         "parameters come from the system file");
    return run_rate_system(a.system, a.dF, a.method, a.facets, a.json, a.time_limit);
  }
  if (a.time_limit)
    throw InputError("--time-limit applies to the faceted 3-D rate problems (--system FILE "
                     "with \"dim\": 3 and --facets K); the one-point 2-D problem is solved in "
                     "bounded time");
  if (a.facets != 0)
    throw InputError("--facets applies to 3-D points (--system FILE with \"dim\": 3, "
                     "docs/contact_3d.md)");
  for (const CLI::Option* o : a.one_point_required)
    if (o->count() == 0) throw InputError(o->get_name() + " is required (or give --system FILE)");
  const rate::ContactParameters p = model_parameters(a.model);
  rate::ContactState st;
  const auto label = rate::state_from_string(a.state);
  if (!label) throw InputError("--state must be a, b, c or d, got '" + a.state + "'");
  st.label = *label;
  st.P_N = a.P_N;
  st.sgn_PT = a.sgn_PT;
  throw_if_invalid(st.validate(p), "contact state");
  if (a.dF.size() != 2) throw InputError("--dF needs two values: DFT DFN");
  const rate::LoadRate f{a.dF[0], a.dF[1]};
  const auto method = rate::rate_method_from_string(a.method);
  if (!method)
    throw InputError("--method must be enumerate, analytic, lemke, fb-newton or ipopt, got '" +
                     a.method + "'");
  const rate::CheckedRateSolution checked = rate::solve_rate_problem_checked(p, st, f, *method);
  const rate::RateSolutionSet& s = checked.set;
  int code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  const std::string& problem = checked.problem;
  const bool single = checked.reference.has_value();
  if (single && s.solutions.empty())
    std::cerr << "cpkit rate: " << s.message << "; the enumeration has "
              << (checked.reference->count() < 0 ? std::string("infinitely many")
                                                 : std::to_string(checked.reference->count()))
              << " solution(s)\n";
  const rate::RateSolutionSet* reference = single ? &*checked.reference : nullptr;
  if (a.json) print_json(rate::rate_set_json(s, reference)); else print_text(s, a, reference);
  if (!problem.empty()) {
    std::cerr << "cpkit rate: " << problem << '\n';
    code = checked.inconclusive ? kExitInconclusive : kExitDisagreement;
  }
  return code;
}

}  // namespace

void add_rate_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<RateArgs>();
  auto* cmd = app.add_subcommand(
      "rate", "Rate problem of the one-point contact problem [Stromberg et al. 1996, Sec. 4.3]");
  auto* state = cmd->add_option("--state", args->state,
                                "contact state: a (open), b (grazing), c (stick), d (sliding)");
  add_model_options(*cmd, args->model);
  // required for one point only; checked in run_rate (with --system they come from the file)
  args->one_point_required = {state};
  for (const char* n : {"--a11", "--a12", "--a22", "--mu"}) {
    CLI::Option* o = cmd->get_option(n);
    o->required(false);
    args->one_point_required.push_back(o);
  }
  cmd->add_option("--P_N", args->P_N, "normal force in states c/d (> 0)")->default_str("");
  cmd->add_option("--sgnPT", args->sgn_PT, "sign of P_T in state d (+1 or -1)");
  auto* dF = cmd->add_option("--dF", args->dF,
                             "load rate: DFT DFN (one point); 2N numbers T_1 N_1 T_2 N_2 ... "
                             "with --system (default: the file's dF); --DF is accepted too")
                 ->expected(1, -1);
  args->one_point_required.push_back(dF);
  cmd->add_option("--system", args->system,
                  "N-point system file (JSON, docs/file_formats.md): solve its rate problem");
  cmd->add_option("--method", args->method,
                  "enumerate (cross-checked against analytic), analytic, lemke, "
                  "fb-newton, ipopt");
  cmd->add_option("--facets", args->facets,
                  "3-D system (\"dim\": 3): solve the faceted problem with K facets (3..64) "
                  "instead of the exact elliptic one (docs/contact_3d.md)")
      ->default_str("");
  cmd->add_option_function<double>(
      "--time-limit", [args](const double& v) { args->time_limit = v; },
      "3-D system with --facets: wall-clock budget in seconds of the whole solve (default 60); "
      "when it runs out the answer is not complete (exit 5)");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args, &ctx, cmd]() {
    // Options that would have no effect in the chosen state are errors, never silence.
    const std::string st = args->state;
    if (st != "d" && cmd->count("--sgnPT") > 0)
      throw InputError("--sgnPT has no effect in state " + st + ": only state d (sliding) has a "
                       "sign of P_T");
    // Material parameters a user describes once and sweeps over states: accepted (and
    // validated, echoed), with a note, where they do not enter the equations (issue 27).
    if (st == "a" || st == "b")
      for (const char* o : {"--k_a", "--P_s"})
        if (cmd->count(o) > 0)
          std::cerr << "cpkit rate: note: " << o << " does not enter state " << st
                    << " (P_N = 0 there, so no wear: kappa = k_a P_N / (3 P_s) enters states c "
                       "and d); accepted and echoed\n";
    ctx.exit_code = run_rate(*args);
  });
}

}  // namespace cpkit::cli
