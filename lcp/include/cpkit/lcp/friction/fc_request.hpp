#pragma once
/// \file fc_request.hpp
/// What `cpkit fc solve|solutions` were asked (docs/cli.md), as given, and the one call that
/// answers each: read the problem file (FCLIB HDF5 or Siconos .dat, local or global, chosen by
/// content), check the options (InputError in the user's words, exit 2), solve, decide the exit
/// code (core/exit_code.hpp: 0 solved, 1 proved no solution, 5 nothing proved). The text and
/// JSON the program prints are here too: r and u flat, contact by contact, normal first.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/lcp/friction/global.hpp"
#include "cpkit/lcp/friction/solutions.hpp"

namespace cpkit::lcp::friction {

/// "a, b, c": the registered friction solver names (messages and --help).
std::string fc_solver_list();

/// The options of `cpkit fc solve` and `cpkit fc solutions` as given.
struct FcRequest {
  std::string file;
  std::string solver = "auto";       ///< solve: a registered friction solver
  double tol = CommonOptions{}.tol;  ///< in the measure below, in (0, 1e-3]
  int max_iter = 0;                  ///< solve: 0 is the solver's default
  double time_limit_s = std::numeric_limits<double>::infinity();
  int starts = FrictionSolutionsOptions{}.starts;  ///< solutions: seeded multistart starts
  unsigned seed = FrictionSolutionsOptions{}.seed;
  /// The measure that decides "solved" (core/friction_measure.hpp): unit_free, relative_q or
  /// relative_max; any other word is an InputError listing them.
  std::string measure = "unit_free";
};

/// `cpkit fc solve`: a local problem, or a global one (M v = H r + f) solved through its
/// condensed local problem or, where M is singular, by the proximal point in v.
struct FcSolveOutcome {
  std::string file;
  bool is_global = false;
  FrictionContactProblem problem;  ///< local: the problem; global: the condensed one solved
  GlobalFrictionContactProblem global_problem;
  GlobalSolveResult global;        ///< is_global: v, the global errors, the condensation
  bool proximal = false;           ///< is_global and M singular: the proximal route
  SolveResult result;
  FrictionMeasure measure = FrictionMeasure::kUnitFree;  ///< what decided result.status
  ExitCode exit_code = kExitOk;
};

FcSolveOutcome run_fc_solve_request(const FcRequest& request);
nlohmann::json fc_solve_json(const FcSolveOutcome& outcome);
std::string fc_solve_text(const FcSolveOutcome& outcome);

/// `cpkit fc solutions`: exit 0 some verified solution (a solution in the measure), 5 none
/// (nothing proved).
struct FcSolutionsOutcome {
  std::string file;
  FrictionContactProblem problem;
  FrictionSolutionSet set;  ///< each solution refined and judged in `measure`
  FrictionMeasure measure = FrictionMeasure::kUnitFree;
  ExitCode exit_code = kExitOk;
};

FcSolutionsOutcome run_fc_solutions_request(const FcRequest& request);
nlohmann::json fc_solutions_json(const FcSolutionsOutcome& outcome);
std::string fc_solutions_text(const FcSolutionsOutcome& outcome);

}  // namespace cpkit::lcp::friction
