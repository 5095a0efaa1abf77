// `cpkit step`: one implicit time step of the one-point contact problem (the incremental
// problem, docs/model.md Sec. 3, docs/simulation.md).
//
//   cpkit step --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X] [--criterion 38|35]
//              [--wear-law archard|mroz --k_M X] --P_T0 X --P_N0 X --g0 X --dF DFT DFN
//              [--all] [--chain active-set,lemke,fb-newton,ipopt] [--json]
//   cpkit step --system FILE --dF <2N numbers> --all [--json]      (N points, system_step.hpp)
//   cpkit step --system FILE3D --dF X Y N [--all|--chain|--facets K|--multistart N]
//                                        ("dim": 3: run_step_3d below)
//
// --all: every solution (complete active-set enumeration; continua as segments/rays, jumps
// flagged; "complete": false when a candidate could be neither verified nor rejected, or a
// solution does not fit in double). Otherwise one solution by the solver chain. Exit codes:
// 0 at least one solution, 1 none, 2 bad input, 5 none was found and the enumeration is not
// complete.
#include <cmath>
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
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/report/json_3d.hpp"
#include "cpkit/rate_problem/step/multistart_cap.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::cli {
namespace {

struct StepArgs {
  ModelArgs model;
  double k_M = 0;
  std::string wear_law = "archard";
  double P_T0 = 0, P_N0 = 0, g0 = 0;
  std::vector<double> DF;
  bool all = false;
  bool json = false;
  std::string chain = "active-set,lemke,fb-newton,ipopt";
  std::string system;  ///< N-point system file (--system)
  int facets = 0;      ///< --facets K (3-D files only)
  int multistart = 0;  ///< --multistart N (3-D files only)
};

std::string values_text(const rate::StepValues& v) {
  std::ostringstream o;
  o.precision(10);
  o << "DP_T=" << v.DP_T << " DP_N=" << v.DP_N << " Dw_T=" << v.Dw_T << " Dw_N=" << v.Dw_N
    << " Dw_Ti=" << v.Dw_Ti << " Dw_w=" << v.Dw_w << " | P_T1=" << v.P_T1 << " P_N1=" << v.P_N1
    << " g1=" << v.g1;
  return o.str();
}

const char* end_text(bool closed) { return closed ? " (closed)" : " (open)"; }

rate::StepProblem make_problem(const StepArgs& a) {
  rate::StepProblem p;
  p.params = model_parameters(a.model);
  p.wear.law = wear_law_option(a.wear_law);
  p.wear.k_M = a.k_M;
  p.state = {a.P_T0, a.P_N0, a.g0};
  if (a.DF.size() != 2) throw InputError("--dF needs two values: DFT DFN");
  p.load = {a.DF[0], a.DF[1]};
  throw_if_invalid(p.validate(), "step");
  return p;
}

int run_all(const rate::StepProblem& p, bool json) {
  const rate::StepSolutionSet s = rate::enumerate_step(p);
  if (json) {
    print_json(rate::step_set_json(s));
  } else {
    std::cout << "step: " << (s.count() < 0 ? std::string("infinitely many")
                                              : std::to_string(s.count()))
              << " solution(s)";
    if (s.continuous_count >= 0)
      std::cout << ", " << s.continuous_count << " continuous (rate-consistent)";
    if (!s.complete) std::cout << " (NOT proved complete)";
    std::cout << "\n";
    for (const auto& sol : s.solutions) {
      std::cout << "  " << rate::to_string(sol.type) << " (" << rate::to_string(sol.kind)
                << (sol.jump ? ", jump" : "") << "): ";
      if (sol.kind == rate::RateSolution::Kind::kPoint) {
        std::cout << values_text(sol.start) << "\n";
      } else if (sol.kind == rate::RateSolution::Kind::kSegment) {
        std::cout << "from " << values_text(sol.start) << end_text(sol.start_closed)
                  << "\n      to " << values_text(sol.end) << end_text(sol.end_closed) << "\n";
      } else {
        std::cout << "from " << values_text(sol.start) << end_text(sol.start_closed)
                  << "\n      direction "
                  << values_text(sol.direction) << "\n";
      }
    }
    if (s.continuous_count == 0 && !s.solutions.empty())
      std::cout << "note: every solution is a jump: the rate problem has no solution in this "
                   "load direction\n";
    if (!s.complete) std::cout << "note: " << s.message << "\n";
  }
  if (!s.solutions.empty()) return kExitOk;
  return s.complete ? kExitNoSolution : kExitInconclusive;
}

int run_one(const rate::StepProblem& p, const std::string& chain, bool json) {
  rate::StepSolveOptions o;
  o.chain.clear();
  std::stringstream ss(chain);
  std::string name;
  while (std::getline(ss, name, ',')) {
    // A typo must not silently shorten the chain (the library skips names not registered,
    // for builds without Ipopt): every name given here must exist.
    if (!name.empty() && name != "active-set" && cpkit::lcp::solvers().find(name) == nullptr) {
      std::string valid = "active-set";
      for (const auto& n : cpkit::lcp::solvers().names(ProblemKind::kMcp)) valid += ", " + n;
      if (cpkit::lcp::solvers().find("lemke") != nullptr) valid += ", lemke";
      throw InputError("--chain: unknown solver '" + name + "' (valid: " + valid + ")");
    }
    o.chain.push_back(name);
  }
  const rate::StepSolveResult r = rate::solve_step(p, o);
  const bool ok = is_solution(r.result.status);
  // The active-set link picked one point out of an exact enumeration: say out of how many
  // (the same enumeration as --all, so that "--all lists them" holds; issue 27).
  std::optional<rate::StepSolutionSet> all;
  if (ok && r.result.solver == "active-set") all = rate::enumerate_step(p);
  const std::string found_text =
      !all ? std::string()
           : all->count() < 0 ? std::string("infinitely many")
                              : std::to_string(all->count());
  if (json) {
    print_json(rate::step_result_json(r, all ? &*all : nullptr));
  } else {
    std::cout << "status: " << to_string(r.result.status) << " (solver " << r.result.solver
              << ", residual " << r.result.residuals.natural << ")\n";
    if (ok)
      std::cout << "  " << rate::to_string(r.type) << ": " << values_text(r.values) << "\n";
    if (!r.result.message.empty()) std::cout << "note: " << r.result.message << "\n";
    if (all)
      std::cout << "1 of " << found_text << (all->count() == 1 ? " solution" : " solutions")
                << (all->complete ? "" : " found (the enumeration is NOT proved complete)")
                << (all->count() == 1 ? "" : "; --all lists them") << "\n";
  }
  return ok ? kExitOk : kExitNoSolution;
}

/// `--system`: every solution of the N-point step (system_step.hpp).
int run_system(const StepArgs& a, const CLI::App& cmd, const rate::SystemFile& file) {
  // The one-point options describe one point; with a system file they would be ignored.
  for (const char* o : {"--a11", "--a12", "--a22", "--mu", "--C_T", "--k_a", "--P_s",
                        "--criterion", "--wear-law", "--k_M", "--P_T0", "--P_N0", "--g0",
                        "--chain"})
    if (cmd.count(o) > 0)
      throw InputError(std::string(o) + " cannot be combined with --system (the system file "
                       "gives every point's parameters and state)");
  if (!a.all)
    throw InputError("--system needs --all (the N-point step reports every solution)");
  rate::SystemStepProblem p;
  p.system = rate::parse_contact_system(file);
  const int N = p.system.n_points();
  if (static_cast<int>(a.DF.size()) != 2 * N)
    throw InputError("--dF needs " + std::to_string(2 * N) + " numbers (DF_T, DF_N per point, " +
                     std::to_string(N) + " points), got " + std::to_string(a.DF.size()));
  p.DF = Eigen::Map<const Eigen::VectorXd>(a.DF.data(), static_cast<Eigen::Index>(a.DF.size()));
  throw_if_invalid(p.validate(), "step");
  const rate::SystemStepSolutionSet s = rate::enumerate_system_step(p);
  auto types_text = [](const rate::SystemStepSolution& sol) {
    std::string t;
    for (std::size_t i = 0; i < sol.types.size(); ++i)
      t += (i ? "/" : "") + std::string(rate::to_string(sol.types[i]));
    return t;
  };
  if (a.json) {
    nlohmann::json j;
    j["cpkit_version"] = CPKIT_VERSION;
    j["input"] = rate::contact_system_json(p.system);
    j["input"]["system"] = a.system;
    j["input"]["DF"] = a.DF;
    j["n_points"] = N;
    j.update(rate::system_step_set_json(s));
    print_json(j);
  } else {
    std::cout << "step (" << N << " points): " << s.solutions.size() << " solution(s)"
              << (s.complete ? " (complete)" : " (NOT proved complete)") << "\n";
    for (const auto& sol : s.solutions) {
      std::cout << "  " << types_text(sol) << "\n";
      for (std::size_t i = 0; i < sol.values.size(); ++i)
        std::cout << "    point " << i + 1 << ": " << values_text(sol.values[i]) << "\n";
    }
    for (const auto& n : s.notes) std::cout << "note: " << n << "\n";
  }
  if (!s.solutions.empty()) return kExitOk;
  return s.complete ? kExitNoSolution : kExitInconclusive;
}

// ---- "dim": 3 files: one 3-D point, or N coupled 3-D points ----
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
int run_system_step_3d(const StepArgs& a, const CLI::App& cmd,
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
  p.wear.law = wear_law_option(a.wear_law);
  p.wear.k_M = a.k_M;
  bool any_open = false;
  for (int i = 0; i < N; ++i) {
    const rate::SystemPoint3d& pt = sys.points[static_cast<std::size_t>(i)];
    if (p.wear.law == rate::WearLaw::kMrozStupkiewicz && pt.k_a != 0)
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
    j.update(rate::system_step_3d_set_json(set, mode != "chain"));
    if (mode == "chain") {
      j["status"] = (r.status == cpkit::Status::kSolved) ? "solved" : "no_solution";
      j["solver"] = (r.status == cpkit::Status::kSolved) ? "fb-soc" : "";
      j["attempts"] = rate::attempts_json(
          {{"fb-soc", r.status, r.solution.residual, r.seconds, r.message, r.iterations}});
    }
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

int run_step_3d(const StepArgs& a, const CLI::App& cmd, const rate::SystemFile& file) {
  // The one-point 2-D options describe a 2-D point; the file gives the 3-D point.
  for (const char* o : {"--a11", "--a12", "--a22", "--mu", "--C_T", "--k_a", "--P_s",
                        "--criterion", "--P_T0", "--P_N0"})
    if (cmd.count(o) > 0)
      throw InputError(std::string(o) + " cannot be combined with a \"dim\": 3 --system file (the "
                       "file gives the point's parameters and state)");
  if (cmd.count("--multistart") > 0) rate::check_multistart_cap(a.multistart, "--multistart");
  const rate::ContactSystem3d sys = rate::parse_contact_system_3d(file);
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
  p.wear.law = wear_law_option(a.wear_law);
  p.wear.k_M = a.k_M;
  if (p.wear.law == rate::WearLaw::kMrozStupkiewicz && p.params.k_a != 0)
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
    j.update(rate::step_3d_set_json(set, mode != "chain"));
    if (mode == "chain") {
      j["status"] = (chain.status == cpkit::Status::kSolved) ? "solved" : "no_solution";
      j["solver"] = chain.solver;
      j["attempts"] = rate::attempts_json(chain.attempts);
    }
    if (mode == "facets") j["facets"] = a.facets;
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

}  // namespace

void add_step_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<StepArgs>();
  auto* cmd = app.add_subcommand(
      "step", "One implicit time step of the one-point contact problem with friction and wear "
              "(the incremental problem, docs/simulation.md)");
  add_model_options(*cmd, args->model);
  // With --system the file gives the model: the one-point options are checked in the callback.
  for (const char* o : {"--a11", "--a12", "--a22", "--mu"}) cmd->get_option(o)->required(false);
  cmd->add_option("--system", args->system,
                  "N-point system file (JSON, docs/file_formats.md); needs --all and 2N --dF values");
  cmd->add_option("--wear-law", args->wear_law,
                  "archard (37) or mroz (Mroz-Stupkiewicz (41), with --k_M)");
  cmd->add_option("--k_M", args->k_M, "Mroz-Stupkiewicz wear constant (>= 0)")->default_str("");
  cmd->add_option("--P_T0", args->P_T0, "tangential force at the start of the step")
      ->default_str("");
  cmd->add_option("--P_N0", args->P_N0, "normal force at the start (>= 0)")->default_str("");
  cmd->add_option("--g0", args->g0, "gap function w_N - w^w at the start (<= 0; 0 in contact)")
      ->default_str("");
  cmd->add_option("--dF", args->DF,
                  "load increment: DFT DFN (2N values with --system); --DF is accepted too")
      ->expected(1, 1 << 20)
      ->required();
  cmd->add_flag("--all", args->all, "every solution (complete active-set enumeration)");
  cmd->add_option("--chain", args->chain,
                  "solver chain for one solution (comma-separated; a 3-D file has its own "
                  "chains, docs/contact_3d.md)");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->add_option("--facets", args->facets,
                  "3-D file: every solution of the faceted step with K facets (no wear)")
      ->default_str("");
  cmd->add_option("--multistart", args->multistart,
                  "3-D file: distinct verified solutions from N + 1 starts (FB-SOC, Ipopt)")
      ->default_str("");
  cmd->callback([args, &ctx, cmd]() {
    // Options that would have no effect in this context are errors, never silence.
    const bool mroz = args->wear_law == "mroz";
    if (cmd->count("--k_M") > 0 && !mroz)
      throw InputError("--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
    if (mroz && cmd->count("--k_M") == 0)
      throw InputError("--wear-law mroz needs --k_M (the Mroz-Stupkiewicz wear constant)");
    if (mroz && cmd->count("--k_a") > 0)
      throw InputError("--k_a (Archard) has no effect with --wear-law mroz: give --k_M instead");
    // The file is read once (a pipe can be read only once) and dispatched on its dimension.
    std::optional<rate::SystemFile> file;
    if (!args->system.empty()) file = rate::read_system_file(args->system);
    if (file && file->dim == 3) {
      ctx.exit_code = run_step_3d(*args, *cmd, *file);
      return;
    }
    for (const char* o : {"--facets", "--multistart"})
      if (cmd->count(o) > 0)
        throw InputError(std::string(o) + " applies to a \"dim\": 3 --system file (one 3-D point)");
    if (args->all && cmd->count("--chain") > 0)
      throw InputError("--chain has no effect with --all (every solution comes from the complete "
                       "active-set enumeration)");
    if (file) {
      ctx.exit_code = run_system(*args, *cmd, *file);
      return;
    }
    for (const char* o : {"--a11", "--a12", "--a22", "--mu", "--P_T0", "--P_N0", "--g0"})
      if (cmd->count(o) == 0)
        throw InputError(std::string(o) + " is required (or --system FILE for N points)");
    const rate::StepProblem p = make_problem(*args);
    ctx.exit_code = args->all ? run_all(p, args->json) : run_one(p, args->chain, args->json);
  });
}

}  // namespace cpkit::cli
