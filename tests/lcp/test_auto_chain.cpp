// The automatic chain "auto": verified answers where Lemke ends on a ray, honest attempts,
// never "solved" on an infeasible problem, "infeasible" only with a re-checked certificate.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"
#include "cpkit/lcp/auto_chain.hpp"
#include "cpkit/lcp/solvers.hpp"

using cpkit::Mat;
using cpkit::Status;
using cpkit::Vec;
using namespace cpkit::lcp;

namespace {

cpkit::LcpProblem load(const std::string& name) {
  return cpkit::read_lcp_file(std::string(CPKIT_TEST_DATA_DIR) + "/lcp/" + name + ".json");
}

/// Independent check (not finalize()): z >= 0, w = M z + q >= 0, z . w = 0 up to tol * scale.
bool is_lcp_solution(const cpkit::LcpProblem& p, const Vec& z, double tol) {
  if (z.size() != p.size()) return false;
  const Mat M = p.dense_M();
  const Vec w = M * z + p.q;
  const double scale = 1 + std::max(p.q.cwiseAbs().maxCoeff(), (M.cwiseAbs() * z.cwiseAbs()).maxCoeff());
  for (Eigen::Index i = 0; i < z.size(); ++i)
    if (z(i) < -tol * scale || w(i) < -tol * scale || std::abs(std::min(z(i), w(i))) > tol * scale)
      return false;
  return true;
}

/// Independent check of a Farkas certificate: y >= 0, M^T y <= 0, q^T y < 0.
bool is_farkas(const cpkit::LcpProblem& p, const Vec& y) {
  const Vec yn = y / y.cwiseAbs().maxCoeff();
  return yn.minCoeff() >= -1e-9 && (p.dense_M().transpose() * yn).maxCoeff() <= 1e-8 &&
         p.q.dot(yn) < -1e-8;
}

/// Bimatrix game LCP with positive cost matrices A, B (m x k): z = (x, y),
/// w = (A y - 1, B^T x - 1). A Nash equilibrium always exists [Lemke-Howson 1964], so the LCP
/// always has a solution.
cpkit::LcpProblem bimatrix(const Mat& A, const Mat& B) {
  const Eigen::Index m = A.rows(), k = A.cols();
  Mat M = Mat::Zero(m + k, m + k);
  M.topRightCorner(m, k) = A;
  M.bottomLeftCorner(k, m) = B.transpose();
  return cpkit::LcpProblem(M, Vec::Constant(m + k, -1.0), "bimatrix");
}

}  // namespace

TEST_CASE("auto solves battle_of_the_sexes although Lemke ends on a ray", "[auto][bimatrix]") {
  const auto p = load("battle_of_the_sexes");
  const auto r = solve_auto(p);
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK(is_lcp_solution(p, r.z, 1e-9));
  REQUIRE(r.attempts.size() >= 2);
  CHECK(r.attempts.front().solver == "lemke");
  CHECK(r.attempts.front().status == Status::kRayTermination);  // expected.lemke_with_covering_ones
  CHECK(r.solver != "lemke");
  CHECK(r.solver == r.attempts.back().solver);
  CHECK(r.attempts.back().status == Status::kSolved);
}

TEST_CASE("auto solves random bimatrix-game LCPs", "[auto][bimatrix]") {
  std::mt19937_64 rng(20261122);
  int lemke_rays = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Index m = 2 + static_cast<Eigen::Index>(rng() % 4), k = 2 + static_cast<Eigen::Index>(rng() % 4);
    Mat A(m, k), B(m, k);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < k; ++j) {
        A(i, j) = 1 + static_cast<double>(rng() % 9);
        B(i, j) = 1 + static_cast<double>(rng() % 9);
      }
    const auto p = bimatrix(A, B);
    CAPTURE(trial, m, k);
    const auto r = solve_auto(p);
    INFO(r.message);
    REQUIRE(r.status == Status::kSolved);
    CHECK(is_lcp_solution(p, r.z, 1e-9));
    lemke_rays += r.attempts.front().status == Status::kRayTermination;
  }
  // Covering vector e on a game LCP: Lemke usually meets a ray at once; the later solvers answer.
  CHECK(lemke_rays > 0);
}

TEST_CASE("auto solves every solvable LCP file", "[auto]") {
  const auto name = GENERATE(as<std::string>{}, "battle_of_the_sexes", "cps_4_qp",
                             "cps_example_4_4_16", "cps_example_4_4_7", "cps_remark_4_1_14",
                             "deudeu", "gould_nonconvex_qp", "lemke_cycling_circulant",
                             "murty_exp_6", "ortiz", "pang_isolated", "siconos_exp_murty_qe_6");
  CAPTURE(name);
  const auto p = load(name);
  const auto r = solvers().find("auto")->solve_lcp(p, {});
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK(is_lcp_solution(p, r.z, 1e-9));
}

TEST_CASE("auto never claims a solution of an infeasible LCP", "[auto][infeasible]") {
  const auto name =
      GENERATE(as<std::string>{}, "infeasible_copositive_plus", "pang_isolated_perturbed");
  CAPTURE(name);
  const auto p = load(name);
  const auto r = solve_auto(p);
  INFO(r.message);
  CHECK_FALSE(cpkit::is_solution(r.status));
  // Both have a Farkas certificate (file: expected.certificate), so auto proves infeasibility.
  REQUIRE(r.status == Status::kInfeasible);
  REQUIRE(r.certificate.has_value());
  CHECK(r.certificate->checked);
  CHECK(is_farkas(p, r.certificate->y));
}

TEST_CASE("auto proves infeasibility by the Farkas LP when Lemke's ray is no proof",
          "[auto][infeasible]") {
  // Indefinite M with row 2 <= 0 and q_2 < 0: w_2 < 0 for every z >= 0, and y = e_2 is a
  // Farkas certificate (M^T e_2 = row 2 <= 0, q^T e_2 < 0).
  Mat M(3, 3);
  M << 1, -2, 3, -1, 2, -1, -0.5, -1, -2;
  Vec q(3);
  q << 1, -1, -0.5;
  const cpkit::LcpProblem p(M, q, "planted_infeasible");
  const auto r = solve_auto(p);
  INFO(r.message);
  REQUIRE(r.status == Status::kInfeasible);
  REQUIRE(r.certificate.has_value());
  CHECK(is_farkas(p, r.certificate->y));
}

TEST_CASE("auto on Siconos' 1x1 trap M = -1, q = -1 is never solved", "[auto][infeasible]") {
  // w = -z - 1 < 0 for every z >= 0; Siconos' 1x1 fast path returns z = -1 as a "solution".
  // y = 1 is a Farkas certificate (M^T y = -1 <= 0, q^T y = -1 < 0).
  const cpkit::LcpProblem p(Mat::Constant(1, 1, -1.0), Vec::Constant(1, -1.0), "siconos_1x1");
  const auto r = solve_auto(p);
  INFO(r.message);
  CHECK_FALSE(cpkit::is_solution(r.status));
  if (r.status == Status::kInfeasible) CHECK(is_farkas(p, r.certificate->y));
}

TEST_CASE("auto for an NCP runs fb-newton, then ipopt, then nlopt", "[auto][mcp]") {
  CHECK(auto_chain_names(cpkit::ProblemKind::kMcp) ==
        std::vector<std::string>{"fb-newton", "ipopt", "nlopt"});
  CHECK(auto_chain_names(cpkit::ProblemKind::kLcp) ==
        std::vector<std::string>{"lemke", "fb-newton", "ipopt", "nlopt"});
  // billups [ncp.md]: unique solution 1 + sqrt(1.01).
  auto p = cpkit::make_ncp(
      1, [](const Vec& x, Vec& F) { F.resize(1); F(0) = (x(0) - 1) * (x(0) - 1) - 1.01; return true; },
      [](const Vec& x, Mat& J) { J.resize(1, 1); J(0, 0) = 2 * (x(0) - 1); return true; },
      "billups");
  const auto r = solve_auto(p);
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z(0) == Approx(1 + std::sqrt(1.01)).epsilon(1e-10));
  REQUIRE(!r.attempts.empty());
  CHECK(r.attempts.front().solver == "fb-newton");
}
