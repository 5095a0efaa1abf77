// `cpkit step --system FILE --dF X Y N` with a "dim": 3 file: one implicit step of a 3-D contact
// point with the elliptic friction-and-wear law (docs/contact_3d.md, "Solvers of the 3-D step");
// with N > 1 points the coupled step by FB-SOC Newton (--chain fb-soc, default) or --multistart
// (system_step_3d.hpp; --all and --facets are refused: no complete enumeration).
//
//   cpkit step --system FILE --dF DFX DFY DFN [--g0 G (state a)] [--wear-law archard|mroz --k_M X]
//              [--all | --chain exact,fb-soc,ipopt | --facets K | --multistart N] [--json]
//
// The start state is the file's point: state a (open: P = 0, --g0 < 0 required), b (grazing:
// P = 0, g0 = 0), c and d (in contact with the file's P_T, P_N, g0 = 0). Modes: --all every
// solution (enumerate_step_3d), --facets K every solution of the faceted problem (no wear),
// --multistart N distinct verified solutions from N + 1 starts (never proved complete), default
// one solution by the chain. Exit codes: 0 solution(s) listed, 1 none, 2 bad input,
// 5 not proved complete (--all, --facets) or none found by --multistart.
#include "step_3d.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/step/multistart_cap.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"

namespace cpkit::cli {
namespace {

using Pair = std::vector<double>;

std::string solution_text(const rate::Step3dSolution& s) {
  const rate::Step3dValues& v = s.values;
  std::ostringstream o;
  o.precision(10);
  o << rate::to_string(s.type) << ": P_T1=[" << v.P_T1(0) << ", " << v.P_T1(1)
    << "] P_N1=" << v.P_N1 << " DP=[" << v.DP_T(0) << ", " << v.DP_T(1) << ", " << v.DP_N
    << "] Dw=[" << v.Dw_T(0) << ", " << v.Dw_T(1) << ", " << v.Dw_N << "] Dw_Ti=["
    << v.Dw_Ti(0) << ", " << v.Dw_Ti(1) << "] Dw_w=" << v.Dw_w << " lambda=" << v.lambda;
  o.precision(6);
  if (s.type == rate::SolutionType::kSlip) o << " slip_angle=" << s.slip_angle;
  o << " residual=" << s.residual;
  return o.str();
}

/// N > 1 coupled points: FB-SOC Newton on the 4N unknowns (--chain fb-soc, the default) or
/// --multistart N; no complete enumeration exists for coupled 3-D points (--all, --facets are
/// refused). --g0 G gives the gap of every state-a point.
int run_system_step_3d(const Step3dCliArgs& a, const CLI::App& cmd,
                       const rate::ContactSystem3d& sys) {
  const int N = sys.n_points();
  if (a.all || cmd.count("--facets") > 0)
    throw InputError(std::string(a.all ? "--all" : "--facets") + " is not available for " +
                     std::to_string(N) + " coupled 3-D points: there is no complete enumeration "
                     "of the coupled 3-D step (only one point, N = 1, is enumerated exactly); use "
                     "--chain fb-soc (default) or --multistart N");
  const bool chain_given = cmd.count("--chain") > 0;
  if (chain_given && cmd.count("--multistart") > 0)
    throw InputError("--chain and --multistart are alternative modes: give at most one");
  if (chain_given && a.chain != "fb-soc")
    throw InputError("--chain '" + a.chain + "': for " + std::to_string(N) + " coupled 3-D points "
                     "the only link is fb-soc (exact and ipopt are one-point solvers)");
  if (a.DF.size() != static_cast<std::size_t>(3 * N))
    throw InputError("--dF needs 3N = " + std::to_string(3 * N) + " numbers for " +
                     std::to_string(N) + " 3-D points (DF_TX DF_TY DF_N per point), got " +
                     std::to_string(a.DF.size()));
  rate::SystemStep3dProblem p;
  p.system = sys;
  const auto law = rate::wear_law_from_string(a.wear_law);
  if (!law) throw InputError("--wear-law must be archard or mroz, got '" + a.wear_law + "'");
  p.wear.law = *law;
  p.wear.k_M = a.k_M;
  bool any_open = false;
  for (int i = 0; i < N; ++i) {
    const rate::SystemPoint3d& pt = sys.points[static_cast<std::size_t>(i)];
    if (*law == rate::WearLaw::kMrozStupkiewicz && pt.k_a != 0)
      throw InputError(a.system + ": point " + std::to_string(i + 1) + ": its k_a (Archard) has "
                       "no effect with --wear-law mroz: remove it from the file or use "
                       "--wear-law archard");
    rate::Step3dState st;
    if (pt.state.state == 'a') {
      any_open = true;
      if (cmd.count("--g0") == 0 || !(a.g0 < 0))
        throw InputError("point " + std::to_string(i + 1) + " is in state a (open): give the gap "
                         "of the open points with --g0 G, G < 0");
      st.g0 = a.g0;
    } else {
      st.P_T0 = pt.state.P_T;
      st.P_N0 = pt.state.P_N;
    }
    p.states.push_back(st);
  }
  if (!any_open && cmd.count("--g0") > 0)
    throw InputError("--g0 applies to state-a (open) points; no point of this file is in state a");
  p.DF = Eigen::Map<const Eigen::VectorXd>(a.DF.data(), 3 * N);
  if (cmd.count("--multistart") > 0 && a.multistart < 1)
    throw InputError("--multistart needs N >= 1 starts, got " + std::to_string(a.multistart));
  throw_if_invalid(p.validate(), "step");

  const std::string mode = cmd.count("--multistart") > 0 ? "multistart" : "chain";
  rate::SystemStep3dSolutionSet set;
  rate::SystemStep3dSolveResult r;
  int code = kExitOk;
  if (mode == "multistart") {
    set = rate::multistart_system_step_3d(p, a.multistart, 1);
    code = set.solutions.empty() ? kExitInconclusive : kExitOk;
  } else {
    r = rate::solve_system_step_3d_fb_soc(p);
    if ((r.status == cpkit::Status::kSolved)) set.solutions.push_back(r.solution);
    set.message = r.message;
    code = (r.status == cpkit::Status::kSolved) ? kExitOk : kExitNoSolution;
  }
  const std::string name = sys.name.empty() ? a.system : sys.name;
  if (a.json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    nlohmann::json states = nlohmann::json::array(), pt0 = nlohmann::json::array(),
                   pn0 = nlohmann::json::array(), g0 = nlohmann::json::array();
    for (int i = 0; i < N; ++i) {
      const rate::Step3dState& st = p.states[static_cast<std::size_t>(i)];
      states.push_back(std::string(1, sys.points[static_cast<std::size_t>(i)].state.state));
      pt0.push_back(Pair{st.P_T0(0), st.P_T0(1)});
      pn0.push_back(st.P_N0);
      g0.push_back(st.g0);
    }
    nlohmann::json in = {{"system", a.system}, {"name", sys.name}, {"n_points", N},
                         {"state", states},    {"P_T0", pt0},      {"P_N0", pn0},
                         {"g0", g0},           {"DF", a.DF},
                         {"wear_law", std::string(rate::to_string(p.wear.law))},
                         {"mode", mode}};
    if (p.wear.law == rate::WearLaw::kMrozStupkiewicz) in["k_M"] = p.wear.k_M;
    if (mode == "multistart") in["multistart"] = a.multistart;
    if (mode == "chain") in["chain"] = std::vector<std::string>{"fb-soc"};
    j["input"] = in;
    j["dim"] = 3;
    j["n_points"] = N;
    j["mode"] = mode;
    if (mode == "chain") {
      j["status"] = (r.status == cpkit::Status::kSolved) ? "solved" : "no_solution";
      j["solver"] = (r.status == cpkit::Status::kSolved) ? "fb-soc" : "";
      const double res = r.solution.residual;
      j["attempts"] = nlohmann::json::array(
          {{{"solver", "fb-soc"}, {"solved", (r.status == cpkit::Status::kSolved)},
            {"residual", std::isfinite(res) ? nlohmann::json(res) : nlohmann::json(nullptr)},
            {"iterations", r.iterations}, {"seconds", r.seconds}, {"message", r.message}}});
    } else {
      j["complete"] = false;
      j["found"] = set.count();
    }
    if (!set.message.empty()) j["message"] = set.message;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& s : set.solutions) {
      nlohmann::json pts = nlohmann::json::array();
      for (const auto& x : s.points) pts.push_back(rate::step_3d_solution_json(x));
      sols.push_back({{"points", pts}, {"residual", s.residual}});
    }
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "step, " << N << " coupled 3-D points " << name << " (states ";
    for (const auto& pt : sys.points) std::cout << pt.state.state;
    std::cout << "), ";
    if (mode == "chain")
      std::cout << "FB-SOC Newton: "
                << ((r.status == cpkit::Status::kSolved) ? "solved in " + std::to_string(r.iterations) + " iterations"
                             : std::string("no solution found"))
                << "\n";
    else
      std::cout << "multistart\nsolutions found: " << set.count()
                << " (NOT proved complete: not a count)\n";
    int k = 0;
    for (const auto& s : set.solutions) {
      std::ostringstream o;
      o.precision(6);
      o << s.residual;
      std::cout << "  solution " << ++k << " (residual " << o.str() << "):\n";
      int i = 0;
      for (const auto& x : s.points) std::cout << "    point " << ++i << " " << solution_text(x) << "\n";
    }
    if (!set.message.empty()) std::cout << "note: " << set.message << "\n";
  }
  return code;
}

}  // namespace

int run_step_3d(const Step3dCliArgs& a, const CLI::App& cmd) {
  // The one-point 2-D options describe a 2-D point; the file gives the 3-D point.
  for (const char* o : {"--a11", "--a12", "--a22", "--mu", "--C_T", "--k_a", "--P_s",
                        "--criterion", "--P_T0", "--P_N0"})
    if (cmd.count(o) > 0)
      throw InputError(std::string(o) + " cannot be combined with a \"dim\": 3 --system file (the "
                       "file gives the point's parameters and state)");
  if (cmd.count("--multistart") > 0) rate::check_multistart_cap(a.multistart, "--multistart");
  const rate::ContactSystem3d sys = rate::parse_contact_system_3d(a.file);
  if (sys.n_points() != 1) return run_system_step_3d(a, cmd, sys);
  const bool chain_given = cmd.count("--chain") > 0;
  const int modes = (a.all ? 1 : 0) + (chain_given ? 1 : 0) + (cmd.count("--facets") > 0 ? 1 : 0) +
                    (cmd.count("--multistart") > 0 ? 1 : 0);
  if (modes > 1)
    throw InputError("--all, --chain, --facets and --multistart are alternative modes: give at "
                     "most one");
  if (a.DF.size() != 3)
    throw InputError("--dF needs 3 numbers for a 3-D point (DF_TX DF_TY DF_N), got " +
                     std::to_string(a.DF.size()));
  rate::Step3dProblem p;
  p.params = sys.point_parameters(0);
  const auto law = rate::wear_law_from_string(a.wear_law);
  if (!law) throw InputError("--wear-law must be archard or mroz, got '" + a.wear_law + "'");
  p.wear.law = *law;
  p.wear.k_M = a.k_M;
  if (*law == rate::WearLaw::kMrozStupkiewicz && p.params.k_a != 0)
    throw InputError(a.system + ": the point's k_a (Archard) has no effect with --wear-law mroz: "
                     "remove it from the file or use --wear-law archard");
  const rate::ContactState3d& st = sys.points[0].state;
  if (st.state == 'a') {
    if (cmd.count("--g0") == 0 || !(a.g0 < 0))
      throw InputError("the point is in state a (open): give its gap with --g0 G, G < 0");
    p.state.g0 = a.g0;
  } else {
    if (cmd.count("--g0") > 0)
      throw InputError(std::string("--g0 applies to a state-a (open) point; the point is in "
                       "state ") + st.state + " (in contact, g0 = 0)");
    p.state.P_T0 = st.P_T;
    p.state.P_N0 = st.P_N;
  }
  p.DF = Eigen::Vector3d(a.DF[0], a.DF[1], a.DF[2]);
  if (cmd.count("--facets") > 0 && p.wear_coefficient() != 0)
    throw InputError("--facets is the faceted LCP without wear; with wear (k_a or k_M > 0) the "
                     "faceted step is nonlinear: use --all (exact) or --multistart");
  if (cmd.count("--multistart") > 0 && a.multistart < 1)
    throw InputError("--multistart needs N >= 1 starts, got " + std::to_string(a.multistart));
  throw_if_invalid(p.validate(), "step");

  std::string mode = "chain";
  if (a.all) mode = "all";
  if (cmd.count("--facets") > 0) mode = "facets";
  if (cmd.count("--multistart") > 0) mode = "multistart";

  rate::Step3dSolutionSet set;
  rate::Step3dChainResult chain;
  rate::Step3dChainOptions copt;
  if (mode == "chain" && chain_given) {
    copt.chain.clear();
    std::stringstream ss(a.chain);
    std::string name;
    while (std::getline(ss, name, ',')) copt.chain.push_back(name);
    throw_if_invalid(copt.validate(), "--chain");
  }
  int code = kExitOk;
  if (mode == "all") {
    set = rate::enumerate_step_3d(p);
    code = !set.complete ? kExitInconclusive : set.solutions.empty() ? kExitNoSolution : kExitOk;
  } else if (mode == "facets") {
    set = rate::solve_step_3d_faceted(p, a.facets).set;
    code = !set.complete ? kExitInconclusive : set.solutions.empty() ? kExitNoSolution : kExitOk;
  } else if (mode == "multistart") {
    set = rate::multistart_step_3d(p, a.multistart, 1);
    code = set.solutions.empty() ? kExitInconclusive : kExitOk;
  } else {
    chain = rate::solve_step_3d(p, copt);
    set.complete = false;
    if ((chain.status == cpkit::Status::kSolved)) set.solutions.push_back(chain.solution);
    set.message = chain.message;
    code = (chain.status == cpkit::Status::kSolved) ? kExitOk : kExitNoSolution;
  }
  const std::string name = sys.name.empty() ? a.system : sys.name;
  if (a.json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    nlohmann::json in = {{"system", a.system},
                         {"name", sys.name},
                         {"state", std::string(1, st.state)},
                         {"P_T0", Pair{p.state.P_T0(0), p.state.P_T0(1)}},
                         {"P_N0", p.state.P_N0},
                         {"g0", p.state.g0},
                         {"DF", a.DF},
                         {"wear_law", std::string(rate::to_string(p.wear.law))},
                         {"mode", mode}};
    if (p.wear.law == rate::WearLaw::kMrozStupkiewicz) in["k_M"] = p.wear.k_M;
    if (mode == "facets") in["facets"] = a.facets;
    if (mode == "multistart") in["multistart"] = a.multistart;
    if (mode == "chain") in["chain"] = copt.chain;
    j["input"] = in;
    j["dim"] = 3;
    j["mode"] = mode;
    if (mode == "chain") {
      j["status"] = (chain.status == cpkit::Status::kSolved) ? "solved" : "no_solution";
      j["solver"] = chain.solver;
      nlohmann::json at = nlohmann::json::array();
      for (const auto& x : chain.attempts)
        at.push_back({{"solver", x.solver}, {"solved", (x.status == cpkit::Status::kSolved)},
                      {"residual", std::isfinite(x.residual) ? nlohmann::json(x.residual) : nlohmann::json(nullptr)},
                      {"iterations", x.iterations}, {"seconds", x.seconds}, {"message", x.message}});
      j["attempts"] = at;
    } else {
      j["complete"] = set.complete;
      if (set.complete) j["count"] = set.count(); else j["found"] = set.count();
    }
    if (mode == "facets") j["facets"] = a.facets;
    if (!set.message.empty()) j["message"] = set.message;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& s : set.solutions) sols.push_back(rate::step_3d_solution_json(s));
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "step, 3-D point " << name << " (state " << st.state << "), ";
    if (mode == "chain") {
      std::cout << "solver chain: " << ((chain.status == cpkit::Status::kSolved) ? "solved by " + chain.solver : std::string("no solution found")) << "\n";
    } else {
      std::cout << (mode == "all" ? "exact" : mode == "facets" ? "faceted with " + std::to_string(a.facets) + " facets" : "multistart") << "\n";
      if (set.complete) std::cout << "count: " << set.count() << "\n";
      else std::cout << "solutions found: " << set.count() << " (NOT proved complete: not a count)\n";
    }
    for (const auto& s : set.solutions) std::cout << "  " << solution_text(s) << "\n";
    if (!set.message.empty()) std::cout << "note: " << set.message << "\n";
  }
  if (code == kExitInconclusive && mode != "multistart")
    std::cerr << "cpkit step: not proved complete: " << set.message << '\n';
  return code;
}

}  // namespace cpkit::cli
