#pragma once
/// \file parameters_3d.hpp
/// Parameters and contact state of one three-dimensional contact point: the 3-D siblings of
/// ContactParameters (parameters.hpp) and ContactState (contact_state.hpp), for the elliptic
/// friction-and-wear law of [Stromberg, Johansson & Klarbring 1996, eqns (38)-(40)]
/// (docs/contact_3d.md). Units as in 2-D: A a stiffness (force/length) on the DOFs
/// (T_X, T_Y, N), C_T a compliance (length/force), P_s a hardness, k_a and mu dimensionless,
/// alpha dimensionless half-axes of the friction ellipse; P_N >= 0 in contact.
#include <Eigen/Core>
#include <string>

#include "cpkit/rate_problem/model/interface_parameters.hpp"

namespace cpkit::rate {

/// One 3-D point alone: its interface data (mu, C_T, k_a, P_s), its stiffness block and its
/// cone, the friction ellipse with half-axes alpha (only the Coulomb criterion (38) in 3-D).
struct ContactParameters3d : InterfaceParameters {
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();  ///< stiffness on (T_X, T_Y, N), SPD
  Eigen::Vector2d alpha{1, 1};  ///< ellipse half-axes (alpha_X, alpha_Y) of (39), > 0
  /// Empty when usable; else names the field (A not symmetric or not SPD, mu <= 0, NaN, ...).
  std::string validate() const;
};

/// The contact state (Sec. 4.2 of the paper, with the elliptic cone): 'a' open, 'b' grazing
/// (P = 0, w_N = w^w), 'c' stick (||P_T|| < mu P_N), 'd' on the cone (||P_T|| = mu P_N > 0).
struct ContactState3d {
  char state = 'b';
  Eigen::Vector2d P_T{0, 0};  ///< current tangential force (c, d)
  double P_N = 0;             ///< current normal force (c, d): > 0
  /// Empty when consistent with `params` (P = 0 in a/b; the cone condition of c/d, to a
  /// relative 1e-9 in d); else names the field.
  std::string validate(const ContactParameters3d& params) const;
};

}  // namespace cpkit::rate
