// finalize() and check_certificate(): the data decide, never the claim. Expected values are
// hand calculations written in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <Eigen/LU>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"

namespace {

using cpkit::BoxLcpProblem;
using cpkit::Certificate;
using cpkit::CommonOptions;
using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::SolveResult;
using cpkit::Status;
using cpkit::Vec;

SolveResult claim(Status s, Vec z) {
  SolveResult r;
  r.status = s;
  r.z = std::move(z);
  return r;
}

}  // namespace

TEST_CASE("Siconos 1x1 trap: M = -1, q = -1, z = -1 claimed solved is refuted", "[finalize]") {
  // w = -z - 1 = 0 at z = -1, but z < 0. Units (residuals.hpp): w is judged at the projection
  // z+ = 0 (w = -1 there); z_ref = |q| / |M| = 1, Z = max(|z+|, z_ref) = 1,
  // s = |q| + |M| min(|z+|, z_ref) = 1; the bound violation |z - z+| / Z = 1: residual 1.
  const LcpProblem p(Mat{{-1}}, Vec{{-1}});
  const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{-1}}), {});
  CHECK(r.status == Status::kNumericalFailure);
  CHECK(r.message.find("refuted") != std::string::npos);
  CHECK(r.w[0] == 0.0);
  CHECK(r.residuals.natural_abs == 1.0);
  CHECK(r.residuals.scale == 1.0);
  CHECK(r.residuals.z_scale == 1.0);
  CHECK(r.residuals.natural == 1.0);
  CHECK(r.residuals.min_z == -1.0);
}

TEST_CASE("M = 0 cases", "[finalize]") {
  SECTION("M = 0, q = -1: any claimed z is refuted (w = -1)") {
    const LcpProblem p(Mat{{0}}, Vec{{-1}});
    for (double z : {0.0, 1.0, 5.0}) {
      const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{z}}), {});
      CHECK(r.status == Status::kNumericalFailure);
      CHECK(r.w[0] == -1.0);
    }
  }
  SECTION("M = 0, q = 0: z = 0 is a solution, even when the solver said otherwise") {
    const LcpProblem p(Mat{{0}}, Vec{{0}});
    const auto r = cpkit::finalize(p, claim(Status::kIterationLimit, Vec{{0}}), {});
    CHECK(r.status == Status::kSolved);
    CHECK(r.message.find("verified as a solution although") != std::string::npos);
  }
  SECTION("M = 0, q = 0: z = 3 is also a solution (w = 0)") {
    const LcpProblem p(Mat{{0}}, Vec{{0}});
    CHECK(cpkit::finalize(p, claim(Status::kSolved, Vec{{3}}), {}).status == Status::kSolved);
  }
}

TEST_CASE("Claims of the wrong size or with non-finite entries", "[finalize]") {
  const LcpProblem p(Mat::Identity(2, 2), Vec{{-1, -1}});
  auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{1}}), {});
  CHECK(r.status == Status::kNumericalFailure);
  CHECK(r.message.find("size 1, expected 2") != std::string::npos);
  r = cpkit::finalize(p, claim(Status::kSolved, Vec{{1, NAN}}), {});
  CHECK(r.status == Status::kNumericalFailure);
  CHECK(r.message.find("non-finite") != std::string::npos);
  // A non-solution claim with an unusable point keeps its status.
  r = cpkit::finalize(p, claim(Status::kStalled, Vec()), {});
  CHECK(r.status == Status::kStalled);
}

TEST_CASE("Solved, solved inaccurately, refuted: the tolerance bands", "[finalize]") {
  // M = I, q = (-1, -1): the solution is z = (1, 1). z = (1 + e, 1): w = (e, 0).
  // z_ref = 1, Z = 1 + e, s_i = 1 + 1 min(1 + e, 1) = 2: row 0 has zn = 1, wn = e / 2 (less a
  // rounding allowance of order 1e-16), so the residual is e / 2.
  const LcpProblem p(Mat::Identity(2, 2), Vec{{-1, -1}});
  CommonOptions o;  // tol 1e-10, tol_acceptable 1e-6
  auto at = [&](double e, Status s) {
    return cpkit::finalize(p, claim(s, Vec{{1 + e, 1}}), o);
  };
  CHECK(at(0, Status::kSolved).status == Status::kSolved);
  CHECK(at(1e-11, Status::kSolved).status == Status::kSolved);
  const auto inacc = at(1e-8, Status::kSolved);
  CHECK(inacc.status == Status::kSolvedInaccurate);
  CHECK(inacc.residuals.natural == Approx(1e-8 / 2).epsilon(1e-6));
  CHECK(at(1e-3, Status::kSolved).status == Status::kNumericalFailure);
  // A claimed failure whose point is far off stays a failure.
  CHECK(at(1e-3, Status::kIterationLimit).status == Status::kIterationLimit);
  // A claimed failure whose point is within tol_acceptable is granted solved_inaccurate.
  CHECK(at(1e-8, Status::kIterationLimit).status == Status::kSolvedInaccurate);
}

TEST_CASE("Residual definitions by hand", "[finalize][residuals]") {
  // M = [[1, -2], [3, 4]], q = (1, -20), z = (2, 3):
  // w = (2 - 6 + 1, 6 + 12 - 20) = (-3, -2); min(z, w) = (-3, -2) -> natural_abs 3 at index 0;
  // |z_i w_i| = (6, 6) -> 6; min z = 2; min w = -3;
  // Units: ||q|| = 20, ||M||_max = 4, z_ref = 5, ||z|| = 3, Z = max(3, 5) = 5;
  // row sums (3, 7); s = (1 + 3 min(3, 5), 20 + 7 min(3, 5)) = (10, 41);
  // zn = (0.4, 0.6), wn = (-0.3, -2/41) (less rounding ~1e-15): residual 0.3 at index 0.
  const LcpProblem p(Mat{{1, -2}, {3, 4}}, Vec{{1, -20}});
  Vec w;
  const auto r = cpkit::lcp_residuals(p, Vec{{2, 3}}, w);
  CHECK(w == Vec{{-3, -2}});
  CHECK(r.natural_abs == 3.0);
  CHECK(r.worst_index == 0);
  CHECK(r.complementarity == 6.0);
  CHECK(r.min_z == 2.0);
  CHECK(r.min_w == -3.0);
  CHECK(r.scale == 41.0);
  CHECK(r.z_scale == 5.0);
  CHECK(r.natural == Approx(0.3).epsilon(1e-12));
  // Sparse storage gives the same numbers.
  LcpProblem sp;
  sp.M_sparse = p.M.sparseView();
  sp.q = p.q;
  Vec w2;
  const auto r2 = cpkit::lcp_residuals(sp, Vec{{2, 3}}, w2);
  CHECK(w2 == w);
  CHECK(r2.scale == 41.0);
  CHECK(r2.natural == r.natural);
  CHECK(r2.natural_abs == 3.0);
}

TEST_CASE("Box LCP residual by hand", "[finalize][residuals]") {
  // l = (0, -1), u = (1, 1), M = I, q = (-2, 0.5), z = (1, -0.5): w = (-1, 0).
  // z - mid(l, u, z - w) = (1 - mid(0, 1, 2), -0.5 - mid(-1, 1, -0.5)) = (0, 0): a solution
  // (z_1 = u_1 with w_1 <= 0, z_2 interior with w_2 = 0).
  BoxLcpProblem b{LcpProblem(Mat::Identity(2, 2), Vec{{-2, 0.5}}), Vec{{0, -1}}, Vec{{1, 1}}};
  const auto r = cpkit::finalize(b, claim(Status::kSolved, Vec{{1, -0.5}}), {});
  CHECK(r.status == Status::kSolved);
  CHECK(r.residuals.natural_abs == 0.0);
  // z = (0.5, -0.5): z_1 interior but w_1 = -1.5: natural map entry 0.5 - mid(0,1,2) = -0.5.
  const auto bad = cpkit::finalize(b, claim(Status::kSolved, Vec{{0.5, -0.5}}), {});
  CHECK(bad.status == Status::kNumericalFailure);
  CHECK(bad.residuals.natural_abs == 0.5);
}

TEST_CASE("Infeasibility certificates are re-checked from the data", "[finalize][certificate]") {
  // M = [[1,-1],[-1,1]], q = (-1,-1): y = (1, 1) gives M^T y = 0, q^T y = -2.
  const LcpProblem p(Mat{{1, -1}, {-1, 1}}, Vec{{-1, -1}});
  auto infeasible = [](Vec y) {
    SolveResult r;
    r.status = Status::kInfeasible;
    r.certificate = Certificate{};
    r.certificate->y = std::move(y);
    return r;
  };
  SECTION("a valid certificate is kept, normalised and measured") {
    const auto r = cpkit::finalize(p, infeasible(Vec{{3, 3}}), {});
    REQUIRE(r.status == Status::kInfeasible);
    REQUIRE(r.certificate);
    CHECK(r.certificate->checked);
    // scaled by a power of two (exactly) to ||y||_inf in [1, 2): 3 / 2 = 1.5
    CHECK(r.certificate->y == Vec{{1.5, 1.5}});
    CHECK(r.certificate->exact);
    CHECK(r.certificate->q_dot_y == -3.0);
    CHECK(r.certificate->max_MTy == 0.0);
  }
  SECTION("refuted certificates become numerical failures") {
    for (const Vec& y : {Vec{{1, 0}}, Vec{{1, 2}}, Vec{{-1, -1}}, Vec{{0, 0}}, Vec{{1, 1, 1}},
                         Vec{{1, NAN}}}) {
      CAPTURE(y);
      const auto r = cpkit::finalize(p, infeasible(y), {});
      CHECK(r.status == Status::kNumericalFailure);
      CHECK_FALSE(r.certificate.has_value());
      CHECK(r.message.find("refuted") != std::string::npos);
    }
  }
  SECTION("infeasible without a certificate") {
    SolveResult c;
    c.status = Status::kInfeasible;
    const auto r = cpkit::finalize(p, c, {});
    CHECK(r.status == Status::kNumericalFailure);
    CHECK(r.message.find("without a certificate") != std::string::npos);
  }
  SECTION("a certificate of a feasible problem cannot pass") {
    // q = (1, 1): z = 0 solves; q^T y > 0 for every y >= 0, y != 0.
    const LcpProblem feasible(p.M, Vec{{1, 1}});
    Certificate c;
    c.y = Vec{{1, 1}};
    CHECK_FALSE(cpkit::check_certificate(feasible, c));
    CHECK_FALSE(c.checked);
    CHECK(c.q_dot_y == 2.0);
  }
  SECTION("a certificate attached to a non-infeasible claim is dropped") {
    SolveResult c = infeasible(Vec{{1, 1}});
    c.status = Status::kRayTermination;
    c.z = Vec{{0, 0}};
    const auto r = cpkit::finalize(p, c, {});
    CHECK(r.status == Status::kRayTermination);
    CHECK_FALSE(r.certificate.has_value());
  }
  SECTION("the 1x1 traps have certificates y = 1") {
    for (double m : {-1.0, 0.0}) {
      Certificate c;
      c.y = Vec{{1}};
      CHECK(cpkit::check_certificate(LcpProblem(Mat{{m}}, Vec{{-1}}), c));
    }
  }
}

TEST_CASE("MCP finalize evaluates F and respects its domain", "[finalize][mcp]") {
  // NCP F(x) = x - 2 on x >= 0: solution x = 2. F undefined for x > 10 (domain test).
  auto mcp = cpkit::make_ncp(1, [](const Vec& x, Vec& F) {
    if (x[0] > 10) return false;
    F = Vec{{x[0] - 2}};
    return true;
  });
  CHECK(cpkit::finalize(mcp, claim(Status::kSolved, Vec{{2}}), {}).status == Status::kSolved);
  const auto out = cpkit::finalize(mcp, claim(Status::kSolved, Vec{{11}}), {});
  CHECK(out.status == Status::kNumericalFailure);
  CHECK(out.message.find("F is undefined") != std::string::npos);
  SolveResult inf;
  inf.status = Status::kInfeasible;
  CHECK(cpkit::finalize(mcp, inf, {}).status == Status::kNumericalFailure);
}

TEST_CASE("A diverging iterate is never granted solved", "[finalize][residuals]") {
  // infeasible_copositive_plus: M = [[1, -1], [-1, 1]], q = (-1, -1). Along z = (t, t),
  // w = (-1, -1) for every t, so min(z, w) = -1 however large t is. A unit that grew with
  // |M||z| would call z = (1e11, 1e11) "solved"; s_i = 1 + 2 min(t, z_ref = 1) = 3 does not:
  // wn_i = -(1 - a_i) / 3 with the rounding allowance a_i = gamma_3 (2 t + 1).
  const LcpProblem p(Mat{{1, -1}, {-1, 1}}, Vec{{-1, -1}});
  for (double t : {1e3, 1e11, 1e14}) {
    CAPTURE(t);
    const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{t, t}}), {});
    CHECK(r.status == Status::kNumericalFailure);
    const double g = 3 * 0x1p-53 / (1 - 3 * 0x1p-53);
    CHECK(r.residuals.natural == Approx((1 - g * (2 * t + 1)) / 3).epsilon(1e-12));
  }
}

TEST_CASE("A genuine solution with a huge z verifies through the rounding allowance",
          "[finalize][residuals]") {
  // cps_example_4_4_16: M = [[1, -1], [-1, 1]], q = (1, -1); every z = (t, t + 1) solves it
  // (w = 0). At t = 1e12 the computed w carries rounding errors of order 1e-4, far above
  // tol s_i; the per-row allowance gamma_3 (|M||z| + |q|)_i covers exactly that.
  const LcpProblem p(Mat{{1, -1}, {-1, 1}}, Vec{{1, -1}});
  const double t = 1e12;
  const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{t, t + 1}}), {});
  CHECK(cpkit::is_solution(r.status));
  CHECK(r.residuals.rounding > 0);
  CHECK(r.residuals.rounding < 1e-2);
}

TEST_CASE("Certificates: exact signs, no magnitude excuses a positive column", "[finalize][certificate]") {
  SECTION("M = diag(1e11, 1), q = (1, -1) is solvable (z = (0, 1)): y = (0, 1) is refuted") {
    // (M^T y)_2 = 1 > 0: a tolerance relative to max|M| = 1e11 would have excused it.
    const LcpProblem p(Mat{{1e11, 0}, {0, 1}}, Vec{{1, -1}});
    for (double big : {1e11, 1e200}) {
      LcpProblem q = p;
      q.M(0, 0) = big;
      Certificate c;
      c.y = Vec{{0, 1}};
      CHECK_FALSE(cpkit::check_certificate(q, c));
      c.y = Vec{{1e-20, 1}};
      CHECK_FALSE(cpkit::check_certificate(q, c));
    }
  }
  SECTION("a column that is positive by one unit in the last place is refuted") {
    // M = [[1, -1], [-1, 1 + 2^-52]], y = (1, 1): (M^T y)_2 = 2^-52 > 0 exactly; q^T y = -2.
    const LcpProblem p(Mat{{1, -1}, {-1, 1 + 0x1p-52}}, Vec{{-1, -1}});
    Certificate c;
    c.y = Vec{{1, 1}};
    // Within rounding of forming M^T y (gamma_3 (|M|^T y)_2 ~ 6.7e-16 > 2.2e-16): accepted as
    // a certificate of a problem within rounding, flagged not exact.
    CHECK(cpkit::check_certificate(p, c));
    CHECK_FALSE(c.exact);
    // Ten thousand ulps are not rounding: refuted.
    const LcpProblem far(Mat{{1, -1}, {-1, 1 + 1e4 * 0x1p-52}}, Vec{{-1, -1}});
    c.y = Vec{{1, 1}};
    CHECK_FALSE(cpkit::check_certificate(far, c));
  }
  SECTION("a floating-point y of a rational certificate is snapped and proven exactly") {
    // M = [[4, 4, -6], [4, 8, -6], [-6, -6, 9]] (PSD), q = (0, 1, -1): y = (3, 0, 2) / 3 gives
    // M^T y = 0 and q^T y = -2/3 exactly; 2/3 is not a double, so the stored y must be snapped.
    const LcpProblem p(Mat{{4, 4, -6}, {4, 8, -6}, {-6, -6, 9}}, Vec{{0, 1, -1}});
    Certificate c;
    c.y = Vec{{1.0, 0.0, 2.0 / 3.0}};
    REQUIRE(cpkit::check_certificate(p, c));
    CHECK(c.exact);
    CHECK(c.max_MTy == 0.0);
    CHECK(c.y[0] / c.y[2] == 1.5);
  }
  SECTION("the verdict does not depend on units") {
    // M = [[-2, 1], [1, -2]], q = (-1, -1): y = (1, 1), M^T y = (-1, -1), q^T y = -2.
    for (double a : {1e-300, 1e-12, 1.0, 1e12, 1e300}) {
      for (double b : {1e-12, 1.0, 1e12}) {
        if (!std::isfinite(a * b)) continue;  // q itself would not be representable
        CAPTURE(a, b);
        const LcpProblem p(b * Mat{{-2, 1}, {1, -2}}, a * b * Vec{{-1, -1}});
        Certificate c;
        c.y = Vec{{1, 1}};
        CHECK(cpkit::check_certificate(p, c));
        CHECK(c.exact);
      }
    }
  }
}

TEST_CASE("Verdicts do not depend on units", "[finalize][units]") {
  // M = [[2, 1], [1, 2]], q = (-5, -6): the unique solution is z = (4/3, 7/3).
  const Mat M{{2, 1}, {1, 2}};
  const Vec q{{-5, -6}}, zs{{4.0 / 3, 7.0 / 3}};
  for (double a : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    for (double b : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
      CAPTURE(a, b);
      const LcpProblem p(b * M, a * b * q);
      // The solution (scaled by a) is accepted, z = 0 never (however small q is), and a point
      // off by 1e-3 relative is refuted, in every unit.
      CHECK(cpkit::finalize(p, claim(Status::kSolved, a * zs), {}).status == Status::kSolved);
      const auto zero = cpkit::finalize(p, claim(Status::kSolved, Vec::Zero(2)), {});
      CHECK(zero.status == Status::kNumericalFailure);
      CHECK(zero.residuals.natural == Approx(5.0 / 5.0).epsilon(1e-12));  // wn_0 = -5 / |q_0|
      const auto off = cpkit::finalize(p, claim(Status::kSolved, a * zs * (1 + 1e-3)), {});
      CHECK(off.status == Status::kNumericalFailure);
      Vec w;
      const auto r1 = cpkit::lcp_residuals(p, a * Vec{{1.0, 2.0}}, w);
      const auto r0 = cpkit::lcp_residuals(LcpProblem(M, q), Vec{{1.0, 2.0}}, w);
      CHECK(r1.natural == Approx(r0.natural).epsilon(1e-12));
    }
  }
}

TEST_CASE("A huge row excuses nothing in a small one; nothing non-finite is solved",
          "[finalize][units]") {
  SECTION("M = [[1e16, 0], [0, -1]], q = (1, -1) has no solution: w = (1.2e15, -1) is refuted") {
    const LcpProblem p(Mat{{1e16, 0}, {0, -1}}, Vec{{1, -1}});
    const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{0.12, 0}}), {});
    CHECK(r.status == Status::kNumericalFailure);
    CHECK(r.residuals.natural >= 1.0);  // row 1: wn = -1 / (1 + 1 min(0.12, 1e-16)) ~ -1
  }
  SECTION("M = I, q = (1e16, -1): z = 0 is refuted (the solution is (0, 1))") {
    const LcpProblem p(Mat::Identity(2, 2), Vec{{1e16, -1}});
    CHECK(cpkit::finalize(p, claim(Status::kSolved, Vec::Zero(2)), {}).status ==
          Status::kNumericalFailure);
    CHECK(cpkit::finalize(p, claim(Status::kSolved, Vec{{0, 0.5}}), {}).status ==
          Status::kNumericalFailure);
    CHECK(cpkit::finalize(p, claim(Status::kSolved, Vec{{0, 1}}), {}).status == Status::kSolved);
  }
  SECTION("overflowing |M||z| or NaN in w is never solved") {
    const LcpProblem p(Mat{{1e300, -1e300}, {-1e300, 1e300}}, Vec{{1, -1}});
    const auto r = cpkit::finalize(p, claim(Status::kSolved, Vec{{1e300, 1e300}}), {});
    CHECK(r.status == Status::kNumericalFailure);
    const LcpProblem t(Mat{{1e-320}}, Vec{{-1}});
    CHECK(cpkit::finalize(t, claim(Status::kSolved, Vec{{1e308}}), {}).status ==
          Status::kNumericalFailure);
    CHECK(cpkit::finalize(t, claim(Status::kSolved, Vec{{0}}), {}).status ==
          Status::kNumericalFailure);
  }
}

TEST_CASE("small_lcp_natural is lcp_residuals' number, bit for bit, n = 1..4", "[residuals]") {
  // The C API's allocation-free verdict must decide as finalize() does: the same unit-free
  // residual from the same data, on a seeded family of mixed-scale problems and candidates
  // (exact solutions of a basis, random points with negative entries, zeros, huge and tiny z).
  std::mt19937 rng(20261129);
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> e(-6, 6), pick(0, 4);
  int compared = 0, solved = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int n = 1 + trial % cpkit::kSmallLcpMax;
    Mat M(n, n);
    Vec q(n), z(n);
    for (int i = 0; i < n; ++i) {
      q[i] = g(rng) * std::ldexp(1.0, e(rng));
      for (int j = 0; j < n; ++j) M(i, j) = pick(rng) == 0 ? 0.0 : g(rng) * std::ldexp(1.0, e(rng));
    }
    switch (trial % 5) {
      case 0: z = Vec::Zero(n); break;
      case 1: z = Vec::NullaryExpr(n, [&] { return g(rng); }); break;       // some z_i < 0
      case 2: z = Vec::NullaryExpr(n, [&] { return 1e200 * std::abs(g(rng)); }); break;
      default: {  // the basic solution of a random basis, z_S = -M_SS^{-1} q_S, others 0
        z = Vec::Zero(n);
        std::vector<int> S;
        for (int i = 0; i < n; ++i)
          if (pick(rng) < 3) S.push_back(i);
        Mat A(S.size(), S.size());
        Vec b(S.size());
        for (std::size_t a = 0; a < S.size(); ++a) {
          b[a] = -q[S[a]];
          for (std::size_t c = 0; c < S.size(); ++c) A(a, c) = M(S[a], S[c]);
        }
        if (S.empty()) break;  // the empty basis: z = 0 (Eigen asserts on a 0 x 0 LU)
        const Vec x = A.fullPivLu().solve(b);
        for (std::size_t a = 0; a < S.size(); ++a) z[S[a]] = x[a];
      }
    }
    Vec w_general;
    const double general = cpkit::lcp_residuals(LcpProblem(M, q), z, w_general).natural;
    double w_small[cpkit::kSmallLcpMax];
    const double small = cpkit::small_lcp_natural(n, M.data(), q.data(), z.data(), w_small);
    INFO("trial " << trial << " n " << n);
    REQUIRE(std::memcmp(&small, &general, sizeof small) == 0);  // bit for bit (+inf included)
    for (int i = 0; i < n; ++i) REQUIRE(w_small[i] == w_general[i]);
    ++compared;
    if (general <= CommonOptions{}.tol) ++solved;
  }
  CHECK(compared == 4000);
  CHECK(solved >= 200);  // the family exercises the accepted side of the verdict too
  double w[1];
  CHECK(std::isinf(cpkit::small_lcp_natural(5, nullptr, nullptr, nullptr, w)));  // n > 4: no number
}
