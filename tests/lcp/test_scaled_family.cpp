// The same problem in other units gets the same answer, from every solver (issue 11, part 1).
// A seeded family of LCPs with unique solutions (integer symmetric positive definite M), the
// solution known exactly from a rational brute-force enumeration (enumerate_brute_force.hpp,
// independent of cpkit), is given to every registered solver in the units q -> a q and
// (M, q) -> b (M, q) for a, b in {1e-12, 1e-6, 1, 1e6, 1e12}. Every answer must be `solved` and
// equal a times the exact solution.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "lcp/enumerate_brute_force.hpp"
#include "test_budget.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;

struct Case {
  std::string name;
  std::vector<std::vector<int>> M;
  std::vector<int> q;
};

std::vector<Case> family() {
  std::vector<Case> out;
  // deudeu (Siconos' test problem) and the first example in units of 1e-12.
  out.push_back({"deudeu", {{2, 1}, {1, 2}}, {-5, -6}});
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> e(-2, 2), qd(-6, 6);
  for (int k = 0; k < 4; ++k) {
    const int n = 3 + k % 3;
    std::vector<std::vector<int>> B(n, std::vector<int>(n)), M(n, std::vector<int>(n));
    for (auto& row : B)
      for (int& v : row) v = e(rng);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        int s = i == j ? 1 : 0;  // M = B^T B + I: symmetric positive definite
        for (int r = 0; r < n; ++r) s += B[r][i] * B[r][j];
        M[i][j] = s;
      }
    std::vector<int> q(n);
    for (int& v : q) v = qd(rng);
    q[0] = -std::abs(q[0]) - 1;  // at least one negative entry: z = 0 is not the solution
    out.push_back({"spd" + std::to_string(k), M, q});
  }
  return out;
}

}  // namespace

TEST_CASE("Every solver: same verdict and same (rescaled) solution in every unit",
          "[units][solvers]") {
  const auto& registry = cpkit::lcp::solvers();
  for (const Case& c : family()) {
    const brute::Exact ex = brute::brute_force(c.M, c.q);
    REQUIRE(ex.vertices.size() == 1);  // a P-matrix: exactly one solution
    const int n = static_cast<int>(c.q.size());
    Mat M(n, n);
    Vec q(n), zstar(n);
    for (int i = 0; i < n; ++i) {
      q[i] = c.q[i];
      zstar[i] = ex.vertices[0][i].val();
      for (int j = 0; j < n; ++j) M(i, j) = c.M[i][j];
    }
    // Under the sanitizers (10-20x slower) the extremes and 1 only: 9 unit pairs, not 25.
    const std::vector<double> factors = cpkit::test::kSanitizedBuild
                                            ? std::vector<double>{1e-12, 1.0, 1e12}
                                            : std::vector<double>{1e-12, 1e-6, 1.0, 1e6, 1e12};
    for (const cpkit::SolverEntry& entry : registry.entries()) {
      if (!entry.solve_lcp) continue;
      for (double a : factors) {
        for (double b : factors) {
          CAPTURE(c.name, entry.info.name, a, b);
          const LcpProblem p(b * M, a * b * q);
          const cpkit::SolveResult r = entry.solve_lcp(p, cpkit::CommonOptions{});
          INFO(r.message);
          CHECK(r.status == cpkit::Status::kSolved);
          if (r.z.size() == n)
            CHECK((r.z / a - zstar).cwiseAbs().maxCoeff() <= 1e-8 * zstar.cwiseAbs().maxCoeff());
        }
      }
    }
  }
}

TEST_CASE("The issue's tiny problem: z = (4/3, 7/3) 1e-12, never z = 0", "[units][solvers]") {
  const LcpProblem p(Mat{{2, 1}, {1, 2}}, Vec{{-5e-12, -6e-12}});
  for (const cpkit::SolverEntry& entry : cpkit::lcp::solvers().entries()) {
    if (!entry.solve_lcp) continue;
    CAPTURE(entry.info.name);
    const auto r = entry.solve_lcp(p, cpkit::CommonOptions{});
    REQUIRE(r.status == cpkit::Status::kSolved);
    CHECK(r.z[0] == Approx(4.0 / 3 * 1e-12).epsilon(1e-9));
    CHECK(r.z[1] == Approx(7.0 / 3 * 1e-12).epsilon(1e-9));
  }
}

TEST_CASE("No solver claims a solution of M = [[1e16, 0], [0, -1]], q = (1, -1)",
          "[units][solvers]") {
  // w_2 = -z_2 - 1 < 0 for every z_2 >= 0: no solution; y = (0, 1) is an exact certificate.
  const LcpProblem p(Mat{{1e16, 0}, {0, -1}}, Vec{{1, -1}});
  for (const cpkit::SolverEntry& entry : cpkit::lcp::solvers().entries()) {
    if (!entry.solve_lcp) continue;
    CAPTURE(entry.info.name);
    const auto r = entry.solve_lcp(p, cpkit::CommonOptions{});
    INFO(r.message);
    CHECK_FALSE(cpkit::is_solution(r.status));
  }
}

TEST_CASE("Contact LCPs with q ~ 1e-10: every solver agrees with the enumeration in any units",
          "[units][cross_verify]") {
  // 12-variable polyhedral-friction contact LCPs (tests/data/lemke/contact_lcp.py; M ~ 1,
  // q ~ 1e-10, degenerate): the case where Ipopt's answer was refuted by exact
  // arithmetic and `lcp verify` blamed a correct enumeration. No disagreement may occur, in the
  // given units or rescaled.
  for (const char* name : {"contact_2c_seed1", "contact_2c_seed2_sym", "contact_2c_seed3_mixed",
                           "contact_2c_seed5_mixed"}) {
    const LcpProblem base =
        cpkit::read_lcp_file(std::string(CPKIT_TEST_DATA_DIR) + "/lemke/" + name + ".json");
    for (double a : {1.0, 1e10, 1e-6}) {
      CAPTURE(name, a);
      LcpProblem p = base;
      p.q *= a;
      const auto rep = cpkit::lcp::cross_verify(p);
      for (const auto& d : rep.disagreements) INFO(d);
      CHECK(rep.consistent());
      int answered = 0;
      for (const auto& c : rep.checks) answered += c.verdict == cpkit::lcp::Verdict::kConsistent;
      CHECK(answered >= 3);  // lemke, fb-newton, auto at least, each verified in the set
    }
  }
}

TEST_CASE("Badly scaled data: every solver finds z = (0, 1) of diag(big, 1), q = (1, -1)",
          "[units][solvers]") {
  // w = (big z_1 + 1, z_2 - 1): z_1 = 0 (w_1 = 1 > 0), z_2 = 1 (w_2 = 0), by hand.
  for (double big : {1e11, 1e200}) {
    const LcpProblem p(Mat{{big, 0}, {0, 1}}, Vec{{1, -1}});
    for (const cpkit::SolverEntry& entry : cpkit::lcp::solvers().entries()) {
      if (!entry.solve_lcp) continue;
      CAPTURE(big, entry.info.name);
      const auto r = entry.solve_lcp(p, cpkit::CommonOptions{});
      INFO(r.message);
      REQUIRE(r.status == cpkit::Status::kSolved);
      CHECK(std::abs(r.z[0]) <= 1e-10 / big);
      CHECK(r.z[1] == Approx(1).epsilon(1e-10));
    }
  }
}
