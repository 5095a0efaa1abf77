#pragma once
/// \file friction_problem.hpp
/// Three-dimensional frictional contact problems as other contact codes export them (FCLIB,
/// Siconos' FrictionContact / GlobalFrictionContact files) [Acary, Bremond, Huber, INRIA RR-9118,
/// 2018]. docs/friction_contact.md derives the conditions and the verdicts.
///
/// Sign and ordering conventions (those of FCLIB and Siconos): contact i owns rows 3i..3i+2,
/// normal component first, then the two tangential ones, in the contact's local frame. Units are
/// the exporting code's: r is an impulse or a force, u a velocity or a displacement, W = u per r.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <string>

namespace cpkit {

/// Local problem, n_c contacts (De Saxce's form):
///   u = W r + q,   r_i in K_{mu_i},   u_hat_i = u_i + (mu_i ||u_{T,i}||, 0, 0) in K*_{mu_i},
///   r_i . u_hat_i = 0,   with K_mu = {(r_N, r_T) : ||r_T|| <= mu r_N}, K*_mu = K_{1/mu}.
/// W is square (3 n_c), symmetric positive semidefinite and often rank-deficient (rigid
/// bodies); symmetry is not enforced by validate() (a reader may check it to rounding).
struct FrictionContactProblem {
  Eigen::SparseMatrix<double> W;  ///< Delassus operator, 3 n_c x 3 n_c (column-major)
  Eigen::VectorXd q;              ///< free velocity, 3 n_c
  Eigen::VectorXd mu;             ///< friction coefficient per contact, n_c, each >= 0
  std::string name;               ///< label (file stem, or the file's "info" text)
  std::string note;               ///< optional free text from the file

  Eigen::Index contacts() const noexcept { return mu.size(); }
  /// Empty when usable; otherwise a message naming what is wrong (sizes, non-finite entries,
  /// negative or non-finite mu).
  std::string validate() const;
};

/// Global problem, n_c contacts, m degrees of freedom:
///   M v = H r + f,   u = H^T v + w,   and the local conditions above on (r, u).
/// M is m x m (symmetric positive semidefinite), H is m x 3 n_c.
struct GlobalFrictionContactProblem {
  Eigen::SparseMatrix<double> M;  ///< m x m
  Eigen::SparseMatrix<double> H;  ///< m x 3 n_c
  Eigen::VectorXd f;              ///< m
  Eigen::VectorXd w;              ///< 3 n_c
  Eigen::VectorXd mu;             ///< n_c, each >= 0
  std::string name;
  std::string note;

  Eigen::Index contacts() const noexcept { return mu.size(); }
  Eigen::Index dofs() const noexcept { return f.size(); }
  std::string validate() const;
};

}  // namespace cpkit
