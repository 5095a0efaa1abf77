// `cpkit step`: one implicit time step of the one-point contact problem (the incremental
// problem, docs/model.md Sec. 3, docs/simulation.md).
//
//   cpkit step --a11 X --a12 X --a22 X --mu X [--C_T X] [--k_a X --P_s X] [--criterion 38|35]
//              [--wear-law archard|mroz --k_M X] --P_T0 X --P_N0 X --g0 X --dF DFT DFN
//              [--all] [--chain active-set,lemke,fb-newton,ipopt] [--json]
//   cpkit step --system FILE --dF <2N numbers> --all [--json]      (N points, system_step.hpp)
//   cpkit step --system FILE3D --dF X Y N [--all|--chain|--facets K|--multistart N]
//                                        ("dim": 3, one point: step_3d.cpp)
//
// --all: every solution (complete active-set enumeration; continua as segments/rays, jumps
// flagged; "complete": false when a candidate could be neither verified nor rejected, or a
// solution does not fit in double). Otherwise one solution by the solver chain. Exit codes:
// 0 at least one solution, 1 none, 2 bad input, 5 none was found and the enumeration is not
// complete.
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "model_options.hpp"
#include "step_3d.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
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
  int facets = 0;      ///< --facets K (3-D files only, step_3d.cpp)
  int multistart = 0;  ///< --multistart N (3-D files only)
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
  if (a.DF.size() != 2) throw InputError("--dF needs two values: DFT DFN");
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
    j["complete"] = s.complete;
    if (!s.complete) j["message"] = s.message;
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
    if (all) {
      if (all->count() < 0) j["solutions_found"] = "inf"; else j["solutions_found"] = all->count();
      j["listed"] = 1;
      j["enumeration_complete"] = all->complete;
    }
    print_json(j);
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
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& q : p.system.points)
      pts.push_back({{"mu", q.mu}, {"C_T", q.C_T}, {"k_a", q.k_a}, {"P_s", q.P_s},
                     {"P_T", q.P_T}, {"P_N", q.P_N}, {"g", q.g}});
    nlohmann::json A = nlohmann::json::array();
    for (Eigen::Index r = 0; r < p.system.A.rows(); ++r) {
      std::vector<double> row(p.system.A.cols());
      for (Eigen::Index c = 0; c < p.system.A.cols(); ++c) row[c] = p.system.A(r, c);
      A.push_back(row);
    }
    j["input"] = {{"system", a.system}, {"name", p.system.name}, {"A", A}, {"points", pts},
                  {"DF", a.DF}};
    j["n_points"] = N;
    j["count"] = s.solutions.size();
    j["complete"] = s.complete;
    j["notes"] = s.notes;
    nlohmann::json sols = nlohmann::json::array();
    for (const auto& sol : s.solutions) {
      nlohmann::json e;
      std::vector<std::string> types;
      for (auto t : sol.types) types.emplace_back(rate::to_string(t));
      e["types"] = types;
      std::vector<double> f[9];
      for (const auto& v : sol.values) {
        const double x[9] = {v.DP_T, v.DP_N, v.Dw_T, v.Dw_N, v.Dw_Ti, v.Dw_w, v.P_T1, v.P_N1, v.g1};
        for (int k = 0; k < 9; ++k) f[k].push_back(x[k]);
      }
      const char* names[9] = {"DP_T", "DP_N", "Dw_T", "Dw_N", "Dw_Ti", "Dw_w", "P_T1", "P_N1", "g1"};
      nlohmann::json vals;
      for (int k = 0; k < 9; ++k) vals[names[k]] = f[k];
      e["values"] = vals;
      e["residual"] = sol.residual;
      sols.push_back(e);
    }
    j["solutions"] = sols;
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
      Step3dCliArgs a3{args->system, args->DF, args->wear_law, args->k_M, args->g0, args->all,
                       args->json, args->chain, args->facets, args->multistart, *file};
      ctx.exit_code = run_step_3d(a3, *cmd);  // step_3d.cpp
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
