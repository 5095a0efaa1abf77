#pragma once
/// \file friction_verdict.hpp
/// The verdict on a candidate r of a 3-D frictional contact problem (friction_problem.hpp):
/// one unit-free acceptance number, and the two published normalisations for comparison.
/// docs/friction_contact.md derives it; docs/conventions.md ("What within tolerance means")
/// gives the LCP rule it extends.
///
/// For a candidate r (u = W r + q recomputed from the data), with n = 3 n_c rows, contact i
/// owning rows 3i..3i+2 (normal first) and d_i the largest |W| entry of contact i's diagonal block:
///   r_ref   = ||q||_inf / ||W||_max          the data's own size of r (none when q = 0 or W = 0)
///   cap_i   = max(r_ref, ||q_i||_inf / d_i)  the largest r_i the data can explain at contact i
///   rc_j    = min(|r_j|, cap_i(j))            r entry by entry, capped at the data's size
///   c_k     = (|W| rc)_k                     what row k of W r can be at r's own size, entry by
///             entry (so that one contact's r enters only the rows it couples to) and capped
///             (so that a diverging r gains nothing)
///   s_k     = |q_k| + c_k                    the unit of the row u_k (as the LCP's s_k)
///   S_i     = ||q_i||_2 + max_{k in i} c_k   the unit of contact i's velocity u_i (one unit for
///             the normal and the tangential rows: the cone mixes them)
///   R_i     = max(||r_i||_inf, S_i / d_i)    the unit of contact i's r_i: its own size, or the
///             size the data give it; never another contact's
///   a_k     = gamma_{m_k+1} (c_k + |q_k|)    what rounding may excuse in u_k: the worst-case
///             error of forming u_k in double precision (m_k stored entries in row k) [Higham
///             2002, Sec. 3.1] at the data's size of r. It never grows with |r|: where |r|
///             exceeds the cap in row k, u_k is formed in twice the working precision (Dot2,
///             [Ogita, Rump, Oishi 2005]), whose own error (2 u |u_k| + gamma^2 (|W||r| + |q|)_k)
///             is added; an r so large that even that exceeds the data's allowance (|r| beyond
///             1/eps of the cap) cannot be verified: that contact's number is +inf.
///   u'_k    = u_k moved towards 0 by a_k     (|u_k| <= a_k counts as zero)
///   cone_i   = ||rn - P_K(rn - un_hat)||_2, rn = r_i / R_i, un = u'_i / S_i: the natural map in
///              unit-free variables. Nothing is subtracted from it: it is never smaller than
///              the distance of rn to the cone, so an r outside K_mu is never excused, and no
///              friction coefficient, however large, multiplies an allowance;
///   normal_i = |min(max(1, mu) r_N / R_i, u'_N / s_N)|: Signorini's 0 <= r_N _|_ u_N >= 0
///              (r_N read by the friction force it allows, so that at a huge mu a tiny r_N
///              carrying a large r_T is a contact, whose u_N must be 0), which every
///              solution satisfies (stick and slip have u_N = 0), judged in the normal row's
///              own units as the LCP rule does;
///   coulomb_i = max(0, ||r_T|| - mu r_N) / R_i: Coulomb's bound read in r_T's units (the
///              distance to the cone is ~||r_T|| / mu for a huge mu and would excuse a friction
///              force without normal force);
///   unit_free = max_i max(cone_i, normal_i, coulomb_i)  (+inf when anything is NaN/Inf).
/// Invariant under q -> a q (r -> a r) and (W, q) -> b (W, q) (r unchanged), for all a, b > 0
/// (exactly for powers of two, to rounding otherwise).
/// - r = 0 is never accepted when some q_N < 0: at r = 0, s_N = |q_N| and normal_i = 1, however
///   small q_N is next to q_T or next to other contacts.
/// - A diverging r is never accepted: the units of u and the allowance stop growing at the
///   data's size, and u itself is formed accurately enough to show its violation.
/// - One contact's size excuses nothing in another: units are per contact and per row, and a
///   row's unit sees only the r entries the row couples to.
/// - Rank-deficient and zero W are normal (r_ref then comes from the nonzero entries).
/// What it does not promise: a small unit_free says r solves a problem within tol of the data
/// (in these units), not that r is near every solution, nor that no other solution exists.
#include <Eigen/Core>
#include <vector>

#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_errors.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit {

/// Errors of r (size 3 n_c). Throws InputError when the problem is invalid (validate()) or r
/// has the wrong size; a non-finite r gives unit_free = +inf (and NaN relative errors).
FrictionErrors friction_errors(const FrictionContactProblem& problem, const Eigen::VectorXd& r);

/// The data-only part of the units (||q||_inf, ||W||_max, W's row sums and counts, each
/// contact's block size d_i and cap_i), computed once per problem so that solvers can test every
/// iterate cheaply. O(n_c) memory: the verdict reads W itself, by columns (no copy of W).
struct FrictionUnits {
  double q_inf = 0;
  double w_max = 0;
  Eigen::VectorXd row_sums;                             ///< ||W_k,:||_1
  Eigen::VectorXd row_gamma;                            ///< gamma_{m_k + 1}
  Eigen::VectorXd block_max;                            ///< d_i (w_max where the block is 0)
  Eigen::VectorXd r_cap;                                ///< cap_i (+inf when there is no r_ref)
};
FrictionUnits friction_units(const FrictionContactProblem& problem);

/// friction_errors() with units = friction_units(problem) already computed by the caller (a
/// solver that judges many answers of one problem computes them once).
FrictionErrors friction_errors(const FrictionContactProblem& problem, const FrictionUnits& units,
                               const Eigen::VectorXd& r);

/// One contact of a candidate: its state and its share of unit_free (max(cone_i, normal_i) of
/// the header comment). The state is read in the unit-free variables, after the rounding
/// allowance, and decided against a bound `tol` (the tolerance the answer was accepted with), so
/// that a velocity or a force within that bound counts as zero:
///   separated  r_N / R_i <= tol               (no normal force within the bound);
///   stick      otherwise, when ||u'_T|| / S_i <= tol  (no sliding within the bound; this
///              includes a stick at the cone's edge);
///   slip       otherwise (r_T on the cone's edge, u_T opposite to it).
enum class ContactState { kSeparated, kStick, kSlip };
const char* to_string(ContactState s) noexcept;  ///< "separated", "stick", "slip"
struct ContactReport {
  ContactState state = ContactState::kSeparated;
  double error = 0;
};

/// One contact's units (header comment): R_i of r_i, S_i of u_i, s_N of its normal row.
struct ContactUnits3 {
  double R = 0, S = 0, s_N = 0;
};
/// The verdict of one contact from its units, for callers that form u_i and its units
/// themselves (global problems, u = H^T v + w: lcp/friction/global.hpp). `u_reduced` is u_i
/// already moved towards 0 by its rounding allowance. error = max(cone_i, normal_i, coulomb_i) (+inf when
/// anything is NaN/Inf); the state as friction_contacts() decides it.
ContactReport judge_contact(const Vec3& r, const Vec3& u_reduced, const ContactUnits3& units,
                            double mu, double state_tol = 0);

/// Everything the verdict computes for r with u = W r + q (given, from the caller: a solver's
/// own u; finalize() recomputes it). `errors` may be nullptr. Residuals: natural = unit_free;
/// natural_abs = max_i ||natural map of contact i|| (problem units); complementarity =
/// max_i |r_i . u_hat_i|; min_z = min_i r_N,i; min_w = min_i u_N,i; worst_index = first row of
/// the worst contact; scale = max_i S_i; z_scale = max_i R_i; rounding = max_k a_k / s_k, the
/// largest allowance in its row's units. `state_tol`: the bound of ContactReport's states.
Residuals friction_residuals(const FrictionContactProblem& problem, const FrictionUnits& units,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             FrictionErrors* errors = nullptr,
                             std::vector<ContactReport>* contacts = nullptr,
                             double state_tol = 0);

/// The unit_free number of ONE contact (n_c = 1) from its dense 3 x 3 W, without building a
/// problem or allocating (the C API's per-call path): u receives W r + q, formed as finalize()
/// forms it, and the value returned is friction_residuals(...).natural of the problem whose W
/// stores stored[k] entries in row k (the entries not stored are exact zeros; stored ones may be
/// zeros too: the rounding allowance counts them). The same number bit for bit
/// (tests/core/test_friction_verdict.cpp); +inf for a non-finite r or u.
double one_contact_unit_free(const Mat3& W, const int stored[3], const Vec3& q, double mu,
                             const Vec3& r, Vec3& u);

/// Per-contact report of r (u = W r + q recomputed), states decided against `tol`; the default
/// (tol < 0) is the answer's own unit_free: a force or a sliding velocity smaller than the
/// accuracy of the answer is not told from zero (0: only the rounding allowance counts as zero).
/// Sizes checked as friction_errors().
std::vector<ContactReport> friction_contacts(const FrictionContactProblem& problem,
                                             const Eigen::VectorXd& r, double tol = -1);

/// The decision, as the LCP finalize() (finalize.hpp): claim.z holds r (3 n_c); w receives
/// u = W r + q recomputed; residuals as friction_residuals(); kSolved when unit_free <= tol,
/// kSolvedInaccurate up to tol_acceptable, whatever was claimed; a claimed solution the data
/// refute (or a z of wrong size / non-finite) becomes kNumericalFailure with a message;
/// kInfeasible is never granted (no certificate format for friction problems yet). Throws
/// InputError when the problem is invalid.
SolveResult finalize(const FrictionContactProblem& problem, SolveResult claim,
                     const CommonOptions& options);
/// The same with units = friction_units(problem) already computed by the caller: the same
/// checks and decision, without building the units again (a small problem's solve spent a
/// tenth of its time there).
SolveResult finalize(const FrictionContactProblem& problem, const FrictionUnits& units,
                     SolveResult claim, const CommonOptions& options);

}  // namespace cpkit
