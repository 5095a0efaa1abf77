// `cpkit lcp verify FILE [--json] [--skip NAME ...] [--time-limit S]`
// Cross-verification (cross_verify): enumerates the solution set, runs every registered solver
// that accepts the problem, and prints one row per solver: status, residual (finalize() scale
// and data scale), whether its z is in the enumerated set, and the verdict. JSON fields:
//   enumeration {complete, count ("inf" or integer), continuum, num_extreme, ambiguous},
//   solvers [{solver, status, residual, data_residual, in_set, solution_index, verdict,
//   seconds, message}], disagreements [strings], consistent (bool).
//   verdict ("consistent", "disagreement" or "inconclusive").
// Exit codes: 0 the enumeration is complete and every solver is consistent with it; 3 a
// disagreement was found (listed); 5 inconclusive: the enumeration is incomplete (time limit)
// and no disagreement was found, so nothing was verified; 2 bad input (including n above the
// enumeration's size limit).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cli_options.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "lcp_actions.hpp"

namespace cpkit::cli {
namespace {

struct LcpVerifyArgs {
  std::string file;
  bool json = false;
  std::vector<std::string> skip;
  double time_limit_s = 60;
};

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

/// consistent (complete and no disagreement), disagreement (any, even against an incomplete
/// enumeration: those verdicts do not depend on completeness), inconclusive (otherwise).
std::string verdict_name(const lcp::CrossVerifyReport& rep) {
  if (!rep.consistent()) return "disagreement";
  return rep.set.complete ? "consistent" : "inconclusive";
}

nlohmann::json report_json(const lcp::CrossVerifyReport& rep, const LcpProblem& p) {
  nlohmann::json j;
  if (!p.name.empty()) j["problem"] = p.name;
  const lcp::SolutionSet& s = rep.set;
  j["enumeration"] = {{"complete", s.complete},
                      {"count", s.infinite ? nlohmann::json("inf") : nlohmann::json(s.count())},
                      {"continuum", s.infinite},
                      {"num_extreme", s.count()},
                      {"ambiguous", s.ambiguous},
                      {"seconds", s.seconds}};
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& c : rep.checks)
    rows.push_back({{"solver", c.solver},
                    {"status", std::string(to_string(c.status))},
                    {"residual", number_or_null(c.residual)},
                    {"data_residual", number_or_null(c.data_residual)},
                    {"in_set", c.in_set},
                    {"solution_index", c.solution_index},
                    {"verdict", std::string(lcp::to_string(c.verdict))},
                    {"seconds", c.seconds},
                    {"message", c.message}});
  j["solvers"] = rows;
  j["disagreements"] = rep.disagreements;
  // "consistent" only when the check was conclusive: an incomplete enumeration verifies nothing.
  j["consistent"] = rep.consistent() && s.complete;
  j["verdict"] = verdict_name(rep);
  return j;
}

std::string report_text(const lcp::CrossVerifyReport& rep, const LcpProblem& p) {
  std::ostringstream o;
  const lcp::SolutionSet& s = rep.set;
  if (!p.name.empty()) o << "problem: " << p.name << " (n = " << p.size() << ")\n";
  o << "enumeration: " << (s.complete ? "complete" : "INCOMPLETE") << ", "
    << (s.infinite ? "infinite (continuum), " : "") << s.count() << " extreme solution(s)";
  if (s.ambiguous) o << ", " << s.ambiguous << " ambiguous sign test(s)";
  o << '\n';
  char line[256];
  std::snprintf(line, sizeof line, "%-12s %-18s %-11s %-11s %-7s %-30s %9s\n", "solver", "status",
                "residual", "data_res", "in_set", "verdict", "seconds");
  o << line;
  for (const auto& c : rep.checks) {
    const std::string in = cpkit::is_solution(c.status)
                               ? (c.in_set ? (c.solution_index >= 0 ? "#" + std::to_string(c.solution_index)
                                                                   : std::string("piece"))
                                           : std::string("NO"))
                               : std::string("-");
    std::snprintf(line, sizeof line, "%-12s %-18s %-11.3g %-11.3g %-7s %-30s %9.4f\n",
                  c.solver.c_str(), std::string(to_string(c.status)).c_str(), c.residual,
                  c.data_residual, in.c_str(), std::string(lcp::to_string(c.verdict)).c_str(),
                  c.seconds);
    o << line;
  }
  if (rep.consistent() && s.complete) {
    o << "consistent: every solver agrees with the enumeration\n";
  } else if (rep.consistent()) {
    o << "INCONCLUSIVE: the enumeration is incomplete"
      << (s.message.empty() ? std::string() : " (" + s.message + ")")
      << "; no solver contradicted the solutions found so far, but answers outside them could "
         "not be checked (raise --time-limit)\n";
  } else {
    o << "DISAGREEMENTS (" << rep.disagreements.size() << "):\n";
    for (const auto& d : rep.disagreements) o << "  " << d << '\n';
  }
  return o.str();
}

int run_lcp_verify(const LcpVerifyArgs& a) {
  const LcpProblem problem = read_lcp_file(a.file);
  lcp::CrossVerifyOptions opt;
  for (const auto& name : a.skip) {
    // A misspelt name would silently run the solver it meant to skip.
    const SolverEntry* e = lcp::solvers().find(name);
    if (e == nullptr || !e->accepts(ProblemKind::kLcp)) {
      std::string valid;
      for (const auto& n : lcp::solvers().names(ProblemKind::kLcp))
        valid += (valid.empty() ? "" : ", ") + n;
      throw InputError("--skip: unknown solver '" + name + "' (valid: " + valid + ")");
    }
  }
  opt.skip = a.skip;
  opt.solve.time_limit_s = a.time_limit_s;
  opt.enumeration.time_limit_s = a.time_limit_s;
  throw_if_invalid_option(opt.validate(), {{"EnumerationOptions::time_limit_s", "--time-limit"},
                                           {"time_limit_s", "--time-limit"}});
  const lcp::CrossVerifyReport rep = lcp::cross_verify(problem, opt);
  if (a.json)
    print_json(report_json(rep, problem));
  else
    std::cout << report_text(rep, problem) << std::flush;
  if (!rep.consistent()) return kExitDisagreement;
  return rep.set.complete ? kExitOk : kExitInconclusive;
}

}  // namespace

void add_lcp_verify(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<LcpVerifyArgs>();
  auto* cmd = lcp.add_subcommand(
      "verify", "Run every registered solver and check each answer against the full solution set");
  cmd->add_option("FILE", args->file, "problem file (.json or Siconos .dat)")->required();
  cmd->add_flag("--json", args->json, "print one JSON object on stdout");
  cmd->add_option("--skip", args->skip, "solver names not to run");
  cmd->add_option("--time-limit", args->time_limit_s,
                  "wall-clock limit per solver and for the enumeration (default 60 s)");
  cmd->callback([args, &ctx]() { ctx.exit_code = run_lcp_verify(*args); });
}

}  // namespace cpkit::cli
