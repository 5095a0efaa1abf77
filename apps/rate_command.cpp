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
// N points (rate_system.cpp): cpkit rate --system FILE [--dF ... 2N numbers] [--json]
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

namespace cpkit::cli {

/// `cpkit rate --system FILE` (rate_system.cpp).
int run_rate_system(const std::string& path, const std::vector<double>& dF,
                    const std::string& method, int facets, bool json,
                    std::optional<double> time_limit);

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

nlohmann::json rates_json(const rate::Rates& r) {
  nlohmann::json j;
  j["dP_T"] = r.dP_T;
  j["dP_N"] = r.dP_N;
  j["dw_T"] = r.dw_T;
  j["dw_N"] = r.dw_N;
  j["dw_Ti"] = r.dw_Ti;
  j["dw_w"] = r.dw_w;
  return j;
}

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

/// `reference`: the enumerated set a single solver's answer was checked against (or null).
nlohmann::json set_json(const rate::RateSolutionSet& s, const rate::RateSolutionSet* reference) {
  nlohmann::json j;
  j["complete"] = s.complete;
  // A count only when the set is complete: one solver's one solution is not "count 1".
  if (s.complete) {
    if (s.count() < 0) j["count"] = "inf"; else j["count"] = s.count();
  } else {
    j["found"] = s.solutions.size();
  }
  if (reference && reference->complete) {
    if (reference->count() < 0) j["enumerated_count"] = "inf";
    else j["enumerated_count"] = reference->count();
  }
  j["types"] = sorted_types(s);
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& p : s.solutions) {
    nlohmann::json e;
    e["type"] = std::string(rate::to_string(p.type));
    e["kind"] = std::string(rate::to_string(p.kind));
    switch (p.kind) {
      case rate::RateSolution::Kind::kPoint:
        e["rates"] = rates_json(p.start);
        break;
      case rate::RateSolution::Kind::kSegment:
        e["start"] = rates_json(p.start);
        e["start_closed"] = p.start_closed;
        e["end"] = rates_json(p.end);
        e["end_closed"] = p.end_closed;
        break;
      case rate::RateSolution::Kind::kRay:
        e["start"] = rates_json(p.start);
        e["start_closed"] = p.start_closed;
        e["direction"] = rates_json(p.direction);
        break;
    }
    sols.push_back(e);
  }
  j["solutions"] = sols;
  j["Lambda"] = s.Lambda;
  j["D_plus"] = s.D_plus;  // D_s = a11 - s mu a12 (docs/model.md Sec. 2.2), as the text prints
  j["D_minus"] = s.D_minus;
  j["unique_for_all_directions"] = s.unique_for_all_directions;
  return j;
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
  const rate::RateSolutionSet s = rate::solve_rate_problem(p, st, f, *method);
  int code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  std::string problem;
  bool inconclusive = false;  // the enumeration could not decide: exit 5, never 3
  rate::RateSolutionSet ref;
  const bool single = single_solver(*method);
  if (*method == rate::RateMethod::kEnumerate) {
    const rate::RateSolutionSet analytic =
        rate::solve_rate_problem(p, st, f, rate::RateMethod::kAnalytic);
    std::string why;
    if (!s.complete) {
      problem = "the enumeration is not conclusive: " + s.message;
      inconclusive = true;
    } else if (!analytic.complete) {
      problem = "the analytic route cannot decide a sign: " + analytic.message;
      inconclusive = true;
    } else if (!rate::same_solution_sets(s, analytic, 1e-7, &why)) {
      problem = "enumeration and analytic routes disagree: " + why;
    }
  } else if (*method == rate::RateMethod::kAnalytic && !s.complete) {
    problem = "the analytic route cannot decide a sign: " + s.message;
    inconclusive = true;
  } else if (single) {
    ref = rate::solve_rate_problem(p, st, f, rate::RateMethod::kEnumerate);
    // the solver's point is accurate to its residual (solved_inaccurate allows up to 1e-6)
    const double tol = std::max(1e-6, 1e3 * s.residual);
    if (!s.solutions.empty() && !rate::contains(ref, s.solutions.front().start, tol)) {
      problem = a.method + "'s solution is not in the enumerated solution set";
    } else if (!s.solutions.empty() &&
               ref.solutions[rate::find_piece(ref, s.solutions.front().start, tol)].type !=
                   s.solutions.front().type) {
      problem = a.method + "'s solution has another type than the enumerated set's piece";
    } else if (s.solutions.empty()) {
      std::cerr << "cpkit rate: " << s.message << "; the enumeration has "
                << (ref.count() < 0 ? std::string("infinitely many")
                                    : std::to_string(ref.count()))
                << " solution(s)\n";
    }
  }
  const rate::RateSolutionSet* reference = single ? &ref : nullptr;
  if (a.json) print_json(set_json(s, reference)); else print_text(s, a, reference);
  if (!problem.empty()) {
    std::cerr << "cpkit rate: " << problem << '\n';
    code = inconclusive ? kExitInconclusive : kExitDisagreement;
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
