// Cross-verification: every registered solver against the complete enumeration (the property
// "no solution returned by any registered solver is missing from the set"), and the detection
// of each kind of disagreement with deliberately wrong solvers in a private registry.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/solvers.hpp"

using namespace cpkit::lcp;
using cpkit::Mat;
using cpkit::Status;
using cpkit::Vec;

namespace {

/// Known disagreements, keyed by (solver, problem name): "solved" answers with |z| ~ 1e16..1e26
/// on an infeasible LCP were accepted by finalize() while its residual scale was
/// 1 + || |M||z| || (w stays at -1). If such an answer appears, cross_verify must flag it as
/// not_a_solution (asserted below); with the core's current scale it should not appear.
bool known_failure(const std::string& solver, const std::string& problem) {
  return (solver == "ipopt" || solver == "nlopt") && problem == "infeasible_copositive_plus";
}

CrossVerifyOptions fast_options() {
  CrossVerifyOptions o;
  o.solve.time_limit_s = 2;  // Ipopt can take seconds on infeasible problems
  return o;
}

void require_consistent(const CrossVerifyReport& rep, const std::string& name = {}) {
  int known = 0;
  for (const SolverCheck& c : rep.checks) {
    CAPTURE(c.solver, std::string(cpkit::to_string(c.status)), c.residual, c.message);
    if (known_failure(c.solver, name)) {
      if (is_disagreement(c.verdict)) ++known;
      if (cpkit::is_solution(c.status)) CHECK(c.verdict == Verdict::kNotASolution);
      continue;
    }
    if (cpkit::is_solution(c.status)) {
      // an independent look at the answer: the set's own membership test
      CHECK(c.in_set);
    }
    if (c.status == Status::kInfeasible) CHECK(rep.set.solutions.empty());
    CHECK_FALSE(is_disagreement(c.verdict));
  }
  for (const auto& d : rep.disagreements) UNSCOPED_INFO(d);
  CHECK(int(rep.disagreements.size()) == known);
}

cpkit::SolveResult claim(const cpkit::LcpProblem& p, Status s, Vec z) {
  cpkit::SolveResult r;
  r.status = s;
  r.z = std::move(z);
  r.w = p.w(r.z);
  return r;
}

cpkit::SolverEntry fake(const std::string& name, cpkit::LcpSolveFn fn) {
  cpkit::SolverEntry e;
  e.info.name = name;
  e.info.description = "test double";
  e.solve_lcp = std::move(fn);
  return e;
}

}  // namespace

TEST_CASE("cross_verify: every registered solver on every reference problem", "[cross_verify]") {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CPKIT_TEST_DATA_DIR "/lcp")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const cpkit::LcpProblem p = cpkit::read_lcp_json(entry.path().string());
    CAPTURE(entry.path().filename().string());
    const CrossVerifyReport rep = cross_verify(p, fast_options());
    REQUIRE(rep.set.complete);
    CHECK(rep.checks.size() >= 1);  // at least lemke is registered
    require_consistent(rep, p.name);
  }
  CHECK(files >= 14);
}

TEST_CASE("cross_verify: random LCPs with several solutions", "[cross_verify]") {
  std::mt19937 rng(77);
  std::normal_distribution<double> g(0, 1);
  const CrossVerifyOptions opt = fast_options();
  for (int t = 0; t < 6; ++t) {
    const int n = 5 + t % 3;
    Mat M(n, n);
    Vec q(n);
    for (int i = 0; i < n; ++i) {
      q(i) = g(rng);
      for (int j = 0; j < n; ++j) M(i, j) = g(rng);
    }
    CAPTURE(t);
    require_consistent(cross_verify(cpkit::LcpProblem(M, q), opt));
  }
}

TEST_CASE("cross_verify: the rate LCP with a ray of z (separation)", "[cross_verify]") {
  // state b of docs/model.md with A = [[2, .5], [.5, 1]], mu = .3, C_T = .1, dF = (.5, -1):
  // every solution has dP_N = 0 and lies on the ray (0, xi, 0) + t (0, 1, 1).
  const double a11 = 2, a12 = 0.5, a22 = 1, CT = 0.1, mu = 0.3, dFT = 0.5, dFN = -1;
  const double detA = a11 * a22 - a12 * a12, D0 = a22 + CT * detA;
  const double S = (1 + a11 * CT) * dFN - a12 * CT * dFT, tt = a22 * dFT - a12 * dFN;
  Mat M(3, 3);
  M << 1 + a11 * CT, a12, -a12, mu * D0 - a12, detA, -detA, mu * D0 + a12, -detA, detA;
  Vec q(3);
  q << -S, -tt, tt;
  const CrossVerifyReport rep = cross_verify(cpkit::LcpProblem(M, q), fast_options());
  REQUIRE(rep.set.infinite);
  require_consistent(rep);
}

TEST_CASE("cross_verify: each kind of disagreement is detected", "[cross_verify]") {
  Mat M(2, 2);
  M << 2, 1, 1, 2;
  Vec q(2);
  q << -1, -1;  // unique solution (1/3, 1/3)
  const cpkit::LcpProblem p(M, q);
  cpkit::SolverRegistry reg;
  reg.add(fake("honest", [](const cpkit::LcpProblem& pr, const cpkit::CommonOptions& o) {
    return cpkit::finalize(pr, claim(pr, Status::kSolved, Vec::Constant(2, 1.0 / 3)), o);
  }));
  reg.add(fake("liar-infeasible", [](const cpkit::LcpProblem& pr, const cpkit::CommonOptions&) {
    return claim(pr, Status::kInfeasible, Vec::Zero(2));
  }));
  reg.add(fake("liar-solved", [](const cpkit::LcpProblem& pr, const cpkit::CommonOptions&) {
    return claim(pr, Status::kSolved, Vec::Constant(2, 1.0));
  }));
  reg.add(fake("gives-up", [](const cpkit::LcpProblem& pr, const cpkit::CommonOptions&) {
    return claim(pr, Status::kIterationLimit, Vec::Zero(2));
  }));
  reg.add(fake("thrower", [](const cpkit::LcpProblem&, const cpkit::CommonOptions&) -> cpkit::SolveResult {
    throw std::runtime_error("boom");
  }));
  const CrossVerifyReport rep = cross_verify(p, {}, reg);
  REQUIRE(rep.checks.size() == 5);
  CHECK(rep.checks[0].verdict == Verdict::kConsistent);
  CHECK(rep.checks[0].solution_index == 0);
  CHECK(rep.checks[1].verdict == Verdict::kInfeasibleButSolvable);
  CHECK(rep.checks[2].verdict == Verdict::kNotASolution);
  CHECK(rep.checks[3].verdict == Verdict::kNoAnswer);
  CHECK(rep.checks[4].verdict == Verdict::kError);
  CHECK(rep.disagreements.size() == 3);
  CHECK_FALSE(rep.consistent());

  // an enumeration stopped short (max_piece_dim = 1 on the 5-dimensional piece of M = 0,
  // q = 0, where every z >= 0 solves) is not complete: a verified answer outside what it found
  // is "unchecked", not a disagreement; with the complete enumeration it is consistent.
  const cpkit::LcpProblem zero(Mat::Zero(5, 5), Vec::Zero(5));
  cpkit::SolverRegistry reg2;
  reg2.add(fake("interior", [](const cpkit::LcpProblem& pr, const cpkit::CommonOptions& o) {
    return cpkit::finalize(pr, claim(pr, Status::kSolved, Vec::Constant(5, 0.5)), o);
  }));
  CrossVerifyOptions strict;
  strict.enumeration.max_piece_dim = 1;
  const CrossVerifyReport partial = cross_verify(zero, strict, reg2);
  REQUIRE_FALSE(partial.set.complete);
  CHECK(partial.checks[0].verdict == Verdict::kUnchecked);
  CHECK(partial.consistent());
  CrossVerifyOptions full;
  full.enumeration.max_piece_dim = 5;
  const CrossVerifyReport ok = cross_verify(zero, full, reg2);
  REQUIRE(ok.set.complete);
  REQUIRE(ok.set.infinite);
  CHECK(ok.checks[0].verdict == Verdict::kConsistent);
}
