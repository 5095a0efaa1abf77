#pragma once
/// \file global.hpp
/// Global 3-D frictional contact problems (friction_problem.hpp):
///   M v = H r + f,   u = H^T v + w,   local cone conditions on (r, u),
/// solved by condensation where M can be factorized [Acary, Bremond, Huber, INRIA RR-9118]:
///   W = H^T M^-1 H,   q = H^T M^-1 f + w   (sparse LDL^T of M, solves, never an inverse),
/// the local problem solved by a registered friction solver, then v = M^-1 (H r + f).
/// Units are the file's: v is M's unknown (a velocity), r an impulse, W = u per r.
///
/// The verdict is in the GLOBAL variables and unit-free:
///   balance = max_k |M v - H r - f|_k / ((|M| |v|)_k + (|H| |r|)_k + |f_k|)   (0/0 = 0),
///             invariant under f -> a f (r, v -> a r, a v) and M -> b M (v -> v / b);
///   local   = the unit-free number of friction_verdict.hpp for r with u = H^T v + w, in the
///             GLOBAL data's units: u = w + H^T M^-1 (H r + f), so row k of u has the unit
///             s_k = |w_k| + (|H^T| v_size)_k, v_size_j = (|f_j| + (|H| rc)_j) / M_jj (the size
///             the balance's terms give v_j on a degree of freedom with mass; rc = |r| capped
///             entry by entry at the condensed problem's cap_i), so that a W = H^T M^-1 H inflated
///             by a rounded rigid mode of M (entries ~1e16) excuses nothing; r_i in
///             max(||r_i||, S_i / d_i), d_i the condensed W's block; invariant under the same
///             scalings;
///   kSolved when both are <= tol, kSolvedInaccurate when both are <= tol_acceptable.
/// A singular (or not positive definite, or not symmetric) M is said in the message and the
/// status is kNotRun; a singular symmetric M is solved in the global variables by
/// solve_global_proximal (below), which `cpkit fc solve` calls then.
#include <string>

#include <Eigen/Core>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// What M is, as condensation found it: condensable only when symmetric positive definite to
/// rounding. A caller picks its route by this value (a singular M: the proximal point in v).
enum class MassMatrix { kPositiveDefinite, kZero, kNotSymmetric, kSingular, kIndefinite };

/// The condensed local problem; `ok` is false (`mass` says what M is, `message` says it in
/// words) when M is not symmetric positive definite to rounding.
struct CondensedProblem {
  FrictionContactProblem local;
  bool ok = false;
  MassMatrix mass = MassMatrix::kPositiveDefinite;
  std::string message;
};

/// Throws InputError when the global problem is invalid (validate()).
CondensedProblem condense(const GlobalFrictionContactProblem& problem);

/// The two unit-free numbers of the verdict (file comment).
struct GlobalErrors {
  double balance = 0;
  double local = 0;
};

/// Verdict numbers of (v, r); u = H^T v + w. Throws InputError on wrong sizes.
GlobalErrors global_errors(const GlobalFrictionContactProblem& problem,
                           const FrictionContactProblem& condensed, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& r);

struct GlobalSolveResult {
  SolveResult result;  ///< z = r (3 n_c), w = u = H^T v + w; status: the global verdict
  Eigen::VectorXd v;   ///< m (empty when M could not be factorized)
  GlobalErrors errors;
  CondensedProblem condensed;  ///< the local problem solved (its errors are the local ones)
};

/// Condenses, solves the local problem with the registry's friction solver `solver` (e.g.
/// "auto"), recovers v and decides in the global variables. Throws InputError for an invalid
/// problem, options or an unknown solver name.
GlobalSolveResult solve_global(const GlobalFrictionContactProblem& problem,
                               const std::string& solver, const CommonOptions& options = {});

/// A solver in the global variables for a symmetric M that cannot be condensed (singular:
/// degrees of freedom without mass), opt-in (solve_global still says kNotRun there). Proximal
/// point in v [Rockafellar 1976]: (v_{k+1}, r_{k+1}) solves the global problem with
///   M + rho I   and   f + rho v_k,
/// whose M + rho I is positive definite and is condensed and solved by solve_global(); a fixed
/// point v_{k+1} = v_k is a solution of the original problem, since then M v = H r + f.
/// rho_0 = rho_factor * max_i |M_ii| (M's units, so the iterates scale with the problem), then
/// rho_{k+1} = max(rho_k / 10, 1e-6 max_i |M_ii|) (a geometric fall as prox's alpha: 6 outer
/// iterations instead of 48 at a fixed rho on tests/lcp/test_friction_global.cpp's case). Stops
/// when the verdict passes: balance of the ORIGINAL M v = H r + f (global.hpp's unit-free number)
/// and the local number of r with u = H^T v + w, in the units of the last regularized
/// condensed problem (H^T (M + rho I)^-1 H and its q), both <= tol; kStalled when the larger
/// of the two has not halved in 20 outer iterations (a problem without solution: v grows and
/// each regularized problem gets harder). options.max_iterations bounds the outer iterations
/// (0: 200). result.iterations = outer iterations; `condensed` is
/// the last regularized problem. kNotRun when M is not symmetric or is zero (no scale for rho);
/// InputError as solve_global.
GlobalSolveResult solve_global_proximal(const GlobalFrictionContactProblem& problem,
                                        const std::string& solver,
                                        const CommonOptions& options = {},
                                        double rho_factor = 1.0);

}  // namespace cpkit::lcp::friction
