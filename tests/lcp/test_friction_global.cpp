// Global friction problems by condensation (lcp/friction/global.hpp), on problems solved by hand.
#include <catch2/catch.hpp>

#include <Eigen/SparseCore>

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
