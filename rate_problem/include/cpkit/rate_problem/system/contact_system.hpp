#pragma once
/// \file contact_system.hpp
/// N contact points in 2-D coupled through a condensed stiffness (docs/model.md, "N contact
/// points"): what a finite-element code hands over after condensing onto the contact DOFs.
///
/// Conventions (the one-point conventions of docs/contact_model.md, point by point):
/// - DOFs are interleaved per point: (T_1, N_1, T_2, N_2, ...); A is the 2N x 2N symmetric
///   positive definite stiffness on them, its diagonal 2x2 block of point i is that point's
///   [[a11, a12], [a12, a22]]. Equilibrium: F - P = A w.
/// - P_N >= 0 is compressive, g = w_N - w^w <= 0 is "not penetrating" (0: in contact).
/// - Load vectors (dF, patterns e1, e2, increments DF) are 2N-vectors in the same order.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// One contact point of a system: its interface parameters (mu, C_T, k_a, P_s) and its
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

/// The N-point system (read from the JSON system file, docs/file_formats.md).
struct ContactSystem {
  std::string name;
  Eigen::MatrixXd A;                ///< 2N x 2N, SPD, interleaved (T_1, N_1, T_2, N_2, ...)
  std::vector<SystemPoint> points;  ///< N points
  Criterion criterion = Criterion::kCoulomb;
  std::optional<Eigen::VectorXd> dF;              ///< load rate (2N), optional
  std::optional<Eigen::VectorXd> pattern1, pattern2;  ///< e1, e2 for direction maps (2N each)

  int n_points() const noexcept { return static_cast<int>(points.size()); }
  /// The one-point parameters of point i (its diagonal 2x2 block of A and its interface data).
  ContactParameters point_parameters(int i) const;
  /// Empty when usable; else one line naming the field and the point (1-based, as in the
  /// file): sizes, A not symmetric / not positive definite, NaN/Inf, mu <= 0, state b with
  /// P_N != 0, state d with |P_T| != mu P_N, ...
  std::string validate() const;
};

/// Reads a system file (JSON, read once: system_file.hpp). Throws cpkit::InputError naming the
/// field and point for every inconsistency, unknown keys and a "dim": 3 file included.
ContactSystem read_contact_system(const std::string& path);
ContactSystem parse_contact_system(const std::string& json_text, const std::string& source = "system");
/// The 2-D system of a file already read (read_system_file; its dim must be 2).
ContactSystem parse_contact_system(const SystemFile& file);

}  // namespace cpkit::rate
