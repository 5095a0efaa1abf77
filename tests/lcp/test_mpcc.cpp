// The MPCCs of shared/problems/mpcc.md (MacMPEC, Leyffer) solved by solve_mpcc with both
// reformulations and both NLP backends. Expected values are the hand-derived minimisers and
// objective values of mpcc.md, never the solver's own output.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/mpcc.hpp"
#include "test_budget.hpp"

using cpkit::Mat;
using cpkit::test::family_size;
using cpkit::Vec;
using namespace cpkit::lcp;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A test MPCC with its known answer.
struct Case {
  MpccProblem problem;
  double f_star = 0;
  Vec x_star;  ///< empty when only the objective is known
  double x_tol = 1e-6;
};

Vec v(std::initializer_list<double> list) {
  Vec r(static_cast<Eigen::Index>(list.size()));
  Eigen::Index i = 0;
  for (double d : list) r(i++) = d;
  return r;
}

/// Fills the objective callbacks from f, grad f and hess f.
template <class F, class Gr, class He>
void set_objective(MpccProblem& p, F f, Gr g, He h) {
  p.objective = [f](const Vec& x, double& out) { out = f(x); return true; };
  p.gradient = [g](const Vec& x, Vec& out) { out = g(x); return true; };
  // Only f (and, where noted, G) are nonlinear in these problems: c and H are linear.
  p.hessian = [h](const Vec& x, double sigma, const Vec&, const Vec&, const Vec&, Mat& Hs) {
    Hs = sigma * h(x);
    return true;
  };
}

/// Linear pairs G = A x + a, H = B x + b.
void set_linear_pairs(MpccProblem& p, Mat A, Vec a, Mat B, Vec b) {
  p.p = A.rows();
  p.G = [A, a](const Vec& x, Vec& out) { out = A * x + a; return true; };
  p.G_jacobian = [A](const Vec&, Mat& J) { J = A; return true; };
  p.H = [B, b](const Vec& x, Vec& out) { out = B * x + b; return true; };
  p.H_jacobian = [B](const Vec&, Mat& J) { J = B; return true; };
}

void set_linear_constraints(MpccProblem& p, Mat C, Vec lo, Vec hi) {
  p.m = C.rows();
  p.constraints = [C](const Vec& x, Vec& out) { out = C * x; return true; };
  p.constraint_jacobian = [C](const Vec&, Mat& J) { J = C; return true; };
  p.c_lower = lo;
  p.c_upper = hi;
}

Case ralph1() {
  Case c;
  auto& p = c.problem;
  p.name = "ralph1";
  p.n = 2;  // (x, y)
  p.lower = v({0, 0});
  p.upper = v({kInf, kInf});
  p.x0 = v({1, 1});  // not stated in mpcc.md; documented here
  set_objective(p, [](const Vec& x) { return 2 * x(0) - x(1); },
                [](const Vec&) { return v({2, -1}); }, [](const Vec&) { return Mat::Zero(2, 2); });
  Mat A(1, 2), B(1, 2);
  A << 0, 1;    // G = y
  B << -1, 1;   // H = y - x
  set_linear_pairs(p, A, v({0}), B, v({0}));
  c.f_star = 0;
  c.x_star = v({0, 0});
  return c;
}

Case ralph2() {
  Case c;
  auto& p = c.problem;
  p.name = "ralph2";
  p.n = 2;
  p.lower = v({0, -kInf});
  p.upper = v({kInf, kInf});
  p.x0 = v({1, 1});
  set_objective(
      p, [](const Vec& x) { return x(0) * x(0) + x(1) * x(1) - 4 * x(0) * x(1); },
      [](const Vec& x) { return v({2 * x(0) - 4 * x(1), 2 * x(1) - 4 * x(0)}); },
      [](const Vec&) {
        Mat h(2, 2);
        h << 2, -4, -4, 2;
        return h;
      });
  Mat A(1, 2), B(1, 2);
  A << 1, 0;
  B << 0, 1;
  set_linear_pairs(p, A, v({0}), B, v({0}));
  c.f_star = 0;
  c.x_star = v({0, 0});
  // Degenerate minimiser: on the piece x = 0 the bound y >= 0 is active with a zero multiplier,
  // which an interior-point method reaches only to O(sqrt(mu)).
  c.x_tol = 1e-5;
  return c;
}

/// scholtes1 (variant 1) and scholtes2 (variant 2): G = -e^x + y1 - e^{y2} is nonlinear.
Case scholtes12(int variant) {
  Case c;
  auto& p = c.problem;
  p.name = variant == 1 ? "scholtes1" : "scholtes2";
  p.n = 3;  // (x, y1, y2)
  p.lower = v({0, -kInf, -kInf});
  p.upper = v({kInf, kInf, kInf});
  p.x0 = v({1, 1, 1});
  const double a = variant == 1 ? 2.5 : 0.0, w = variant == 1 ? 1.0 : 10.0;
  p.objective = [a, w](const Vec& x, double& f) {
    f = std::pow(x(0) + 1, 2) + std::pow(x(1) - a, 2) + w * std::pow(x(2) + 1, 2);
    return true;
  };
  p.gradient = [a, w](const Vec& x, Vec& g) {
    g = v({2 * (x(0) + 1), 2 * (x(1) - a), 2 * w * (x(2) + 1)});
    return true;
  };
  p.hessian = [w](const Vec& x, double sigma, const Vec&, const Vec& lG, const Vec&, Mat& Hs) {
    Hs = Mat::Zero(3, 3);
    Hs(0, 0) = 2 * sigma - lG(0) * std::exp(x(0));
    Hs(1, 1) = 2 * sigma;
    Hs(2, 2) = 2 * w * sigma - lG(0) * std::exp(x(2));
    return true;
  };
  Mat C(1, 3);
  C << 0, 0, 1;  // y2 >= 0
  set_linear_constraints(p, C, v({0}), v({kInf}));
  p.p = 1;
  p.G = [](const Vec& x, Vec& G) {
    G = v({-std::exp(x(0)) + x(1) - std::exp(x(2))});
    return true;
  };
  p.G_jacobian = [](const Vec& x, Mat& J) {
    J.resize(1, 3);
    J << -std::exp(x(0)), 1, -std::exp(x(2));
    return true;
  };
  p.H = [](const Vec& x, Vec& H) { H = v({x(0)}); return true; };
  p.H_jacobian = [](const Vec&, Mat& J) {
    J.resize(1, 3);
    J << 1, 0, 0;
    return true;
  };
  c.f_star = variant == 1 ? 2.0 : 15.0;
  c.x_star = variant == 1 ? v({0, 2.5, 0}) : v({0, 2, 0});
  return c;
}

Case scholtes3() {
  Case c;
  auto& p = c.problem;
  p.name = "scholtes3";
  p.n = 2;
  p.lower = v({0, 0});
  p.upper = v({kInf, kInf});
  p.x0 = v({1e-4, 1e-4});  // next to the C-stationary point (0, 0)
  set_objective(p,
                [](const Vec& x) { return 0.5 * ((x(0) - 1) * (x(0) - 1) + (x(1) - 1) * (x(1) - 1)); },
                [](const Vec& x) { return v({x(0) - 1, x(1) - 1}); },
                [](const Vec&) { return Mat::Identity(2, 2); });
  Mat A(1, 2), B(1, 2);
  A << 1, 0;
  B << 0, 1;
  set_linear_pairs(p, A, v({0}), B, v({0}));
  c.f_star = 0.5;  // at (1, 0) or (0, 1): only the value is checked
  return c;
}

Case scholtes4() {
  Case c;
  auto& p = c.problem;
  p.name = "scholtes4";
  p.n = 3;
  p.lower = v({0, 0, -kInf});
  p.upper = v({kInf, kInf, kInf});
  p.x0 = v({1, 1, 1});  // not stated in mpcc.md; documented here
  set_objective(p, [](const Vec& x) { return x(0) + x(1) - x(2); },
                [](const Vec&) { return v({1, 1, -1}); }, [](const Vec&) { return Mat::Zero(3, 3); });
  Mat C(2, 3);
  C << 4, 0, -1, 0, 4, -1;
  set_linear_constraints(p, C, v({0, 0}), v({kInf, kInf}));
  Mat A(1, 3), B(1, 3);
  A << 1, 0, 0;
  B << 0, 1, 0;
  set_linear_pairs(p, A, v({0}), B, v({0}));
  c.f_star = 0;
  c.x_star = v({0, 0, 0});
  return c;
}

Case scholtes5() {
  Case c;
  auto& p = c.problem;
  p.name = "scholtes5";
  p.n = 3;
  p.lower = v({0, 0, 0});
  p.upper = v({kInf, kInf, kInf});
  p.x0 = v({1, 1, 1});  // not stated; documented here
  set_objective(
      p,
      [](const Vec& x) {
        return std::pow(x(0) - 1, 2) + std::pow(x(1) - 2, 2) + std::pow(x(2) + 1, 2);
      },
      [](const Vec& x) { return v({2 * (x(0) - 1), 2 * (x(1) - 2), 2 * (x(2) + 1)}); },
      [](const Vec&) { return Mat(2 * Mat::Identity(3, 3)); });
  Mat A(2, 3), B(2, 3);
  A << 1, 0, 0, 0, 1, 0;
  B << 0, 0, 1, 0, 0, 1;
  set_linear_pairs(p, A, v({0, 0}), B, v({0, 0}));
  c.f_star = 1;
  c.x_star = v({1, 2, 0});
  return c;
}

Case bard1() {
  Case c;
  auto& p = c.problem;
  p.name = "bard1";
  p.n = 5;  // (x, y, l1, l2, l3)
  p.lower = Vec::Zero(5);
  p.upper = Vec::Constant(5, kInf);
  p.x0 = Vec::Zero(5);  // not stated; documented here
  set_objective(
      p, [](const Vec& x) { return std::pow(x(0) - 5, 2) + std::pow(2 * x(1) + 1, 2); },
      [](const Vec& x) { return v({2 * (x(0) - 5), 4 * (2 * x(1) + 1), 0, 0, 0}); },
      [](const Vec&) {
        Mat h = Mat::Zero(5, 5);
        h(0, 0) = 2;
        h(1, 1) = 8;
        return h;
      });
  Mat C(1, 5);
  C << -1.5, 2, 1, -0.5, 1;  // 2(y - 1) - 1.5 x + l1 - 0.5 l2 + l3 = 0
  set_linear_constraints(p, C, v({2}), v({2}));
  Mat A(3, 5), B(3, 5);
  A << 3, -1, 0, 0, 0, -1, 0.5, 0, 0, 0, -1, -1, 0, 0, 0;
  B << 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1;
  set_linear_pairs(p, A, v({-3, 4, 7}), B, v({0, 0, 0}));
  c.f_star = 17;
  c.x_star = v({1, 0, 3.5, 0, 0});
  return c;
}

Case jr(int variant) {
  Case c;
  auto& p = c.problem;
  p.name = variant == 1 ? "jr1" : "jr2";
  p.n = 2;
  p.lower = v({-kInf, 0});
  p.upper = v({kInf, kInf});
  p.x0 = v({0, 0});  // not stated; documented here
  if (variant == 1)
    set_objective(p, [](const Vec& x) { return std::pow(x(0) - 1, 2) + x(1) * x(1); },
                  [](const Vec& x) { return v({2 * (x(0) - 1), 2 * x(1)}); },
                  [](const Vec&) { return Mat(2 * Mat::Identity(2, 2)); });
  else
    set_objective(p, [](const Vec& x) { return std::pow(x(1) - 1, 2) + x(0) * x(0); },
                  [](const Vec& x) { return v({2 * x(0), 2 * (x(1) - 1)}); },
                  [](const Vec&) { return Mat(2 * Mat::Identity(2, 2)); });
  Mat A(1, 2), B(1, 2);
  A << 0, 1;
  B << -1, 1;
  set_linear_pairs(p, A, v({0}), B, v({0}));
  c.f_star = 0.5;
  c.x_star = v({0.5, 0.5});
  return c;
}

std::vector<Case> all_cases() {
  return {ralph1(), ralph2(), scholtes12(1), scholtes12(2), scholtes3(), scholtes4(),
          scholtes5(), bard1(), jr(1), jr(2)};
}

void check_case(const Case& c, const MpccResult& r) {
  std::string trace;
  for (const auto& s : r.subproblems)
    trace += s.kind + " " + std::to_string(s.parameter) + " " + s.nlp_status +
             " f=" + std::to_string(s.objective) + " comp=" + std::to_string(s.complementarity) +
             "\n";
  INFO(r.message << "\n" << trace);
  REQUIRE(cpkit::is_solution(r.status));
  CHECK(r.complementarity <= 1e-7);
  CHECK(r.infeasibility <= 1e-7);
  // Objective to 1e-6 relative (absolute when the known value is 0).
  CHECK(std::abs(r.objective - c.f_star) <= 1e-6 * std::max(1.0, std::abs(c.f_star)));
  if (c.x_star.size() > 0) CHECK((r.x - c.x_star).lpNorm<Eigen::Infinity>() <= c.x_tol);
}

}  // namespace

TEST_CASE("MacMPEC problems reach the known minimum with Ipopt", "[mpcc][ipopt]") {
  const auto reform = GENERATE(MpccReformulation::kScholtes, MpccReformulation::kPenalty);
  const auto idx = GENERATE(range(0, family_size(10, 4)));
  const Case c = all_cases()[static_cast<std::size_t>(idx)];
  CAPTURE(c.problem.name, to_string(reform));
  MpccOptions o;
  o.reformulation = reform;
  check_case(c, solve_mpcc(c.problem, o));
}

TEST_CASE("MacMPEC problems with Ipopt's limited-memory Hessian", "[mpcc][ipopt]") {
  const auto idx = GENERATE(range(0, family_size(10, 4)));
  const Case c = all_cases()[static_cast<std::size_t>(idx)];
  CAPTURE(c.problem.name);
  MpccOptions o;
  o.exact_hessian = false;
  check_case(c, solve_mpcc(c.problem, o));
}

TEST_CASE("MacMPEC problems with NLopt SLSQP", "[mpcc][nlopt]") {
  const auto reform = GENERATE(MpccReformulation::kScholtes, MpccReformulation::kPenalty);
  const auto idx = GENERATE(range(0, family_size(10, 4)));
  const Case c = all_cases()[static_cast<std::size_t>(idx)];
  CAPTURE(c.problem.name, to_string(reform));
  MpccOptions o;
  o.backend = NlpBackend::kNlopt;
  o.reformulation = reform;
  check_case(c, solve_mpcc(c.problem, o));
}

TEST_CASE("scholtes3 from next to its C-stationary point is not stuck there", "[mpcc]") {
  // From x0 = (1e-4, 1e-4) and from the C-stationary point (0, 0) itself (where f = 1): the
  // piece polish enumerates both branches of the biactive pair and ends at f = 0.5.
  Case c = scholtes3();
  const auto start = GENERATE(0, 1);
  if (start == 1) c.problem.x0 = v({0, 0});
  const auto backend = GENERATE(NlpBackend::kIpopt, NlpBackend::kNlopt);
  CAPTURE(start, to_string(backend));
  MpccOptions o;
  o.backend = backend;
  const MpccResult r = solve_mpcc(c.problem, o);
  REQUIRE(cpkit::is_solution(r.status));
  CHECK(r.objective == Approx(0.5).epsilon(1e-6));
  CHECK(std::min(r.x(0), r.x(1)) <= 1e-8);
  CHECK(std::max(r.x(0), r.x(1)) == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("the result records every subproblem of the Scholtes schedule", "[mpcc]") {
  const Case c = ralph2();
  MpccOptions o;
  o.polish = false;
  o.t_initial = 1.0;
  o.t_factor = 0.1;
  o.t_min = 1e-4;
  const MpccResult r = solve_mpcc(c.problem, o);
  REQUIRE(!r.subproblems.empty());
  CHECK(r.subproblems.front().kind == "scholtes");
  CHECK(r.subproblems.front().parameter == 1.0);
  for (std::size_t k = 1; k < r.subproblems.size(); ++k)
    CHECK(r.subproblems[k].parameter == Approx(r.subproblems[k - 1].parameter * 0.1));
  CHECK(r.subproblems.size() <= 5);  // t = 1, 0.1, ..., 1e-4
}

TEST_CASE("a relaxation ending with complementarity violated is reported as such", "[mpcc]") {
  // scholtes3 stopped at t = 1e-2: the relaxed point (0.1, 0.1) violates x1 x2 = 0.
  const Case c = scholtes3();
  MpccOptions o;
  o.polish = false;
  o.t_initial = 1.0;
  o.t_min = 1e-2;
  const MpccResult r = solve_mpcc(c.problem, o);
  CHECK(r.status == cpkit::Status::kStalled);
  CHECK(r.complementarity > 1e-3);
}

TEST_CASE("invalid MPCC problems and options throw InputError", "[mpcc][input]") {
  Case c = ralph1();
  MpccOptions o;
  o.t_factor = 1.5;
  CHECK_THROWS_AS(solve_mpcc(c.problem, o), cpkit::InputError);
  o = MpccOptions{};
  o.nlp_tol = std::nan("");
  CHECK_THROWS_AS(solve_mpcc(c.problem, o), cpkit::InputError);
  c.problem.x0 = v({1, 2, 3});
  CHECK_THROWS_AS(solve_mpcc(c.problem, {}), cpkit::InputError);
  c = ralph1();
  c.problem.G = nullptr;
  CHECK_THROWS_AS(solve_mpcc(c.problem, {}), cpkit::InputError);
  c = ralph1();
  c.problem.lower = v({1, 0});
  c.problem.upper = v({0, 1});
  CHECK_THROWS_AS(solve_mpcc(c.problem, {}), cpkit::InputError);
}

TEST_CASE("reformulation and backend names (mpcc.hpp)", "[mpcc][input]") {
  using cpkit::lcp::MpccReformulation;
  using cpkit::lcp::NlpBackend;
  CHECK(cpkit::lcp::to_string(MpccReformulation::kScholtes) == "scholtes");
  CHECK(cpkit::lcp::to_string(MpccReformulation::kPenalty) == "penalty");
  CHECK(cpkit::lcp::mpcc_reformulation_from_string("scholtes") == MpccReformulation::kScholtes);
  CHECK(cpkit::lcp::mpcc_reformulation_from_string("penalty") == MpccReformulation::kPenalty);
  CHECK(cpkit::lcp::mpcc_reformulation_from_string("l1-penalty") == MpccReformulation::kPenalty);
  CHECK_FALSE(cpkit::lcp::mpcc_reformulation_from_string("Scholtes"));
  CHECK(cpkit::lcp::to_string(NlpBackend::kIpopt) == "ipopt");
  CHECK(cpkit::lcp::to_string(NlpBackend::kNlopt) == "nlopt");
  CHECK(cpkit::lcp::nlp_backend_from_string("ipopt") == NlpBackend::kIpopt);
  CHECK(cpkit::lcp::nlp_backend_from_string("nlopt") == NlpBackend::kNlopt);
  CHECK_FALSE(cpkit::lcp::nlp_backend_from_string(""));
}
