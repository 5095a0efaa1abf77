// The examples of docs/library.md, compiled and run by the test suite
// (ctest name: docs.library_example) so that the documentation cannot go stale.
#include <cpkit/core/core.hpp>
#include <cpkit/lcp/auto_chain.hpp>
#include <cpkit/lcp/enumerate.hpp>
#include <cpkit/lcp/fb_newton.hpp>
#include <cpkit/lcp/lemke.hpp>
#include <cpkit/lcp/solvers.hpp>
#include <cpkit/rate_problem/rate/point_rate.hpp>
#include <cpkit/rate_problem/step/step_enumeration.hpp>
#include <cmath>
#include <iostream>
#include <string>

// The folder of the example problem files: the program's argument if given, else the one the
// build defines (the test suite passes -DCPKIT_EXAMPLE_DATA=<repository>/tests/data/lcp), else
// the repository's tests/data/lcp relative to the current folder (run from the top folder).
#ifndef CPKIT_EXAMPLE_DATA
#define CPKIT_EXAMPLE_DATA "tests/data/lcp"
#endif

int main(int argc, char** argv) {
  const std::string data_dir = argc > 1 ? argv[1] : CPKIT_EXAMPLE_DATA;
  int failures = 0;
  auto expect = [&](bool ok, const char* what) {
    std::cout << (ok ? "ok   " : "FAIL ") << what << '\n';
    if (!ok) ++failures;
  };

  // 1. One LCP, one solver. M = [[2, 1], [1, 2]], q = (-5, -6): z = (4/3, 7/3), w = 0.
  cpkit::LcpProblem p(cpkit::Mat{{2, 1}, {1, 2}}, cpkit::Vec{{-5, -6}}, "hand-2x2");
  cpkit::lcp::LemkeOptions lo;
  lo.common.tol = 1e-12;
  const cpkit::SolveResult r = cpkit::lcp::solve_lemke(p, lo);
  expect(r.status == cpkit::Status::kSolved && std::abs(r.z[0] - 4.0 / 3.0) < 1e-12,
         "lemke solves the 2x2 example");
  std::cout << cpkit::to_text(r);

  // 2. Any registered solver by name (the CLI's --solver uses the same registry).
  for (const std::string& name : cpkit::lcp::solvers().names(cpkit::ProblemKind::kLcp)) {
    const cpkit::SolverEntry* entry = cpkit::lcp::solvers().find(name);
    const cpkit::SolveResult ri = entry->solve_lcp(p, cpkit::CommonOptions{});
    expect(cpkit::is_solution(ri.status), ("registered solver solves it: " + name).c_str());
  }

  // 3. Every solution: battle of the sexes has exactly three equilibria.
  const cpkit::LcpProblem game = cpkit::read_lcp_file(data_dir + "/battle_of_the_sexes.json");
  const cpkit::lcp::SolutionSet all = cpkit::lcp::enumerate_all(game);
  expect(all.complete && !all.infinite && all.count() == 3, "enumeration finds 3 equilibria");

  // 4. A nonlinear complementarity problem: F(x) = (x - 1)^2 - 1.01 (Billups), x* = 1 + sqrt(1.01).
  cpkit::McpProblem ncp = cpkit::make_ncp(
      1, [](const cpkit::Vec& x, cpkit::Vec& F) { F.resize(1); F[0] = (x[0] - 1) * (x[0] - 1) - 1.01; return true; },
      [](const cpkit::Vec& x, cpkit::Mat& J) { J.resize(1, 1); J(0, 0) = 2 * (x[0] - 1); return true; });
  ncp.x0 = cpkit::Vec::Zero(1);
  const cpkit::SolveResult rn = cpkit::lcp::solve_fb_newton(ncp);
  expect(cpkit::is_solution(rn.status) && std::abs(rn.z[0] - (1 + std::sqrt(1.01))) < 1e-9,
         "fb-newton solves billups");

  // 5. The rate problem of Fig. 5(b): state b, a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 3,
  //    load direction theta = 0.4 (inside the sector with three solutions).
  cpkit::rate::ContactParameters cp;
  cp.a11 = 1; cp.a12 = 0.5; cp.a22 = 1; cp.C_T = 0.25; cp.mu = 3;
  cpkit::rate::ContactState st;  // state b
  const cpkit::rate::RateSolutionSet rs =
      cpkit::rate::solve_rate_problem(cp, st, {std::cos(0.4), std::sin(0.4)});
  expect(rs.count() == 3, "rate problem has three solutions at theta = 0.4");
  for (const auto& s : rs.solutions)
    std::cout << "  " << cpkit::rate::to_string(s.type) << ": dP_N = " << s.start.dP_N << '\n';

  // 6. One time step with wear: all solutions.
  cpkit::rate::StepProblem step;
  step.params = cp;
  step.params.k_a = 0.1;
  step.state = {0.0, 1.0, 0.0};  // P_T0, P_N0, g0
  step.load = {0.01, 0.0};
  const cpkit::rate::StepSolutionSet ss = cpkit::rate::enumerate_step(step);
  expect(ss.count() >= 1, "the step has a solution");

  return failures == 0 ? 0 : 1;
}
