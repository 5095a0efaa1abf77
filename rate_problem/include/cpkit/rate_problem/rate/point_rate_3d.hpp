#pragma once
/// \file point_rate_3d.hpp
/// The rate problem of one three-dimensional contact point with the elliptic friction-and-wear
/// law of [Stromberg, Johansson & Klarbring 1996, eqns (38)-(40)]: two tangential directions
/// (X, Y) and one normal N. Derivation: docs/contact_3d.md.
///
/// Units and signs as for one 2-D point (docs/model.md): A is a stiffness (force/length) on the
/// DOFs (T_X, T_Y, N), symmetric positive definite; P = (P_T, P_N) is the contact force with
/// P_N >= 0 in contact; w_N - w^w <= 0 (w_N < w^w: open); the irreversible slip dw_T^i points
/// along the normal of the friction ellipse at the traction (normality). Rates of the
/// equilibrium (47): dF - dP = A dw, dw_T = C_T dP_T + dw_T^i.
///
/// The friction norm (39) is ||p_T|| = sqrt((p_TX / alpha_X)^2 + (p_TY / alpha_Y)^2) =
/// |D^-1 p_T| with D = diag(alpha_X, alpha_Y); criterion (38): ||P_T|| <= mu P_N; wear (40):
/// dw^w = k P_N |D dw_T^i|, k = k_a / (3 P_s). alpha = (1, 1) is the isotropic law, whose wear
/// (40) is Archard's (37).
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/model/parameters_3d.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

/// Solution types: SolutionType (model/rates.hpp) with kOpen, kSeparation, kStick and kSlip.

struct Rates3d {
  Eigen::Vector2d dP_T{0, 0};
  double dP_N = 0;
  Eigen::Vector2d dw_T{0, 0};
  double dw_N = 0;
  Eigen::Vector2d dw_Ti{0, 0};  ///< irreversible slip rate
  double dw_w = 0;              ///< wear rate (40)
};

/// A point of the solution set, or a ray (state d with a singular consistency condition).
struct RateSolution3d {
  SolutionType type = SolutionType::kStick;
  bool ray = false;
  Rates3d at;                   ///< the point; a ray's origin
  bool origin_included = true;  ///< a ray: is `at` part of it (a slip ray starting at the
                                ///< stick solution is not: that point is the stick)
  Rates3d direction;            ///< a ray's direction
  /// Slip: unit vector along dw_T^i (for a ray: along its direction), and its angle
  /// atan2(y, x) in (-pi, pi].
  Eigen::Vector2d slip_direction{0, 0};
  double slip_angle = 0;
};

/// The solution set of a 3-D rate problem, of one point (Solution = RateSolution3d) or of N
/// points (SystemRateRow3d, system_rate_3d.hpp), by the exact route or the faceted one
/// (faceted_rate_3d.hpp, system_rate_3d.hpp): the listed solutions (points and rays, each
/// with its `ray` flag), whether the list is the whole set, and why not.
template <class Solution>
struct RateSet3dOf {
  std::vector<Solution> solutions;
  bool complete = true;  ///< every solution is listed (false: `message` says why)
  std::string message;
  int facets = 0;          ///< 0: the exact route; k: the faceted one (a polygon of k facets)
  long long nodes = 0;     ///< the faceted route: enumeration search nodes (over every case)
  bool timed_out = false;  ///< the time limit ended the faceted N-point solve (then incomplete)
  int count() const noexcept { return static_cast<int>(solutions.size()); }
  bool infinite() const noexcept {  ///< some solution is a ray
    return std::any_of(solutions.begin(), solutions.end(), [](const Solution& s) { return s.ray; });
  }
};
using RateSolutionSet3d = RateSet3dOf<RateSolution3d>;

/// Every solution of the rate problem for the load rate dF = (dF_TX, dF_TY, dF_N).
/// States a, c: one solution (linear systems). State d: a 1x1 complementarity problem in the
/// plastic multiplier (slip along the ellipse's normal at P_T). State b: separation, stick, and
/// slip in every direction t(phi) for which the 3x2 rate system is consistent; the consistency
/// condition is a trigonometric quadratic g(phi) = 0, solved for all its real roots through a
/// quartic (Eigen's companion-matrix polynomial solver) refined by Newton on g itself; every
/// root must be simple (|g'| clearly nonzero) and the signs of g between the roots must
/// alternate, or the set says complete = false (docs/contact_3d.md, "Completeness").
/// Throws InputError for invalid input.
RateSolutionSet3d solve_rate_3d(const ContactParameters3d& params, const ContactState3d& state,
                                const Eigen::Vector3d& dF);

/// The slip-direction function of state b: g(phi) = det[e_N + mu G t, H t, dF] with
/// t = (cos phi, sin phi) (docs/contact_3d.md, eqn (3D.6)), as the coefficients
/// (a, b, d, e, f) of a c^2 + b c s + d s^2 + e c + f s. Exposed for tests and maps.
struct SlipDirectionFunction {
  double a = 0, b = 0, d = 0, e = 0, f = 0;
  double operator()(double phi) const noexcept;
  double derivative(double phi) const noexcept;
  double scale() const noexcept;  ///< sum of |coefficients|
};
SlipDirectionFunction slip_direction_function(const ContactParameters3d& params,
                                              const Eigen::Vector3d& dF);

}  // namespace cpkit::rate
