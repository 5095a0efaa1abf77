#pragma once
/// \file cone_complementarity_fb.hpp
/// Semismooth Newton on the Fischer-Burmeister reformulation of a second-order-cone
/// complementarity problem (soc_problem.hpp), registered as "fb-soc" for ProblemKind::kSoc
/// (the same entry solves friction problems, friction/fb_soc.hpp)
/// [Fukushima, Luo, Tseng 2001; Chen, Tseng 2005].
///
/// Per block b, with w = M z + q: Phi_b = fb(z_b, w_b) (scalar FB) for a half-line, and
/// Phi_b = z_b + w_b - sqrt(z_b o z_b + w_b o w_b) (Jordan product o) for a Lorentz cone; the
/// kernels and their Jacobian elements are cpkit's one implementation
/// (cpkit/lcp/detail/fischer_burmeister.hpp). J = A + B M with A, B block diagonal. The loop is
/// damped_newton() (damped_newton.hpp): Armijo on |Phi|^2 / 2 with a gradient fallback.
///
/// Units: the problem is first scaled by powers of two (exactly) so that ||q||_inf and
/// ||M||_max are in [1, 2): the iterates do not depend on the problem's units. Stopping: the
/// verdict's unit-free residual (soc_residuals) <= common.tol. Every result comes from
/// finalize(const SocProblem&, ...). Defaults: common.max_iterations = 0 means 100.
/// Deterministic. Dense M (the size of the 3-D step systems: up to a few hundred rows).
#include <Eigen/Core>

#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/soc_problem.hpp"

namespace cpkit::lcp {

struct SocFbOptions {
  CommonOptions common;
  /// Start z (size n, finite); empty: z = 0.
  Eigen::VectorXd z0;
};

/// Solves the problem; throws InputError when it (or z0, or the options) is invalid.
SolveResult solve_soc_fb(const SocProblem& problem, const SocFbOptions& options = {});

/// Adds the cone entry point to a registry entry (the "fb-soc" friction entry).
SolverEntry with_soc_fb(SolverEntry entry);

}  // namespace cpkit::lcp
