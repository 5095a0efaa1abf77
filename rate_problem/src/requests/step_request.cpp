#include "cpkit/rate_problem/requests/step_request.hpp"

#include <sstream>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/step/multistart_cap.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "../model/options_given.hpp"

namespace cpkit::rate {

namespace {

using detail::option;
using detail::Given;

std::vector<std::string> split_chain(const std::string& chain) {
  std::vector<std::string> names;
  std::stringstream ss(chain);
  std::string name;
  while (std::getline(ss, name, ',')) names.push_back(name);
  return names;
}

ExitCode set_exit_code(bool found, bool complete) {
  if (found) return kExitOk;
  return complete ? kExitNoSolution : kExitInconclusive;
}

/// --wear-law (default archard) and --k_M.
WearModel wear_model(const StepRequest& r) {
  WearModel w;
  w.law = wear_law_option(r.wear_law.value_or("archard"));
  w.k_M = r.k_M.value_or(0);
  return w;
}

StepProblem point_problem(const StepRequest& r) {
  StepProblem p;
  p.params = model_parameters(r.model);
  p.wear = wear_model(r);
  p.state = {*r.P_T0, *r.P_N0, *r.g0};
  if (r.DF.size() != 2) throw InputError("--dF needs two values: DFT DFN");
  p.load = {r.DF[0], r.DF[1]};
  throw_if_invalid(p.validate(), "step");
  return p;
}

void run_point_chain(const StepRequest& r, const StepProblem& p, StepOutcome& out) {
  StepSolveOptions o;
  o.chain.clear();
  for (const std::string& name : split_chain(r.chain.value_or(kDefaultStepChain))) {
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
  out.one = solve_step(p, o);
  const bool ok = is_solution(out.one.status);
  // The active-set link picked one point out of an exact enumeration: say out of how many
  // (the same enumeration as --all, so that "--all lists them" holds; issue 27).
  if (ok && out.one.solver == "active-set") {
    out.set = enumerate_step(p);
    out.has_enumeration = true;
  }
  out.exit_code = ok ? kExitOk : kExitNoSolution;
}

/// `--system` of dim 2: every solution of the N-point step (system_step.hpp).
void run_system(const StepRequest& r, const SystemFile& file, StepOutcome& out) {
  // The one-point options describe one point; with a system file they would be ignored.
  std::vector<Given> options = detail::model_options_given(r.model);
  options.insert(options.end(), {option("--wear-law", r.wear_law), option("--k_M", r.k_M),
                                 option("--P_T0", r.P_T0), option("--P_N0", r.P_N0),
                                 option("--g0", r.g0), option("--chain", r.chain)});
  detail::refuse_given(options, " cannot be combined with --system (the system file gives "
                                "every point's parameters and state)");
  if (!r.all) throw InputError("--system needs --all (the N-point step reports every solution)");
  SystemStepProblem& p = out.system_problem;
  p.system = parse_contact_system(file);
  const int N = p.system.n_points();
  if (static_cast<int>(r.DF.size()) != 2 * N)
    throw InputError("--dF needs " + std::to_string(2 * N) + " numbers (DF_T, DF_N per point, " +
                     std::to_string(N) + " points), got " + std::to_string(r.DF.size()));
  p.DF = Eigen::Map<const Eigen::VectorXd>(r.DF.data(), static_cast<Eigen::Index>(r.DF.size()));
  throw_if_invalid(p.validate(), "step");
  out.route = StepRoute::kSystem;
  out.system_set = enumerate_system_step(p);
  out.exit_code = set_exit_code(!out.system_set.solutions.empty(), out.system_set.complete);
}

/// The start states of a 3-D system's points: the file's P_T, P_N for points in contact (b, c,
/// d), --g0 for the open ones (a). Refuses a point's k_a with --wear-law mroz and a --g0 that
/// applies to no point; the messages speak of "the point" for one point.
std::vector<Step3dState> states_3d(const StepRequest& r, const ContactSystem3d& sys,
                                   const WearModel& wear) {
  const int N = sys.n_points();
  std::vector<Step3dState> states;
  bool any_open = false;
  for (int i = 0; i < N; ++i) {
    const SystemPoint3d& pt = sys.points[static_cast<std::size_t>(i)];
    const std::string point = N == 1 ? "the point" : "point " + std::to_string(i + 1);
    if (wear.law == WearLaw::kMrozStupkiewicz && pt.k_a != 0)
      throw InputError(r.system + ": " + (N == 1 ? "the point's" : point + ": its") +
                       " k_a (Archard) has no effect with --wear-law mroz: remove it from the "
                       "file or use --wear-law archard");
    Step3dState st;
    if (pt.state.state == 'a') {
      any_open = true;
      if (!r.g0 || !(*r.g0 < 0))
        throw InputError(point + " is in state a (open): give " +
                         (N == 1 ? "its gap" : std::string("the gap of the open points")) +
                         " with --g0 G, G < 0");
      st.g0 = *r.g0;
    } else {
      if (N == 1 && r.g0)
        throw InputError(std::string("--g0 applies to a state-a (open) point; the point is in "
                                     "state ") + pt.state.state + " (in contact, g0 = 0)");
      st.P_T0 = pt.state.P_T;
      st.P_N0 = pt.state.P_N;
    }
    states.push_back(st);
  }
  if (!any_open && r.g0)
    throw InputError("--g0 applies to state-a (open) points; no point of this file is in state a");
  return states;
}

void check_multistart(const StepRequest& r) {
  if (r.multistart && *r.multistart < 1)
    throw InputError("--multistart needs N >= 1 starts, got " + std::to_string(*r.multistart));
}

ExitCode set_3d_exit_code(const std::string& mode, bool found, bool complete) {
  if (mode == "multistart") return found ? kExitOk : kExitInconclusive;
  return !complete ? kExitInconclusive : found ? kExitOk : kExitNoSolution;
}

/// N > 1 coupled points: FB-SOC Newton on the 4N unknowns (--chain fb-soc, the default) or
/// --multistart N; no complete enumeration exists for coupled 3-D points (--all, --facets are
/// refused). --g0 G gives the gap of every state-a point.
void run_system_3d(const StepRequest& r, StepOutcome& out) {
  Step3dOutcome& o = out.step_3d;
  const int N = o.system.n_points();
  if (r.all || r.facets)
    throw InputError(std::string(r.all ? "--all" : "--facets") + " is not available for " +
                     std::to_string(N) + " coupled 3-D points: there is no complete enumeration "
                     "of the coupled 3-D step (only one point, N = 1, is enumerated exactly); use "
                     "--chain fb-soc (default) or --multistart N");
  if (r.chain && r.multistart)
    throw InputError("--chain and --multistart are alternative modes: give at most one");
  if (r.chain && *r.chain != "fb-soc")
    throw InputError("--chain '" + *r.chain + "': for " + std::to_string(N) + " coupled 3-D points "
                     "the only link is fb-soc (exact and ipopt are one-point solvers)");
  if (r.DF.size() != static_cast<std::size_t>(3 * N))
    throw InputError("--dF needs 3N = " + std::to_string(3 * N) + " numbers for " +
                     std::to_string(N) + " 3-D points (DF_TX DF_TY DF_N per point), got " +
                     std::to_string(r.DF.size()));
  SystemStep3dProblem p;
  p.system = o.system;
  p.wear = wear_model(r);
  p.states = states_3d(r, o.system, p.wear);
  p.DF = Eigen::Map<const Eigen::VectorXd>(r.DF.data(), 3 * N);
  check_multistart(r);
  throw_if_invalid(p.validate(), "step");

  o.states = p.states;
  o.wear = p.wear;
  o.mode = r.multistart ? "multistart" : "chain";
  if (o.mode == "multistart") {
    o.system_set = multistart_system_step_3d(p, *r.multistart, 1);
  } else {
    const SystemStep3dSolveResult s = solve_system_step_3d_fb_soc(p);
    const bool found = s.status == Status::kSolved;
    if (found) o.system_set.solutions.push_back(s.solution);
    o.system_set.complete = false;  // one Newton solve: never a list of every solution
    o.system_set.message = s.message;
    o.chain = {"fb-soc"};
    o.status = s.status;
    o.solver = found ? "fb-soc" : "";
    o.attempts = {{"fb-soc", s.status, s.solution.residual, s.seconds, s.message, s.iterations}};
    o.iterations = s.iterations;
  }
  out.exit_code = o.mode == "chain" ? (o.status == Status::kSolved ? kExitOk : kExitNoSolution)
                                    : set_3d_exit_code(o.mode, o.system_set.count() > 0, false);
}

/// A "dim": 3 file: one 3-D point (modes --all, --facets K, --multistart N, or the chain), or
/// N coupled points (run_system_3d).
void run_step_3d(const StepRequest& r, const SystemFile& file, StepOutcome& out) {
  // The one-point 2-D options describe a 2-D point; the file gives the 3-D point.
  std::vector<Given> options = detail::model_options_given(r.model);
  options.insert(options.end(), {option("--P_T0", r.P_T0), option("--P_N0", r.P_N0)});
  detail::refuse_given(options, " cannot be combined with a \"dim\": 3 --system file (the file "
                                "gives the point's parameters and state)");
  if (r.multistart) check_multistart_cap(*r.multistart, "--multistart");
  Step3dOutcome& o = out.step_3d;
  o.system = parse_contact_system_3d(file);
  if (o.system.n_points() != 1) {
    out.route = StepRoute::kSystem3d;
    run_system_3d(r, out);
    return;
  }
  const int modes = (r.all ? 1 : 0) + (r.chain ? 1 : 0) + (r.facets ? 1 : 0) +
                    (r.multistart ? 1 : 0);
  if (modes > 1)
    throw InputError("--all, --chain, --facets and --multistart are alternative modes: give at "
                     "most one");
  if (r.DF.size() != 3)
    throw InputError("--dF needs 3 numbers for a 3-D point (DF_TX DF_TY DF_N), got " +
                     std::to_string(r.DF.size()));
  Step3dProblem p;
  p.params = o.system.point_parameters(0);
  p.wear = wear_model(r);
  o.states = states_3d(r, o.system, p.wear);
  p.state = o.states[0];
  p.DF = Eigen::Vector3d(r.DF[0], r.DF[1], r.DF[2]);
  if (r.facets && p.wear_coefficient() != 0)
    throw InputError("--facets is the faceted LCP without wear; with wear (k_a or k_M > 0) the "
                     "faceted step is nonlinear: use --all (exact) or --multistart");
  check_multistart(r);
  throw_if_invalid(p.validate(), "step");

  out.route = StepRoute::kPoint3d;
  o.wear = p.wear;
  o.mode = r.all ? "all" : r.facets ? "facets" : r.multistart ? "multistart" : "chain";
  if (o.mode == "all") {
    o.set = enumerate_step_3d(p);
  } else if (o.mode == "facets") {
    o.set = solve_step_3d_faceted(p, *r.facets).set;
  } else if (o.mode == "multistart") {
    o.set = multistart_step_3d(p, *r.multistart, 1);
  } else {
    Step3dChainOptions copt;
    if (r.chain) {
      copt.chain = split_chain(*r.chain);
      throw_if_invalid(copt.validate(), "--chain");
    }
    const Step3dChainResult c = solve_step_3d(p, copt);
    o.set.complete = false;
    if (c.status == Status::kSolved) o.set.solutions.push_back(c.solution);
    o.set.message = c.message;
    o.chain = copt.chain;
    o.status = c.status;
    o.solver = c.solver;
    o.attempts = c.attempts;
  }
  out.exit_code = o.mode == "chain" ? (o.status == Status::kSolved ? kExitOk : kExitNoSolution)
                                    : set_3d_exit_code(o.mode, o.set.count() > 0, o.set.complete);
  if (out.exit_code == kExitInconclusive && o.mode != "multistart")
    out.errors.push_back("not proved complete: " + o.set.message);
}

}  // namespace

StepOutcome run_step_request(const StepRequest& r) {
  // Options that would have no effect in this context are errors, never silence.
  const bool mroz = r.wear_law == "mroz";
  if (r.k_M && !mroz)
    throw InputError("--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
  if (mroz && !r.k_M)
    throw InputError("--wear-law mroz needs --k_M (the Mroz-Stupkiewicz wear constant)");
  if (mroz && r.model.k_a)
    throw InputError("--k_a (Archard) has no effect with --wear-law mroz: give --k_M instead");
  // The file is read once (a pipe can be read only once) and dispatched on its dimension.
  std::optional<SystemFile> read;
  if (!r.file && !r.system.empty()) read = read_system_file(r.system);
  const SystemFile* file = r.file ? &*r.file : read ? &*read : nullptr;
  StepOutcome out;
  out.system = r.system;
  out.DF = r.DF;
  out.facets = r.facets.value_or(0);
  out.multistart = r.multistart.value_or(0);
  if (file && file->dim == 3) {
    run_step_3d(r, *file, out);
    return out;
  }
  detail::refuse_given({option("--facets", r.facets), option("--multistart", r.multistart)},
                       " applies to a \"dim\": 3 --system file (one 3-D point)");
  if (r.all && r.chain)
    throw InputError("--chain has no effect with --all (every solution comes from the complete "
                     "active-set enumeration)");
  if (file) {
    run_system(r, *file, out);
    return out;
  }
  detail::require_given({option("--a11", r.model.a11), option("--a12", r.model.a12),
                         option("--a22", r.model.a22), option("--mu", r.model.mu),
                         option("--P_T0", r.P_T0), option("--P_N0", r.P_N0), option("--g0", r.g0)},
                        " is required (or --system FILE for N points)");
  const StepProblem p = point_problem(r);
  if (r.all) {
    out.route = StepRoute::kPointAll;
    out.set = enumerate_step(p);
    out.exit_code = set_exit_code(!out.set.solutions.empty(), out.set.complete);
  } else {
    out.route = StepRoute::kPointChain;
    run_point_chain(r, p, out);
  }
  return out;
}

}  // namespace cpkit::rate
