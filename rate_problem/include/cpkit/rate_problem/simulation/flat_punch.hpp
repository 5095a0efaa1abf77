#pragma once
/// \file flat_punch.hpp
/// A flat punch of N contact points on an elastic half-plane, condensed onto the contact DOFs
/// (docs/simulation.md, "Partial slip of a flat punch"): the demonstration system of the
/// N-point simulation.
///
/// The contact width b is cut into N strips of width h = b/N with centres x_i. A line load on
/// the surface of an elastic half-plane (plane strain, modulus E* = E/(1 - nu^2)) displaces the
/// surface by u(x) = (2/(pi E*)) (L0 - ln|x|) per unit load (Johnson, Contact Mechanics, eqn
/// 2.19b, up to the constant L0 that fixes the datum); averaged over a strip, the compliance of
/// the strips is C_ij = (2/(pi E*)) (L0 - ln|x_i - x_j|) for i != j and
/// C_ii = (2/(pi E*)) (L0 - ln(h/2) + 1). The tangential and normal directions are taken
/// uncoupled (a12 = 0: Dundurs' constant beta = 0, similar materials), both with C, so
/// A = C^-1 in each direction, interleaved (T_1, N_1, ...). L0 = ln(b) + 2 keeps C positive
/// definite (-ln|x - y| is a positive definite kernel on intervals shorter than 4, and L0 adds
/// a positive constant); the constructor checks it by a Cholesky factorisation.
///
/// Loading: pattern 1 (tangential) is the traction of a rigid tangential displacement of the
/// punch, A_TT 1 scaled to total 1 (largest at the edges: the half-plane's edge concentration);
/// pattern 2 (normal) is a uniform pressure of total 1 (a flexible pad). With the fretting cycle
/// F = F_T(t) e1 + F_N(t) e2 and |F_T| < mu F_N, the edges reach the friction limit first.
#include "cpkit/rate_problem/model/interface_parameters.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// The punch; its interface parameters (mu, C_T, k_a, P_s) are every point's.
struct FlatPunch : InterfaceParameters {
  int n_points = 5;     ///< N >= 2
  double width = 1;     ///< b (length)
  double modulus = 1;   ///< E* (force / length^2 per unit thickness)
};

/// The system: A (2N x 2N), N points in state b (grazing, P = 0, g = 0), pattern1 and
/// pattern2 as above. Throws InputError for invalid settings (N < 2, width or modulus <= 0,
/// a parameter rejected by ContactParameters::validate).
ContactSystem flat_punch_system(const FlatPunch& punch);

}  // namespace cpkit::rate
