#pragma once
/// \file cross_verify.hpp
/// Cross-verification: every registered LCP solver against the complete solution set.
///
/// cross_verify() enumerates the solution set (enumerate_all) and runs every solver of
/// cpkit::lcp::solvers() that accepts the problem (iterating over the registry: solvers added
/// later are included automatically). For each it reports the status, the residual recomputed
/// from the data, and whether the answer z is one of the enumerated extreme solutions or lies in
/// a positive-dimensional piece. Answers are compared on z and w only, never on bases or on
/// which point of a continuum a solver returned.
///
/// Disagreements (docs/enumeration.md, "Cross-verification"):
/// - kNotASolution:        status solved / solved_inaccurate but the residual recomputed from
///                         the data exceeds tol_acceptable: the same unit-free number and band as
///                         finalize() (residuals.hpp), so a diverging iterate with w = -1 on an
///                         infeasible LCP never passes, whatever the units;
/// - kInfeasibleButSolvable: status infeasible while the enumeration found a solution;
/// - kProvesIncomplete:    a verified solution that the (complete) enumeration does not contain.
/// Solver failures without a claim (ray termination, iteration limit, ...) are not
/// disagreements; they are listed as such.
#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/enumerate.hpp"

namespace cpkit::lcp {

struct CrossVerifyOptions {
  EnumerationOptions enumeration;  ///< options of the enumeration
  CommonOptions solve;             ///< options passed to every solver
  /// Membership tolerance for a solver's z (SolutionSet::contains, in the units of the
  /// acceptance test); raised to the answer's own residual when that is larger.
  double membership_tol = 1e-7;
  std::vector<std::string> skip;   ///< registry names not to run (e.g. slow ones)
  std::string validate() const;
};

enum class Verdict {
  kConsistent,              ///< a solution in the set, or infeasible on an empty set
  kNoAnswer,                ///< the solver failed without a claim (not a disagreement)
  kNotASolution,            ///< claimed solved, the data refute it
  kInfeasibleButSolvable,   ///< claimed infeasible, the enumeration found solutions
  kProvesIncomplete,        ///< a verified solution missing from a complete enumeration
  kUnchecked,               ///< a verified solution not in an incomplete enumeration
  kError,                   ///< the solver threw; message holds what()
};
std::string_view to_string(Verdict v) noexcept;
/// True for the three disagreement verdicts (and kError).
bool is_disagreement(Verdict v) noexcept;

struct SolverCheck {
  std::string solver;
  Status status = Status::kNotRun;
  double residual = 0;        ///< unit-free residual recomputed from the data (residuals.hpp)
  double data_residual = 0;   ///< ||min(z, w)||_inf in the problem's units (information only)
  bool in_set = false;        ///< z is an extreme solution or lies in a piece
  int solution_index = -1;    ///< index of the matching extreme solution (-1: none / in a piece)
  Verdict verdict = Verdict::kNoAnswer;
  double seconds = 0;
  std::string message;        ///< the solver's message, or what disagrees
};

struct CrossVerifyReport {
  SolutionSet set;                    ///< the enumeration
  std::vector<SolverCheck> checks;    ///< one per solver run, registry order
  std::vector<std::string> disagreements;  ///< one line per disagreement
  bool consistent() const { return disagreements.empty(); }
};

/// Throws InputError for invalid problems/options or n above the enumeration's size limit.
CrossVerifyReport cross_verify(const LcpProblem& problem, const CrossVerifyOptions& options = {});
/// The same against the solvers of `registry` (tests, or a subset of solvers).
CrossVerifyReport cross_verify(const LcpProblem& problem, const CrossVerifyOptions& options,
                               const SolverRegistry& registry);

}  // namespace cpkit::lcp
