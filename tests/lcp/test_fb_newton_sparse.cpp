// fb-newton on sparse LCPs: the discretized 2-D obstacle problem (5-point Laplacian, an
// M-matrix, so the LCP has a unique solution [Cottle-Pang-Stone 1992, Thm 3.11.10]) compared
// with a projected SOR reference written here, a non-symmetric (convection) variant that takes
// the SparseLU path, and the committed Matrix Market example read through its JSON file.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"
#include "cpkit/lcp/fb_newton.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::SparseMat;
using cpkit::Status;
using cpkit::Vec;
using cpkit::lcp::solve_fb_newton;

// Obstacle problem on the unit square, m x m interior grid: load f = -20 downwards, obstacle
// psi = -0.2 - (x - 1/2)^2 - (y - 1/2)^2 below the membrane, u = 0 on the boundary. z = u - psi.
// convection > 0 adds the upwind term convection * h * (u_ij - u_i-1,j) (non-symmetric, still a
// diagonally dominant M-matrix).
LcpProblem obstacle(int m, double convection = 0.0) {
  const int n = m * m;
  const double h = 1.0 / (m + 1);
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 + convection * h);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0 - convection * h);
      if (i < m - 1) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
      if (j < m - 1) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
  LcpProblem p;
  p.M_sparse.resize(n, n);
  p.M_sparse.setFromTriplets(t.begin(), t.end());
  p.M_sparse.makeCompressed();
  Vec psi(n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double x = (i + 1) * h, y = (j + 1) * h;
      psi[id(i, j)] = -0.2 - ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5));
    }
  p.q = p.M_sparse * psi + Vec::Constant(n, 20.0 * h * h);
  p.name = "obstacle_" + std::to_string(m) + "x" + std::to_string(m);
  return p;
}

// Projected SOR: z_i <- max(0, z_i - omega (M z + q)_i / M_ii), row by row, until the largest
// change is below `stop`. Converges for symmetric positive definite M with 0 < omega < 2 and for
// diagonally dominant M-matrices with omega = 1 [Cottle-Pang-Stone 1992, Sec. 5.2].
Vec psor(const LcpProblem& p, double omega, double stop, int max_sweeps) {
  const SparseMat Mr = SparseMat(p.M_sparse.transpose());  // column-major of M^T: rows of M
  const Eigen::Index n = p.size();
  Vec z = Vec::Zero(n), diag(n);
  for (Eigen::Index i = 0; i < n; ++i) diag[i] = p.M_sparse.coeff(i, i);
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    double change = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      double wi = p.q[i];
      for (SparseMat::InnerIterator it(Mr, i); it; ++it) wi += it.value() * z[it.row()];
      const double next = std::max(0.0, z[i] - omega * wi / diag[i]);
      change = std::max(change, std::abs(next - z[i]));
      z[i] = next;
    }
    if (change < stop) break;
  }
  return z;
}

double natural_abs(const LcpProblem& p, const Vec& z) {
  const Vec w = p.M_sparse * z + p.q;
  return z.cwiseMin(w).lpNorm<Eigen::Infinity>();
}

}  // namespace

TEST_CASE("obstacle problem n = 10,000: fb-newton equals projected SOR", "[fb][sparse][obstacle]") {
  const auto p = obstacle(100);
  REQUIRE(p.is_sparse());
  REQUIRE(p.size() == 10000);
  const double omega = 2.0 / (1.0 + std::sin(M_PI / 101.0));  // optimal SOR factor for m = 100
  const Vec ref = psor(p, omega, 1e-15, 20000);
  REQUIRE(natural_abs(p, ref) <= 1e-12);
  const auto r = solve_fb_newton(p);
  CAPTURE(r.iterations, r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK((r.z - ref).lpNorm<Eigen::Infinity>() <= 1e-9);
  CHECK(natural_abs(p, r.z) <= 1e-10 * (1 + p.q.lpNorm<Eigen::Infinity>()));
  // Non-trivial contact set: both z = 0 (membrane on the obstacle) and z > 0 occur.
  const auto contact = (r.z.array() <= 1e-12).count();
  CHECK(contact > 100);
  CHECK(contact < 9000);
}

TEST_CASE("non-symmetric sparse LCP (SparseLU path) and dense storage agree with PSOR",
          "[fb][sparse]") {
  const auto p = obstacle(30, 40.0);
  const Vec ref = psor(p, 1.0, 1e-15, 50000);
  REQUIRE(natural_abs(p, ref) <= 1e-12);
  const auto r = solve_fb_newton(p);
  REQUIRE(r.status == Status::kSolved);
  CHECK((r.z - ref).lpNorm<Eigen::Infinity>() <= 1e-9);

  LcpProblem dense(p.dense_M(), p.q, "dense_copy");
  const auto d = solve_fb_newton(dense);
  REQUIRE(d.status == Status::kSolved);
  CHECK((d.z - ref).lpNorm<Eigen::Infinity>() <= 1e-9);
}

TEST_CASE("sparse LCP from Matrix Market files named by a JSON file", "[fb][sparse][io]") {
  const std::string path = std::string(CPKIT_TEST_DATA_DIR) + "/sparse/obstacle_6x6.json";
  const auto p = cpkit::read_lcp_file(path);
  REQUIRE(p.is_sparse());
  REQUIRE(p.size() == 36);
  std::ifstream in(path);
  const auto j = nlohmann::json::parse(in);
  const auto& s = j.at("expected").at("solutions").at(0);
  Vec expected(36);
  for (Eigen::Index i = 0; i < 36; ++i) expected[i] = s.at(static_cast<size_t>(i)).get<double>();

  const auto* e = cpkit::lcp::solvers().find("fb-newton");
  REQUIRE(e != nullptr);
  REQUIRE(e->accepts(p));
  const auto r = e->solve_lcp(p, cpkit::CommonOptions{});
  REQUIRE(r.status == Status::kSolved);
  CHECK((r.z - expected).lpNorm<Eigen::Infinity>() <= 1e-10);
  // The hand-built generator and the file describe the same problem.
  const auto g = obstacle(6);
  CHECK((Vec(g.M_sparse * expected + g.q) - Vec(p.M_sparse * expected + p.q))
            .lpNorm<Eigen::Infinity>() <= 1e-14);
}

TEST_CASE("sparse box LCP: obstacle with an upper bound on z", "[fb][sparse][box]") {
  // Capping z at u = 0.05 turns the problem into a box LCP; its solution is the PSOR solution of
  // the box problem (projection onto [0, u]), computed here.
  const auto p = obstacle(20);
  const double u = 0.05;
  cpkit::BoxLcpProblem b{p, Vec::Zero(p.size()), Vec::Constant(p.size(), u)};
  const SparseMat Mr = SparseMat(p.M_sparse.transpose());
  Vec z = Vec::Zero(p.size());
  for (int sweep = 0; sweep < 20000; ++sweep) {
    double change = 0;
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      double wi = p.q[i];
      for (SparseMat::InnerIterator it(Mr, i); it; ++it) wi += it.value() * z[it.row()];
      const double next = std::min(u, std::max(0.0, z[i] - 1.5 * wi / 4.0));
      change = std::max(change, std::abs(next - z[i]));
      z[i] = next;
    }
    if (change < 1e-15) break;
  }
  const auto r = solve_fb_newton(b);
  REQUIRE(r.status == Status::kSolved);
  CHECK((r.z - z).lpNorm<Eigen::Infinity>() <= 1e-9);
  CHECK((r.z.array() >= u - 1e-12).count() > 0);  // the cap is active somewhere
}
