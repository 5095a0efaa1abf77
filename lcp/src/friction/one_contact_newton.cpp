// One solution of one contact from a start, state by state (one_contact_newton.hpp).
#include "cpkit/lcp/friction/one_contact_newton.hpp"

#include <Eigen/LU>
#include <cmath>

#include "cpkit/lcp/friction/one_contact.hpp"

namespace cpkit::lcp::friction {
namespace {

// Newton steps in phi: at most this many, each cut to half a radian (a step beyond it would
// jump to another root of the direction equation, or nowhere).
constexpr int kSlipSteps = 16;
constexpr double kMaxStep = 0.5;

// Slip from the direction phi0 on: r = r_N e(phi), e = (1, -mu cos phi, -mu sin phi), u_N = 0,
// u_T parallel to d = (cos phi, sin phi) (one_contact.hpp's slip equations). Newton's method on
// the direction equation g(phi) = v_1 sin phi - v_2 cos phi = 0, v_j = (A e)_N b_j - b_N (A e)_j
// (u_T times (A e)_N). False when Newton does not settle or the answer is no solution.
bool slip_from(const Mat3& A, const Vec3& b, double mu, double phi0, Vec3& r) {
  // v_j(phi) = P_j + Q_j cos phi + R_j sin phi.
  double P[3], Q[3], R[3];
  for (int j = 1; j < 3; ++j) {
    P[j] = -b[0] * A(j, 0) + b[j] * A(0, 0);
    Q[j] = -b[0] * (-mu * A(j, 1)) + b[j] * (-mu * A(0, 1));
    R[j] = -b[0] * (-mu * A(j, 2)) + b[j] * (-mu * A(0, 2));
  }
  double phi = phi0;
  bool settled = false;
  for (int it = 0; it < kSlipSteps && !settled; ++it) {
    const double c = std::cos(phi), s = std::sin(phi);
    const double v1 = P[1] + Q[1] * c + R[1] * s, v2 = P[2] + Q[2] * c + R[2] * s;
    const double dv1 = -Q[1] * s + R[1] * c, dv2 = -Q[2] * s + R[2] * c;
    const double g = v1 * s - v2 * c, dg = dv1 * s + v1 * c - dv2 * c + v2 * s;
    if (!(std::abs(dg) > 0)) return false;
    double step = g / dg;
    if (!std::isfinite(step)) return false;
    step = std::max(-kMaxStep, std::min(kMaxStep, step));
    phi -= step;
    settled = std::abs(step) <= 1e-14 * std::max(1.0, std::abs(phi));
  }
  if (!settled) return false;
  const Vec3 e(1, -mu * std::cos(phi), -mu * std::sin(phi));
  const double we = A.row(0).dot(e);
  if (!(we != 0)) return false;
  r = (-b[0] / we) * e;
  return r[0] > 0 && one_contact_residual(A, b, mu, r) <= kOneContactLocalTol;
}

// The direction angle of the slip whose tangential force is opposite to t (r_T = -|r_T| d).
double opposite_angle(double t1, double t2) { return std::atan2(-t2, -t1); }

// Two angles closer than this start the same Newton iteration (to its accuracy).
bool same_angle(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * M_PI)) < 1e-12;
}

}  // namespace

bool one_contact_newton(const Mat3& A, const Mat3* A_inv, const Vec3& b, double mu,
                        const Vec3& start, Vec3& r) {
  const bool start_contact = start[0] > 0;
  if (!start_contact && b[0] >= 0) {  // separated, and it may stay so
    r.setZero();
    return true;
  }
  if (mu == 0) {  // the normal row alone: Signorini
    if (b[0] >= 0) {
      r.setZero();
      return true;
    }
    if (!(A(0, 0) > 0)) return false;
    r = Vec3(-b[0] / A(0, 0), 0, 0);
    return true;
  }
  // Slip from where the start slips.
  double tried[3];
  int n_tried = 0;
  auto slip = [&](double phi) {
    for (int k = 0; k < n_tried; ++k)
      if (same_angle(tried[k], phi)) return false;
    tried[n_tried++] = phi;
    return slip_from(A, b, mu, phi, r);
  };
  const double start_t = std::hypot(start[1], start[2]);
  if (start_contact && start_t > 0 && start_t >= (1 - 1e-9) * mu * start[0] &&
      slip(opposite_angle(start[1], start[2])))
    return true;
  // Stick: u = 0.
  const Mat3 own_inverse = A_inv ? Mat3() : A.inverse();
  const Vec3 x = -((A_inv ? *A_inv : own_inverse) * b);
  const double x_t = std::hypot(x[1], x[2]);
  if (x[0] > 0 && x_t <= mu * x[0] &&
      (A_inv || one_contact_residual(A, b, mu, x) <= kOneContactLocalTol)) {
    r = x;
    return true;
  }
  // Slip opposite to the stick force that the cone cannot carry.
  if (x_t > 0 && std::isfinite(x_t) && slip(opposite_angle(x[1], x[2]))) return true;
  // Slip along the sliding velocity at the normal-row guess (u_N = 0, r_T = 0).
  if (b[0] < 0 && A(0, 0) > 0) {
    const double r_n = -b[0] / A(0, 0);
    const double v1 = A(1, 0) * r_n + b[1], v2 = A(2, 0) * r_n + b[2];
    if ((v1 != 0 || v2 != 0) && slip(std::atan2(v2, v1))) return true;
  }
  if (b[0] >= 0) {  // a start in contact that may separate
    r.setZero();
    return true;
  }
  return false;
}

}  // namespace cpkit::lcp::friction
