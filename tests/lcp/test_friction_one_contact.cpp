// Every solution of one frictional contact (one_contact.hpp) against closed forms and against a
// brute-force search written here: a fine grid of slip directions phi with bisection on the
// sign changes of the tangential-parallelism residual computed by plain matrix products, the
// stick solution by dense LU, and separation from the sign of b_N.
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

#include "cpkit/lcp/friction/one_contact.hpp"
#include "friction_check.hpp"

namespace {

using cpkit::Mat3;
using cpkit::Vec3;
using cpkit::lcp::friction::one_contact_nearest;
using cpkit::lcp::friction::one_contact_solutions;

double check1(const Mat3& W, const Vec3& b, double mu, const Vec3& r) {
  Eigen::SparseMatrix<double> Ws = Eigen::MatrixXd(W).sparseView();
  return cpkit::test::friction_violation(Ws, Eigen::VectorXd(b), Eigen::VectorXd::Constant(1, mu),
                                         Eigen::VectorXd(r));
}

// Brute force: every solution by a grid over phi (slip), LU (stick), the sign of b_N (separation).
std::vector<Vec3> brute_force(const Mat3& W, const Vec3& b, double mu) {
  std::vector<Vec3> out;
  if (b[0] >= 0) out.push_back(Vec3::Zero());
  const Vec3 rs = W.fullPivLu().solve(-b);
  if (rs[0] > 0 && std::hypot(rs[1], rs[2]) <= mu * rs[0]) out.push_back(rs);
  auto slip = [&](double phi, Vec3& r, double& s) {
    const Vec3 e(1, -mu * std::cos(phi), -mu * std::sin(phi));
    const double rN = -b[0] / (W.row(0) * e);
    r = rN * e;
    const Vec3 u = W * r + b;  // u_N = 0 by construction
    s = u[1] * std::cos(phi) + u[2] * std::sin(phi);
    return u[1] * std::sin(phi) - u[2] * std::cos(phi);  // u_T x d
  };
  const int N = 20000;
  const double h = 2 * M_PI / N;
  Vec3 r;
  double s;
  double f0 = slip(0, r, s);
  for (int k = 0; k < N; ++k) {
    double a = k * h, c = a + h;
    const double f1 = slip(c, r, s);
    if ((f0 < 0) != (f1 < 0)) {
      double fa = f0;
      for (int it = 0; it < 200 && c - a > 1e-15; ++it) {
        const double m = 0.5 * (a + c);
        const double fm = slip(m, r, s);
        if ((fm < 0) == (fa < 0)) {
          a = m;
          fa = fm;
        } else {
          c = m;
        }
      }
      slip(0.5 * (a + c), r, s);
      if (r[0] > 0 && s > 0) out.push_back(r);
    }
    f0 = f1;
  }
  return out;
}

}  // namespace

TEST_CASE("one contact, W = I, mu = 0.5: the closed-form solutions", "[friction][one_contact]") {
  const Mat3 W = Mat3::Identity();
  SECTION("stick: b = (-1, 0.2, 0) -> r = (1, -0.2, 0) only") {
    const auto s = one_contact_solutions(W, Vec3(-1, 0.2, 0), 0.5);
    REQUIRE(s.count == 1);
    CHECK((s.r[0] - Vec3(1, -0.2, 0)).norm() < 1e-15);
  }
  SECTION("slip: b = (-1, 1, 0) -> r = (1, -0.5, 0) (u = (0, 0.5, 0)) only") {
    const auto s = one_contact_solutions(W, Vec3(-1, 1, 0), 0.5);
    REQUIRE(s.count == 1);
    CHECK((s.r[0] - Vec3(1, -0.5, 0)).norm() < 1e-14);
  }
  SECTION("slip along a diagonal: b = (-2, 3, 4) -> r = (2, -0.6, -0.8)") {
    // r_N = 2, r_T = -mu r_N (3, 4)/5 = (-0.6, -0.8), u_T = (2.4, 3.2) parallel to (3, 4).
    const auto s = one_contact_solutions(W, Vec3(-2, 3, 4), 0.5);
    REQUIRE(s.count == 1);
    CHECK((s.r[0] - Vec3(2, -0.6, -0.8)).norm() < 1e-14);
  }
  SECTION("separation: b = (1, 3, -2) -> r = 0 only") {
    const auto s = one_contact_solutions(W, Vec3(1, 3, -2), 0.5);
    REQUIRE(s.count == 1);
    CHECK(s.r[0] == Vec3::Zero());
  }
  SECTION("mu = 0: b = (-2, 1, 0) -> r = (2, 0, 0)") {
    const auto s = one_contact_solutions(W, Vec3(-2, 1, 0), 0.0);
    REQUIRE(s.count == 1);
    CHECK((s.r[0] - Vec3(2, 0, 0)).norm() < 1e-15);
  }
}

TEST_CASE("one contact: every solution, against a brute-force search", "[friction][one_contact]") {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.05, 2.0);
  int total = 0, several = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Mat3 J;
    for (int i = 0; i < 9; ++i) J(i / 3, i % 3) = g(rng);
    // Symmetric positive definite (Delassus blocks), and every 3rd trial non-symmetric.
    Mat3 W = J * J.transpose() + 0.05 * Mat3::Identity();
    if (trial % 3 == 0) W += 0.3 * J;
    const Vec3 b(g(rng), g(rng), g(rng));
    const double mu = U(rng);
    const auto s = one_contact_solutions(W, b, mu);
    for (int k = 0; k < s.count; ++k) CHECK(check1(W, b, mu, s.r[k]) < 1e-9);
    const auto bf = brute_force(W, b, mu);
    for (const Vec3& r : bf) {
      bool found = false;
      for (int k = 0; k < s.count; ++k) found = found || (s.r[k] - r).norm() <= 1e-7 * (1 + r.norm());
      CHECK(found);
    }
    CHECK(s.count >= static_cast<int>(bf.size()));
    CHECK(s.count >= 1);
    total += s.count;
    several += s.count > 1;
    // The nearest solution is one of them, the closest.
    const Vec3 near(g(rng), g(rng), g(rng));
    const Vec3 rn = one_contact_nearest(W, b, mu, near);
    double best = 1e300;
    for (int k = 0; k < s.count; ++k) best = std::min(best, (s.r[k] - near).norm());
    CHECK((rn - near).norm() == Approx(best));
  }
  CHECK(total >= 300);
  CHECK(several > 0);  // non-symmetric W: several solutions occur in this sample
}

TEST_CASE("one contact: a singular W with a consistent b is solved", "[friction][one_contact]") {
  // W = diag(1, 0, 0) (no tangential compliance), b = (-1, 0, 0): r = (1, 0, 0) sticks
  // (u = 0, r in the cone); the minimum-norm stick solution is that one.
  const Mat3 W = Vec3(1, 0, 0).asDiagonal();
  const auto s = one_contact_solutions(W, Vec3(-1, 0, 0), 0.3);
  REQUIRE(s.count >= 1);
  bool found = false;
  for (int k = 0; k < s.count; ++k) found = found || (s.r[k] - Vec3(1, 0, 0)).norm() < 1e-14;
  CHECK(found);
}
