// `cpkit fc solve|solutions`: the option checks, the solves, the exit codes, the text and JSON
// (field names and text are what users script against, kept character for character).
#include "cpkit/lcp/friction/fc_request.hpp"

#include <chrono>
#include <limits>
#include <sstream>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/option_words.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/report.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp::friction {
namespace {

CommonOptions common_options(const FcRequest& a) {
  CommonOptions o;
  if (!(a.tol > 0 && a.tol <= 1e-3))
    throw InputError("--tol must be in (0, 1e-3] (the unit-free residual: a larger tolerance "
                     "would call almost any r solved), got " + num_text(a.tol));
  o.tol = a.tol;
  if (o.tol_acceptable < o.tol) o.tol_acceptable = o.tol;
  o.max_iterations = a.max_iter;
  o.time_limit_s = a.time_limit_s;
  throw_if_invalid_option(o.validate(), {{"tol", "--tol"},
                                         {"max_iterations", "--max-iter"},
                                         {"time_limit_s", "--time-limit"}});
  return o;
}

/// True when r is an answer to judge against p: sized as p's r, and p not empty (a global
/// problem whose M could not be condensed leaves both empty: nothing to judge, not "0 x 0").
bool has_answer(const SolveResult& r, const FrictionContactProblem& p) {
  return r.z.size() > 0 && r.z.size() == p.W.rows();
}

/// One result as the fc commands print it: r and u flat (contact by contact, normal first),
/// the three errors of friction_verdict.hpp recomputed from the data, and the solver's counts.
nlohmann::json fc_result_json(const SolveResult& r, const FrictionContactProblem& p) {
  const nlohmann::json full = to_json(r);
  nlohmann::json j;
  j["status"] = full["status"];
  j["solver"] = r.solver;
  j["r"] = full["z"];
  j["u"] = full["w"];
  const bool sized = has_answer(r, p);
  const FrictionErrors e = sized ? friction_errors(p, r.z)
                                 : FrictionErrors{std::numeric_limits<double>::infinity(),
                                                  std::numeric_limits<double>::quiet_NaN(),
                                                  std::numeric_limits<double>::quiet_NaN()};
  j["errors"] = {{"unit_free", e.unit_free}, {"relative_q", e.relative_q},
                 {"relative_max", e.relative_max}};
  auto& per = j["per_contact"] = nlohmann::json::array();
  if (sized)
    for (const auto& c : friction_contacts(p, r.z))
      per.push_back({{"state", to_string(c.state)}, {"error", c.error}});
  j["iterations"] = r.iterations;
  j["seconds"] = r.seconds;
  j["message"] = r.message;
  if (full.contains("attempts")) j["attempts"] = full["attempts"];
  return j;
}

nlohmann::json problem_json(const std::string& file, const FrictionContactProblem& p) {
  return {{"file", file}, {"problem", p.name}, {"contacts", p.contacts()},
          {"W_nonzeros", p.W.nonZeros()}};
}

std::string result_line(const SolveResult& r, const FrictionContactProblem& p) {
  std::ostringstream s;
  s << "status:     " << to_string(r.status) << "\nsolver:     " << r.solver;
  if (has_answer(r, p)) {
    const FrictionErrors e = friction_errors(p, r.z);
    s << "\nerrors:     unit-free " << e.unit_free << ", relative to |q| " << e.relative_q
      << ", relative to max(|q|, |r|, |u|) " << e.relative_max;
    int count[3] = {0, 0, 0};
    for (const auto& c : friction_contacts(p, r.z))
      ++count[static_cast<int>(c.state)];
    s << "\ncontacts:   " << count[1] << " stick, " << count[2] << " slip, " << count[0]
      << " separated";
  }
  s << "\niterations: " << r.iterations << "\nseconds:    " << r.seconds;
  if (!r.message.empty()) s << "\nmessage:    " << r.message;
  s << '\n';
  return s.str();
}

/// The measure that decided "solved", when it is not the default unit-free number.
std::string measure_line(FrictionMeasure m) {
  if (m == FrictionMeasure::kUnitFree) return {};
  return std::string("measure:    ") + to_string(m) + " (decides solved; unit-free must accept)\n";
}

const SolverEntry& fc_solver(const std::string& name) {
  const SolverEntry* entry = solvers().find(name);
  if (entry == nullptr || !entry->accepts(ProblemKind::kFrictionContact))
    throw InputError("unknown friction solver '" + name + "' (valid: " + fc_solver_list() + ")");
  return *entry;
}

/// "1 contact", "2 contacts" (the problem lines of the text output).
std::string count_text(Eigen::Index n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

ExitCode exit_code(Status s) {
  if (is_solution(s)) return kExitOk;
  return s == Status::kInfeasible ? kExitNoSolution : kExitInconclusive;
}

/// A global problem (M v = H r + f, u = H^T v + w): condensed, solved locally, judged in the
/// global variables (global.hpp); where M is singular (degrees of freedom without mass) it is
/// solved in its own variables by the proximal point in v (solve_global_proximal).
void solve_global_once(const FcRequest& a, const CommonOptions& options, FcSolveOutcome& out) {
  const SolverEntry& entry = fc_solver(a.solver);
  const GlobalFrictionContactProblem& g = out.global_problem;
  out.global = solve_global(g, entry.info.name, options);
  const CondensedProblem& c = out.global.condensed;
  out.proximal = !c.ok && c.mass == MassMatrix::kSingular;
  if (out.proximal) out.global = solve_global_proximal(g, entry.info.name, options);
  out.problem = out.global.condensed.local;
  out.result = out.global.result;
}

/// solve_global_once, judged in out.measure on the condensed problem: solved again at a lower
/// unit-free tolerance while above tol in it (measure_solve.hpp; the best answer is kept).
void solve_global_request(const FcRequest& a, FcSolveOutcome& out) {
  const CommonOptions options = common_options(a);
  const auto start = std::chrono::steady_clock::now();
  double t = first_unit_free_tol(options, out.measure);
  CommonOptions first = options;
  first.tol = t;
  solve_global_once(a, first, out);
  for (int k = 0; k < kMaxTightenings && out.measure != FrictionMeasure::kUnitFree; ++k) {
    if (!has_answer(out.result, out.problem)) break;
    const FrictionErrors e = friction_errors(out.problem, out.result.z);
    const auto next = next_unit_free_tol(t, measured(e, out.measure), options.tol);
    if (!is_solution(out.result.status) || !(e.unit_free <= options.tol_acceptable) || !next)
      break;
    const double left = options.time_limit_s -
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!(left > 0)) break;
    t = *next;
    CommonOptions tighter = options;
    tighter.tol = t;
    tighter.time_limit_s = left;
    FcSolveOutcome again = out;
    solve_global_once(a, tighter, again);
    const int iterations = out.result.iterations + again.result.iterations;  // all the solves'
    const double seconds = out.result.seconds + again.result.seconds;
    const bool better =
        better_in_measure(out.problem, again.result, out.result, options, out.measure);
    if (better) out = std::move(again);
    out.result.iterations = iterations;
    out.result.seconds = seconds;
    if (!better) break;
  }
  if (has_answer(out.result, out.problem))
    decide_in_measure(out.problem, out.result, options, out.measure);
}

}  // namespace

std::string fc_solver_list() {
  std::string out;
  for (const auto& name : solvers().names(ProblemKind::kFrictionContact))
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

FcSolveOutcome run_fc_solve_request(const FcRequest& a) {
  FcSolveOutcome out;
  out.file = a.file;
  // Read once (a pipe holds either kind); validates; names the file; a damaged file is
  // reported as the kind it most likely is.
  out.measure = parse_friction_measure(a.measure, "--measure");
  FrictionProblemFile file = read_friction_problem_file(a.file);
  if (file.is_global) {
    out.global_problem = std::move(file.global);
    out.is_global = true;
    solve_global_request(a, out);
    out.exit_code = exit_code(out.result.status);
    return out;
  }
  out.problem = std::move(file.local);
  const CommonOptions options = common_options(a);
  const SolverEntry& entry = fc_solver(a.solver);
  out.result = solve_in_measure(out.problem, entry, options, out.measure);
  out.exit_code = exit_code(out.result.status);
  return out;
}

nlohmann::json fc_solve_json(const FcSolveOutcome& out) {
  if (!out.is_global) {
    nlohmann::json j = problem_json(out.file, out.problem);
    j.update(fc_result_json(out.result, out.problem));
    return j;
  }
  const GlobalFrictionContactProblem& g = out.global_problem;
  const GlobalSolveResult& s = out.global;
  // The global errors exist only where v was computed; otherwise null (0 would read as perfect).
  const bool judged = s.v.size() == g.dofs();
  const nlohmann::json global = {
      {"dofs", g.dofs()},
      {"condensed", s.condensed.ok && !out.proximal},  // M itself
      {"route", out.proximal ? "proximal" : "condensed"},
      {"errors", judged ? nlohmann::json{{"balance", s.errors.balance}, {"local", s.errors.local}}
                        : nlohmann::json{{"balance", nullptr}, {"local", nullptr}}}};
  nlohmann::json j = {{"file", out.file}, {"problem", g.name}, {"contacts", g.contacts()},
                      {"global", global}};
  j.update(fc_result_json(out.result, out.problem));
  j["v"] = std::vector<double>(s.v.data(), s.v.data() + s.v.size());
  return j;
}

std::string fc_solve_text(const FcSolveOutcome& out) {
  std::ostringstream o;
  const SolveResult& r = out.result;
  if (!out.is_global) {
    o << "problem:    " << out.problem.name << " (" << count_text(out.problem.contacts(), "contact")
      << ")\n" << measure_line(out.measure) << result_line(r, out.problem);
    return o.str();
  }
  const GlobalFrictionContactProblem& g = out.global_problem;
  o << "problem:    " << g.name << " (global: " << count_text(g.contacts(), "contact") << ", "
    << count_text(g.dofs(), "dof") << ")\n" << measure_line(out.measure);
  if (out.proximal)
    o << "route:      proximal point in v (M is singular: no condensation), " << r.iterations
      << " outer iterations\n";
  if (out.global.condensed.ok && out.global.v.size() == g.dofs())
    o << "global:     balance " << out.global.errors.balance << ", local "
      << out.global.errors.local << " (unit-free)\n" << result_line(r, out.problem);
  else if (out.global.condensed.ok)  // the local solver returned no r: nothing judged
    o << result_line(r, out.problem);
  else
    o << "status:     " << to_string(r.status) << "\nmessage:    " << r.message << '\n';
  return o.str();
}

FcSolutionsOutcome run_fc_solutions_request(const FcRequest& a) {
  FcSolutionsOutcome out;
  out.file = a.file;
  out.measure = parse_friction_measure(a.measure, "--measure");
  out.problem = read_friction_problem(a.file);
  FrictionSolutionsOptions o;
  o.common = common_options(a);
  o.starts = a.starts;
  o.seed = a.seed;
  throw_if_invalid_option(o.validate(), {{"starts", "--starts"},
                                         {"tol", "--tol"},
                                         {"time_limit_s", "--time-limit"}});
  out.set = friction_solutions(out.problem, o);
  bool any = false;
  for (auto& s : out.set.solutions) {
    s = refine_in_measure(out.problem, std::move(s), o.common, out.measure);
    any = any || is_solution(s.status);
  }
  out.exit_code = any ? kExitOk : kExitInconclusive;
  return out;
}

nlohmann::json fc_solutions_json(const FcSolutionsOutcome& out) {
  nlohmann::json j = problem_json(out.file, out.problem);
  auto& list = j["solutions"] = nlohmann::json::array();
  for (const auto& s : out.set.solutions) list.push_back(fc_result_json(s, out.problem));
  auto& families = j["families"] = nlohmann::json::array();
  for (const auto& f : out.set.families) {
    nlohmann::json basis = nlohmann::json::array();
    for (Eigen::Index c = 0; c < f.basis.cols(); ++c)
      basis.push_back(std::vector<double>(f.basis.col(c).data(), f.basis.col(c).data() + f.basis.rows()));
    std::vector<int> members;
    for (int m : f.members) members.push_back(m + 1);
    families.push_back({{"solutions", members}, {"dimension", f.dimension()}, {"basis", basis}});
  }
  j["complete"] = out.set.complete;
  j["message"] = out.set.message;
  return j;
}

std::string fc_solutions_text(const FcSolutionsOutcome& out) {
  std::ostringstream o;
  o << "problem:    " << out.problem.name << " (" << count_text(out.problem.contacts(), "contact")
    << ")\n" << measure_line(out.measure) << out.set.solutions.size()
    << " distinct verified solution(s), complete: "
    << (out.set.complete ? "yes" : "no") << "\n" << out.set.message << '\n';
  for (std::size_t k = 0; k < out.set.solutions.size(); ++k)
    o << "-- solution " << k + 1 << '\n' << result_line(out.set.solutions[k], out.problem);
  return o.str();
}

}  // namespace cpkit::lcp::friction
