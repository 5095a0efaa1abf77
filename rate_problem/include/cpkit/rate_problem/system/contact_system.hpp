#pragma once
/// \file contact_system.hpp
/// N contact points coupled through a condensed stiffness (docs/model.md, "N contact points";
/// docs/contact_3d.md, "N points"): what a finite-element code hands over after condensing onto
/// the contact DOFs, in 2-D or 3-D. One type, ContactSystemOf<Dim>, with the dimension as a
/// parameter; ContactSystem (2-D) and ContactSystem3d are its two instances.
///
/// Conventions (the one-point conventions of docs/contact_model.md, point by point):
/// - DOFs are interleaved per point: 2-D (T_1, N_1, T_2, N_2, ...), 3-D (T_X1, T_Y1, N_1, T_X2,
///   ...); A is the Dim N x Dim N symmetric positive definite stiffness on them, its diagonal
///   Dim x Dim block of point i is that point's own stiffness. Equilibrium: F - P = A w.
/// - P_N >= 0 is compressive, g = w_N - w^w <= 0 is "not penetrating" (0: in contact).
/// - Load vectors (dF, patterns e1, e2, increments DF) are Dim N-vectors in the same order.
/// - 3-D points have, besides the interface data, the half-axes alpha = [alpha_X, alpha_Y] of
///   their friction ellipse (39) (default [1, 1]) and a state a|b|c|d with P_N (c, d) and
///   P_T = [P_TX, P_TY] (c: default [0, 0]; d: required, on the ellipse ||P_T|| = mu P_N); only
///   the Coulomb criterion (38), and no load patterns.
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/interface_parameters.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/parameters_3d.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// One 2-D contact point of a system: its interface parameters (mu, C_T, k_a, P_s) and its
/// current state.
struct SystemPoint : InterfaceParameters {
  /// The state as the rate problem needs it (label, P_N for c/d, sgn P_T for d). When the file
  /// gives the current values instead, it is classified from them.
  ContactState state;
  /// Current values (steps and simulations need them): P_T, P_N and the gap function
  /// g = w_N - w^w <= 0. From the file when given; else P_T = sgn P_T mu P_N in d, 0 in a/b,
  /// P_N = state.P_N, g = 0 (a: g must be given, < 0).
  double P_T = 0, P_N = 0, g = 0;
  bool values_given = false;  ///< the file gave P_T, P_N, g (not a state label)
};

/// One 3-D contact point of a system: its interface parameters (mu, C_T, k_a, P_s), the
/// half-axes of its friction ellipse and its state.
struct SystemPoint3d : InterfaceParameters {
  Eigen::Vector2d alpha{1, 1};
  ContactState3d state;
};

/// A point of a system, and the parameters of one point alone, in dimension Dim (2 or 3).
template <int Dim>
using SystemPointOf = std::conditional_t<Dim == 2, SystemPoint, SystemPoint3d>;
template <int Dim>
using PointParametersOf = std::conditional_t<Dim == 2, ContactParameters, ContactParameters3d>;

/// The N-point system in dimension Dim (read from the JSON system file, docs/file_formats.md).
template <int Dim>
struct ContactSystemOf {
  static_assert(Dim == 2 || Dim == 3, "a contact system is 2-D or 3-D");
  static constexpr int kDim = Dim;

  std::string name;
  Eigen::MatrixXd A;                       ///< Dim N x Dim N, SPD, interleaved per point
  std::vector<SystemPointOf<Dim>> points;  ///< N points
  Criterion criterion = Criterion::kCoulomb;  ///< 2-D; 3-D points follow Coulomb (38) only
  std::optional<Eigen::VectorXd> dF;       ///< load rate (Dim N), optional
  std::optional<Eigen::VectorXd> pattern1, pattern2;  ///< 2-D: e1, e2 for direction maps

  int n_points() const noexcept { return static_cast<int>(points.size()); }
  /// The one-point parameters of point i: its diagonal Dim x Dim block of A and its interface
  /// data (2-D: with the system's criterion; 3-D: with its ellipse).
  PointParametersOf<Dim> point_parameters(int i) const;
  /// Empty when usable; else one line naming the field and the point (1-based, as in the
  /// file): sizes, A not symmetric / not positive definite, NaN/Inf, mu <= 0, state b with
  /// P_N != 0, state d off its friction limit, ...
  std::string validate() const;
};
using ContactSystem = ContactSystemOf<2>;
using ContactSystem3d = ContactSystemOf<3>;

/// The system of a file already read (read_system_file), of dimension Dim: one reader for both
/// dimensions, the points' fields read by the dimension's own kernel. Throws cpkit::InputError
/// "source: ..." naming the field and point for every inconsistency (unknown keys, sizes, A not
/// symmetric to 1e-10 relative / not positive definite / numerically singular, NaN, a state d
/// point off its friction limit, a file of the other dimension, ...). A is returned exactly
/// symmetric.
template <int Dim>
ContactSystemOf<Dim> parse_contact_system_of(const SystemFile& file);

/// The 2-D readers (a "dim": 3 file is refused).
ContactSystem read_contact_system(const std::string& path);
ContactSystem parse_contact_system(const std::string& json_text, const std::string& source = "system");
ContactSystem parse_contact_system(const SystemFile& file);
/// The 3-D readers (only a "dim": 3 file).
ContactSystem3d read_contact_system_3d(const std::string& path);
ContactSystem3d parse_contact_system_3d(const std::string& json_text,
                                        const std::string& source = "system");
ContactSystem3d parse_contact_system_3d(const SystemFile& file);

}  // namespace cpkit::rate
