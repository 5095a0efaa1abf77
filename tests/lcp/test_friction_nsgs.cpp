// NSGS on frictional contact problems (nsgs.hpp): every solve re-checked here by the test's own
// computation (friction_check.hpp: u recomputed densely, the three conditions of De Saxce's form
// checked directly), on random full-rank and rank-deficient Delassus operators and at scales.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using cpkit::test::rigid_like;

}  // namespace

TEST_CASE("nsgs solves random problems; the test re-checks every solution", "[friction][nsgs]") {
  cpkit::test::check_random_rigid_problems([](const FrictionContactProblem& p) {
    cpkit::lcp::friction::NsgsOptions o;
    o.common.tol = 1e-10;
    o.common.max_iterations = 5000;
    return cpkit::lcp::friction::solve_nsgs(p, o);
  });
}

TEST_CASE("nsgs: one contact with W = I converges in one sweep to the closed form",
          "[friction][nsgs]") {
  FrictionContactProblem p;
  p.W = MatrixXd::Identity(3, 3).sparseView();
  p.q = (VectorXd(3) << -2, 3, 4).finished();
  p.mu = VectorXd::Constant(1, 0.5);
  const auto res = cpkit::lcp::friction::solve_nsgs(p);
  REQUIRE(res.status == Status::kSolved);
  CHECK(res.iterations == 1);
  CHECK((res.z - (VectorXd(3) << 2, -0.6, -0.8).finished()).norm() < 1e-14);
}

TEST_CASE("nsgs: a zero diagonal block and a singular one are regularised", "[friction][nsgs]") {
  // Contact 0: W_00 = diag(1, 0, 0) (singular), q_0 = (-1, 0, 0): r_0 = (1, 0, 0).
  // Contact 1: W_11 = 0, q_1 = (2, 1, 0): separated, r_1 = 0 (any r_1 with u_1 = q_1 fixed in
  // K* ... r_1 = 0 is the one NSGS reaches from 0).
  MatrixXd W = MatrixXd::Zero(6, 6);
  W(0, 0) = 1;
  FrictionContactProblem p;
  p.W = W.sparseView();
  p.q = (VectorXd(6) << -1, 0, 0, 2, 1, 0).finished();
  p.mu = VectorXd::Constant(2, 0.3);
  const auto res = cpkit::lcp::friction::solve_nsgs(p);
  REQUIRE(res.status == Status::kSolved);
  CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, res.z) < 1e-9);
}

TEST_CASE("nsgs: the same verdict at every scale of q and of (W, q)", "[friction][nsgs]") {
  std::mt19937 rng(11);
  auto p = rigid_like(rng, 4, 14);
  for (int i = 0; i < 4; ++i) p.q[3 * i] = -std::abs(p.q[3 * i]);
  const auto base = cpkit::lcp::friction::solve_nsgs(p);
  REQUIRE(base.status == Status::kSolved);
  for (double a : {1e-12, 1e-6, 1e6, 1e12}) {
    auto pa = p;
    pa.q *= a;
    const auto ra = cpkit::lcp::friction::solve_nsgs(pa);
    CHECK(ra.status == Status::kSolved);
    CHECK((ra.z / a - base.z).norm() <= 1e-6 * base.z.norm());
    auto pb = p;
    pb.W *= a;
    pb.q *= a;
    const auto rb = cpkit::lcp::friction::solve_nsgs(pb);
    CHECK(rb.status == Status::kSolved);
    CHECK((rb.z - base.z).norm() <= 1e-6 * base.z.norm());
  }
}

TEST_CASE("nsgs is registered for friction problems only", "[friction][nsgs]") {
  const auto* e = cpkit::lcp::solvers().find("nsgs");
  REQUIRE(e != nullptr);
  CHECK(e->accepts(cpkit::ProblemKind::kFrictionContact));
  CHECK_FALSE(e->accepts(cpkit::ProblemKind::kLcp));
}

TEST_CASE("nsgs: bad input throws a named error", "[friction][nsgs]") {
  FrictionContactProblem p;
  p.W = MatrixXd::Identity(3, 3).sparseView();
  p.q = VectorXd::Zero(4);
  p.mu = VectorXd::Constant(1, 0.5);
  CHECK_THROWS_WITH(cpkit::lcp::friction::solve_nsgs(p), Catch::Contains("q has 4 entries"));
}
