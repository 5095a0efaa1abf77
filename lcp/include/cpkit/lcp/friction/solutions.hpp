#pragma once
/// \file solutions.hpp
/// Several solutions of a local 3-D frictional contact problem (friction_problem.hpp): real
/// rigid-body problems are not unique, and users want to know.
///
/// Two routes (the message of the set says which ran and what "complete" means for it):
/// - Small problems (n_c <= max_enumeration_contacts): every solution of the FACETED problem
///   (the cone K_mu replaced by an inscribed pyramid, faceted.hpp) by complete enumeration of
///   its LCP (enumerate.hpp); each is then polished on the true cone and kept when the true
///   verdict (finalize) accepts it. Completeness of the faceted enumeration is NOT completeness
///   for the true problem (a solution of the true cone need not be near a faceted one, and two
///   faceted solutions may polish to the same true one), so `complete` is false on this route
///   too unless every contact's solution is proved unique by other means (not attempted yet);
///   the message reports the faceted count and whether that enumeration was complete.
/// - Larger problems: multistart (seeded, deterministic) with the registered friction solvers
///   and proximal point runs from seeded starts in the cones; complete = false always.
/// Distinct: two verified r are the same solution when
///   ||r_a - r_b||_inf <= 1e-6 max(||r_a||_inf, ||r_b||_inf, r_ref),  r_ref = ||q||_inf/||W||_max
/// (unit-free: unchanged when q is scaled, or W and q together). Only finalize() verdicts of
/// kSolved are listed (tol of `common`), each a full SolveResult (z = r, w = u).
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

struct FrictionSolutionSet {
  std::vector<SolveResult> solutions;  ///< distinct verified solutions, in the order found
  bool complete = false;               ///< true only when proved: every solution is listed
  std::string message;                 ///< the route, counts, and what complete means here
};

struct FrictionSolutionsOptions {
  CommonOptions common;  ///< tol for the verdict; time_limit_s for the whole search
  int starts = 20;       ///< seeded starts of the multistart route
  unsigned seed = 1;
  int max_enumeration_contacts = 5;  ///< enumeration of the faceted problem up to this n_c
  /// Empty when usable; otherwise names the bad field.
  std::string validate() const;
};

/// Throws InputError on an invalid problem or options.
FrictionSolutionSet friction_solutions(const FrictionContactProblem& problem,
                                       const FrictionSolutionsOptions& options);

}  // namespace cpkit::lcp::friction
