#pragma once
/// \file one_contact.hpp
/// Every solution of the frictional contact problem of ONE contact (friction_problem.hpp with
/// n_c = 1), in closed form: the fallback of the cheap local solve (one_contact_newton.hpp) in
/// NSGS (nsgs.hpp) and in the C API's one-contact call, the proof that a contact has exactly one
/// solution, and a building block of its own.
///
///   u = W r + b,  r in K_mu,  u_hat = u + (mu |u_T|, 0, 0) in K*_mu,  r . u_hat = 0,
/// W a 3x3 matrix (normal first; need not be symmetric), mu >= 0. A solution is one of
///   separation  r = 0, b_N >= 0;
///   stick       u = 0, i.e. W r = -b, with r in K_mu (unique when W is invertible);
///   slip        u_N = 0, u_T = s d (s > 0, |d| = 1), r = r_N (1, -mu d), r_N > 0.
/// Slip: with d = (cos phi, sin phi), the normal row gives r_N = -b_N / (W e)_N, e = (1, -mu d),
/// and the tangential rows must be parallel to d: (-b_N (W e)_T + (W e)_N b_T) x d = 0, a
/// trigonometric polynomial of degree 2 in phi, i.e. z^2 f = a polynomial of degree 4 in
/// z = e^{i phi}: its roots on the unit circle (Aberth-Ehrlich iteration, refined by Newton's
/// method in phi) are the candidate slip directions, at most 4. mu = 0 is solved directly
/// (r = (max(0, -b_N / W_NN), 0, 0) when W_NN > 0).
/// Every candidate is kept when its natural-map residual, in the local units
/// R = max(|r|_inf, |b|_inf / |W|_max), S = |b|_2 + |W|_max-row-sum min(|r|_inf, |b|_inf/|W|_max),
/// is at most 1e-9 (rounding of the closed forms included). Units are the caller's; nothing is
/// allocated.
#include <Eigen/Core>

#include "cpkit/core/friction_cone.hpp"

namespace cpkit::lcp::friction {

/// The local acceptance of a candidate: its natural-map residual in the local units above.
inline constexpr double kOneContactLocalTol = 1e-9;

/// Up to 6 solutions (separation, stick, 4 slips), duplicates removed.
struct OneContactSolutions {
  Vec3 r[6];
  int count = 0;
};

/// Every solution found (see the file comment). A singular W may have a continuum of stick
/// solutions: then only the minimum-norm one (complete orthogonal decomposition) is listed.
OneContactSolutions one_contact_solutions(const Mat3& W, const Vec3& b, double mu);

/// The solution closest to `near` (Euclidean), or, when no candidate passes the local test
/// (an infeasible or numerically degenerate contact), the candidate with the smallest local
/// residual. `residual` (optional) receives that candidate's local residual.
Vec3 one_contact_nearest(const Mat3& W, const Vec3& b, double mu, const Vec3& near,
                         double* residual = nullptr);

/// The local unit-free natural-map residual of the file comment.
double one_contact_residual(const Mat3& W, const Vec3& b, double mu, const Vec3& r);

}  // namespace cpkit::lcp::friction
