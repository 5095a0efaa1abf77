// `cpkit fc solve FILE [--solver S] [--tol T] [--max-iter K] [--time-limit S] [--json]`
// `cpkit fc solutions FILE [--starts K] [--seed N] [--tol T] [--time-limit S] [--json]`
// `cpkit fc bench FILE... [--solvers a,b] --out PREFIX` (fc_bench.hpp)
// 3-D frictional contact problems from FCLIB (HDF5) or Siconos FrictionContact .dat files
// (cpkit/core/friction_io.hpp). `solve` runs one solver of cpkit::lcp::solvers() that accepts
// friction problems; `solutions` lists distinct verified solutions (lcp/friction/solutions.hpp).
// Exit codes: 0 solved (at least one solution), 1 proved no solution (a re-checked certificate),
// 2 bad input or usage, 5 not solved (nothing proved).
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "cli_common.hpp"
#include "cli_options.hpp"
#include "fc_bench.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/report.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/friction/global.hpp"
#include "cpkit/lcp/friction/solutions.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::cli {
namespace {

struct FcArgs {
  std::string file;
  std::string solver = "auto";
  bool json = false;
  double tol = CommonOptions{}.tol;
  int max_iter = 0;
  double time_limit_s = std::numeric_limits<double>::infinity();
  int starts = lcp::friction::FrictionSolutionsOptions{}.starts;
  unsigned seed = lcp::friction::FrictionSolutionsOptions{}.seed;
};

std::string fc_solver_list() {
  std::string out;
  for (const auto& name : cpkit::lcp::solvers().names(ProblemKind::kFrictionContact))
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

CommonOptions common_options(const FcArgs& a) {
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

/// One result as the fc commands print it: r and u flat (contact by contact, normal first),
/// the three errors of friction_verdict.hpp recomputed from the data, and the solver's counts.
nlohmann::json fc_result_json(const SolveResult& r, const FrictionContactProblem& p) {
  const nlohmann::json full = to_json(r);
  nlohmann::json j;
  j["status"] = full["status"];
  j["solver"] = r.solver;
  j["r"] = full["z"];
  j["u"] = full["w"];
  const bool sized = r.z.size() == p.W.rows();
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

nlohmann::json problem_json(const FcArgs& a, const FrictionContactProblem& p) {
  return {{"file", a.file}, {"problem", p.name}, {"contacts", p.contacts()},
          {"W_nonzeros", p.W.nonZeros()}};
}

std::string result_line(const SolveResult& r, const FrictionContactProblem& p) {
  std::ostringstream s;
  s << "status:     " << to_string(r.status) << "\nsolver:     " << r.solver;
  if (r.z.size() == p.W.rows()) {
    const FrictionErrors e = friction_errors(p, r.z);
    s << "\nerrors:     unit-free " << e.unit_free << ", relative to |q| " << e.relative_q
      << ", relative to max(|q|, |r|, |u|) " << e.relative_max;
    int count[3] = {0, 0, 0};
    for (const auto& c : friction_contacts(p, r.z)) ++count[static_cast<int>(c.state)];
    s << "\ncontacts:   " << count[1] << " stick, " << count[2] << " slip, " << count[0]
      << " separated";
  }
  s << "\niterations: " << r.iterations << "\nseconds:    " << r.seconds;
  if (!r.message.empty()) s << "\nmessage:    " << r.message;
  s << '\n';
  return s.str();
}

const SolverEntry& fc_solver(const std::string& name) {
  const SolverEntry* entry = cpkit::lcp::solvers().find(name);
  if (entry == nullptr || !entry->accepts(ProblemKind::kFrictionContact))
    throw InputError("unknown friction solver '" + name + "' (valid: " + fc_solver_list() + ")");
  return *entry;
}

int exit_code(Status s) {
  if (is_solution(s)) return kExitOk;
  return s == Status::kInfeasible ? kExitNoSolution : kExitInconclusive;
}

/// A global problem (M v = H r + f, u = H^T v + w): condensed, solved locally, judged in the
/// global variables (lcp/friction/global.hpp); where M is singular (degrees of freedom without
/// mass) it is solved in its own variables by the proximal point in v (solve_global_proximal).
/// The output adds v, the dofs, the route and the two unit-free global errors; "errors" are the
/// condensed (for the proximal route: the last regularized) local problem's.
int run_fc_solve_global(const FcArgs& a, const GlobalFrictionContactProblem& g) {
  const CommonOptions options = common_options(a);
  const SolverEntry& entry = fc_solver(a.solver);
  auto out = lcp::friction::solve_global(g, entry.info.name, options);
  const bool singular = !out.condensed.ok && out.condensed.message.rfind("M is singular", 0) == 0;
  if (singular) out = lcp::friction::solve_global_proximal(g, entry.info.name, options);
  const auto& c = out.condensed;
  const SolveResult& r = out.result;
  const nlohmann::json global = {{"dofs", g.dofs()},
                                 {"condensed", c.ok && !singular},  // M itself
                                 {"route", singular ? "proximal" : "condensed"},
                                 {"errors", {{"balance", out.errors.balance},
                                             {"local", out.errors.local}}}};
  if (a.json) {
    nlohmann::json j = {{"file", a.file}, {"problem", g.name}, {"contacts", g.contacts()},
                        {"global", global}};
    j.update(fc_result_json(r, c.local));
    j["v"] = std::vector<double>(out.v.data(), out.v.data() + out.v.size());
    print_json(j);
  } else {
    std::cout << "problem:    " << g.name << " (global: " << g.contacts() << " contacts, "
              << g.dofs() << " dofs)\n";
    if (singular)
      std::cout << "route:      proximal point in v (M is singular: no condensation), "
                << r.iterations << " outer iterations\n";
    if (c.ok) std::cout << "global:     balance " << out.errors.balance << ", local "
                        << out.errors.local << " (unit-free)\n" << result_line(r, c.local);
    else std::cout << "status:     " << to_string(r.status) << "\nmessage:    " << r.message << '\n';
    std::cout << std::flush;
  }
  return exit_code(r.status);
}

int run_fc_solve(const FcArgs& a) {
  FrictionContactProblem p;
  try {
    p = read_friction_problem(a.file);  // validates; names the file
  } catch (const InputError& local_error) {
    // Not a local problem: a global one is solved; anything else reports the local reader's
    // message (the file is most likely a damaged local problem).
    GlobalFrictionContactProblem g;
    try {
      g = read_global_friction_problem(a.file);
    } catch (const InputError&) {
      throw local_error;
    }
    return run_fc_solve_global(a, g);
  }
  const CommonOptions options = common_options(a);
  const SolverEntry* entry = &fc_solver(a.solver);
  SolveResult r = entry->solve_fc(p, options);
  if (r.solver.empty()) r.solver = entry->info.name;
  if (a.json) {
    nlohmann::json j = problem_json(a, p);
    j.update(fc_result_json(r, p));
    print_json(j);
  } else {
    std::cout << "problem:    " << p.name << " (" << p.contacts() << " contacts)\n"
              << result_line(r, p) << std::flush;
  }
  return exit_code(r.status);
}

int run_fc_solutions(const FcArgs& a) {
  const FrictionContactProblem p = read_friction_problem(a.file);
  lcp::friction::FrictionSolutionsOptions o;
  o.common = common_options(a);
  if (a.starts < 1) throw InputError("--starts must be at least 1, got " + std::to_string(a.starts));
  o.starts = a.starts;
  o.seed = a.seed;
  throw_if_invalid(o.validate(), "fc solutions");
  const auto set = lcp::friction::friction_solutions(p, o);
  if (a.json) {
    nlohmann::json j = problem_json(a, p);
    auto& list = j["solutions"] = nlohmann::json::array();
    for (const auto& s : set.solutions) list.push_back(fc_result_json(s, p));
    j["complete"] = set.complete;
    j["message"] = set.message;
    print_json(j);
  } else {
    std::cout << "problem:    " << p.name << " (" << p.contacts() << " contacts)\n"
              << set.solutions.size() << " distinct verified solution(s), complete: "
              << (set.complete ? "yes" : "no") << "\n" << set.message << '\n';
    for (std::size_t k = 0; k < set.solutions.size(); ++k)
      std::cout << "-- solution " << k + 1 << '\n' << result_line(set.solutions[k], p);
    std::cout << std::flush;
  }
  return set.solutions.empty() ? kExitInconclusive : kExitOk;
}

void add_common(CLI::App* cmd, FcArgs& a) {
  cmd->add_option("FILE", a.file, "problem file: FCLIB local problem (HDF5) or Siconos "
                                  "FrictionContact .dat (chosen by content)")
      ->required();
  cmd->add_flag("--json", a.json, "print one JSON object on stdout");
  cmd->add_option("--tol", a.tol, "tolerance on the unit-free residual (default 1e-10, at most 1e-3)");
  cmd->add_option("--time-limit", a.time_limit_s, "wall-clock limit in seconds");
}

}  // namespace

void add_fc_command(CLI::App& app, Context& ctx) {
  auto* fc = app.add_subcommand("fc", "3-D frictional contact problems (FCLIB, Siconos .dat)");
  fc->require_subcommand(1);
  auto solve = std::make_shared<FcArgs>();
  auto* s = fc->add_subcommand("solve", "Solve a frictional contact problem u = W r + q, "
                                        "r in K_mu, u_hat in K*_mu, r . u_hat = 0");
  add_common(s, *solve);
  s->add_option("--solver", solve->solver,
                "solver name from the registry (default auto; valid: " + fc_solver_list() + ")");
  s->add_option("--max-iter", solve->max_iter, "iteration limit (0: the solver's default)");
  s->callback([solve, &ctx]() { ctx.exit_code = run_fc_solve(*solve); });

  auto sols = std::make_shared<FcArgs>();
  auto* l = fc->add_subcommand("solutions", "List distinct verified solutions (every solution of "
                                            "the faceted problem for small n_c; multistart, "
                                            "complete: false, otherwise)");
  add_common(l, *sols);
  l->add_option("--starts", sols->starts, "seeded starts of the multistart route (default 20)");
  l->add_option("--seed", sols->seed, "seed of the starts (default 1)");
  l->callback([sols, &ctx]() { ctx.exit_code = run_fc_solutions(*sols); });

  auto bench = std::make_shared<FcBenchArgs>();
  auto* b = fc->add_subcommand("bench", "Every solver on every file: PREFIX.csv (status, "
                                        "iterations, seconds, the three errors) and PREFIX.png "
                                        "(Dolan-More performance profile)");
  b->add_option("FILE", bench->files, "problem files (FCLIB local HDF5 or Siconos .dat)")
      ->required();
  b->add_option("--solvers", bench->solvers,
                "comma-separated solver names (default: every friction solver: " +
                    fc_solver_list() + ")")
      ->delimiter(',');
  b->add_option("--out", bench->out, "prefix of PREFIX.csv and PREFIX.png")->required();
  b->add_option("--tol", bench->tol, "tolerance on the unit-free residual (default 1e-10)");
  b->add_option("--time-limit", bench->time_limit_s, "seconds per solve (default 60)");
  b->add_flag("--no-plot", bench->no_plot, "write the CSV only");
  b->callback([bench, &ctx]() { ctx.exit_code = run_fc_bench(*bench); });
}

}  // namespace cpkit::cli
