// Global friction problems by condensation (lcp/friction/global.hpp), on problems solved by hand.
#include <catch2/catch.hpp>

#include <Eigen/SparseCore>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/global.hpp"

namespace {

using Eigen::VectorXd;

cpkit::GlobalFrictionContactProblem one_contact(double m, double fn, double ft) {
  cpkit::GlobalFrictionContactProblem g;
  Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(3, 3);
  g.M = M.sparseView();
  g.H = Eigen::MatrixXd::Identity(3, 3).sparseView();
  g.f = VectorXd(3);
  g.f << fn, ft, 0;
  g.w = VectorXd::Zero(3);
  g.mu = VectorXd::Constant(1, 0.5);
  g.name = "hand";
  return g;
}

}  // namespace

// M = m I, H = I, w = 0: W = I / m, q = f / m. With f = (-4, 1, 0) and mu = 0.5 the contact
// sticks: r = (4, -1, 0) (|r_T| = 1 <= 2), u = 0, v = (H r + f) / m = 0.
// With f = (-4, 3, 0) it slips: r_T at the cone's edge, r = (4, -2, 0), u_N = 0, u_T = (1/m, 0).
TEST_CASE("global: one contact, stick and slip by hand, at every scale", "[friction][global]") {
  for (double m : {1e-9, 2.0, 1e9}) {
    for (double s : {1e-9, 1.0, 1e9}) {
      CAPTURE(m, s);
      const auto stick = cpkit::lcp::friction::solve_global(one_contact(m, -4 * s, 1 * s), "auto");
      CHECK(stick.result.status == cpkit::Status::kSolved);
      CHECK((stick.result.z - VectorXd((VectorXd(3) << 4 * s, -1 * s, 0).finished())).norm() <=
            1e-9 * s);
      CHECK(stick.v.norm() <= 1e-9 * s / m);
      const auto slip = cpkit::lcp::friction::solve_global(one_contact(m, -4 * s, 3 * s), "auto");
      CHECK(slip.result.status == cpkit::Status::kSolved);
      CHECK((slip.result.z - VectorXd((VectorXd(3) << 4 * s, -2 * s, 0).finished())).norm() <=
            1e-9 * s);
      CHECK((slip.v - VectorXd((VectorXd(3) << 0, s / m, 0).finished())).norm() <= 1e-9 * s / m);
      CHECK(slip.errors.balance <= 1e-14);
    }
  }
}

TEST_CASE("global: a singular or indefinite M is said, not solved", "[friction][global]") {
  auto g = one_contact(2.0, -4, 0);
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(3, 3);
  M(2, 2) = 0;  // a degree of freedom without mass
  g.M = M.sparseView();
  auto out = cpkit::lcp::friction::solve_global(g, "auto");
  CHECK(out.result.status == cpkit::Status::kNotRun);
  CHECK(!out.condensed.ok);
  CHECK(out.result.message.find("singular") != std::string::npos);
  M(2, 2) = -1;
  g.M = M.sparseView();
  out = cpkit::lcp::friction::solve_global(g, "auto");
  CHECK(out.result.status == cpkit::Status::kNotRun);
  CHECK(out.result.message.find("positive") != std::string::npos);
  CHECK_THROWS_AS(cpkit::lcp::friction::solve_global(g, "nope"), cpkit::InputError);
}

// The global proximal route on a singular M: M = diag(1, 1, 0) (the third degree of freedom
// has no mass), H = I, w = 0, mu = 0.5, f = (-4, 3, 1). By hand: row 3 of the balance,
// 0 v_2 = r_2 + f_2, forces r_2 = -1; u_N = v_0 = 0 with r_N = 4 (row 1: v_0 = r_N - 4);
// stick would need r_T = -(3, 1), |r_T| = 3.16 > mu r_N = 2: slip, r_T = -2 (cos t, sin t)
// with sin t = 1/2, so r = (4, -sqrt 3, -1); row 2: v_1 = 3 - sqrt 3; u_T parallel to
// (cos t, sin t): v_2 = v_1 tan t = (3 - sqrt 3) / sqrt 3 -- fixed by the friction law alone.
TEST_CASE("global proximal: a degree of freedom without mass, solved by hand at every scale",
          "[friction][global]") {
  for (double m : {1e-6, 1.0, 1e6}) {
    for (double s : {1e-6, 1.0, 1e6}) {
      CAPTURE(m, s);
      auto g = one_contact(m, -4 * s, 3 * s);
      Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(3, 3);
      M(2, 2) = 0;
      g.M = M.sparseView();
      g.f[2] = 1 * s;
      const auto plain = cpkit::lcp::friction::solve_global(g, "auto");
      CHECK(plain.result.status == cpkit::Status::kNotRun);  // unchanged: opt-in route only
      const auto out = cpkit::lcp::friction::solve_global_proximal(g, "auto");
      INFO(out.result.message);
      REQUIRE(out.result.status == cpkit::Status::kSolved);
      const double r3 = std::sqrt(3.0);
      const VectorXd r = (VectorXd(3) << 4, -r3, -1).finished() * s;
      const VectorXd v = (VectorXd(3) << 0, 3 - r3, (3 - r3) / r3).finished() * (s / m);
      CHECK((out.result.z - r).norm() <= 1e-7 * r.norm());
      CHECK((out.v - v).norm() <= 1e-7 * v.norm());
      CHECK(out.errors.balance <= 1e-10);
    }
  }
}

TEST_CASE("global proximal: no solution, never solved", "[friction][global]") {
  // As above with f_2 = 3: row 3 needs r_2 = -3, beyond the cone (|r_T| <= mu r_N = 2): the
  // massless degree of freedom cannot be held by friction; no (v, r) exists.
  auto g = one_contact(1.0, -4, 3);
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(3, 3);
  M(2, 2) = 0;
  g.M = M.sparseView();
  g.f[2] = 3;
  const auto out = cpkit::lcp::friction::solve_global_proximal(g, "auto");
  INFO(out.result.message);
  CHECK_FALSE(cpkit::is_solution(out.result.status));
  CHECK(out.result.status == cpkit::Status::kStalled);  // stopped early, not after 200 steps
}

TEST_CASE("global proximal: an M without scale is said, not solved", "[friction][global]") {
  auto g = one_contact(1.0, -4, 0);
  g.M = Eigen::MatrixXd::Zero(3, 3).sparseView();
  const auto out = cpkit::lcp::friction::solve_global_proximal(g, "auto");
  CHECK(out.result.status == cpkit::Status::kNotRun);
  CHECK(out.result.message.find("zero") != std::string::npos);
  CHECK_THROWS_AS(cpkit::lcp::friction::solve_global_proximal(g, "auto", {}, -1.0),
                  cpkit::InputError);
}
