// "auto" for frictional contact problems (friction/auto.hpp): the chain, its record of every
// attempt, and every answer re-checked by the test's own computation (friction_check.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/auto.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;

}  // namespace

TEST_CASE("auto: registered under the one name 'auto' for friction problems too",
          "[friction][auto]") {
  const auto* e = cpkit::lcp::solvers().find("auto");
  REQUIRE(e != nullptr);
  CHECK(e->accepts(cpkit::ProblemKind::kFrictionContact));
  CHECK(e->accepts(cpkit::ProblemKind::kLcp));
  const auto names = cpkit::lcp::solvers().names(cpkit::ProblemKind::kFrictionContact);
  CHECK(std::find(names.begin(), names.end(), "nsgs") != names.end());
  CHECK(std::find(names.begin(), names.end(), "fb-soc") != names.end());
}

TEST_CASE("auto: the first solver that verifies ends the chain; attempts recorded",
          "[friction][auto]") {
  // One contact, W = I, q = (-2, 3, 4): slip r = (2, -0.6, -0.8) (closed form).
  FrictionContactProblem p;
  p.W = MatrixXd::Identity(3, 3).sparseView();
  p.q = (VectorXd(3) << -2, 3, 4).finished();
  p.mu = VectorXd::Constant(1, 0.5);
  const auto r = cpkit::lcp::solvers().find("auto")->solve_fc(p, {});
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.solver == "nsgs");  // one sweep is exact for one contact
  REQUIRE(r.attempts.size() == 1);
  CHECK(r.attempts[0].solver == "nsgs");
  CHECK(r.attempts[0].status == Status::kSolved);
  CHECK((r.z - (VectorXd(3) << 2, -0.6, -0.8).finished()).norm() < 1e-9);
}

TEST_CASE("auto: when nsgs is stopped short, prox and fb-soc follow",
          "[friction][auto]") {
  std::mt19937 rng(23);
  std::normal_distribution<double> g;
  const int nc = 6, m = 10;  // rank 10 < 18
  MatrixXd H(m, 3 * nc);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < 3 * nc; ++j) H(i, j) = g(rng);
  VectorXd v(m);
  for (int i = 0; i < m; ++i) v[i] = g(rng);
  FrictionContactProblem p;
  p.W = (H.transpose() * H).sparseView();
  p.q = H.transpose() * v;
  for (int i = 0; i < nc; ++i) p.q[3 * i] = -std::abs(p.q[3 * i]);
  p.mu = VectorXd::Constant(nc, 0.4);
  cpkit::CommonOptions o;
  o.max_iterations = 1;  // every solver gets one iteration / sweep: the chain must go on
  const auto r = cpkit::lcp::friction::solve_auto(p, o);
  // nsgs (one sweep), prox, fb-soc (non-monotone, from the best r), fb-soc (monotone, r = 0).
  REQUIRE(r.attempts.size() >= 4);
  CHECK(r.attempts[0].solver == "nsgs");
  CHECK(r.attempts[1].solver == "prox");
  CHECK(r.attempts[2].solver == "fb-soc");
  CHECK(r.attempts[3].solver == "fb-soc");
  CHECK(r.attempts[3].message.find("monotone line search") == 0);
  for (const auto& a : r.attempts) CHECK(!a.solver.empty());
  if (cpkit::is_solution(r.status))
    CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, r.z) < 1e-6);
  // Without the limit: solved, and the test's own check agrees.
  const auto full = cpkit::lcp::friction::solve_auto(p, {});
  REQUIRE(full.status == Status::kSolved);
  CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, full.z) < 1e-7);
}

TEST_CASE("auto: an infeasible contact is never reported solved", "[friction][auto]") {
  // W = 0 on a contact with q_N = -1: u_N = -1 whatever r is.
  FrictionContactProblem p;
  p.W = MatrixXd::Zero(3, 3).sparseView();
  p.q = (VectorXd(3) << -1, 0, 0).finished();
  p.mu = VectorXd::Constant(1, 0.5);
  cpkit::CommonOptions o;
  o.max_iterations = 50;
  o.time_limit_s = 5;
  const auto r = cpkit::lcp::friction::solve_auto(p, o);
  CHECK_FALSE(cpkit::is_solution(r.status));
  CHECK(r.attempts.size() >= 2);
}

TEST_CASE("auto: an answer accepted only just is polished (FrictionContact3D_RR_1c, tol 1e-8)",
          "[friction][auto]") {
  // fb-soc stops at a unit-free 3.8e-9, which is 1.1e-7 by Acary-Bremond-Huber's |q|
  // normalisation; the polish must bring the test's own dense re-check below 1e-8 of |q| too.
  const auto p = cpkit::read_friction_problem(std::string(CPKIT_TEST_DATA_DIR) +
                                              "/fclib/local/FrictionContact3D_RR_1c.dat");
  cpkit::CommonOptions o;
  o.tol = 1e-8;
  const auto r = cpkit::lcp::solvers().find("auto")->solve_fc(p, o);
  REQUIRE(r.status == Status::kSolved);
  CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, r.z) < 1e-8);
  const Eigen::VectorXd u = MatrixXd(p.W) * r.z + p.q;
  double e2 = 0;  // the natural map's |.|^2 by hand: r_i - P_K(r_i - u_hat_i), one contact
  {
    const double mu = p.mu[0];
    const Eigen::Vector3d ri = r.z.head<3>(), ui = u.head<3>();
    Eigen::Vector3d y = ri - ui;
    y[0] -= mu * ui.tail<2>().norm();
    const double yn = y[0], yt = y.tail<2>().norm();
    Eigen::Vector3d proj = y;
    if (yt <= mu * yn) {
    } else if (mu * yt <= -yn) {
      proj.setZero();
    } else {
      const double a = (mu * yt + yn) / (mu * mu + 1);
      proj[0] = a;
      proj.tail<2>() = mu * a * y.tail<2>() / yt;
    }
    e2 = (ri - proj).squaredNorm();
  }
  CHECK(std::sqrt(e2) / p.q.norm() < 1e-8);
}
