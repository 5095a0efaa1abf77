#pragma once
/// \file friction_verdict.hpp
/// The verdict on a candidate r of a 3-D frictional contact problem (friction_problem.hpp):
/// one unit-free acceptance number, and the two published normalisations for comparison.
/// docs/friction_contact.md derives it; docs/conventions.md ("What within tolerance means")
/// gives the LCP rule it extends.
///
/// For a candidate r (u = W r + q recomputed from the data), with n = 3 n_c rows:
///   r_ref = ||q||_inf / ||W||_max        the data's own size of r (none when q = 0 or W = 0)
///   R     = max(||r||_inf, r_ref)        the unit of r (every contact's r_i)
///   c_k   = ||W_k,:||_1 min(||r||_inf, r_ref)   what row k of W r can be at r's own size,
///           capped at the data's size so that it never grows with a diverging r
///   s_k   = |q_k| + c_k                  the unit of the row u_k (as the LCP's s_k)
///   S_i   = ||q_i||_2 + max_{k in i} c_k  the unit of contact i's velocity u_i (one unit for
///           the normal and the tangential rows: the cone mixes them)
///   a_k   = gamma_{m_k+1} ((|W| |r|)_k + |q_k|)   the worst-case rounding error of forming u_k
///           (m_k stored entries in row k) [Higham 2002, Sec. 3.1]
///   cone_i   = ||rn - P_K(rn - un_hat)||_2 - (1 + mu_i) ||a_i||_2 / S_i  (at least 0), where
///              rn = r_i / R, un = u_i / S_i: the natural map in unit-free variables, less the
///              largest change rounding of u_i can make to it (the map is 1-Lipschitz in u_hat
///              and u -> u_hat is (1 + mu)-Lipschitz);
///   normal_i = |min(r_N / R, u_N' / s_N)|, u_N' = u_N reduced by a_N towards 0: Signorini's
///              0 <= r_N _|_ u_N >= 0, which every solution satisfies (stick and slip have
///              u_N = 0), judged in the normal row's own units as the LCP rule does;
///   unit_free = max_i max(cone_i, normal_i)  (+inf when anything is NaN/Inf).
/// Invariant under q -> a q (r -> a r) and (W, q) -> b (W, q) (r unchanged), for all a, b > 0
/// (exactly for powers of two, to rounding otherwise).
/// - r = 0 is never accepted when some q_N < 0: at r = 0, s_N = |q_N| and normal_i = 1, however
///   small q_N is next to q_T.
/// - A diverging r is never accepted: the units of u stop growing at the data's size.
/// - One contact's size excuses nothing in another: units are per contact and per row.
/// - Rank-deficient and zero W are normal (r_ref then comes from the nonzero entries).
#include <Eigen/Core>
#include <vector>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit {

/// Errors of a candidate r. The natural map per contact is r_i - P_K(r_i - u_hat_i); E is the
/// Euclidean norm of all of them together, in the problem's units.
struct FrictionErrors {
  double unit_free = 0;     ///< the acceptance number of the header comment (unit-free)
  double relative_q = 0;    ///< E / ||q||_2 [Acary, Bremond, Huber 2018] (E when ||q||_2 <= eps)
  double relative_max = 0;  ///< E / max(||q||_2, ||r||_2, ||u||_2) (E when that max <= eps)
};
// relative_max is Siconos 4.4's fc3d_compute_error(problem, r, u, tol, options, norm, &error)
// with norm = ||q||_2 (what its solvers pass): it divides E by max(norm, ||r||_2, ||u||_2) when
// that exceeds DBL_EPSILON (checked against python3-siconos). relative_q divides by ||q||_2 under
// the same guard. Both are information: they depend on the problem's units.

/// Errors of r (size 3 n_c). Throws InputError when the problem is invalid (validate()) or r
/// has the wrong size; a non-finite r gives unit_free = +inf (and NaN relative errors).
FrictionErrors friction_errors(const FrictionContactProblem& problem, const Eigen::VectorXd& r);

/// The data-only part of the units (||q||_inf, ||W||_max, |W| and its row sums and counts),
/// computed once per problem so that solvers can test every iterate cheaply.
struct FrictionUnits {
  double q_inf = 0;
  double w_max = 0;
  Eigen::SparseMatrix<double> abs_W;  ///< |W|
  Eigen::VectorXd row_sums;           ///< ||W_k,:||_1
  Eigen::VectorXd row_gamma;          ///< gamma_{m_k + 1}
};
FrictionUnits friction_units(const FrictionContactProblem& problem);

/// One contact of a candidate: its state and its share of unit_free (max(cone_i, normal_i) of
/// the header comment). The state compares the two sides of each complementarity in the
/// unit-free variables, so it needs no tolerance and does not depend on units:
///   separated  r_N / R < u_N' / s_N         (the normal impulse is the smaller side);
///   stick      otherwise, when the margin inside the cone (mu r_N - ||r_T||) / R is at least
///              ||u_T|| / S_i (the sliding velocity is the smaller side; ties are stick);
///   slip       otherwise (r_T on the cone's edge, u_T opposite to it).
enum class ContactState { kSeparated, kStick, kSlip };
const char* to_string(ContactState s) noexcept;  ///< "separated", "stick", "slip"
struct ContactReport {
  ContactState state = ContactState::kSeparated;
  double error = 0;
};

/// Everything the verdict computes for r with u = W r + q (given, from the caller: a solver's
/// own u; finalize() recomputes it). `errors` may be nullptr. Residuals: natural = unit_free;
/// natural_abs = max_i ||natural map of contact i|| (problem units); complementarity =
/// max_i |r_i . u_hat_i|; min_z = min_i r_N,i; min_w = min_i u_N,i; worst_index = first row of
/// the worst contact; scale = max_i S_i; z_scale = R; rounding = largest deducted allowance.
Residuals friction_residuals(const FrictionContactProblem& problem, const FrictionUnits& units,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             FrictionErrors* errors = nullptr,
                             std::vector<ContactReport>* contacts = nullptr);

/// Per-contact report of r (u = W r + q recomputed); sizes checked as friction_errors().
std::vector<ContactReport> friction_contacts(const FrictionContactProblem& problem,
                                             const Eigen::VectorXd& r);

/// The decision, as the LCP finalize() (finalize.hpp): claim.z holds r (3 n_c); w receives
/// u = W r + q recomputed; residuals as friction_residuals(); kSolved when unit_free <= tol,
/// kSolvedInaccurate up to tol_acceptable, whatever was claimed; a claimed solution the data
/// refute (or a z of wrong size / non-finite) becomes kNumericalFailure with a message;
/// kInfeasible is never granted (no certificate format for friction problems yet). Throws
/// InputError when the problem is invalid.
SolveResult finalize(const FrictionContactProblem& problem, SolveResult claim,
                     const CommonOptions& options);

}  // namespace cpkit
