// The cheap local solve of one contact (one_contact_newton.hpp) against hand answers, against
// Siconos' answer on a coupled contact (python3-siconos, fc3d_driver NSN_AC and NSGS, tol 1e-15),
// and against the closed form of every solution (one_contact_solutions, itself checked against a
// brute-force search in test_friction_one_contact.cpp) on seeded random contacts: whatever it
// returns is one of those solutions, and it answers the great majority of them.
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>
#include <random>

#include "../test_budget.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/friction/one_contact_newton.hpp"

namespace {

using cpkit::Mat3;
using cpkit::Vec3;
using cpkit::lcp::friction::one_contact_newton;
using cpkit::lcp::friction::one_contact_solutions;

// The answer from `start`, with and without the caller's inverse (both must agree).
Vec3 solve(const Mat3& W, const Vec3& b, double mu, const Vec3& start = Vec3::Zero()) {
  Vec3 r, r_own;
  const Mat3 inv = W.inverse();
  REQUIRE(one_contact_newton(W, &inv, b, mu, start, r));
  REQUIRE(one_contact_newton(W, nullptr, b, mu, start, r_own));
  CHECK((r - r_own).norm() <= 1e-14 * (1 + r.norm()));
  return r;
}

// The unit-free verdict (friction_verdict.hpp) of r on the contact, all nine entries stored.
double verdict(const Mat3& W, const Vec3& b, double mu, const Vec3& r) {
  const int stored[3] = {3, 3, 3};
  Vec3 u;
  return cpkit::one_contact_unit_free(W, stored, b, mu, r, u);
}

}  // namespace

TEST_CASE("one-contact local solve: W = I by hand", "[friction][one_contact]") {
  const Mat3 I = Mat3::Identity();
  // Stick: u = 0, r = -b inside the cone.
  CHECK((solve(I, Vec3(-1, 0.2, 0), 0.5) - Vec3(1, -0.2, 0)).norm() < 1e-15);
  // Slip: r_N = 1, r_T = -mu r_N b_T / |b_T|, u_T = b_T + r_T = (0.5, 0).
  CHECK((solve(I, Vec3(-1, 1, 0), 0.5) - Vec3(1, -0.5, 0)).norm() < 1e-14);
  // Slip along a diagonal: r = (2, -0.6, -0.8), u_T = (2.4, 3.2) parallel to (3, 4).
  CHECK((solve(I, Vec3(-2, 3, 4), 0.5) - Vec3(2, -0.6, -0.8)).norm() < 1e-14);
  // Separation, from r = 0 and from a start in contact.
  CHECK(solve(I, Vec3(1, 3, -2), 0.5) == Vec3::Zero());
  CHECK(solve(I, Vec3(1, 3, -2), 0.5, Vec3(1, 0.1, 0)) == Vec3::Zero());
  // mu = 0: the normal row alone.
  CHECK((solve(I, Vec3(-2, 1, 0), 0.0) - Vec3(2, 0, 0)).norm() < 1e-15);
  // From a slipping start on the other side of the cone: the same unique slip.
  CHECK((solve(I, Vec3(-1, 1, 0), 0.5, Vec3(1, 0.5, 0)) - Vec3(1, -0.5, 0)).norm() < 1e-14);
}

TEST_CASE("one-contact local solve: a singular W is left to the closed form",
          "[friction][one_contact]") {
  // W = diag(1, 0, 0), b = (-1, 0, 0), mu = 0.3: every r = (1, r_T) with |r_T| <= 0.3 sticks
  // (a continuum). No inverse and no slip direction: the local solve finds nothing, and the
  // closed form gives its minimum-norm stick (1, 0, 0).
  const Mat3 W = Vec3(1, 0, 0).asDiagonal();
  const Vec3 b(-1, 0, 0);
  Vec3 r;
  CHECK_FALSE(one_contact_newton(W, nullptr, b, 0.3, Vec3::Zero(), r));
  const Vec3 fallback = cpkit::lcp::friction::one_contact_nearest(W, b, 0.3, Vec3::Zero());
  CHECK((fallback - Vec3(1, 0, 0)).norm() < 1e-14);
}

TEST_CASE("one-contact local solve: a coupled W against Siconos' answer",
          "[friction][one_contact]") {
  // W = [[2, .5, .3], [.5, 1.5, .2], [.3, .2, 1]], b = (-1, .4, -.3), mu = 0.3 (bench_capi_call's
  // contact). python3-siconos 4.4, fc3d_driver, NSN_AC and NSGS at tol 1e-15, both:
  // r = (0.53175792494243512, -0.15336926277375779, 0.043895938340029153), a slip (|r_T| =
  // mu r_N, u_N = 0, u_T = (0.44460425597858672, -0.12725053673199188)).
  Mat3 W;
  W << 2, .5, .3, .5, 1.5, .2, .3, .2, 1;
  const Vec3 b(-1, .4, -.3);
  const Vec3 siconos(0.53175792494243512, -0.15336926277375779, 0.043895938340029153);
  const Vec3 r = solve(W, b, 0.3);
  CHECK((r - siconos).norm() <= 1e-14);
  CHECK(verdict(W, b, 0.3, r) <= 1e-14);
}

TEST_CASE("one-contact local solve: one of the closed form's solutions, on random contacts",
          "[friction][one_contact]") {
  // Random SPD W (J J^T + 0.05 I, Delassus blocks), every third trial made non-symmetric (where
  // a contact may have several solutions or none), b ~ N(0, I), mu in [0.05, 2]; starts: r = 0
  // and a random point of the cone (nsgs' r_i). Whatever the local solve returns must be one of
  // the closed form's solutions and pass the unit-free verdict at 1e-9; where it returns
  // nothing the closed form is what answers.
  std::mt19937 rng(58);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.05, 2.0), angle(0, 2 * M_PI), unit(0, 1);
  const int trials = cpkit::test::family_size(3000, 300);
  int found = 0, found_spd = 0, spd = 0, none = 0, several_found = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Mat3 J;
    for (int i = 0; i < 9; ++i) J(i / 3, i % 3) = g(rng);
    Mat3 W = J * J.transpose() + 0.05 * Mat3::Identity();
    const bool symmetric = trial % 3 != 0;
    if (!symmetric) W += 0.3 * J;
    const Vec3 b(g(rng), g(rng), g(rng));
    const double mu = U(rng);
    // The start: r = 0 on even trials, else inside or on the cone.
    Vec3 start = Vec3::Zero();
    if (trial % 2) {
      const double rn = unit(rng) + 0.1, phi = angle(rng);
      const double t = (trial % 4 == 1 ? 1.0 : unit(rng)) * mu * rn;
      start = Vec3(rn, t * std::cos(phi), t * std::sin(phi));
    }
    CAPTURE(trial, W, b, mu, start);
    const auto all = one_contact_solutions(W, b, mu);
    spd += symmetric;
    Vec3 r;
    const Mat3 inv = W.inverse();
    if (!one_contact_newton(W, &inv, b, mu, start, r)) {
      ++none;
      // The fallback answers: a positive definite W has a solution [Klarbring, Pang 1998].
      if (symmetric) REQUIRE(all.count >= 1);
      continue;
    }
    ++found;
    found_spd += symmetric;
    several_found += all.count > 1;
    REQUIRE(verdict(W, b, mu, r) <= 1e-9);
    bool among = false;
    for (int k = 0; k < all.count; ++k)
      among = among || (all.r[k] - r).norm() <= 1e-7 * (1 + r.norm());
    REQUIRE(among);
  }
  // The cheap solve answers (nearly) every Delassus contact and most of the others; the
  // sample holds contacts with several solutions, where it returns one of them.
  CHECK(found_spd >= spd * 99 / 100);
  CHECK(found >= trials * 95 / 100);
  CHECK(several_found >= trials / 100);
  CHECK(none <= trials / 20);
}
