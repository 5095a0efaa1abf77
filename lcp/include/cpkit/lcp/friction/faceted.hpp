#pragma once
/// \file faceted.hpp
/// The faceted (polyhedral) approximation of a local 3-D frictional contact problem
/// (friction_problem.hpp) as an LCP, and Lemke's method on it ("lemke" for friction problems).
///
/// Faceting [Stewart, Trinkle 1996; Anitescu, Potra 1997]: contact i's disc of tangential
/// forces {|r_T| <= mu r_N} is replaced by the inscribed regular k-gon with vertices
/// mu r_N d_j, d_j = (cos 2 pi j/k, sin 2 pi j/k), j = 0..k-1. Unknowns per contact, in this
/// order: r_N, beta_1..beta_k (r_T = sum_j beta_j d_j), lambda (a slip speed); with
/// r = G z (G: 3 n_c x n_c (k+2)) the LCP is
///   w = M z + G^T q,  M = G^T W G + C,  0 <= z _|_ w >= 0, where per contact
///   w_{r_N}    = u_N                       (Signorini)
///   w_{beta_j} = d_j . u_T + lambda        (lambda >= the slip speed along every -d_j)
///   w_lambda   = mu r_N - sum_j beta_j     (r_T inside the k-gon scaled by mu r_N)
/// (C holds the 1's, mu's and -1's of the last two rows). M is copositive when W is PSD
/// (z^T M z = (Gz)^T W (Gz) + mu r_N lambda >= 0 for z >= 0).
/// Facet error: the k-gon's inradius is cos(pi/k) times the disc's radius, so the faceted
/// cone K_k satisfies K_{mu cos(pi/k)} subset K_k subset K_mu; faceting changes the friction
/// law by at most the relative amount 1 - cos(pi/k) (7.6 % for k = 8, 1.9 % for k = 16).
/// A faceted solution is therefore a CANDIDATE for the true problem: stick and separation
/// solutions inside K_k are exact, slip ones are off by up to the facet error.
///
/// Stick contacts make the LCP's solution set a polytope of beta's for one r (k - 2
/// dimensions): several LCP solutions may give the same r (solutions.hpp deduplicates in r).
#include <Eigen/Core>
#include <string>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// Largest number of contacts the faceted Lemke accepts (dense LCP of n_c (k + 2) unknowns;
/// larger problems: Status::kUnsupported with a message).
inline constexpr Eigen::Index kFacetedMaxContacts = 100;

struct FacetedLcp {
  LcpProblem lcp;          ///< dense, n_c (k + 2) unknowns
  Eigen::MatrixXd G;       ///< r = G z
  int facets = 0;          ///< k
  double facet_error = 0;  ///< 1 - cos(pi / k)
};

/// Builds the LCP of the file comment (k >= 3). Throws InputError on an invalid problem or k.
FacetedLcp faceted_lcp(const FrictionContactProblem& problem, int facets);

struct FacetedLemkeOptions {
  CommonOptions common;  ///< tol: the verdict on the TRUE problem; max_iterations: Lemke's pivots
  int facets = 8;        ///< k >= 3
  /// Polish the faceted answer on the true cone (polish_on_true_cone()) when the verdict does
  /// not accept it as it is
  /// started from it, and return the polished r when the verdict accepts it.
  bool polish = true;
  Eigen::VectorXd covering;  ///< Lemke's covering vector (empty: all ones), n_c (k + 2)
  /// Empty when usable; otherwise names the bad field.
  std::string validate() const;
};

/// Lemke's method on the faceted LCP; the result (z = r, w = u) is judged by
/// finalize(FrictionContactProblem) on the TRUE cone. The message says that the answer is the
/// faceted one (or its polished version) and gives the facet error and both true-cone errors.
/// Problems with more than kFacetedMaxContacts contacts: kUnsupported. Throws InputError on
/// an invalid problem or options.
SolveResult solve_faceted_lemke(const FrictionContactProblem& problem,
                                const FacetedLemkeOptions& options = {});

/// The solution of the TRUE problem near a candidate r0 (a faceted answer): prox from r0 with
/// Gauss-Seidel inner solves and sigma = 1e-3 (small proximal weights and nearest one-contact
/// solutions keep each step near the previous iterate; at most 40 x 50 sweeps), then, when
/// that is not verified, fb-soc from r0. Returns the first kSolved result, else the one with
/// the smaller residual; solver = "polish".
SolveResult polish_on_true_cone(const FrictionContactProblem& problem, const Eigen::VectorXd& r0,
                                const CommonOptions& options);

/// `entry` (the LCP "lemke" entry) with solve_fc set to solve_faceted_lemke (default options,
/// polished): "lemke" then accepts friction problems too.
SolverEntry with_faceted_lemke(SolverEntry entry);

}  // namespace cpkit::lcp::friction

namespace cpkit::lcp::friction {

/// Every solution of the faceted problem, by complete enumeration of its LCP (enumerate.hpp),
/// as distinct r. `regularisation` (>= 0, relative to W's size: the largest |W_kk|) is added to
/// the diagonal of the LCP's r_N and beta rows: with it a stick contact's facet weights are
/// unique (without it they form a (k - 2)-dimensional polytope for ONE r, which the
/// enumeration has to walk). The list then belongs to the regularised faceted problem (its
/// solutions move by O(regularisation) relative to the faceted ones). Enumeration costs up to
/// 2^(n_c (k + 2)) bases: only small problems finish (measured: 2 contacts, k = 4: ms; the
/// 4-contact rigid box of the tests, k = 4: ~60 s; k = 8 does not finish for 4 contacts).
/// friction_solutions() uses k = 4 up to 3 contacts, k = 3 beyond, and at most 5 s.
struct FacetedSolutionList {
  FacetedLcp faceted;              ///< the (regularised) LCP enumerated
  std::vector<Eigen::VectorXd> r;  ///< its solutions in r = G z, distinct (unit-free, 1e-6)
  int extreme = 0;                 ///< extreme LCP solutions (several may share one r)
  bool complete = false;           ///< the LCP enumeration was complete (faceted problem only)
  bool infinite = false;           ///< the LCP's set has pieces of positive dimension
  std::string message;             ///< the enumeration's account when not complete
};

/// Throws InputError on an invalid problem, facets outside [3, 64], n_c (k + 2) > 64 or a
/// negative regularisation.
FacetedSolutionList faceted_solutions(const FrictionContactProblem& problem, int facets,
                                      double regularisation, double time_limit_s);

}  // namespace cpkit::lcp::friction
