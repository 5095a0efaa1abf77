#pragma once
/// \file lcp_request.hpp
/// What `cpkit lcp solve|verify|enumerate` were asked (docs/cli.md), as given, and the one call
/// that answers each: read the problem file, check the options (InputError in the user's words:
/// "--tol must be ...", exit 2), run, decide the exit code (core/exit_code.hpp). The text and
/// JSON the program prints are here too (lcp_report.cpp), for Python and tests.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/enumerate.hpp"

namespace cpkit::lcp {

/// The solver used when none is named: `cpkit lcp solve` and Python's `cpkit.solve` (one
/// default for both). "auto" is the chain (auto_chain.hpp): Lemke first, then FB Newton, the
/// enumeration and the MPCC solvers when Lemke finds no solution (e.g. a secondary ray that
/// proves nothing).
inline constexpr char kDefaultSolver[] = "auto";

/// "a, b, c": the registered LCP solver names (messages and --help).
std::string lcp_solver_list();

/// The answer to a verify or enumerate request: the problem as read, the library's result and
/// the exit code decided from it.
template <class Result>
struct LcpOutcome {
  LcpProblem problem;
  Result result;
  ExitCode exit_code = kExitOk;
};

// `cpkit lcp solve`.

struct LcpSolveRequest {
  std::string file;
  std::string q_file;  ///< --q: the q of a Matrix Market or .npy M (default FILE.q.mtx/.q.npy)
  std::string solver = kDefaultSolver;  ///< --solver (default auto)
  bool json = false;  ///< --json (--trace with --all-solvers needs it)
  double tol = CommonOptions{}.tol;  ///< on the unit-free residual; at most 1e-3
  int max_iter = 0;                  ///< 0: the solver's default
  double time_limit_s = std::numeric_limits<double>::infinity();
  bool trace = false;
  bool all_solvers = false;  ///< every registered solver that accepts the problem
};

struct LcpSolveOutcome {
  LcpProblem problem;
  bool all_solvers = false;
  std::vector<SolveResult> results;  ///< one; --all-solvers: one per registry entry run
  std::vector<std::string> entries;  ///< the registry entries run ("solver" is who produced z)
  ExitCode exit_code = kExitOk;      ///< 0 some result is a verified solution, else 1
  /// What to try next when no solution was found and none was proved impossible (no result
  /// `infeasible`): exit 1 is then no proof. Empty otherwise. Text "hint:", JSON "hint".
  std::string hint;
};

/// Reads the file, checks the options, runs the solver (or every solver): every result has been
/// through finalize(). InputError for a bad file, option or solver name.
LcpSolveOutcome run_lcp_solve_request(const LcpSolveRequest& request);
/// `cpkit lcp solve --json`: the result (core/report.hpp's to_json, with "problem"); with
/// --all-solvers {problem, n, solved_by_any, results: [... with "entry"]}.
nlohmann::json lcp_solve_json(const LcpSolveOutcome& outcome);
/// The text report: the result (with its pivot trace), or the table of every solver.
std::string lcp_solve_text(const LcpSolveOutcome& outcome);

// `cpkit lcp verify`.

struct LcpVerifyRequest {
  std::string file;
  std::vector<std::string> skip;  ///< registered solver names not to run
  double time_limit_s = 60;       ///< per solver and for the enumeration
};

/// Exit 0 complete and consistent; 3 a disagreement (even against an incomplete enumeration);
/// 5 inconclusive: incomplete enumeration, no disagreement.
using LcpVerifyOutcome = LcpOutcome<CrossVerifyReport>;
LcpVerifyOutcome run_lcp_verify_request(const LcpVerifyRequest& request);
/// enumeration {complete, count, continuum, num_extreme, ambiguous, seconds}, solvers [...],
/// disagreements, consistent, verdict ("consistent", "disagreement" or "inconclusive").
nlohmann::json lcp_verify_json(const LcpVerifyOutcome& outcome);
std::string lcp_verify_text(const LcpVerifyOutcome& outcome);

// `cpkit lcp enumerate`.

struct LcpEnumerateRequest {
  std::string file;
  double tol = EnumerationOptions{}.tol;
  double time_limit_s = EnumerationOptions{}.time_limit_s;
  int max_size = EnumerationOptions{}.max_size;
};

/// Exit 0 a solution; 1 none and the enumeration is complete; 5 none found, incomplete.
using LcpEnumerateOutcome = LcpOutcome<SolutionSet>;
LcpEnumerateOutcome run_lcp_enumerate_request(const LcpEnumerateRequest& request);
/// n, complete, count ("inf" when infinite), num_extreme, continuum, solutions [{z, w, basis}],
/// directions and pieces (when infinite), ambiguous, nodes, seconds, message.
nlohmann::json lcp_enumerate_json(const LcpEnumerateOutcome& outcome);
std::string lcp_enumerate_text(const LcpEnumerateOutcome& outcome);

}  // namespace cpkit::lcp
