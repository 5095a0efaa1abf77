// Second-order-cone complementarity (soc_problem.hpp) and its FB semismooth Newton solver
// (cone_complementarity_fb.hpp). Independent sources: Moreau's decomposition (M = I: z = P_K(-q), w = P_K(q),
// hand-computed below), the LCP solver Lemke on half-line blocks (a second algorithm), and a
// projected-gradient fixed point z = P_K(z - t (M z + q)) written here (SPD M: unique solution).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/soc_problem.hpp"
#include "cpkit/lcp/damped_newton.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "cpkit/lcp/cone_complementarity_fb.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace {

using cpkit::SocProblem;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// The test's own Lorentz-cone projection (spectral formula).
Eigen::Vector3d proj(const Eigen::Vector3d& v) {
  const double t = std::hypot(v[1], v[2]);
  if (t <= v[0]) return v;
  if (t <= -v[0]) return Eigen::Vector3d::Zero();
  const double a = 0.5 * (v[0] + t);
  return Eigen::Vector3d(a, a * v[1] / t, a * v[2] / t);
}

// Second route for SPD M: projected gradient z <- P_K(z - t (M z + q)), t = 1 / lambda_max.
VectorXd projected_gradient(const SocProblem& p) {
  const double L = Eigen::SelfAdjointEigenSolver<MatrixXd>(p.M).eigenvalues().maxCoeff();
  VectorXd z = VectorXd::Zero(p.size());
  for (int it = 0; it < 200000; ++it) {
    const VectorXd y = z - (p.M * z + p.q) / L;
    VectorXd zn(p.size());
    Eigen::Index k = 0;
    for (int s : p.blocks) {
      if (s == 1) zn[k] = std::max(y[k], 0.0);
      else zn.segment<3>(k) = proj(y.segment<3>(k));
      k += s;
    }
    const double step = (zn - z).lpNorm<Eigen::Infinity>();
    z = zn;
    if (step <= 1e-15 * (1 + z.lpNorm<Eigen::Infinity>())) break;
  }
  return z;
}

SocProblem one_cone(const Eigen::Vector3d& q) {
  SocProblem p;
  p.M = MatrixXd::Identity(3, 3);
  p.q = q;
  p.blocks = {3};
  return p;
}

}  // namespace

TEST_CASE("fb-soc on one cone with M = I reaches Moreau's closed form", "[soc]") {
  // -q = (1, -2, 0): |tail| = 2 > 1, so z = P_K(-q) = 1.5 (1, -1, 0) and w = z + q = (0.5, 0.5, 0)
  // (by hand: z0 = (1 + 2) / 2, tail scaled by z0 / 2).
  const auto res = cpkit::lcp::solve_soc_fb(one_cone({-1, 2, 0}));
  REQUIRE(res.status == Status::kSolved);
  CHECK(res.z[0] == Approx(1.5).margin(1e-9));
  CHECK(res.z[1] == Approx(-1.5).margin(1e-9));
  CHECK(res.z[2] == Approx(0).margin(1e-9));
  CHECK(res.w[0] == Approx(0.5).margin(1e-9));
  CHECK(res.w[1] == Approx(0.5).margin(1e-9));
  // q inside the cone: z = 0 (interior of w); -q inside: w = 0, z = -q.
  const auto a = cpkit::lcp::solve_soc_fb(one_cone({2, 1, 1}));
  REQUIRE(a.status == Status::kSolved);
  CHECK(a.z.norm() == Approx(0).margin(1e-9));
  const auto b = cpkit::lcp::solve_soc_fb(one_cone({-3, 1, -2}));
  REQUIRE(b.status == Status::kSolved);
  CHECK((b.z - Eigen::Vector3d(3, -1, 2)).norm() == Approx(0).margin(1e-9));
}

TEST_CASE("fb-soc: the verdict and the solve do not depend on units", "[soc]") {
  // Closed form above; q scaled by a (z -> a z), then (M, q) by b (z unchanged).
  for (double a : {1e-12, 1e-6, 1.0, 1e6, 1e12})
    for (double b : {1e-12, 1.0, 1e12}) {
      SocProblem p = one_cone(Eigen::Vector3d(-1, 2, 0) * a);
      p.M *= b;
      p.q *= b;
      const auto res = cpkit::lcp::solve_soc_fb(p);
      INFO("a = " << a << ", b = " << b);
      REQUIRE(res.status == Status::kSolved);
      CHECK((res.z / a - Eigen::Vector3d(1.5, -1.5, 0)).norm() == Approx(0).margin(1e-9));
      // A wrong candidate (z off the cone by 1%) is refused at every scale.
      cpkit::SolveResult claim;
      claim.status = Status::kSolved;
      claim.z = Eigen::Vector3d(1.5, -1.515, 0) * a;
      const auto v = cpkit::finalize(p, claim, cpkit::CommonOptions{});
      CHECK(v.status == Status::kNumericalFailure);
      // By hand (soc_problem.hpp): Z = 2a, S_b = ab (sqrt5 + 1.515), the natural map of
      // (z / Z, w / S_b) has norm 0.0060100287... (computed in double by python3).
      CHECK(v.residuals.natural == Approx(0.006010028722214578).epsilon(1e-9));
    }
}

TEST_CASE("fb-soc on half-line blocks agrees with Lemke (an LCP)", "[soc]") {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N(0, 1);
  for (int rep = 0; rep < 10; ++rep) {
    const int n = 6;
    MatrixXd G(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) G(i, j) = N(rng);
    SocProblem p;
    p.M = G * G.transpose() + MatrixXd::Identity(n, n);  // SPD: one solution
    p.q = VectorXd(n);
    for (int i = 0; i < n; ++i) p.q[i] = N(rng);
    p.blocks.assign(n, 1);
    const auto res = cpkit::lcp::solve_soc_fb(p);
    REQUIRE(res.status == Status::kSolved);
    const auto lemke = cpkit::lcp::solve_lemke(cpkit::LcpProblem(p.M, p.q));
    REQUIRE(lemke.status == Status::kSolved);
    CHECK((res.z - lemke.z).lpNorm<Eigen::Infinity>() <= 1e-8 * (1 + lemke.z.norm()));
  }
}

TEST_CASE("fb-soc on mixed cone blocks agrees with projected gradient (SPD M)", "[soc]") {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0, 1);
  for (int rep = 0; rep < 10; ++rep) {
    SocProblem p;
    p.blocks = {3, 1, 3, 3};
    const int n = 10;
    MatrixXd G(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) G(i, j) = N(rng);
    p.M = G * G.transpose() + 0.5 * MatrixXd::Identity(n, n);
    p.q = VectorXd(n);
    for (int i = 0; i < n; ++i) p.q[i] = N(rng);
    const auto res = cpkit::lcp::solve_soc_fb(p);
    REQUIRE(res.status == Status::kSolved);
    const VectorXd ref = projected_gradient(p);
    CHECK((res.z - ref).lpNorm<Eigen::Infinity>() <= 1e-6 * (1 + ref.norm()));
  }
}

TEST_CASE("cone problems: registry and bad input", "[soc]") {
  const auto* e = cpkit::lcp::solvers().find("fb-soc");
  REQUIRE(e != nullptr);
  CHECK(e->accepts(cpkit::ProblemKind::kSoc));
  CHECK(e->accepts(cpkit::ProblemKind::kFrictionContact));
  const auto names = cpkit::lcp::solvers().names(cpkit::ProblemKind::kSoc);
  CHECK(std::find(names.begin(), names.end(), "fb-soc") != names.end());
  const auto r = e->solve_soc(one_cone({-1, 2, 0}), cpkit::CommonOptions{});
  CHECK(r.status == Status::kSolved);
  SocProblem bad = one_cone({1, 0, 0});
  bad.blocks = {2, 1};
  CHECK_THROWS_WITH(cpkit::lcp::solve_soc_fb(bad), Catch::Contains("block 0 has size 2"));
  bad.blocks = {1, 1};
  CHECK_THROWS_WITH(cpkit::lcp::solve_soc_fb(bad), Catch::Contains("sum to 2"));
}

TEST_CASE("damped_newton: fixed-size root by hand, and a stop without a root", "[soc][newton]") {
  using V2 = Eigen::Vector2d;
  using M2 = Eigen::Matrix2d;
  // Phi(z) = (z0^2 - 2, z1 - 1): the root (sqrt 2, 1) by hand.
  auto eval = [](const V2& z, V2& phi, M2& J) {
    phi << z[0] * z[0] - 2, z[1] - 1;
    J << 2 * z[0], 0, 0, 1;
  };
  auto done = [](const V2&, const V2& phi) { return phi.cwiseAbs().maxCoeff() <= 1e-15; };
  V2 z(5, -3);
  cpkit::lcp::DampedNewtonStats st;
  const auto stop = cpkit::lcp::damped_newton<V2, M2>(z, eval, done, {}, st);
  CHECK(stop == cpkit::lcp::DampedNewtonStop::kDone);
  CHECK(z[0] == Approx(std::sqrt(2.0)).epsilon(1e-15));
  CHECK(z[1] == 1.0);
  CHECK(st.iterations <= 10);
  // Phi(z) = z^2 + 1 has no real root: the loop must stop without claiming (Psi's stationary
  // point is z = 0; the Newton step is not a descent direction near it, the gradient is 0).
  using V1 = Eigen::Matrix<double, 1, 1>;
  auto eval1 = [](const V1& x, V1& phi, V1& J) {
    phi[0] = x[0] * x[0] + 1;
    J(0, 0) = 2 * x[0];
  };
  auto done1 = [](const V1&, const V1& phi) { return std::abs(phi[0]) <= 1e-15; };
  V1 x;
  x[0] = 0.7;
  cpkit::lcp::DampedNewtonStats st1;
  const auto stop1 = cpkit::lcp::damped_newton<V1, V1>(x, eval1, done1, {}, st1);
  CHECK(stop1 != cpkit::lcp::DampedNewtonStop::kDone);
  CHECK(st1.merit >= 0.5);  // Psi >= 1/2 everywhere
}
