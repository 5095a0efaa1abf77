// `cpkit step`: one implicit time step of the one-point contact problem (the incremental
// problem, docs/model.md Sec. 3, docs/simulation.md).
//
//   cpkit step --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X] [--criterion 38|35]
//              [--wear-law archard|mroz --k_M X] --P_T0 X --P_N0 X --g0 X --DF DFT DFN
//              [--all] [--chain active-set,lemke,fb-newton,ipopt] [--json]
//
// --all: every solution (complete active-set enumeration; continua as segments/rays, jumps
// flagged). Otherwise one solution by the solver chain. Exit codes: 0 at least one solution,
// 1 none, 2 bad input.
#include <iostream>
#include <memory>
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
};

nlohmann::json values_json(const rate::StepValues& v) {
  nlohmann::json j;
  j["DP_T"] = v.DP_T;
  j["DP_N"] = v.DP_N;
  j["Dw_T"] = v.Dw_T;
  j["Dw_N"] = v.Dw_N;
  j["Dw_Ti"] = v.Dw_Ti;
  j["Dw_w"] = v.Dw_w;
  j["P_T1"] = v.P_T1;
  j["P_N1"] = v.P_N1;
  j["g1"] = v.g1;
  return j;
}

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
  const auto law = rate::wear_law_from_string(a.wear_law);
  if (!law) throw InputError("--wear-law must be archard or mroz, got '" + a.wear_law + "'");
  p.wear.law = *law;
  p.wear.k_M = a.k_M;
  p.state = {a.P_T0, a.P_N0, a.g0};
  if (a.DF.size() != 2) throw InputError("--DF needs two values: DFT DFN");
  p.load = {a.DF[0], a.DF[1]};
  throw_if_invalid(p.validate(), "step");
  return p;
}

int run_all(const rate::StepProblem& p, bool json) {
  const rate::StepSolutionSet s = rate::enumerate_step(p);
  std::set<std::string> types;
  for (const auto& sol : s.solutions) types.insert(std::string(rate::to_string(sol.type)));
  if (json) {
    nlohmann::json j;
    if (s.count() < 0) j["count"] = "inf"; else j["count"] = s.count();
    j["types"] = std::vector<std::string>(types.begin(), types.end());
    j["continuous_count"] = s.continuous_count;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& sol : s.solutions) {
      nlohmann::json e;
      e["type"] = std::string(rate::to_string(sol.type));
      e["kind"] = std::string(rate::to_string(sol.kind));
      switch (sol.kind) {
        case rate::RateSolution::Kind::kPoint:
          e["values"] = values_json(sol.start);
          break;
        case rate::RateSolution::Kind::kSegment:
          e["start"] = values_json(sol.start);
          e["start_closed"] = sol.start_closed;
          e["end"] = values_json(sol.end);
          e["end_closed"] = sol.end_closed;
          break;
        case rate::RateSolution::Kind::kRay:
          e["start"] = values_json(sol.start);
          e["start_closed"] = sol.start_closed;
          e["direction"] = values_json(sol.direction);
          break;
      }
      e["jump"] = sol.jump;
      e["residual"] = sol.residual;
      sols.push_back(e);
    }
    j["solutions"] = sols;
    print_json(j);
  } else {
    std::cout << "step: " << (s.count() < 0 ? std::string("infinitely many")
                                              : std::to_string(s.count()))
              << " solution(s)";
    if (s.continuous_count >= 0)
      std::cout << ", " << s.continuous_count << " continuous (rate-consistent)";
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
  }
  return s.solutions.empty() ? kExitNoSolution : kExitOk;
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
  if (json) {
    nlohmann::json j;
    j["status"] = std::string(to_string(r.result.status));
    j["solver"] = r.result.solver;
    if (ok) {
      j["type"] = std::string(rate::to_string(r.type));
      j["values"] = values_json(r.values);
    }
    j["residual"] = r.result.residuals.natural;
    nlohmann::json at = nlohmann::json::array();
    for (const auto& a : r.result.attempts)
      at.push_back({{"solver", a.solver}, {"status", std::string(to_string(a.status))},
                    {"residual", a.residual}, {"seconds", a.seconds}, {"message", a.message}});
    j["attempts"] = at;
    j["message"] = r.result.message;
    print_json(j);
  } else {
    std::cout << "status: " << to_string(r.result.status) << " (solver " << r.result.solver
              << ", residual " << r.result.residuals.natural << ")\n";
    if (ok)
      std::cout << "  " << rate::to_string(r.type) << ": " << values_text(r.values) << "\n";
    if (!r.result.message.empty()) std::cout << "note: " << r.result.message << "\n";
  }
  return ok ? kExitOk : kExitNoSolution;
}

}  // namespace

void add_step_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<StepArgs>();
  auto* cmd = app.add_subcommand(
      "step", "One implicit time step of the one-point contact problem with friction and wear "
              "(the incremental problem, docs/simulation.md)");
  add_model_options(*cmd, args->model);
  cmd->add_option("--wear-law", args->wear_law,
                  "archard (37, default) or mroz (Mroz-Stupkiewicz (41), with --k_M)");
  cmd->add_option("--k_M", args->k_M, "Mroz-Stupkiewicz wear constant (>= 0)");
  cmd->add_option("--P_T0", args->P_T0, "tangential force at the start of the step")->required();
  cmd->add_option("--P_N0", args->P_N0, "normal force at the start (>= 0)")->required();
  cmd->add_option("--g0", args->g0, "gap function w_N - w^w at the start (<= 0; 0 in contact)")
      ->required();
  cmd->add_option("--DF", args->DF, "load increment: DFT DFN")->expected(2)->required();
  cmd->add_flag("--all", args->all, "every solution (complete active-set enumeration)");
  cmd->add_option("--chain", args->chain,
                  "solver chain for one solution (comma-separated; default "
                  "active-set,lemke,fb-newton,ipopt)");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args, &ctx, cmd]() {
    // Options that would have no effect in this context are errors, never silence.
    const bool mroz = args->wear_law == "mroz";
    if (cmd->count("--k_M") > 0 && !mroz)
      throw InputError("--k_M is the Mroz-Stupkiewicz wear constant: it needs --wear-law mroz");
    if (mroz && cmd->count("--k_M") == 0)
      throw InputError("--wear-law mroz needs --k_M (the Mroz-Stupkiewicz wear constant)");
    if (mroz && cmd->count("--k_a") > 0)
      throw InputError("--k_a (Archard) has no effect with --wear-law mroz: give --k_M instead");
    if (args->all && cmd->count("--chain") > 0)
      throw InputError("--chain has no effect with --all (every solution comes from the complete "
                       "active-set enumeration)");
    const rate::StepProblem p = make_problem(*args);
    ctx.exit_code = args->all ? run_all(p, args->json) : run_one(p, args->chain, args->json);
  });
}

}  // namespace cpkit::cli
