// Tests of the proximal point method for frictional contact (friction/prox.hpp). Expected
// values: the closed forms of friction_examples.hpp (derived there by hand), the rigid box's
// equilibrium (total impulses from Newton's law), and every result re-checked by the
// independent check violation() of friction_examples.hpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/lcp/friction/auto.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
using cpkit::lcp::friction::ProxOptions;
using cpkit::lcp::friction::solve_prox;
using cpkit::test::DiagContact;

// |F_nat| / |q| (FCLIB's and Siconos' error), written here from its definition: F = r -
// P_K(r - u_hat), u = W r + q, u_hat = (u_N + mu |u_T|, u_T), P_K the projection on the cone
// |x_T| <= mu x_N in closed form; no cpkit cone or verdict code.
double natural_map_error(const cpkit::FrictionContactProblem& p, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = Eigen::MatrixXd(p.W) * r + p.q;
  double sum = 0;
  for (Eigen::Index i = 0; i < p.mu.size(); ++i) {
    const double m = p.mu[i];
    const Eigen::Vector3d ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
    Eigen::Vector3d x = ri;
    x[0] -= ui[0] + m * ui.tail<2>().norm();
    x.tail<2>() -= ui.tail<2>();
    const double t = x.tail<2>().norm();
    Eigen::Vector3d proj = x;                          // inside the cone
    if (m * t <= -x[0]) proj.setZero();                // inside the polar cone
    else if (t > m * x[0]) {                           // onto the cone's edge
      const double a = (x[0] + m * t) / (1 + m * m);
      proj << a, m * a * x[1] / t, m * a * x[2] / t;
    }
    sum += (ri - proj).squaredNorm();
  }
  return std::sqrt(sum) / p.q.norm();
}

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
  ProxOptions bad_after_failure;
  bad_after_failure.shrink_after_failure = 0.5;
  CHECK_THROWS_AS(solve_prox(p, bad_after_failure), cpkit::InputError);
  bad_after_failure.shrink_after_failure = std::nan("");
  CHECK_THROWS_AS(solve_prox(p, bad_after_failure), cpkit::InputError);
  ProxOptions bad_cap;
  bad_cap.newton_after_failure = -1;
  CHECK_THROWS_AS(solve_prox(p, bad_cap), cpkit::InputError);
  ProxOptions bad_full_step;
  bad_full_step.full_step_below = 2;  // a step length: at most the full step, 1
  CHECK_THROWS_AS(solve_prox(p, bad_full_step), cpkit::InputError);
  cpkit::lcp::friction::FbSocOptions bad_fb;
  bad_fb.full_step_below = -0.5;
  CHECK_THROWS_AS(cpkit::lcp::friction::solve_fb_soc(p, bad_fb), cpkit::InputError);
  p.mu[0] = -1;
  CHECK_THROWS_AS(solve_prox(p), cpkit::InputError);
}

TEST_CASE("prox: real files to |F_nat|/|q| <= 1e-8, in at most Siconos PROX's outer iterations",
          "[friction][prox]") {
  // PROX's outer iterations: Debian's Siconos 4.4.0, fc3d_driver with SICONOS_FRICTION_3D_PROX
  // defaults, tol 1e-8, from r = 0 (docs/benchmarks.md, h59).
  struct Case {
    const char* file;
    int prox_outer;
  };
  const Case cases[] = {{"Confeti-ex03-Fc3D-SBM.dat", 56},
                        {"Rover1039.dat", 27},
                        {"NESpheres_10_1.dat", 7},
                        {"FC3D_Example1.dat", 6}};
  const cpkit::SolverEntry entry = cpkit::lcp::friction::prox_entry();
  int decided = 0;
  for (const Case& c : cases) {
    INFO(c.file);
    const auto p = cpkit::read_friction_problem(CPKIT_TEST_DATA_DIR "/fclib/local/" +
                                                std::string(c.file));
    cpkit::CommonOptions o;
    o.tol = 1e-8;
    const cpkit::SolveResult r = cpkit::lcp::friction::solve_in_measure(
        p, entry, o, cpkit::FrictionMeasure::kRelativeQ);
    CHECK(r.status == Status::kSolved);
    REQUIRE(r.z.size() == p.q.size());
    CHECK(natural_map_error(p, r.z) <= 1e-8);
    CHECK(cpkit::test::violation(p, r.z) <= 1e-6);
    CHECK(r.iterations <= c.prox_outer);  // outer iterations over every solve of the measure
    ++decided;
  }
  REQUIRE(decided == 4);
}

TEST_CASE("prox: the rank-deficient BoxesStack1 with each inner solver", "[friction][prox]") {
  // 52 contacts, W of rank 78 / 156: the Alart-Curnier inner solve (the default) and the FB one
  // both reach |F_nat|/|q| <= 1e-8 by the check above.
  const auto p = cpkit::read_friction_problem(CPKIT_TEST_DATA_DIR
                                              "/fclib/local/BoxesStack1-i100000-32.hdf5.dat");
  for (const auto inner : {cpkit::lcp::friction::ProxInner::kAlartCurnier,
                           cpkit::lcp::friction::ProxInner::kFbSoc}) {
    ProxOptions o;
    o.inner = inner;
    o.common.tol = 1e-8;
    const cpkit::SolveResult r = solve_prox(p, o);
    CHECK(r.status == Status::kSolved);
    REQUIRE(r.z.size() == p.q.size());
    CHECK(natural_map_error(p, r.z) <= 1e-8);
  }
}

TEST_CASE("prox: after an inner solve fails, alpha falls gently and inner solves are cut short",
          "[friction][prox]") {
  // W = H^T H with H 30 x 60 (rank 30, 20 contacts: more contact rows than body coordinates),
  // mu = 1 as on RockPile_tob1, seeded: a problem where prox's inner Newton fails at the
  // smallest alphas. After a failure, alpha / 30 (h64's rule) then alpha * 10 again wasted the
  // failed solves' Newton steps (50 each); alpha / 3 and inner solves of at most 15 steps waste
  // fewer. Both answers are checked by the natural map written above.
  std::mt19937 rng(10);
  cpkit::FrictionContactProblem p = cpkit::test::rigid_like(rng, 20, 30);
  p.mu.setConstant(1.0);
  REQUIRE(Eigen::FullPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(p.W)).rank() == 30);
  ProxOptions gentle;
  gentle.common.tol = 1e-8;
  ProxOptions steep = gentle;
  steep.shrink_after_failure = steep.shrink;  // the rule before: alpha / 30 after a failure too,
  steep.newton_after_failure = 0;             // and every inner solve to fb-soc's own stop
  // "..., N inner solves not converged, ..." (prox's message)
  auto failures = [](const cpkit::SolveResult& r) {
    const std::size_t end = r.message.find(" inner solves not converged");
    REQUIRE(end != std::string::npos);
    const std::size_t begin = r.message.rfind(' ', end - 1) + 1;
    return std::stoi(r.message.substr(begin, end - begin));
  };
  const cpkit::SolveResult a = solve_prox(p, gentle), b = solve_prox(p, steep);
  INFO(a.message << " | " << b.message);
  REQUIRE(a.status == Status::kSolved);
  REQUIRE(b.status == Status::kSolved);
  CHECK(natural_map_error(p, a.z) <= 1e-8);
  CHECK(natural_map_error(p, b.z) <= 1e-8);
  CHECK(failures(b) >= 2);  // the case exercises the rule
  CHECK(failures(a) >= 1);
  CHECK(a.function_evals < b.function_evals);  // inner Newton steps
}

TEST_CASE("prox and auto: a time limit that runs out mid-solve is a time limit, never bad input",
          "[friction][prox]") {
  // prox read the time left twice (check, then the inner solve's limit); between the two reads
  // it could pass 0, and fb-soc refused the limit <= 0 as bad input ("time_limit_s must be > 0",
  // RockPile_tob1 at 40 s, h64); auto read it twice the same way. Limits from 10 us to 10 ms
  // end the solve at every stage of BoxesStack1 (prox solves it in about 0.1 s).
  const auto p = cpkit::read_friction_problem(CPKIT_TEST_DATA_DIR
                                              "/fclib/local/BoxesStack1-i100000-32.hdf5.dat");
  const std::vector<double> limits = cpkit::test::time_limit_sweep(1e-5, 1e-2, 1.25);
  REQUIRE(limits.size() >= 30);
  for (double limit : limits) {
    INFO("time limit " << limit << " s");
    ProxOptions o;
    o.common.tol = 1e-8;
    o.common.time_limit_s = limit;
    cpkit::SolveResult r;
    REQUIRE_NOTHROW(r = solve_prox(p, o));
    CHECK((r.status == Status::kTimeLimit || cpkit::is_solution(r.status)));
    REQUIRE_NOTHROW(r = cpkit::lcp::friction::solve_auto(p, o.common));
    // Solved, or cut by the clock: never the unverified answer's own status (iteration_limit,
    // stalled), which would say the chain failed where it only ran out of time.
    CHECK((r.status == Status::kTimeLimit || cpkit::is_solution(r.status)));
  }
}
