// Tests of the Ipopt friction fallback (friction/ipopt_fc.hpp). Expected values: the closed
// forms of friction_examples.hpp, the rigid box's equilibrium (H r = -f at rest), and every r
// re-checked by the independent check violation() of friction_examples.hpp.
#include <catch2/catch.hpp>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/ipopt_fc.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::IpoptFcOptions;
using cpkit::lcp::friction::solve_ipopt_fc;
using cpkit::test::DiagContact;

}  // namespace

TEST_CASE("ipopt fc: one contact closed forms, two decoupled contacts in other units",
          "[friction][ipopt]") {
  const DiagContact cases[] = {
      {2.0, 1.0, 0.3, Eigen::Vector3d(0.5, 1.0, -2.0)},   // separation
      {2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},  // stick
      {2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 3.0, -4.0)},  // slip
  };
  for (const DiagContact& c : cases) {
    const auto p = cpkit::test::diagonal_problem({c});
    const auto res = solve_ipopt_fc(p);
    INFO(res.message);
    REQUIRE(res.status == Status::kSolved);
    const Eigen::Vector3d expect = cpkit::test::diagonal_closed_form(c);
    CHECK((res.z - expect).lpNorm<Eigen::Infinity>() <= 1e-8 * std::max(1.0, expect.norm()));
    CHECK(cpkit::test::violation(p, res.z) <= 1e-8);
  }
  const std::vector<DiagContact> cs = {cases[1], cases[2]};
  Eigen::VectorXd expect(6);
  expect << cpkit::test::diagonal_closed_form(cs[0]), cpkit::test::diagonal_closed_form(cs[1]);
  for (const double a : {1e-8, 1e8}) {
    auto p = cpkit::test::diagonal_problem(cs);
    p.q *= a;
    p.W *= 1 / a;  // r -> a^2 r
    const auto res = solve_ipopt_fc(p);
    INFO(res.message);
    REQUIRE(res.status == Status::kSolved);
    CHECK((res.z / (a * a) - expect).lpNorm<Eigen::Infinity>() <= 1e-8 * expect.norm());
  }
}

TEST_CASE("ipopt fc: rank-deficient box, registry, refusals", "[friction][ipopt]") {
  cpkit::test::Box box;
  box.push = Eigen::Vector2d(3.0, 2.0);
  Eigen::MatrixXd H;
  const auto p = cpkit::test::box_problem(box, &H);
  const auto* e = cpkit::lcp::solvers().find("ipopt");
  REQUIRE(e != nullptr);
  REQUIRE(e->accepts(cpkit::ProblemKind::kFrictionContact));
  REQUIRE(e->accepts(cpkit::ProblemKind::kLcp));
  const auto res = e->solve_fc(p, {});
  INFO(res.message);
  REQUIRE(res.status == Status::kSolved);
  CHECK(cpkit::test::violation(p, res.z) <= 1e-8);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f << box.h * box.push[0], box.h * box.push[1], -box.h * box.m * box.g, 0, 0, 0;
  CHECK((H * res.z + f).lpNorm<Eigen::Infinity>() <= 1e-8 * box.h * box.m * box.g);

  std::vector<DiagContact> many(101, DiagContact{1.0, 1.0, 0.5, Eigen::Vector3d(-1, 0, 0)});
  const auto big = solve_ipopt_fc(cpkit::test::diagonal_problem(many));
  CHECK(big.status == Status::kUnsupported);
  CHECK(big.message.find("at most 100 contacts") != std::string::npos);
  IpoptFcOptions bad;
  bad.r0 = Eigen::VectorXd::Zero(5);
  CHECK_THROWS_AS(solve_ipopt_fc(p, bad), cpkit::InputError);
}
