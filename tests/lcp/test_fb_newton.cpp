// Tests of the Fischer-Burmeister semismooth Newton method on NCPs and MCPs (fb_newton.hpp).
// The problems are those of shared/problems/ncp.md, written here as C++ callbacks with their
// known solutions from the literature (closed forms are derived in the comments); every answer
// is also re-checked here against the MCP conditions computed in this file.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/fb_newton.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace {

using cpkit::Mat;
using cpkit::McpProblem;
using cpkit::SolveResult;
using cpkit::Status;
using cpkit::Vec;
using cpkit::lcp::FbNewtonOptions;
using cpkit::lcp::solve_fb_newton;

constexpr double kInf = std::numeric_limits<double>::infinity();

// MCP conditions checked here from F and the bounds: l <= x <= u and, per component,
// x_i = l_i => F_i >= 0, x_i = u_i => F_i <= 0, inside => F_i = 0; returns the largest violation
// of ||x - mid(l, u, x - F)||_inf (the natural residual, written out independently).
double mcp_violation(const McpProblem& p, const Vec& x) {
  Vec F(p.n);
  if (!p.F(x, F)) return kInf;
  double v = 0;
  for (Eigen::Index i = 0; i < p.n; ++i) {
    double proj = x[i] - F[i];
    if (proj < p.lower[i]) proj = p.lower[i];
    if (proj > p.upper[i]) proj = p.upper[i];
    v = std::max(v, std::abs(x[i] - proj));
  }
  return v;
}

McpProblem make_box(Eigen::Index n, cpkit::FunctionCallback F, cpkit::JacobianCallback J,
                    const Vec& l, const Vec& u, std::string name) {
  McpProblem p;
  p.n = n;
  p.F = std::move(F);
  p.jacobian = std::move(J);
  p.lower = l;
  p.upper = u;
  p.name = std::move(name);
  return p;
}

// billups: F(x) = (x - 1)^2 - 1.01 on x >= 0 [Billups 1995; MCPLIB billups]. From x = 0 the FB
// merit has a local minimizer near x = -0.005 that is not a solution (min-map Newton fails,
// monotone FB Newton stalls there); the watchdog escape must reach x* = 1 + sqrt(1.01).
McpProblem billups() {
  auto p = cpkit::make_ncp(
      1,
      [](const Vec& x, Vec& F) {
        F.resize(1);
        F[0] = (x[0] - 1) * (x[0] - 1) - 1.01;
        return true;
      },
      [](const Vec& x, Mat& J) {
        J.resize(1, 1);
        J(0, 0) = 2 * (x[0] - 1);
        return true;
      },
      "billups");
  p.x0 = Vec::Zero(1);
  return p;
}

// munson1: F = (x1 + 2x2 + 3x3 - 1, x2 - x3 + 1, x1 + x2 + 1), x >= 0; unique solution (1, 0, 0)
// (F = (0, 1, 2) there) [MCPLIB munson1].
McpProblem munson1() {
  return cpkit::make_ncp(
      3,
      [](const Vec& x, Vec& F) {
        F.resize(3);
        F << x[0] + 2 * x[1] + 3 * x[2] - 1, x[1] - x[2] + 1, x[0] + x[1] + 1;
        return true;
      },
      [](const Vec&, Mat& J) {
        J.resize(3, 3);
        J << 1, 2, 3, 0, 1, -1, 1, 1, 0;
        return true;
      },
      "munson1");
}

// PATH C-API example (test_Example): F = M z + q on [0, 10]^4, solution (2.8, 0, 0.8, 1.2).
Mat path_M() {
  Mat M(4, 4);
  M << 0, 0, -1, -1, 0, 0, 1, -2, 1, -1, 2, -2, 1, 2, -2, 4;
  return M;
}
Vec path_q() {
  Vec q(4);
  q << 2, 2, -2, -6;
  return q;
}

// PATH C-API example II: nonlinear F on [0, 10]^4, interior solution
// (1.28475, 0.972916, 0.909376, 1.17304) (to about 6 digits).
McpProblem path_nonlinear_box() {
  return make_box(
      4,
      [](const Vec& x, Vec& F) {
        F.resize(4);
        F[0] = -x[2] * x[2] - x[3] + 2;
        F[1] = x[2] * x[2] * x[2] - 2 * x[3] * x[3] + 2;
        F[2] = std::pow(x[0], 5) - x[1] + 2 * x[2] - 2 * x[3] - 2;
        F[3] = x[0] + 2 * x[1] * x[1] * x[1] - 2 * x[2] + 4 * x[3] - 6;
        return true;
      },
      [](const Vec& x, Mat& J) {
        J.setZero(4, 4);
        J(0, 2) = -2 * x[2];
        J(0, 3) = -1;
        J(1, 2) = 3 * x[2] * x[2];
        J(1, 3) = -4 * x[3];
        J(2, 0) = 5 * std::pow(x[0], 4);
        J(2, 1) = -1;
        J(2, 2) = 2;
        J(2, 3) = -2;
        J(3, 0) = 1;
        J(3, 1) = 6 * x[1] * x[1];
        J(3, 2) = -2;
        J(3, 3) = 4;
        return true;
      },
      Vec::Zero(4), Vec::Constant(4, 10.0), "path_nonlinear_box");
}

// Modified Mathiesen NCP (ncp.md): solution set {(t, 0, 0, 0): 0 <= t <= 3}, all degenerate.
// F is undefined at x2 = -1 or x3 = -1 (the callback says so). No Jacobian: finite differences.
McpProblem mathiesen_modified() {
  return cpkit::make_ncp(
      4,
      [](const Vec& x, Vec& F) {
        if (x[1] <= -1 || x[2] <= -1) return false;
        F.resize(4);
        F[0] = -x[1] + x[2] + x[3];
        F[1] = x[0] - (4.5 * x[2] + 2.7 * x[3]) / (x[1] + 1);
        F[2] = 5 - x[0] - (0.5 * x[2] + 0.3 * x[3]) / (x[2] + 1);
        F[3] = 3 - x[0];
        return true;
      },
      {}, "mathiesen_modified");
}

}  // namespace

TEST_CASE("Billups: FB with the watchdog escapes the merit's local minimizer", "[fb][ncp]") {
  const auto p = billups();
  FbNewtonOptions o;
  o.common.record_trace = true;
  const auto r = solve_fb_newton(p, o);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z[0] == Approx(1 + std::sqrt(1.01)).epsilon(1e-12));
  CHECK(mcp_violation(p, r.z) <= 1e-10);
  // The escape happened (the monotone method alone stalls near x = -0.005).
  bool watchdog = false;
  for (const auto& e : r.trace) watchdog = watchdog || e.kind == "watchdog";
  CHECK(watchdog);

  SECTION("without the watchdog the method stalls at the local minimizer, never 'solved'") {
    FbNewtonOptions plain;
    plain.watchdog_steps = 0;
    const auto s = solve_fb_newton(p, plain);
    CHECK_FALSE(cpkit::is_solution(s.status));
    CHECK(s.z[0] == Approx(-0.005).margin(1e-3));
  }
}

TEST_CASE("munson1 from the origin", "[fb][ncp]") {
  const auto p = munson1();
  const auto r = solve_fb_newton(p);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z[0] == Approx(1).epsilon(1e-9));
  CHECK(std::abs(r.z[1]) <= 1e-9);
  CHECK(std::abs(r.z[2]) <= 1e-9);
  CHECK(mcp_violation(p, r.z) <= 1e-9);
  CHECK(r.jacobian_evals >= 1);
  CHECK(r.function_evals >= r.iterations + 1);

  SECTION("the same with finite differences (no Jacobian callback)") {
    auto q = munson1();
    q.jacobian = {};
    const auto s = solve_fb_newton(q);
    REQUIRE(s.status == Status::kSolved);
    CHECK(s.z[0] == Approx(1).epsilon(1e-8));
    // Each finite-difference Jacobian costs n = 3 evaluations of F.
    CHECK(s.function_evals >= s.iterations + 1 + 3 * s.jacobian_evals);
  }
  SECTION("non-monotone line search and penalized FB reach the same point") {
    FbNewtonOptions o;
    o.nonmonotone_memory = 5;
    o.penalty_lambda = 0.8;
    const auto s = solve_fb_newton(p, o);
    REQUIRE(s.status == Status::kSolved);
    CHECK(s.z[0] == Approx(1).epsilon(1e-9));
  }
}

TEST_CASE("PATH linear example on the box [0, 10]^4 (MCP and box LCP)", "[fb][mcp]") {
  const Mat M = path_M();
  const Vec q = path_q();
  Vec expected(4);
  expected << 2.8, 0, 0.8, 1.2;
  // Hand check of the stated solution: w = M z + q = (0, 0.4, 0, 0), z2 = 0 at its lower bound
  // with w2 >= 0, the others strictly inside with w = 0.
  const Vec w = M * expected + q;
  REQUIRE(std::abs(w[0]) < 1e-12);
  REQUIRE(w[1] == Approx(0.4));

  cpkit::BoxLcpProblem box{cpkit::LcpProblem(M, q, "path_linear_box"), Vec::Zero(4),
                           Vec::Constant(4, 10.0)};
  const auto rb = solve_fb_newton(box);
  REQUIRE(rb.status == Status::kSolved);
  CHECK((rb.z - expected).lpNorm<Eigen::Infinity>() <= 1e-9);

  const auto mcp = cpkit::box_lcp_as_mcp(box);
  const auto rm = solve_fb_newton(mcp);
  REQUIRE(rm.status == Status::kSolved);
  CHECK((rm.z - expected).lpNorm<Eigen::Infinity>() <= 1e-9);

  SECTION("sparse Jacobian callback (SparseLU path)") {
    McpProblem s = cpkit::box_lcp_as_mcp(box);
    const cpkit::SparseMat Ms = M.sparseView();
    s.jacobian = {};
    s.sparse_jacobian = [Ms](const Vec&, cpkit::SparseMat& J) {
      J = Ms;
      return true;
    };
    const auto rs = solve_fb_newton(s);
    REQUIRE(rs.status == Status::kSolved);
    CHECK((rs.z - expected).lpNorm<Eigen::Infinity>() <= 1e-9);
  }
}

TEST_CASE("PATH nonlinear example on the box [0, 10]^4", "[fb][mcp]") {
  const auto p = path_nonlinear_box();
  const auto r = solve_fb_newton(p);
  REQUIRE(r.status == Status::kSolved);
  Vec expected(4);
  expected << 1.28475, 0.972916, 0.909376, 1.17304;
  CHECK((r.z - expected).lpNorm<Eigen::Infinity>() <= 2e-5);
  // Interior solution: F = 0 there (checked here).
  Vec F(4);
  REQUIRE(p.F(r.z, F));
  CHECK(F.lpNorm<Eigen::Infinity>() <= 1e-9);
}

TEST_CASE("Siconos mixed MCP with a free variable", "[fb][mcp]") {
  // z1 free, z2 >= 0; F = (2 z1 + z2 - 5, z1 + 2 z2 - 6). Hand solution: F = 0 gives
  // z = (4/3, 7/3), and z2 > 0 is consistent.
  McpProblem p = make_box(
      2,
      [](const Vec& z, Vec& F) {
        F.resize(2);
        F << 2 * z[0] + z[1] - 5, z[0] + 2 * z[1] - 6;
        return true;
      },
      [](const Vec&, Mat& J) {
        J.resize(2, 2);
        J << 2, 1, 1, 2;
        return true;
      },
      Vec::Constant(2, 0.0), Vec::Constant(2, kInf), "siconos_mcp_mixed");
  p.lower[0] = -kInf;
  const auto r = solve_fb_newton(p);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z[0] == Approx(4.0 / 3).epsilon(1e-10));
  CHECK(r.z[1] == Approx(7.0 / 3).epsilon(1e-10));

  SECTION("a free variable whose solution is negative, and an upper-bounded one") {
    // z1 free, z2 <= 1 (l = -inf): F = (z1 + 3, z2 + 4) -> z1 = -3; z2 = 1 would need F2 <= 0
    // but F2 = 5 > 0, so z2 decreases without a lower bound to F2 = 0: z2 = -4.
    McpProblem s = make_box(
        2,
        [](const Vec& z, Vec& F) {
          F.resize(2);
          F << z[0] + 3, z[1] + 4;
          return true;
        },
        {}, Vec::Constant(2, -kInf), Vec::Constant(2, kInf), "free_and_upper");
    s.upper[1] = 1;
    const auto t = solve_fb_newton(s);
    REQUIRE(t.status == Status::kSolved);
    CHECK(t.z[0] == Approx(-3).epsilon(1e-10));
    CHECK(t.z[1] == Approx(-4).epsilon(1e-10));
  }
}

TEST_CASE("modified Mathiesen: any point of the solution segment is right", "[fb][ncp]") {
  const auto p = mathiesen_modified();
  for (const double s : {0.0, 1.0}) {
    CAPTURE(s);
    FbNewtonOptions o;
    o.x0 = Vec::Constant(4, s);
    o.common.tol = 1e-8;  // degenerate solutions: linear convergence near the segment
    const auto r = solve_fb_newton(p, o);
    REQUIRE(cpkit::is_solution(r.status));
    CHECK(r.z[0] >= -1e-6);
    CHECK(r.z[0] <= 3 + 1e-6);
    CHECK(std::abs(r.z[1]) <= 1e-6);
    CHECK(std::abs(r.z[2]) <= 1e-6);
    CHECK(std::abs(r.z[3]) <= 1e-6);
    CHECK(mcp_violation(p, r.z) <= 1e-6);
  }
}

TEST_CASE("domain errors in F shorten the step instead of failing", "[fb][ncp][domain]") {
  // NCP F(x) = 8 - x^1.5 (undefined for x < 0): two solutions, x = 0 (F = 8 >= 0) and x = 4
  // (F = 0, 4^1.5 = 8). From x = 1
  // (F = 7) the full Newton step leaves the domain: a = 1, b = 7, r = sqrt(50), Phi = 8 - r,
  // H = (1 - 1/r) + (1 - 7/r)(-1.5) = 0.8444..., x + d = 1 - Phi/H = -0.1013 (hand calculation),
  // so the line search must treat the undefined F as "step too long".
  for (const bool report_false : {true, false}) {
    CAPTURE(report_false);
    int outside = 0;
    auto p = cpkit::make_ncp(
        1,
        [&outside, report_false](const Vec& x, Vec& F) {
          F.resize(1);
          if (x[0] < 0) {
            ++outside;
            if (report_false) return false;
          }
          F[0] = 8 - std::pow(x[0], 1.5);  // NaN for x < 0 when not reported
          return true;
        },
        [](const Vec& x, Mat& J) {
          if (x[0] < 0) return false;
          J.resize(1, 1);
          J(0, 0) = -1.5 * std::sqrt(x[0]);
          return true;
        },
        "pow_domain");
    FbNewtonOptions o;
    o.x0 = Vec::Constant(1, 1.0);
    const auto r = solve_fb_newton(p, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK((std::abs(r.z[0]) <= 1e-9 || std::abs(r.z[0] - 4) <= 1e-9));
    CHECK(outside > 0);
  }

  SECTION("F undefined at the starting point: a numerical failure, not an exception") {
    auto p = cpkit::make_ncp(1, [](const Vec& x, Vec& F) {
      F.resize(1);
      F[0] = std::log(x[0]);  // -inf at 0
      return true;
    });
    const auto r = solve_fb_newton(p);
    CHECK(r.status == Status::kNumericalFailure);
    CHECK_FALSE(r.message.empty());
  }
}

TEST_CASE("singular Newton matrices fall back to gradient steps", "[fb][singular]") {
  // LCP with M = [[1,1,0],[1,1,0],[0,0,1]], q = (-2,-2,-1) from x0 = (1,1,5): F = (0,0,4), so the
  // first two rows of H are rows of M (Da = 0, Db = 1): identical, H is singular. The gradient
  // of Psi is along x3 only; z* = (1,1,1) solves it (w = 0), found by hand.
  Mat M(3, 3);
  M << 1, 1, 0, 1, 1, 0, 0, 0, 1;
  Vec q(3);
  q << -2, -2, -1;
  auto p = cpkit::lcp_as_mcp(cpkit::LcpProblem(M, q, "singular_rows"));
  FbNewtonOptions o;
  o.x0 = Vec(3);
  o.x0 << 1, 1, 5;
  const auto r = solve_fb_newton(p, o);
  CHECK(r.gradient_steps > 0);
  REQUIRE(cpkit::is_solution(r.status));
  CHECK(mcp_violation(p, r.z) <= 1e-8);

  SECTION("a stationary point of the merit with a singular Jacobian ends without a solution") {
    // Free variable, F(x) = x^2 + 1 has no zero; at x0 = 0, F' = 0 and grad Psi = 0.
    McpProblem s = make_box(
        1,
        [](const Vec& x, Vec& F) {
          F.resize(1);
          F[0] = x[0] * x[0] + 1;
          return true;
        },
        [](const Vec& x, Mat& J) {
          J.resize(1, 1);
          J(0, 0) = 2 * x[0];
          return true;
        },
        Vec::Constant(1, -kInf), Vec::Constant(1, kInf), "no_root");
    const auto t = solve_fb_newton(s);
    CHECK(t.status == Status::kStalled);
    CHECK_FALSE(cpkit::is_solution(t.status));
  }
}

TEST_CASE("warm start, trace and counters", "[fb][trace]") {
  const auto p = munson1();
  SECTION("warm start at the solution needs no iteration") {
    FbNewtonOptions o;
    o.x0 = Vec(3);
    o.x0 << 1, 0, 0;
    const auto r = solve_fb_newton(p, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK(r.iterations == 0);
  }
  SECTION("trace: one start row plus one row per iteration, residuals as finalize measures") {
    FbNewtonOptions o;
    o.common.record_trace = true;
    const auto r = solve_fb_newton(p, o);
    REQUIRE(r.status == Status::kSolved);
    REQUIRE(r.trace.size() == static_cast<size_t>(r.iterations) + 1);
    CHECK(r.trace.front().kind == "start");
    CHECK(r.trace.back().residual == Approx(r.residuals.natural).margin(1e-15));
    for (size_t k = 1; k < r.trace.size(); ++k) {
      CHECK(r.trace[k].iteration == static_cast<int>(k));
      CHECK(r.trace[k].step > 0);
      CHECK(r.trace[k].step <= 1);
    }
  }
  SECTION("iteration limit: never solved, last point kept") {
    FbNewtonOptions o;
    o.common.max_iterations = 1;
    const auto r = solve_fb_newton(p, o);
    CHECK(r.status == Status::kIterationLimit);
    CHECK(r.iterations == 1);
  }
}

TEST_CASE("invalid input throws InputError naming the problem", "[fb][input]") {
  auto p = munson1();
  FbNewtonOptions o;
  o.x0 = Vec::Constant(3, std::nan(""));
  CHECK_THROWS_AS(solve_fb_newton(p, o), cpkit::InputError);
  o.x0 = Vec::Zero(2);
  CHECK_THROWS_AS(solve_fb_newton(p, o), cpkit::InputError);
  FbNewtonOptions bad;
  bad.armijo_sigma = 0.7;
  CHECK_THROWS_WITH(solve_fb_newton(p, bad), Catch::Contains("armijo_sigma"));
  bad = FbNewtonOptions{};
  bad.penalty_lambda = 0;
  CHECK_THROWS_WITH(solve_fb_newton(p, bad), Catch::Contains("penalty_lambda"));
  auto q = p;
  q.lower[1] = std::nan("");
  CHECK_THROWS_WITH(solve_fb_newton(q), Catch::Contains("munson1"));
}

TEST_CASE("registry entry fb-newton", "[fb][registry]") {
  const auto* e = cpkit::lcp::solvers().find("fb-newton");
  REQUIRE(e != nullptr);
  CHECK(e->info.sparse);
  CHECK(e->info.dense);
  REQUIRE(e->solve_lcp);
  REQUIRE(e->solve_box_lcp);
  REQUIRE(e->solve_mcp);
  const auto r = e->solve_mcp(munson1(), cpkit::CommonOptions{});
  CHECK(r.status == Status::kSolved);
  CHECK(r.solver == "fb-newton");
}
