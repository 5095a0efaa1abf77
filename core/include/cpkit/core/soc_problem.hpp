#pragma once
/// \file soc_problem.hpp
/// Second-order-cone complementarity problems (SOCCP) and their unit-free verdict.
///
/// Find z with w = M z + q and, block by block,
///   z_b in K_b,   w_b in K_b,   z_b . w_b = 0,
/// where a block of size 1 is the half-line {v >= 0} (an LCP row) and a block of size 3 is the
/// Lorentz cone K = {(v0, v1, v2) : v0 >= ||(v1, v2)||_2} (self-dual). Blocks partition the rows
/// in order. Units: z and w have their own units; M maps z-units to w-units (as an LCP).
///
/// Verdict (the friction verdict of friction_verdict.hpp with mu = 1 and no De Saxce term):
///   z_ref = ||q||_inf / ||M||_max,  Z = max(||z||_inf, z_ref)          the unit of z
///   c_k = ||M_k,:||_1 min(||z||_inf, z_ref),  S_b = ||q_b||_2 + max_{k in b} c_k  unit of w_b
///   a_k = gamma_{n+1} ((|M| |z|)_k + |q_k|)                          rounding of forming w_k
///   r_b = max(0, ||zn_b - P_K(zn_b - wn_b)||_2 - ||a_b||_2 / S_b),  zn = z / Z, wn_b = w_b / S_b
///   natural = max_b r_b  (+inf when anything is NaN/Inf).
/// Invariant under q -> a q (z -> a z) and (M, q) -> b (M, q) (z unchanged), a, b > 0.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit {

struct SocProblem {
  Eigen::MatrixXd M;        ///< n x n, dense (w-units per z-unit)
  Eigen::VectorXd q;        ///< n (w-units)
  std::vector<int> blocks;  ///< block sizes, each 1 (half-line) or 3 (Lorentz cone); sum = n
  std::string name;         ///< label

  Eigen::Index size() const noexcept { return q.size(); }
  /// Empty when usable; otherwise names what is wrong (sizes, block sizes, non-finite entries).
  std::string validate() const;
};

/// The natural map z - P_K(z - w) of one block (size 1 or 3), in the block's own variables.
Eigen::Vector3d soc_natural_map(const Eigen::Vector3d& z, const Eigen::Vector3d& w, int size);

/// The verdict's numbers for z with w = M z + q given (a solver's own w; finalize() recomputes
/// it). natural = the unit-free number above; natural_abs = max_b ||natural map||_2 (units of z);
/// complementarity = max_b |z_b . w_b|; min_z / min_w = smallest first entry of a block;
/// worst_index = first row of the worst block; scale = max_b S_b; z_scale = Z.
Residuals soc_residuals(const SocProblem& problem, const Eigen::VectorXd& z,
                        const Eigen::VectorXd& w);

/// The decision, as the LCP finalize() (finalize.hpp): w = M z + q recomputed; kSolved when
/// natural <= tol, kSolvedInaccurate up to tol_acceptable, whatever was claimed; a refuted claim
/// (or a z of wrong size / non-finite) becomes kNumericalFailure; kInfeasible is never granted
/// (no certificate format for cones). Throws InputError when the problem is invalid.
SolveResult finalize(const SocProblem& problem, SolveResult claim, const CommonOptions& options);

}  // namespace cpkit
