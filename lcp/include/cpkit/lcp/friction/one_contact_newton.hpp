#pragma once
/// \file one_contact_newton.hpp
/// One solution of ONE contact's frictional problem, found cheaply from a start: the local solve
/// of NSGS (nsgs.hpp) and of the C API's one-contact call, tried before the closed form of every
/// solution (one_contact.hpp), which stays for what this does not find. Notation of
/// one_contact.hpp: u = A r + b, r in K_mu, u_hat = u + (mu |u_T|, 0, 0) in K*_mu, r . u_hat = 0.
///
/// Each state's own equations, the start's state first (as Siconos' NSGS starts its local Newton
/// at the contact's current force):
///   separation  r = 0, when b_N >= 0 (exact);
///   stick       x = -A^-1 b, when x_N > 0 and |x_T| <= mu x_N (u = 0 up to the rounding of
///               A^-1: with the caller's inverse, which it trusts, that is all; with an inverse
///               computed here, the local residual must also be at most 1e-9);
///   slip        r = r_N (1, -mu cos phi, -mu sin phi) with u_N = 0 and u_T parallel to
///               (cos phi, sin phi): Newton's method on the direction equation of
///               one_contact.hpp in phi (steps cut at half a radian), from the start's own
///               direction when it slips, then from the stick trial's (-x_T / |x_T|), then from
///               the sliding velocity at the normal-row guess r = (-b_N / A_NN, 0, 0); accepted
///               when r_N > 0 and the local residual (one_contact_residual) is at most 1e-9;
///   mu = 0      r = (-b_N / A_NN, 0, 0) when b_N < 0 < A_NN (exact).
/// The order: a start at r_N <= 0 tries separation, stick, slip; a start in stick tries stick,
/// slip, separation; a start that slips tries slip from its direction, stick, the other slips,
/// separation. Where the contact has several solutions, the one found is its start's state's
/// when that state has one, not necessarily the one nearest to the start. A singular or
/// degenerate contact (no inverse, Newton not settling) is not solved here: false. Cost: a few
/// hundred flops and one sine and cosine per Newton step; no allocation.
#include "cpkit/core/friction_cone.hpp"

namespace cpkit::lcp::friction {

/// One solution of the contact (file comment) into r, true when found; false leaves r
/// unspecified. A_inv: A's inverse when the caller has one it trusts (a well-conditioned A);
/// nullptr: computed here by cofactors, and the stick it gives verified by the local residual.
bool one_contact_newton(const Mat3& A, const Mat3* A_inv, const Vec3& b, double mu,
                        const Vec3& start, Vec3& r);

}  // namespace cpkit::lcp::friction
