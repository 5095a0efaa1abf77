// Tests of the proximal point method for frictional contact (friction/prox.hpp). Expected
// values: the closed forms of friction_examples.hpp (derived there by hand), the rigid box's
// equilibrium (total impulses from Newton's law), and every result re-checked by the
// independent check violation() of friction_examples.hpp.
#include <catch2/catch.hpp>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::ProxOptions;
using cpkit::lcp::friction::solve_prox;
using cpkit::test::DiagContact;

}  // namespace

TEST_CASE("prox: one contact, the three closed forms", "[friction][prox]") {
  const DiagContact cases[] = {
      {2.0, 1.0, 0.3, Eigen::Vector3d(0.5, 1.0, -2.0)},   // separation
      {2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},  // stick: |q_T|/wt = 0.5 <= 0.5*2
      {2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 3.0, -4.0)},  // slip: 5 > 1
      {1.0, 3.0, 0.0, Eigen::Vector3d(-1.0, 3.0, -4.0)},  // frictionless
  };
  for (const DiagContact& c : cases) {
    const auto p = cpkit::test::diagonal_problem({c});
    const auto res = solve_prox(p);
    INFO(res.message);
    REQUIRE(res.status == Status::kSolved);
    const Eigen::Vector3d expect = cpkit::test::diagonal_closed_form(c);
    CHECK((res.z - expect).lpNorm<Eigen::Infinity>() <=
          1e-8 * std::max(1.0, expect.lpNorm<Eigen::Infinity>()));
    CHECK(cpkit::test::violation(p, res.z) <= 1e-8);
  }
}

TEST_CASE("prox: two decoupled contacts, and the same problem in other units", "[friction][prox]") {
  const std::vector<DiagContact> cs = {{2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},
                                       {1.0, 4.0, 0.2, Eigen::Vector3d(-1.0, 6.0, 8.0)}};
  Eigen::VectorXd expect(6);
  expect << cpkit::test::diagonal_closed_form(cs[0]), cpkit::test::diagonal_closed_form(cs[1]);
  for (const double a : {1.0, 1e-9, 1e9}) {
    for (const double b : {1.0, 1e-7, 1e7}) {
      auto p = cpkit::test::diagonal_problem(cs);
      p.q *= a * b;  // q -> a q (r -> a r), then (W, q) -> b (W, q) (r unchanged)
      p.W *= b;
      const auto res = solve_prox(p);
      INFO("a = " << a << ", b = " << b << ": " << res.message);
      REQUIRE(res.status == Status::kSolved);
      CHECK((res.z / a - expect).lpNorm<Eigen::Infinity>() <=
            1e-8 * expect.lpNorm<Eigen::Infinity>());
      CHECK(cpkit::test::violation(p, res.z) <= 1e-8);
    }
  }
}

TEST_CASE("prox: rank-deficient W of a rigid box on 4 corners (12 rows, rank 6)",
          "[friction][prox]") {
  cpkit::test::Box box;
  box.push = Eigen::Vector2d(1.0, -0.5);  // mu m g = 9.8 > |push|: the box sticks
  Eigen::MatrixXd H;
  const auto p = cpkit::test::box_problem(box, &H);
  REQUIRE(Eigen::FullPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(p.W)).rank() == 6);
  const auto res = solve_prox(p);
  INFO(res.message);
  REQUIRE(res.status == Status::kSolved);
  CHECK(cpkit::test::violation(p, res.z) <= 1e-8);
  // At rest: H r = -f, i.e. total normal impulse m g h, tangential -h push, no moment.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f << box.h * box.push[0], box.h * box.push[1], -box.h * box.m * box.g, 0, 0, 0;
  CHECK((H * res.z + f).lpNorm<Eigen::Infinity>() <= 1e-8 * box.h * box.m * box.g);
}

TEST_CASE("prox: registered, refuses bad input", "[friction][prox]") {
  const auto* e = cpkit::lcp::solvers().find("prox");
  REQUIRE(e != nullptr);
  REQUIRE(e->accepts(cpkit::ProblemKind::kFrictionContact));
  CHECK_FALSE(e->accepts(cpkit::ProblemKind::kLcp));
  auto p = cpkit::test::diagonal_problem({{1.0, 1.0, 0.5, Eigen::Vector3d(-1, 0, 0)}});
  ProxOptions o;
  o.r0 = Eigen::VectorXd::Zero(2);
  CHECK_THROWS_AS(solve_prox(p, o), cpkit::InputError);
  ProxOptions bad_alpha0;
  bad_alpha0.alpha0 = -1;
  CHECK_THROWS_AS(solve_prox(p, bad_alpha0), cpkit::InputError);
  ProxOptions bad_shrink;
  bad_shrink.shrink = 0.5;  // alpha would grow after every converged inner solve
  CHECK_THROWS_AS(solve_prox(p, bad_shrink), cpkit::InputError);
  p.mu[0] = -1;
  CHECK_THROWS_AS(solve_prox(p), cpkit::InputError);
}
