// Tests of friction_solutions() (friction/solutions.hpp). Expected values: closed forms
// (friction_examples.hpp), the rigid box's equilibrium (Newton's law: H r = -f at rest), and
// every listed r re-checked by the independent De Saxce check of friction_check.hpp.
#include <catch2/catch.hpp>

#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/solutions.hpp"
#include "friction_check.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::friction_solutions;
using cpkit::lcp::friction::FrictionSolutionsOptions;

double rel_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() /
         std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>());
}

}  // namespace

TEST_CASE("solutions: a rigid box on 4 corners has a continuum: distinct verified solutions",
          "[friction][solutions]") {
  cpkit::test::Box box;
  Eigen::MatrixXd H;
  auto p = cpkit::test::box_problem(box, &H);
  FrictionSolutionsOptions o;
  o.starts = 6;
  o.max_enumeration_contacts = 0;  // the multistart route
  const auto set = friction_solutions(p, o);
  INFO(set.message);
  CHECK_FALSE(set.complete);
  REQUIRE(set.solutions.size() >= 2);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f[2] = -box.h * box.m * box.g;
  for (const auto& s : set.solutions) {
    CHECK(s.status == Status::kSolved);
    CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, s.z) <= 1e-8);
    CHECK((H * s.z + f).lpNorm<Eigen::Infinity>() <= 1e-8 * box.h * box.m * box.g);
  }
  for (std::size_t i = 0; i < set.solutions.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      CHECK(rel_distance(set.solutions[i].z, set.solutions[j].z) > 1e-6);
}

TEST_CASE("solutions: unique problems give one solution, the closed form", "[friction][solutions]") {
  const std::vector<cpkit::test::DiagContact> cs = {
      {2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},
      {1.0, 4.0, 0.2, Eigen::Vector3d(-1.0, 6.0, 8.0)}};
  const auto p = cpkit::test::diagonal_problem(cs);
  FrictionSolutionsOptions o;
  o.starts = 4;
  const auto set = friction_solutions(p, o);
  INFO(set.message);
  REQUIRE(set.solutions.size() == 1);
  Eigen::VectorXd expect(6);
  expect << cpkit::test::diagonal_closed_form(cs[0]), cpkit::test::diagonal_closed_form(cs[1]);
  CHECK(rel_distance(set.solutions[0].z, expect) <= 1e-8);
}

TEST_CASE("solutions: bad options are refused", "[friction][solutions]") {
  const auto p = cpkit::test::diagonal_problem({{1.0, 1.0, 0.5, Eigen::Vector3d(-1, 0, 0)}});
  FrictionSolutionsOptions o;
  o.starts = 0;
  CHECK_THROWS_AS(friction_solutions(p, o), cpkit::InputError);
}
