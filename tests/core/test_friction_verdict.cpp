// The verdict on frictional contact candidates (friction_verdict.hpp): hand-computed one-contact
// cases (stick, slip, separation: closed forms in the comments), unit invariance, refusals
// (r = 0 where a force is needed, a wrong r, NaN). The comparison of the two published relative
// errors with Siconos' own is test_friction_verdict_siconos_peer.cpp (it needs python3-siconos).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_verdict.hpp"

namespace {

using cpkit::CommonOptions;
using cpkit::FrictionContactProblem;
using cpkit::SolveResult;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;

FrictionContactProblem make(const MatrixXd& W, const VectorXd& q, const VectorXd& mu) {
  FrictionContactProblem p;
  p.W = W.sparseView();
  p.q = q;
  p.mu = mu;
  return p;
}

VectorXd v3(double a, double b, double c) { return (VectorXd(3) << a, b, c).finished(); }
VectorXd v1(double a) { return (VectorXd(1) << a).finished(); }

SolveResult claim(const VectorXd& r) {
  SolveResult s;
  s.status = Status::kSolved;
  s.z = r;
  return s;
}

// A random rank-deficient Delassus operator W = J J^T (J: 3 nc x m, m < 3 nc when asked) and
// a q whose normal entries have both signs.
FrictionContactProblem random_problem(std::mt19937& rng, int nc, int m) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 1.0);
  MatrixXd J(3 * nc, m);
  for (int i = 0; i < J.rows(); ++i)
    for (int j = 0; j < m; ++j) J(i, j) = g(rng);
  VectorXd q(3 * nc), mu(nc);
  for (int i = 0; i < 3 * nc; ++i) q[i] = g(rng);
  for (int i = 0; i < nc; ++i) mu[i] = U(rng);
  return make(J * J.transpose(), q, mu);
}

}  // namespace

TEST_CASE("cone projection and De Saxce map: closed forms", "[friction][verdict]") {
  using cpkit::Vec3;
  // In K_0.5: unchanged. In the polar cone (0.5 * 2 <= 1): zero.
  CHECK(cpkit::project_on_cone(Vec3(1, 0.3, 0.4), 0.5) == Vec3(1, 0.3, 0.4));
  CHECK(cpkit::project_on_cone(Vec3(-1, 2, 0), 0.5) == Vec3::Zero());
  // (0.5, -1, 0), mu = 0.5: n = (0.5 + 0.5) / 1.25 = 0.8, r_T = 0.5 * 0.8 * (-1) = -0.4.
  const Vec3 p = cpkit::project_on_cone(Vec3(0.5, -1, 0), 0.5);
  CHECK(p[0] == Approx(0.8));
  CHECK(p[1] == Approx(-0.4));
  CHECK(p[2] == 0.0);
  // mu = 0: the ray; (2, 3, 4) -> (2, 0, 0).
  CHECK(cpkit::project_on_cone(Vec3(2, 3, 4), 0.0) == Vec3(2, 0, 0));
  // u_hat = u + (mu |u_T|, 0, 0): (1, 3, 4), mu = 0.5 -> (3.5, 3, 4).
  CHECK(cpkit::de_saxce(Vec3(1, 3, 4), 0.5) == Vec3(3.5, 3, 4));
}

TEST_CASE("one contact, W = I, mu = 0.5: stick, slip and separation solutions accepted",
          "[friction][verdict]") {
  const MatrixXd W = MatrixXd::Identity(3, 3);
  CommonOptions o;
  SECTION("stick: q = (-1, 0.2, 0), r = -q = (1, -0.2, 0) (|r_T| = 0.2 <= 0.5), u = 0") {
    const auto p = make(W, v3(-1, 0.2, 0), v1(0.5));
    const auto e = cpkit::friction_errors(p, v3(1, -0.2, 0));
    CHECK(e.unit_free == 0.0);
    CHECK(e.relative_q == 0.0);
    CHECK(e.relative_max == 0.0);
    const auto s = cpkit::finalize(p, claim(v3(1, -0.2, 0)), o);
    CHECK(s.status == Status::kSolved);
    CHECK(s.w == VectorXd::Zero(3));
  }
  SECTION("slip: q = (-1, 1, 0), r = (1, -0.5, 0), u = (0, 0.5, 0), u_hat = (0.25, 0.5, 0)") {
    // r on the boundary, r_T opposite to u_T, r . u_hat = 0.25 - 0.25 = 0.
    const auto p = make(W, v3(-1, 1, 0), v1(0.5));
    const auto s = cpkit::finalize(p, claim(v3(1, -0.5, 0)), o);
    CHECK(s.status == Status::kSolved);
    CHECK(s.w[1] == 0.5);
    CHECK(s.residuals.natural == 0.0);
  }
  SECTION("separation: q = (1, 3, -2), r = 0, u = q") {
    const auto p = make(W, v3(1, 3, -2), v1(0.5));
    const auto s = cpkit::finalize(p, claim(VectorXd::Zero(3)), o);
    CHECK(s.status == Status::kSolved);
    CHECK(s.w == v3(1, 3, -2));
  }
  SECTION("frictionless (mu = 0) slip: q = (-2, 1, 0), r = (2, 0, 0), u = (0, 1, 0)") {
    const auto p = make(W, v3(-2, 1, 0), v1(0.0));
    CHECK(cpkit::finalize(p, claim(v3(2, 0, 0)), o).status == Status::kSolved);
  }
}

TEST_CASE("per-contact states: the closed-form stick, slip and separated contacts, at any scale",
          "[friction][verdict]") {
  // Three uncoupled contacts, W = I, mu = 0.5 (the cases above, side by side): stick r = (1,
  // -0.2, 0), slip r = (1, -0.5, 0), separated r = 0. Scaling q (and r) by a, or W and q by b,
  // changes neither a state nor an error's being zero.
  for (double a : {1e-12, 1.0, 1e12}) {
    for (double b : {1e-12, 1.0, 1e12}) {
      CAPTURE(a, b);
      VectorXd q(9), r(9);
      q << -1, 0.2, 0, -1, 1, 0, 1, 3, -2;
      r << 1, -0.2, 0, 1, -0.5, 0, 0, 0, 0;
      const auto p = make(b * MatrixXd::Identity(9, 9), a * b * q, VectorXd::Constant(3, 0.5));
      const auto c = cpkit::friction_contacts(p, a * r);
      REQUIRE(c.size() == 3);
      CHECK(c[0].state == cpkit::ContactState::kStick);
      CHECK(c[1].state == cpkit::ContactState::kSlip);
      CHECK(c[2].state == cpkit::ContactState::kSeparated);
      for (const auto& k : c) CHECK(k.error <= 1e-15);
      CHECK(std::string(cpkit::to_string(c[1].state)) == "slip");
      // A wrong third contact (r_N = 1 where it should separate) carries the error, alone.
      VectorXd bad = a * r;
      bad[6] = a;
      const auto w = cpkit::friction_contacts(p, bad);
      CHECK(w[2].error > 0.1);
      CHECK(w[0].error <= 1e-15);
    }
  }
}

TEST_CASE("wrong candidates are refuted, with the published errors computed by hand",
          "[friction][verdict]") {
  const MatrixXd W = MatrixXd::Identity(3, 3);
  const auto p = make(W, v3(-1, 1, 0), v1(0.5));
  SECTION("r = (1, 0, 0): u = (0, 1, 0), u_hat = (0.5, 1, 0), r - u_hat = (0.5, -1, 0)") {
    // P_K(0.5, -1, 0) = (0.8, -0.4, 0); map = (0.2, 0.4, 0), E = sqrt(0.2);
    // relative_q = E / sqrt(2) = sqrt(0.1); relative_max = E / max(sqrt 2, 1, 1), the same.
    const auto e = cpkit::friction_errors(p, v3(1, 0, 0));
    CHECK(e.relative_q == Approx(std::sqrt(0.1)).epsilon(1e-14));
    CHECK(e.relative_max == Approx(std::sqrt(0.1)).epsilon(1e-14));
    CHECK(e.unit_free > 0.05);
    const auto s = cpkit::finalize(p, claim(v3(1, 0, 0)), {});
    CHECK(s.status == Status::kNumericalFailure);
    CHECK(s.message.find("refuted") != std::string::npos);
  }
  SECTION("r = (3, 0, 0): u = (2, 1, 0), u_hat = (2.5, 1, 0), same projection") {
    // map = (2.2, 0.4, 0), E = sqrt(5); relative_q = sqrt(5 / 2); relative_max = sqrt(5) / 3.
    const auto e = cpkit::friction_errors(p, v3(3, 0, 0));
    CHECK(e.relative_q == Approx(std::sqrt(2.5)).epsilon(1e-14));
    CHECK(e.relative_max == Approx(std::sqrt(5.0) / 3).epsilon(1e-14));
  }
  SECTION("a point outside the cone with u = 0 is refuted: q = (-1, -1, 0), r = (1, 1, 0)") {
    const auto p2 = make(W, v3(-1, -1, 0), v1(0.5));
    CHECK(cpkit::finalize(p2, claim(v3(1, 1, 0)), {}).status == Status::kNumericalFailure);
  }
  SECTION("slightly wrong: the slip solution with r_T off by 1e-6 relative") {
    // r = (1, -0.5 (1 + 1e-6), 0) is outside K by ~4.5e-7 in r's unit R = 1.
    const auto e = cpkit::friction_errors(p, v3(1, -0.5 * (1 + 1e-6), 0));
    CHECK(e.unit_free > 1e-7);
    CHECK(e.unit_free < 1e-5);
    CommonOptions o;
    o.tol = 1e-10;
    o.tol_acceptable = 1e-8;
    CHECK(cpkit::finalize(p, claim(v3(1, -0.5 * (1 + 1e-6), 0)), o).status ==
          Status::kNumericalFailure);
  }
}

TEST_CASE("r = 0 is refused whenever some contact needs a force (q_N < 0)", "[friction][verdict]") {
  const MatrixXd W = MatrixXd::Identity(6, 6);
  // Contact 2's q_N is 1e-12 of its q_T: the cone test alone would see ~1e-12 there; the normal
  // row in its own units (s_N = |q_N| at r = 0) gives |min(0, -1)| = 1.
  VectorXd q(6);
  q << 1, 0, 0, -1e-12, 1, 0;
  const auto p = make(W, q, (VectorXd(2) << 0.5, 0.5).finished());
  const auto e = cpkit::friction_errors(p, VectorXd::Zero(6));
  CHECK(e.unit_free == Approx(1.0).epsilon(1e-14));  // less the rounding allowance of u = q
  CHECK(cpkit::finalize(p, claim(VectorXd::Zero(6)), {}).status == Status::kNumericalFailure);
  // The same at every scale of q and of (W, q).
  for (double a : {1e-12, 1e-6, 1e6, 1e12}) {
    const auto pa = make(W * a, q * a, p.mu);
    CHECK(cpkit::friction_errors(pa, VectorXd::Zero(6)).unit_free == Approx(1.0));
    const auto pb = make(W, q * a, p.mu);
    CHECK(cpkit::friction_errors(pb, VectorXd::Zero(6)).unit_free == Approx(1.0));
  }
  // q = (-1, 0.2, 0), W = I, r = 0: normal |min(0, -1)| = 1 (the cone part: sqrt(0.85 / 1.04)).
  const auto p1 = make(MatrixXd::Identity(3, 3), v3(-1, 0.2, 0), v1(0.5));
  CHECK(cpkit::friction_errors(p1, VectorXd::Zero(3)).unit_free == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("non-finite or mis-sized candidates are refused; invalid problems throw",
          "[friction][verdict]") {
  const auto p = make(MatrixXd::Identity(3, 3), v3(-1, 1, 0), v1(0.5));
  VectorXd r = v3(1, -0.5, 0);
  r[1] = std::nan("");
  CHECK(std::isinf(cpkit::friction_errors(p, r).unit_free));
  auto s = cpkit::finalize(p, claim(r), {});
  CHECK(s.status == Status::kNumericalFailure);
  CHECK(s.message.find("non-finite") != std::string::npos);
  s = cpkit::finalize(p, claim(VectorXd::Zero(4)), {});
  CHECK(s.status == Status::kNumericalFailure);
  CHECK(s.message.find("size 4") != std::string::npos);
  CHECK_THROWS_AS(cpkit::friction_errors(p, VectorXd::Zero(4)), cpkit::InputError);
  auto bad = p;
  bad.mu[0] = -1;
  CHECK_THROWS_AS(cpkit::friction_errors(bad, v3(0, 0, 0)), cpkit::InputError);
  // An overflowing r: never accepted.
  CHECK(cpkit::finalize(p, claim(v3(1e308, 0, 0)), {}).status == Status::kNumericalFailure);
  // An infeasibility claim without a certificate is not granted.
  SolveResult inf;
  inf.status = Status::kInfeasible;
  CHECK(cpkit::finalize(p, inf, {}).status == Status::kNumericalFailure);
}

TEST_CASE("a diverging r is never accepted", "[friction][verdict]") {
  // W = [[1, -1], [-1, 1]] on the normals of two contacts (tangents decoupled, W_T = I),
  // q_N = (-1, -1): r_N = (t, t) has u_N = (-1, -1) for every t. Units (t > 3): r_ref = 1,
  // d_i = 1, cap_i = 1, R_i = t, rn = (1, 0, 0); c_N = |W_N| min(|r|, cap) = 2, s_N = S = 3, so
  // un = (-1/3, 0, 0): normal |min(1, -1/3)| = 1/3 and cone |(1,0,0) - P(4/3, 0, 0)| = 1/3. The
  // rounding allowance no longer grows with t (issue 34, F4-01): u_N is formed in twice the
  // working precision (exactly -1 here), and the allowance is gamma_3 (c_N + |q_N|) + 2u|u_N| +
  // gamma_3^2 (2t + 1), below 1e-15 for every t here: 1/3 at t = 1e3, 1e8, 1e14 and 1e15.
  MatrixXd W = MatrixXd::Identity(6, 6);
  W(0, 0) = W(3, 3) = 1;
  W(0, 3) = W(3, 0) = -1;
  VectorXd q = VectorXd::Zero(6);
  q[0] = q[3] = -1;
  const auto p = make(W, q, (VectorXd(2) << 0.5, 0.5).finished());
  for (double t : {1e3, 1e8, 1e14, 1e15}) {
    VectorXd r = VectorXd::Zero(6);
    r[0] = r[3] = t;
    CAPTURE(t);
    CHECK(cpkit::friction_errors(p, r).unit_free == Approx(1.0 / 3).epsilon(1e-12));
  }
  // Beyond 1/eps of the data's size, r cannot be verified at all: +inf (never solved).
  VectorXd r = VectorXd::Zero(6);
  r[0] = r[3] = 1e40;
  CHECK(std::isinf(cpkit::friction_errors(p, r).unit_free));

  // The verdict reads W in its own storage, by columns: the same numbers when W is left
  // uncompressed (room for more entries in every column) and its entries were inserted
  // columns last to first.
  auto loose = p;
  loose.W = Eigen::SparseMatrix<double>(6, 6);
  loose.W.reserve(Eigen::VectorXi::Constant(6, 4));
  for (int j = 5; j >= 0; --j)
    for (int i = 5; i >= 0; --i)
      if (W(i, j) != 0) loose.W.insert(i, j) = W(i, j);
  REQUIRE(!loose.W.isCompressed());
  for (double t : {1e3, 1e15}) {
    VectorXd rt = VectorXd::Zero(6);
    rt[0] = rt[3] = t;
    CAPTURE(t);
    CHECK(cpkit::friction_errors(loose, rt).unit_free == Approx(1.0 / 3).epsilon(1e-12));
  }
  CHECK(std::isinf(cpkit::friction_errors(loose, r).unit_free));
}

TEST_CASE("unit invariance: same verdict under q -> a q and (W, q) -> b (W, q)",
          "[friction][verdict]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 20; ++trial) {
    const int nc = 1 + trial % 5;
    const auto p = random_problem(rng, nc, trial % 2 ? 3 * nc : std::max(1, 2 * nc - 1));
    // Candidates: the solution of every contact's separation (r = 0), a random r in the cone,
    // and small perturbations of it.
    std::vector<VectorXd> cands{VectorXd::Zero(3 * nc)};
    VectorXd r(3 * nc);
    for (int i = 0; i < nc; ++i) {
      const double n = std::abs(g(rng));
      r.segment<3>(3 * i) << n, 0.5 * p.mu[i] * n * g(rng) / 2, 0.5 * p.mu[i] * n * g(rng) / 2;
    }
    cands.push_back(r);
    cands.push_back(r + 1e-9 * VectorXd::Random(3 * nc));
    for (const VectorXd& c : cands) {
      const double base = cpkit::friction_errors(p, c).unit_free;
      // Powers of two: exactly the same number.
      for (int k : {-40, -20, -7, 9, 20, 40}) {
        const double a = std::ldexp(1.0, k);
        CHECK(cpkit::friction_errors(make(p.W * a, p.q * a, p.mu), c).unit_free == base);
        CHECK(cpkit::friction_errors(make(p.W, p.q * a, p.mu), c * a).unit_free == base);
      }
      // Other factors in 1e-12..1e12: the same to rounding.
      for (double a : {1e-12, 3.7e-5, 0.3, 7.0, 1.9e6, 1e12}) {
        CHECK(cpkit::friction_errors(make(p.W * a, p.q * a, p.mu), c).unit_free ==
              Approx(base).epsilon(1e-9).margin(1e-14));
        CHECK(cpkit::friction_errors(make(p.W, p.q * a, p.mu), c * a).unit_free ==
              Approx(base).epsilon(1e-9).margin(1e-14));
      }
    }
  }
}

TEST_CASE("one_contact_unit_free is the verdict's number, bit for bit", "[friction][verdict]") {
  // The C API's allocation-free verdict of one contact must decide as finalize() does: the same
  // unit_free and u from the same data, on a seeded family: W = J J^T, non-symmetric, diagonal,
  // with entries not stored and exact zeros stored; mixed scales; candidates 0, random, the
  // stick force, the closed-form solution of a diagonal W, and a diverging r (which the verdict
  // forms in twice the working precision).
  std::mt19937 rng(37);
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> e(-5, 5), coin(0, 3);
  const double mus[] = {0.0, 0.3, 1.0, 40.0};
  int compared = 0, solved = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    cpkit::Mat3 W;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) W(i, j) = g(rng);
    if (trial % 3 == 0) W = W * W.transpose();
    if (trial % 3 == 1) W = W.diagonal().cwiseAbs().asDiagonal();
    W *= std::ldexp(1.0, e(rng));
    const cpkit::Vec3 q(g(rng) * std::ldexp(1.0, e(rng)), g(rng), g(rng) * std::ldexp(1.0, e(rng)));
    const double mu = mus[trial % 4];
    // Stored entries: the nonzeros, some zeros stored explicitly, some zeros made by hand.
    std::vector<Eigen::Triplet<double>> t;
    int stored[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (W(i, j) != 0 && coin(rng) == 0 && i != j) W(i, j) = 0;  // a zero, maybe stored
        if (W(i, j) != 0 || coin(rng) == 0) {
          t.emplace_back(i, j, W(i, j));
          ++stored[i];
        }
      }
    FrictionContactProblem p;
    p.W.resize(3, 3);
    p.W.setFromTriplets(t.begin(), t.end());
    p.q = q;
    p.mu = v1(mu);
    cpkit::Vec3 r;
    switch (trial % 5) {
      case 0: r.setZero(); break;
      case 1: r = cpkit::Vec3(g(rng), g(rng), g(rng)); break;
      case 2: r = 1e13 * cpkit::Vec3(1, g(rng), g(rng)); break;
      case 3: r = W.fullPivLu().solve(-q); break;  // stick force (in the cone or not)
      default: {  // W diagonal: r_N = max(0, -q_N / W_NN), r_T the projected stick force
        const double rn = q[0] < 0 && W(0, 0) > 0 ? -q[0] / W(0, 0) : 0;
        cpkit::Vec3 s(rn, -q[1] / W(1, 1), -q[2] / W(2, 2));
        const double nt = s.tail<2>().norm();
        if (nt > mu * rn) s.tail<2>() *= mu * rn / nt;
        r = s.allFinite() ? s : cpkit::Vec3::Zero();
      }
    }
    SolveResult s = claim(r);
    s = cpkit::finalize(p, s, CommonOptions{});
    cpkit::Vec3 u;
    const double fast = cpkit::one_contact_unit_free(W, stored, q, mu, r, u);
    INFO("trial " << trial);
    REQUIRE(std::memcmp(&fast, &s.residuals.natural, sizeof fast) == 0);
    for (int i = 0; i < 3; ++i) REQUIRE(u[i] == s.w[i]);
    ++compared;
    if (s.status == Status::kSolved) ++solved;
  }
  CHECK(compared == 3000);
  CHECK(solved >= 300);  // the accepted side of the verdict is exercised too
  cpkit::Vec3 u;
  const int stored[3] = {1, 1, 1};
  CHECK(std::isinf(cpkit::one_contact_unit_free(cpkit::Mat3::Identity(), stored,
                                                cpkit::Vec3(-1, 0, 0), 0.5,
                                                cpkit::Vec3(NAN, 0, 0), u)));
}
