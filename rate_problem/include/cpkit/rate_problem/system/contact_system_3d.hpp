#pragma once
/// \file contact_system_3d.hpp
/// The system file with three-dimensional points ("dim": 3; docs/file_formats.md, "System
/// file"): A is 3N x 3N on the DOFs interleaved per point (T_X1, T_Y1, N_1, T_X2, ...), and
/// every point has, besides mu, C_T, k_a, P_s, the half-axes "alpha": [alpha_X, alpha_Y] of its
/// friction ellipse (39) (default [1, 1]) and its state: "state" a|b|c|d with "P_N" (c, d) and
/// "P_T": [P_TX, P_TY] (c: default [0, 0]; d: required, on the ellipse ||P_T|| = mu P_N).
/// Load rates "dF" are 3N-vectors in the same order. Only the Coulomb criterion (38).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/model/parameters_3d.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// One 3-D contact point of a system: its interface parameters (mu, C_T, k_a, P_s), the
/// half-axes of its friction ellipse and its state.
struct SystemPoint3d : InterfaceParameters {
  Eigen::Vector2d alpha{1, 1};
  ContactState3d state;
};

struct ContactSystem3d {
  std::string name;
  Eigen::MatrixXd A;                  ///< 3N x 3N, SPD
  std::vector<SystemPoint3d> points;  ///< N points
  std::optional<Eigen::VectorXd> dF;  ///< load rate (3N), optional
  int n_points() const noexcept { return static_cast<int>(points.size()); }
  /// Point i alone: its diagonal 3x3 block of A and its interface data.
  ContactParameters3d point_parameters(int i) const;
};

/// Reads a "dim": 3 system file (read once: system_file.hpp tells its dimension). Throws
/// cpkit::InputError naming the field and point for every inconsistency (unknown keys, sizes, A
/// not symmetric to 1e-10 relative / not positive definite / numerically singular, NaN, a state
/// d point off its ellipse, ...). A is returned exactly symmetric.
ContactSystem3d parse_contact_system_3d(const std::string& json_text,
                                        const std::string& source = "system");
ContactSystem3d read_contact_system_3d(const std::string& path);
/// The 3-D system of a file already read (rate::read_system_file; its dim must be 3).
ContactSystem3d parse_contact_system_3d(const rate::SystemFile& file);

}  // namespace cpkit::rate
