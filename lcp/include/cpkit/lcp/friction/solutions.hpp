#pragma once
/// \file solutions.hpp
/// Several solutions of a local 3-D frictional contact problem (friction_problem.hpp): real
/// rigid-body problems are not unique, and users want to know.
///
/// Two routes (the message of the set says which ran and what "complete" means for it):
/// - Small problems (n_c <= max_enumeration_contacts): every solution of the FACETED problem
///   (the cone K_mu replaced by an inscribed pyramid of 4 facets up to 3 contacts, 3 facets
///   beyond, regularised: faceted.hpp, faceted_solutions()) by complete enumeration of its LCP
///   (enumerate.hpp, at most 5 s: 5 contacts usually do not finish, the message says so);
///   each is verified on the true cone as it is (stick and separation are exact) or polished
///   there by prox (sigma = 1e-3) from it, and kept when the true verdict accepts it; then the
///   multistart below runs as well. Completeness of the faceted enumeration is NOT completeness
///   for the true problem (a solution of the true cone need not be near a faceted one, and two
///   faceted solutions may polish to the same true one), so `complete` is false on this route
///   too unless every contact's solution is proved unique by other means (not attempted yet);
///   the message reports the faceted count and whether that enumeration was complete.
/// - All problems (after the enumeration when it ran): multistart (seeded, deterministic): the
///   registered friction solvers once each ("auto" excluded, "ipopt" only up to 10 contacts), then
///   NSGS, fb-soc and proximal point from each of `starts` seeded points in the cones (r_N uniform
///   in [0, 2 r_ref], r_T uniform in the disc of radius mu r_N; std::mt19937_64(seed), 53-bit
///   uniforms: the same on every platform; nsgs and fb-soc only when they solved the problem from
///   their own start); complete = false always.
/// Distinct: two verified r are the same solution when
///   ||r_a - r_b||_inf <= 1e-6 max(||r_a||_inf, ||r_b||_inf, r_ref),  r_ref = ||q||_inf/||W||_max
/// (unit-free: unchanged when q is scaled, or W and q together). Only finalize() verdicts of
/// kSolved are listed (tol of `common`), each a full SolveResult (z = r, w = u). Distinct r need
/// not be distinct solutions in the sense a user counts: `families` says which share u (a
/// rank-deficient W lets r move in a convex set at fixed u: one continuum, not several).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// Listed solutions that share u (to 1e-6 of max(||u||_inf, ||q||_inf)). For a fixed u the
/// solutions r form a convex set (W r = u - q, and each contact's law is convex in r once u_i
/// is known: r_i = 0 where u_N > 0, a ray where it slides, the cone where it sticks), so the
/// members and every convex combination of them solve the problem: a continuum, not separate
/// solutions. `basis` spans the affine hull of the members' r (orthonormal columns, rank
/// decided at 1e-6 of max(||r||_inf, r_ref)); its dimension is a lower bound of the continuum's.
struct SolutionFamily {
  std::vector<int> members;  ///< indices into FrictionSolutionSet::solutions (0-based)
  Eigen::MatrixXd basis;     ///< 3 n_c x dimension
  int dimension() const { return static_cast<int>(basis.cols()); }
};

struct FrictionSolutionSet {
  std::vector<SolveResult> solutions;  ///< distinct verified solutions, in the order found
  /// The solutions grouped by their u: one family per distinct u, in order of first member;
  /// a family of dimension >= 1 is a continuum of r.
  std::vector<SolutionFamily> families;
  bool complete = false;               ///< true only when proved: every solution is listed
  std::string message;                 ///< the route, counts, and what complete means here
};

struct FrictionSolutionsOptions {
  CommonOptions common;  ///< tol for the verdict; time_limit_s for the whole search
  int starts = 20;       ///< seeded starts of the multistart route, 1..kMaxStarts
  /// Each start runs three solvers: 10,000 starts is hours on a large problem, and more finds
  /// nothing a seed change would not (a bound, so a typo such as 2e9 is refused, not run).
  static constexpr int kMaxStarts = 10000;
  unsigned seed = 1;
  int max_enumeration_contacts = 5;  ///< enumeration of the faceted problem up to this n_c
  /// Empty when usable; otherwise names the bad field.
  std::string validate() const;
};

/// Throws InputError on an invalid problem or options.
FrictionSolutionSet friction_solutions(const FrictionContactProblem& problem,
                                       const FrictionSolutionsOptions& options);

}  // namespace cpkit::lcp::friction
