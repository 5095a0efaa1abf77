// The registry's two general friction solvers, nsgs (nsgs.hpp) and fb-soc (fb_soc.hpp), run by
// name on the same problems: every solve re-checked here by the test's own computation
// (friction_check.hpp: u recomputed densely, the three conditions of De Saxce's form checked
// directly), on random full-rank and rank-deficient Delassus operators, closed forms and scales.
// What differs between them (iteration counts, accuracy of the closed form) is in kCases.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using cpkit::test::rigid_like;

struct Case {
  const char* name;
  int max_iterations_one_contact;  // nsgs: one sweep is exact for W = I; fb-soc: Newton steps
  int min_iterations_one_contact;
  double closed_form_tol;
};
const Case kCases[] = {{"nsgs", 1, 1, 1e-14}, {"fb-soc", 20, 0, 1e-9}};

cpkit::SolveResult solve(const std::string& name, const FrictionContactProblem& p,
                         const cpkit::CommonOptions& o = {}) {
  const auto* e = cpkit::lcp::solvers().find(name);
  REQUIRE(e != nullptr);
  return e->solve_fc(p, o);
}

}  // namespace

TEST_CASE("nsgs and fb-soc solve random problems; the test re-checks every solution",
          "[friction][nsgs][fb-soc]") {
  const Case c = GENERATE(from_range(std::begin(kCases), std::end(kCases)));
  CAPTURE(c.name);
  cpkit::test::check_random_rigid_problems([&](const FrictionContactProblem& p) {
    cpkit::CommonOptions o;
    o.tol = 1e-10;
    o.max_iterations = 5000;
    return solve(c.name, p, o);
  });
}

TEST_CASE("nsgs and fb-soc: one contact with W = I converges to the closed form",
          "[friction][nsgs][fb-soc]") {
  const Case c = GENERATE(from_range(std::begin(kCases), std::end(kCases)));
  CAPTURE(c.name);
  FrictionContactProblem p;
  p.W = MatrixXd::Identity(3, 3).sparseView();
  p.q = (VectorXd(3) << -2, 3, 4).finished();
  p.mu = VectorXd::Constant(1, 0.5);
  const auto res = solve(c.name, p);
  REQUIRE(res.status == Status::kSolved);
  CHECK(res.iterations <= c.max_iterations_one_contact);
  CHECK(res.iterations >= c.min_iterations_one_contact);
  CHECK((res.z - (VectorXd(3) << 2, -0.6, -0.8).finished()).norm() < c.closed_form_tol);
}

TEST_CASE("nsgs and fb-soc: a zero diagonal block and a singular one are regularised",
          "[friction][nsgs][fb-soc]") {
  const Case c = GENERATE(from_range(std::begin(kCases), std::end(kCases)));
  CAPTURE(c.name);
  // Contact 0: W_00 = diag(1, 0, 0) (singular), q_0 = (-1, 0, 0): r_0 = (1, 0, 0).
  // Contact 1: W_11 = 0, q_1 = (2, 1, 0): separated, r_1 = 0 (any r_1 with u_1 = q_1 fixed in
  // K* ... r_1 = 0 is the one NSGS reaches from 0).
  MatrixXd W = MatrixXd::Zero(6, 6);
  W(0, 0) = 1;
  FrictionContactProblem p;
  p.W = W.sparseView();
  p.q = (VectorXd(6) << -1, 0, 0, 2, 1, 0).finished();
  p.mu = VectorXd::Constant(2, 0.3);
  const auto res = solve(c.name, p);
  REQUIRE(res.status == Status::kSolved);
  CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, res.z) < 1e-9);
}

TEST_CASE("nsgs and fb-soc: the same verdict at every scale of q and of (W, q)",
          "[friction][nsgs][fb-soc]") {
  const Case c = GENERATE(from_range(std::begin(kCases), std::end(kCases)));
  CAPTURE(c.name);
  std::mt19937 rng(11);
  auto p = rigid_like(rng, 4, 14);
  for (int i = 0; i < 4; ++i) p.q[3 * i] = -std::abs(p.q[3 * i]);
  const auto base = solve(c.name, p);
  REQUIRE(base.status == Status::kSolved);
  for (double a : {1e-12, 1e-6, 1e6, 1e12}) {
    CAPTURE(a);
    auto pa = p;
    pa.q *= a;
    const auto ra = solve(c.name, pa);
    CHECK(ra.status == Status::kSolved);
    CHECK((ra.z / a - base.z).norm() <= 1e-6 * base.z.norm());
    auto pb = p;
    pb.W *= a;
    pb.q *= a;
    const auto rb = solve(c.name, pb);
    CHECK(rb.status == Status::kSolved);
    CHECK((rb.z - base.z).norm() <= 1e-6 * base.z.norm());
  }
}

TEST_CASE("nsgs and fb-soc are registered for friction problems only",
          "[friction][nsgs][fb-soc]") {
  const Case c = GENERATE(from_range(std::begin(kCases), std::end(kCases)));
  CAPTURE(c.name);
  const auto* e = cpkit::lcp::solvers().find(c.name);
  REQUIRE(e != nullptr);
  CHECK(e->accepts(cpkit::ProblemKind::kFrictionContact));
  CHECK_FALSE(e->accepts(cpkit::ProblemKind::kLcp));
}

TEST_CASE("nsgs and fb-soc: bad input throws a named error", "[friction][nsgs][fb-soc]") {
  FrictionContactProblem p;
  p.W = MatrixXd::Identity(3, 3).sparseView();
  p.q = VectorXd::Zero(4);
  p.mu = VectorXd::Constant(1, 0.5);
  CHECK_THROWS_WITH(cpkit::lcp::friction::solve_nsgs(p), Catch::Contains("q has 4 entries"));
  CHECK_THROWS_WITH(cpkit::lcp::friction::solve_fb_soc(p), Catch::Contains("q has 4 entries"));
  for (const Case& c : kCases) {
    CAPTURE(c.name);
    CHECK_THROWS_WITH(solve(c.name, p), Catch::Contains("q has 4 entries"));
  }
}

TEST_CASE("nsgs: a contact that keeps its state takes the closed forms' closest solution",
          "[friction][nsgs]") {
  // nsgs answers a contact that stays separated, sticking (3x3 inverse) or slipping (Newton on
  // the slip direction) without the closed forms of every solution (nsgs.cpp). Reference: the
  // closed forms themselves (one_contact_nearest). One contact, so one sweep is one local step
  // with b = q, started next to each solution s of a random problem: r0 = 0 at a separation,
  // s moved inside the cone at a stick, s moved along the cone's boundary at a slip.
  std::mt19937 rng(35);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> uni(0.1, 1.0);
  int stick = 0, slip = 0, separation = 0;
  for (int k = 0; k < 500; ++k) {
    Eigen::Matrix3d L;
    for (int i = 0; i < 9; ++i) L(i / 3, i % 3) = g(rng);
    const Eigen::Matrix3d W = L * L.transpose() + 0.3 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d q(g(rng), g(rng), g(rng));
    const double mu = uni(rng);
    FrictionContactProblem p;
    p.W = MatrixXd(W).sparseView();
    p.q = q;
    p.mu = VectorXd::Constant(1, mu);
    const auto all = cpkit::lcp::friction::one_contact_solutions(W, q, mu);
    for (int j = 0; j < all.count; ++j) {
      const Eigen::Vector3d s = all.r[j];
      Eigen::Vector3d r0 = s;
      const double rt = s.tail<2>().norm();
      if (s.isZero(0)) {
        ++separation;
      } else if (rt < 0.99 * mu * s[0]) {
        r0 = s * (1 + 1e-6);  // inside the cone still
        ++stick;
      } else if (rt > 0 && std::abs(rt - mu * s[0]) <= 1e-9 * s[0]) {
        const double phi = std::atan2(-s[2], -s[1]) + 1e-4;  // on the boundary, turned
        r0 = s[0] * (1 + 1e-5) * Eigen::Vector3d(1, -mu * std::cos(phi), -mu * std::sin(phi));
        ++slip;
      } else {
        continue;  // a stick at the cone's edge: either branch may be the closer
      }
      cpkit::lcp::friction::NsgsOptions o;
      o.r0 = r0;
      o.common.max_iterations = 1;
      o.common.tol = 1e-15;
      const auto r = cpkit::lcp::friction::solve_nsgs(p, o);
      const Eigen::Vector3d ref = cpkit::lcp::friction::one_contact_nearest(W, q, mu, r0);
      CAPTURE(k, j, s.transpose(), r.z.transpose(), ref.transpose());
      CHECK((r.z - ref).norm() <= 1e-9 * std::max(1.0, ref.norm()));
    }
  }
  // Every branch of the local step was exercised.
  CHECK(stick >= 30);
  CHECK(slip >= 30);
  CHECK(separation >= 30);
}
