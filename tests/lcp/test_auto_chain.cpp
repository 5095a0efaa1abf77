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
#include "cpkit/lcp/small_lcp.hpp"
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

namespace {

/// Brute force, independent of the tiny route: every complementary basis S solved by a full-
/// pivoting LU, kept when z_S >= 0 and w >= 0 off S; the distinct points (Gaussian data: no
/// degenerate bases, so this lists every solution).
std::vector<Vec> all_solutions_by_bases(const Mat& M, const Vec& q) {
  const Eigen::Index n = q.size();
  std::vector<Vec> found;
  for (unsigned S = 0; S < (1u << n); ++S) {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < n; ++i)
      if (S >> i & 1u) idx.push_back(i);
    Vec z = Vec::Zero(n);
    if (!idx.empty()) {
      const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
      Mat A(k, k);
      Vec b(k);
      for (Eigen::Index a = 0; a < k; ++a) {
        b(a) = -q(idx[a]);
        for (Eigen::Index c = 0; c < k; ++c) A(a, c) = M(idx[a], idx[c]);
      }
      Eigen::FullPivLU<Mat> lu(A);
      if (!lu.isInvertible()) continue;
      const Vec zs = lu.solve(b);
      for (Eigen::Index a = 0; a < k; ++a) z(idx[a]) = zs(a);
    }
    const Vec w = M * z + q;
    const double scale = 1e-9 * (1 + q.cwiseAbs().maxCoeff());
    bool ok = true;
    for (Eigen::Index i = 0; i < n; ++i) ok = ok && z(i) >= -scale && w(i) >= -scale;
    if (!ok) continue;
    bool seen = false;
    for (const Vec& f : found) seen = seen || (f - z).cwiseAbs().maxCoeff() <= scale;
    if (!seen) found.push_back(z);
  }
  return found;
}

bool answered_by_tiny_route(const cpkit::SolveResult& r) {
  return r.attempts.size() == 1 && r.solver == "enumeration" &&
         r.message.find("the one solution of this LCP") != std::string::npos;
}

}  // namespace

TEST_CASE("auto answers a tiny LCP by its one solution, and only when there is one", "[auto][tiny]") {
  // Hand case: M = [[2, 1], [1, 2]], q = (-5, -6): z = (4/3, 7/3), w = 0, no Lemke pivots.
  cpkit::LcpProblem hand(Mat{{2, 1}, {1, 2}}, Vec{{-5, -6}});
  const cpkit::SolveResult r = solve_auto(hand);
  CHECK(r.status == Status::kSolved);
  CHECK(answered_by_tiny_route(r));
  CHECK(r.iterations == 0);
  CHECK(r.z(0) == Approx(4.0 / 3).epsilon(1e-15));
  CHECK(r.z(1) == Approx(7.0 / 3).epsilon(1e-15));
  // A trace asks to watch a solver iterate: Lemke runs (three pivots: z0 in, then z2, z1).
  cpkit::CommonOptions traced;
  traced.record_trace = true;
  const cpkit::SolveResult t = solve_auto(hand, traced);
  CHECK(t.solver == "lemke");
  CHECK(t.trace.size() == 3);

  // A problem with three solutions (battle of the sexes, n = 4) is not the tiny route's.
  CHECK_FALSE(answered_by_tiny_route(solve_auto(load("battle_of_the_sexes"))));
}

TEST_CASE("the tiny route answers exactly the tiny LCPs with one solution, in any units",
          "[auto][tiny]") {
  // Seeded Gaussian problems n = 1..4, half of them positive definite: the route (the one auto
  // takes first) answers only when brute force finds exactly one solution, with that solution,
  // and always on a positive definite M (a P-matrix). In other units (M and q together, or q
  // alone, scaled by 1e-12 and 1e12) it answers the same problems with the same z in those units.
  std::mt19937_64 rng(37);
  std::normal_distribution<double> g;
  int answered = 0, several = 0, pd = 0, pd_answered = 0;
  for (int k = 0; k < 4000; ++k) {
    const int n = 1 + k % 4;
    Mat M(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = g(rng);
    const bool positive_definite = k % 2 == 0;
    if (positive_definite) M = M * M.transpose() + 0.1 * Mat::Identity(n, n);
    Vec q(n);
    for (int i = 0; i < n; ++i) q(i) = g(rng);
    const std::vector<Vec> sols = all_solutions_by_bases(M, q);
    several += sols.size() > 1 ? 1 : 0;
    double z[4], w[4], natural = 0;
    const bool got = solve_small_fast(n, M.data(), q.data(), 1e-10, z, w, natural);
    CAPTURE(k, M, q);
    pd += positive_definite ? 1 : 0;
    pd_answered += positive_definite && got ? 1 : 0;
    if (!got) continue;
    ++answered;
    REQUIRE(sols.size() == 1);
    const Vec zv = Eigen::Map<const Vec>(z, n);
    CHECK((zv - sols[0]).cwiseAbs().maxCoeff() <= 1e-9 * (1 + sols[0].cwiseAbs().maxCoeff()));
    CHECK(is_lcp_solution(cpkit::LcpProblem(M, q), zv, 1e-10));
    for (const double s : {1e-12, 1e12}) {
      const Mat sM = s * M;
      const Vec sq = s * q;
      double zb[4], wb[4], zq[4], wq[4], nb = 0, nq = 0;
      REQUIRE(solve_small_fast(n, sM.data(), sq.data(), 1e-10, zb, wb, nb));  // same z
      REQUIRE(solve_small_fast(n, M.data(), sq.data(), 1e-10, zq, wq, nq));   // z times s
      for (int i = 0; i < n; ++i) {
        CHECK(zb[i] == Approx(z[i]).epsilon(1e-12).margin(1e-12 * zv.cwiseAbs().maxCoeff()));
        CHECK(zq[i] / s == Approx(z[i]).epsilon(1e-12).margin(1e-12 * zv.cwiseAbs().maxCoeff()));
      }
    }
  }
  CHECK(pd_answered == pd);
  CHECK(answered >= 2000);
  CHECK(several >= 50);  // problems with several solutions were met, and none was answered
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
