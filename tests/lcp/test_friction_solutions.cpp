// Tests of friction_solutions() (friction/solutions.hpp). Expected values: closed forms
// (friction_examples.hpp), the rigid box's equilibrium (Newton's law: H r = -f at rest), and
// every listed r re-checked by the independent check violation() of friction_examples.hpp.
#include <catch2/catch.hpp>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/friction/solutions.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::friction_solutions;
using cpkit::lcp::friction::FrictionSolutionsOptions;

double rel_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double d = (a - b).lpNorm<Eigen::Infinity>();
  return d == 0 ? 0.0 : d / std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>());
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
    CHECK(cpkit::test::violation(p, s.z) <= 1e-8);
    CHECK((H * s.z + f).lpNorm<Eigen::Infinity>() <= 1e-8 * box.h * box.m * box.g);
  }
  for (std::size_t i = 0; i < set.solutions.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      CHECK(rel_distance(set.solutions[i].z, set.solutions[j].z) > 1e-6);
  // At rest every corner sticks (u = 0, Newton's law above): the distinct r are ONE continuum,
  // reported as one family sharing u, whose r span an affine set of dimension >= 1 (issue 34).
  REQUIRE(set.families.size() == 1);
  CHECK(set.families[0].members.size() == set.solutions.size());
  CHECK(set.families[0].dimension() >= 1);
  CHECK(set.families[0].dimension() <= static_cast<int>(set.solutions.size()) - 1);
  // Its basis spans the differences of the members (orthonormal columns).
  const Eigen::MatrixXd& B = set.families[0].basis;
  CHECK((B.transpose() * B - Eigen::MatrixXd::Identity(B.cols(), B.cols())).norm() <= 1e-12);
  for (const auto& s : set.solutions) {
    const Eigen::VectorXd d = s.z - set.solutions[0].z;
    CHECK((d - B * (B.transpose() * d)).lpNorm<Eigen::Infinity>() <= 1e-6 * s.z.lpNorm<Eigen::Infinity>());
  }
  // The continuum claim, checked independently: the midpoint of two members solves the problem.
  const Eigen::VectorXd mid = 0.5 * (set.solutions[0].z + set.solutions[1].z);
  CHECK(cpkit::test::violation(p, mid) <= 1e-8);
  CHECK(set.message.find("one continuum") != std::string::npos);
}

TEST_CASE("solutions: unique problems give one solution, the closed form",
          "[friction][solutions]") {
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

namespace {

// A contact (W symmetric positive definite) with three solutions, separation and two slips,
// both for the true cone (h13's closed forms, one_contact.hpp) and for the 4-facet pyramid (the
// brute force below); found by a search over W = A A^T with random one-decimal A.
cpkit::FrictionContactProblem three_solution_contact(bool with_second_contact) {
  Eigen::Matrix3d W;
  W << 0.19, 1.31, -0.31, 1.31, 12.11, -1.89, -0.31, -1.89, 0.77;
  cpkit::FrictionContactProblem p;
  const int nc = with_second_contact ? 2 : 1;
  Eigen::MatrixXd Wd = Eigen::MatrixXd::Zero(3 * nc, 3 * nc);
  Wd.topLeftCorner<3, 3>() = W;
  p.q.resize(3 * nc);
  p.q.head<3>() << 0.1, -0.5, -1.1;
  p.mu.resize(nc);
  p.mu[0] = 0.9;
  if (with_second_contact) {  // decoupled, sticking: one solution
    Wd.bottomRightCorner<3, 3>() = Eigen::Vector3d(2, 1, 1).asDiagonal();
    p.q.tail<3>() << -4.0, 0.3, -0.4;
    p.mu[1] = 0.5;
  }
  p.W = Wd.sparseView();
  return p;
}

// Every complementary basis of the LCP (2^n), solved here with a full-pivoting LU; the
// feasible ones mapped to r = G z and deduplicated (relative 1e-6).
std::vector<Eigen::VectorXd> brute_force_r(const cpkit::lcp::friction::FacetedLcp& f) {
  const Eigen::MatrixXd& M = f.lcp.M;
  const Eigen::VectorXd& q = f.lcp.q;
  const int n = static_cast<int>(q.size());
  std::vector<Eigen::VectorXd> out;
  for (long mask = 0; mask < (1L << n); ++mask) {
    std::vector<int> S;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) S.push_back(i);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    if (!S.empty()) {
      Eigen::MatrixXd A(S.size(), S.size());
      Eigen::VectorXd b(S.size());
      for (std::size_t a = 0; a < S.size(); ++a) {
        b[a] = -q[S[a]];
        for (std::size_t c = 0; c < S.size(); ++c) A(a, c) = M(S[a], S[c]);
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
      if (!lu.isInvertible()) continue;
      const Eigen::VectorXd x = lu.solve(b);
      for (std::size_t a = 0; a < S.size(); ++a) z[S[a]] = x[a];
    }
    const Eigen::VectorXd w = M * z + q;
    const double zs = std::max(z.lpNorm<Eigen::Infinity>(), 1e-300);
    if (z.minCoeff() < -1e-9 * zs ||
        w.minCoeff() < -1e-9 * std::max(1.0, q.lpNorm<Eigen::Infinity>()))
      continue;
    const Eigen::VectorXd r = f.G * z;
    bool seen = false;
    for (const auto& y : out)
      seen = seen ||
             (r - y).lpNorm<Eigen::Infinity>() <=
                 1e-6 * std::max({r.lpNorm<Eigen::Infinity>(), y.lpNorm<Eigen::Infinity>(), 1.0});
    if (!seen) out.push_back(r);
  }
  return out;
}

}  // namespace

TEST_CASE("faceted enumeration: the count and the r's match a brute force over all bases",
          "[friction][solutions]") {
  for (const bool two : {false, true}) {
    const auto p = three_solution_contact(two);
    const auto fs = cpkit::lcp::friction::faceted_solutions(p, 4, 1e-8, 10);
    INFO(fs.message);
    CHECK(fs.complete);
    const auto bf = brute_force_r(fs.faceted);
    REQUIRE(bf.size() == 3);  // the search found 3 on the one contact; the second adds none
    REQUIRE(fs.r.size() == bf.size());
    for (const auto& r : fs.r) {
      double best = 1e300;
      for (const auto& y : bf) best = std::min(best, rel_distance(r, y));
      CHECK(best <= 1e-9);
    }
  }
}

TEST_CASE("solutions: every exact one-contact solution is found and verified",
          "[friction][solutions]") {
  // Peer: h13's closed forms of one contact (one_contact.hpp) list every solution.
  const auto p = three_solution_contact(false);
  const Eigen::Matrix3d W = Eigen::MatrixXd(p.W);
  const auto exact = cpkit::lcp::friction::one_contact_solutions(W, p.q.head<3>(), p.mu[0]);
  REQUIRE(exact.count == 3);
  FrictionSolutionsOptions o;
  o.starts = 8;
  const auto set = friction_solutions(p, o);
  INFO(set.message);
  CHECK_FALSE(set.complete);
  CHECK(set.message.find("complete for the faceted problem") != std::string::npos);
  CHECK(static_cast<int>(set.solutions.size()) == exact.count);
  for (int i = 0; i < exact.count; ++i) {
    double best = 1e300;
    for (const auto& s : set.solutions) best = std::min(best, rel_distance(s.z, exact.r[i]));
    CHECK(best <= 1e-8);
  }
  for (const auto& s : set.solutions) CHECK(cpkit::test::violation(p, s.z) <= 1e-8);
}

TEST_CASE("solutions: the same three solutions in other units", "[friction][solutions]") {
  const auto base = three_solution_contact(false);
  const Eigen::Matrix3d W = Eigen::MatrixXd(base.W);
  const auto exact = cpkit::lcp::friction::one_contact_solutions(W, base.q.head<3>(), base.mu[0]);
  REQUIRE(exact.count == 3);
  for (const double a : {1e-9, 1e9})
    for (const double b : {1e-6, 1e6}) {
      auto p = base;
      p.q *= a * b;  // r -> a r
      p.W *= b;
      FrictionSolutionsOptions o;
      o.starts = 4;
      const auto set = friction_solutions(p, o);
      INFO("a = " << a << ", b = " << b << ": " << set.message);
      REQUIRE(set.solutions.size() == 3);
      for (int i = 0; i < exact.count; ++i) {
        double best = 1e300;
        for (const auto& s : set.solutions)
          best = std::min(best, rel_distance(s.z / a, exact.r[i]));
        CHECK(best <= 1e-8);
      }
    }
}
