// The step solver chain (step_solve.hpp): every solver's verified answer must be one of the
// step's solutions from complete enumeration (compared as physical values, not z).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"

using namespace cpkit::rate;

namespace {

std::vector<StepProblem> corpus(bool wear) {
  std::mt19937 gen(wear ? 3 : 4);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<StepProblem> out;
  while (out.size() < 60) {
    StepProblem p;
    p.params.a11 = 1.5 + u(gen);
    p.params.a22 = 1.5 + u(gen);
    p.params.a12 = 0.6 * u(gen) * std::sqrt(p.params.a11 * p.params.a22);
    p.params.mu = 0.8 + 0.5 * u(gen);
    p.params.C_T = out.size() % 2 ? 0.0 : 0.4;
    if (wear) p.params.k_a = 0.05 + 0.04 * u(gen);
    p.state.P_N0 = out.size() % 3 == 0 ? 0.0 : 0.8 + 0.3 * u(gen);
    p.state.P_T0 = 0.9 * u(gen) * p.params.mu * p.state.P_N0;
    p.load = {u(gen), u(gen)};
    if (p.validate().empty()) out.push_back(p);
  }
  return out;
}

bool in_set(const StepSolutionSet& set, const StepValues& v) {
  for (const auto& s : set.solutions) {
    if (s.kind != RateSolution::Kind::kPoint) return true;  // not in this corpus
    if (std::abs(s.start.P_N1 - v.P_N1) < 1e-6 && std::abs(s.start.P_T1 - v.P_T1) < 1e-6 &&
        std::abs(s.start.Dw_Ti - v.Dw_Ti) < 1e-6 && std::abs(s.start.Dw_N - v.Dw_N) < 1e-6)
      return true;
  }
  return false;
}

}  // namespace

TEST_CASE("DefaultChainSolvesEveryStepWithASolution", "[step][chain]") {
  for (bool wear : {false, true}) {
    for (const auto& p : corpus(wear)) {
      const StepSolutionSet set = enumerate_step(p);
      const StepSolveResult r = solve_step(p);
      CAPTURE(wear, r.message);
      if (set.solutions.empty()) {
        CHECK_FALSE(cpkit::is_solution(r.status));
        continue;
      }
      REQUIRE(cpkit::is_solution(r.status));
      CHECK(r.solver == "active-set");
      CHECK(in_set(set, r.solution.values));
    }
  }
}

TEST_CASE("EveryRegisteredSolverReturnsAnEnumeratedStepSolution", "[step][chain]") {
  const std::string name = GENERATE(as<std::string>{}, "lemke", "fb-newton", "ipopt");
  CAPTURE(name);
  if (cpkit::lcp::solvers().find(name) == nullptr) {
    WARN("solver '" << name << "' is not registered: skipped");
    return;
  }
  for (bool wear : {false, true}) {
    if (wear && name == "lemke") continue;  // an LCP solver: only the no-wear steps
    int solved = 0, total = 0;
    const auto problems = corpus(wear);
    // Ipopt takes ~0.1 s per step: a third of the corpus keeps the test fast.
    const std::size_t n = name == "ipopt" ? problems.size() / 3 : problems.size();
    for (std::size_t i = 0; i < n; ++i) {
      const StepProblem& p = problems[i];
      const StepSolutionSet set = enumerate_step(p);
      if (set.solutions.empty()) continue;
      StepSolveOptions o;
      o.chain = {name};
      const StepSolveResult r = solve_step(p, o);
      ++total;
      if (!cpkit::is_solution(r.status)) continue;
      ++solved;
      CAPTURE(wear, r.solution.values.P_N1, r.solution.values.P_T1, r.solution.values.Dw_Ti);
      CHECK(in_set(set, r.solution.values));
    }
    CAPTURE(wear, solved, total);
    // Local solvers may fail on a few nonconvex steps; a verified answer is never wrong.
    CHECK(solved >= (name == "lemke" ? total : (8 * total) / 10));
  }
}

TEST_CASE("ChainSkipsWhatDoesNotApplyAndRejectsBadOptions", "[step][chain][input]") {
  StepProblem p;
  p.params.k_a = 0.1;
  p.state = {0.1, 1.0, 0.0};
  p.load = {0.5, 0.0};
  StepSolveOptions o;
  o.chain = {"lemke", "no-such-solver"};
  const StepSolveResult r = solve_step(p, o);
  CHECK_FALSE(cpkit::is_solution(r.status));
  CHECK(r.message.find("no-such-solver") != std::string::npos);
  CHECK(r.message.find("lemke") != std::string::npos);
  o.chain.clear();
  CHECK_THROWS_AS(solve_step(p, o), cpkit::InputError);
  o.chain = {"active-set"};
  o.common.tol = -1;
  CHECK_THROWS_AS(solve_step(p, o), cpkit::InputError);
}
