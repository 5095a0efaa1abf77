// The automatic chain runs its solvers by cost (issue 11, sec. 4): Lemke, FB Newton, then the
// expensive searches (the Farkas LP and the MPCC by Ipopt/NLopt). Every attempt is listed.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"
#include "cpkit/lcp/auto_chain.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "peer_skip.hpp"

using cpkit::Mat;
using cpkit::Status;
using cpkit::Vec;

namespace {

std::vector<std::string> attempt_names(const cpkit::SolveResult& r) {
  std::vector<std::string> names;
  for (const auto& a : r.attempts) names.push_back(a.solver);
  return names;
}

}  // namespace

TEST_CASE("auto: FB Newton answers before any Ipopt search when Lemke ends on a ray",
          "[auto][order]") {
  // Battle of the sexes as a bimatrix LCP: M = [[0, A], [B^T, 0]], A = [[1, 3], [4, 2]],
  // B^T = [[2, 4], [3, 1]], q = -1. Lemke with the covering vector of ones ends on a secondary
  // ray after one pivot (the file's "expected"). The three Nash equilibria in closed form
  // (rows of A y = 1 and B^T x = 1 on each support): (1/2, 0, 1, 0), (0, 1, 0, 1/2) and the
  // mixed one (3/10, 1/10, 1/10, 3/10).
  const cpkit::LcpProblem p = cpkit::read_lcp_file(std::string(CPKIT_TEST_DATA_DIR) +
                                                   "/lcp/battle_of_the_sexes.json");
  const cpkit::SolveResult r = cpkit::lcp::solve_auto(p);
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.solver == "fb-newton");
  CHECK(attempt_names(r) == std::vector<std::string>{"lemke", "fb-newton"});
  REQUIRE(r.attempts.size() == 2);
  CHECK(r.attempts[0].status == Status::kRayTermination);
  CHECK(r.attempts[1].status == Status::kSolved);
  const std::vector<std::vector<double>> equilibria = {
      {0.5, 0, 1, 0}, {0, 1, 0, 0.5}, {0.3, 0.1, 0.1, 0.3}};
  REQUIRE(r.z.size() == 4);
  bool matched = false;
  for (const auto& e : equilibria) {
    double d = 0;
    for (int i = 0; i < 4; ++i) d = std::max(d, std::abs(r.z(i) - e[i]));
    matched = matched || d <= 1e-9;
  }
  CHECK(matched);
}

TEST_CASE("auto: the Farkas LP comes after FB Newton and before the MPCC solvers",
          "[auto][order]") {
  // M = [[2, -3], [-1, 1]], q = (-1, -1): y = (1, 2) gives M^T y = (0, -1) <= 0 and
  // q^T y = -3 < 0, so y^T w = (M^T y)^T z + q^T y < 0 for every z >= 0: infeasible. No unit
  // vector and not y = (1, 1) is a certificate (M^T (1, 1) = (1, -2)).
  if (cpkit::lcp::solvers().find("ipopt") == nullptr) {
    CPKIT_SKIP_CHECK("ipopt is not registered in this build: the Farkas LP is not run, order not checked");
    return;
  }
  Mat M(2, 2);
  M << 2, -3, -1, 1;
  Vec q(2);
  q << -1, -1;
  const cpkit::LcpProblem p(M, q, "planted_infeasible_2");
  const cpkit::SolveResult r = cpkit::lcp::solve_auto(p);
  INFO(r.message);
  REQUIRE(r.status == Status::kInfeasible);
  // The attempts follow the order by cost: lemke, fb-newton, farkas-search, ipopt, nlopt.
  const std::vector<std::string> order = {"lemke", "fb-newton", "farkas-search", "ipopt", "nlopt"};
  const auto names = attempt_names(r);
  int last = -1;
  for (const auto& n : names) {
    const int k = static_cast<int>(std::find(order.begin(), order.end(), n) - order.begin());
    CAPTURE(n);
    CHECK(k > last);
    last = k;
  }
  REQUIRE_FALSE(names.empty());
  if (r.attempts.front().status != Status::kInfeasible) {
    // Lemke gave no proof: FB Newton ran next, then the LP found y; no MPCC search after it.
    CHECK(names == std::vector<std::string>{"lemke", "fb-newton", "farkas-search"});
  }
  REQUIRE(r.certificate.has_value());
  const Vec y = r.certificate->y / r.certificate->y.cwiseAbs().maxCoeff();
  CHECK(y.minCoeff() >= 0);
  CHECK((M.transpose() * y).maxCoeff() <= 1e-12);
  CHECK(q(0) * y(0) + q(1) * y(1) < 0);  // q^T y (written out: GCC 12 warns on Eigen's dot here)
}
