#pragma once
/// \file ipopt_fc.hpp
/// Ipopt as the fallback for local 3-D frictional contact problems (friction_problem.hpp): the
/// problem written as an MPCC on the TRUE cone and solved by cpkit's MPCC sequence (mpcc.hpp:
/// Scholtes relaxation, Ipopt, calls serialised by its process-wide mutex).
///
/// Formulation (per contact; s a slip speed, unit-free variables rho = r / R, v = u / U with
/// R = ||q||_inf / ||W||_max, U = ||q||_inf, so W/||W||_max and q/||q||_inf enter):
///   0 <= r_N          _|_  u_N >= 0                       (Signorini)
///   0 <= s            _|_  mu^2 r_N^2 - |r_T|^2 >= 0      (r in K_mu; slip only on its boundary)
///   mu r_N u_T + s r_T = 0                                (2 equalities)
/// Why this is the Coulomb law: stick (s = 0, r_N > 0) gives u_T = 0; slip gives
/// u_T = -s r_T / (mu r_N), opposite to r_T with |u_T| = s; r_N = 0 forces r_T = 0 and leaves
/// u_T free (separation). The multiplication by r_N is what keeps separation free.
/// Exact second derivatives are supplied (the constraints are quadratic in (rho, s)). The
/// result r is judged by finalize(FrictionContactProblem) on the true cone; the MPCC sequence
/// stops early as soon as an iterate passes that verdict.
/// Dense derivatives: problems above kIpoptFcMaxContacts contacts get kUnsupported.
#include <Eigen/Core>
#include <string>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// Largest number of contacts of the Ipopt fallback (dense Jacobians of 4 n_c unknowns).
inline constexpr Eigen::Index kIpoptFcMaxContacts = 100;

struct IpoptFcOptions {
  CommonOptions common;  ///< max_iterations: per NLP (0: 500)
  Eigen::VectorXd r0;    ///< start (empty: r_N = R, r_T = 0 per contact), 3 per contact
  std::string validate(Eigen::Index n) const;
};

/// Throws InputError on an invalid problem or options.
SolveResult solve_ipopt_fc(const FrictionContactProblem& problem,
                           const IpoptFcOptions& options = {});

/// `entry` (the MPCC "ipopt" entry) with solve_fc set to solve_ipopt_fc.
SolverEntry with_ipopt_fc(SolverEntry entry);

}  // namespace cpkit::lcp::friction
