// Tests of the faceted LCP and Lemke on it (friction/faceted.hpp). Expected values: the
// closed forms of friction_examples.hpp, the faceted closed form derived below by hand, the
// LCP conditions recomputed here, and every r re-checked by violation() of friction_examples.hpp.
#include <catch2/catch.hpp>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::FacetedLemkeOptions;
using cpkit::lcp::friction::solve_faceted_lemke;
using cpkit::test::DiagContact;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("faceted LCP: the rows are Signorini, slip speed and the k-gon (hand check)",
          "[friction][faceted]") {
  // One contact, W = diag(2, 1, 1), q = (-4, 3, -4), mu = 0.5, k = 4 (d = +-x, +-y).
  const auto p = cpkit::test::diagonal_problem({{2.0, 1.0, 0.5, Eigen::Vector3d(-4, 3, -4)}});
  const auto f = cpkit::lcp::friction::faceted_lcp(p, 4);
  REQUIRE(f.lcp.size() == 6);
  CHECK(std::abs(f.facet_error - (1 - std::sqrt(0.5))) < 1e-15);
  // z = (r_N, b0..b3, lambda): w_rN = 2 r_N - 4; w_b0 = (b0 - b2) + 3 + lambda (d0 = +x);
  // w_b1 = (b1 - b3) - 4 + lambda; w_lambda = 0.5 r_N - sum b.
  Eigen::VectorXd z(6);
  z << 2, 0.1, 0.2, 0.3, 0.4, 7;
  const Eigen::VectorXd w = f.lcp.M * z + f.lcp.q;
  CHECK(std::abs(w[0] - 0) < 1e-14);
  CHECK(std::abs(w[1] - ((0.1 - 0.3) + 3 + 7)) < 1e-14);
  CHECK(std::abs(w[2] - ((0.2 - 0.4) - 4 + 7)) < 1e-14);
  CHECK(std::abs(w[3] - (-(0.1 - 0.3) - 3 + 7)) < 1e-14);
  CHECK(std::abs(w[5] - (0.5 * 2 - 1.0)) < 1e-14);
  CHECK((f.G * z - Eigen::Vector3d(2, 0.1 - 0.3, 0.2 - 0.4)).norm() < 1e-15);
}

TEST_CASE("faceted Lemke: stick and separation are exact; slip is the faceted closed form",
          "[friction][faceted]") {
  FacetedLemkeOptions raw;
  raw.polish = false;
  for (const DiagContact& c : {DiagContact{2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},
                               DiagContact{2.0, 1.0, 0.3, Eigen::Vector3d(0.5, 1.0, -2.0)}}) {
    const auto p = cpkit::test::diagonal_problem({c});
    const auto res = solve_faceted_lemke(p, raw);
    INFO(res.message);
    REQUIRE(res.status == Status::kSolved);
    CHECK((res.z - cpkit::test::diagonal_closed_form(c)).norm() <=
          1e-12 * std::max(1.0, res.z.norm()));
  }
  // Slip with q_T along the middle of a facet, e = (cos pi/k, sin pi/k): the faceted solution
  // is the facet's midpoint, r = r_N (1, -mu cos(pi/k) e), r_N = -q_N / wn (u_T = (|q_T| -
  // wt mu r_N cos(pi/k)) e is along the facet's outward normal -e reversed, as the faceted law
  // asks, when |q_T| > wt mu r_N cos(pi/k)).
  const int k = 8;
  const Eigen::Vector2d e(std::cos(kPi / k), std::sin(kPi / k));
  const DiagContact c{2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 5 * e[0], 5 * e[1])};
  const auto p = cpkit::test::diagonal_problem({c});
  const auto res = solve_faceted_lemke(p, raw);
  INFO(res.message);
  const double rN = 2, t = -0.5 * rN * std::cos(kPi / k);
  CHECK((res.z - Eigen::Vector3d(rN, t * e[0], t * e[1])).norm() <= 1e-12);
  CHECK_FALSE(cpkit::is_solution(res.status));  // off the true cone by the facet error
  CHECK(res.message.find("faceted") != std::string::npos);
  CHECK(res.message.find("7.61 %") != std::string::npos);  // 1 - cos(pi/8) = 0.0761
  // Polished: the true closed form.
  const auto pol = solve_faceted_lemke(p);
  INFO(pol.message);
  REQUIRE(pol.status == Status::kSolved);
  CHECK((pol.z - cpkit::test::diagonal_closed_form(c)).norm() <= 1e-8);
  CHECK(cpkit::test::violation(p, pol.z) <= 1e-8);
}

TEST_CASE("faceted Lemke: rank-deficient box, registry, refusals", "[friction][faceted]") {
  cpkit::test::Box box;
  box.push = Eigen::Vector2d(3.0, 2.0);
  Eigen::MatrixXd H;
  const auto p = cpkit::test::box_problem(box, &H);
  const auto* e = cpkit::lcp::solvers().find("lemke");
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
  const auto big = solve_faceted_lemke(cpkit::test::diagonal_problem(many));
  CHECK(big.status == Status::kUnsupported);
  CHECK(big.message.find("at most 100 contacts") != std::string::npos);
  FacetedLemkeOptions bad;
  bad.facets = 2;
  CHECK_THROWS_AS(solve_faceted_lemke(p, bad), cpkit::InputError);
}

TEST_CASE("faceted Lemke: the same answer in other units", "[friction][faceted]") {
  const std::vector<DiagContact> cs = {{2.0, 1.0, 0.5, Eigen::Vector3d(-4.0, 0.3, -0.4)},
                                       {1.0, 4.0, 0.2, Eigen::Vector3d(-1.0, 6.0, 8.0)}};
  Eigen::VectorXd expect(6);
  expect << cpkit::test::diagonal_closed_form(cs[0]), cpkit::test::diagonal_closed_form(cs[1]);
  for (const double a : {1e-10, 1e10})
    for (const double b : {1e-8, 1e8}) {
      auto p = cpkit::test::diagonal_problem(cs);
      p.q *= a * b;  // r -> a r
      p.W *= b;
      const auto res = solve_faceted_lemke(p);
      INFO("a = " << a << ", b = " << b << ": " << res.message);
      REQUIRE(res.status == Status::kSolved);
      CHECK((res.z / a - expect).lpNorm<Eigen::Infinity>() <=
            1e-8 * expect.lpNorm<Eigen::Infinity>());
    }
}

TEST_CASE("faceted Lemke: an infeasible problem is reported, never solved", "[friction][faceted]") {
  // W = 0, q_N = -1: u_N = -1 < 0 for every r (hand check): no solution.
  cpkit::FrictionContactProblem p;
  p.W.resize(3, 3);
  p.q = Eigen::Vector3d(-1, 0.2, 0);
  p.mu = Eigen::VectorXd::Constant(1, 0.5);
  const auto res = solve_faceted_lemke(p);
  INFO(res.message);
  CHECK_FALSE(cpkit::is_solution(res.status));
  CHECK(res.status != Status::kInfeasible);  // no certificate for the true cone
  CHECK(res.message.find("faceted problem has no solution") != std::string::npos);
}

TEST_CASE("faceted Lemke: a time limit that runs out mid-solve is a time limit, never bad input",
          "[friction][faceted]") {
  // The polish on the true cone read the time left twice (check, then fb-soc's limit), and the
  // faceted solve passed what was left to the polish unchecked: a limit that ran out in between
  // reached a solver as time_limit_s <= 0, which solvers refuse as bad input (h64 found it in
  // prox). Limits from 10 us to 30 ms end the solve of Confeti-ex03 (54 contacts) at every stage.
  const auto p = cpkit::read_friction_problem(CPKIT_TEST_DATA_DIR
                                              "/fclib/local/Confeti-ex03-Fc3D-SBM.dat");
  const std::vector<double> limits = cpkit::test::time_limit_sweep(1e-5, 3e-2, 1.3);
  REQUIRE(limits.size() >= 30);
  for (double limit : limits) {
    INFO("time limit " << limit << " s");
    FacetedLemkeOptions o;
    o.common.time_limit_s = limit;
    cpkit::SolveResult r;
    REQUIRE_NOTHROW(r = solve_faceted_lemke(p, o));
    CHECK(r.status != Status::kNotRun);
  }
}
