// Tests of Lemke's method (lemke.hpp). Every expected value comes from an independent source:
// a hand calculation (in the comments), the literature (the reference problems of
// tests/data/lcp with their stated outcome and pivot count), a closed form (Murty's example), a
// brute-force enumeration of complementary bases written here, or the residual / certificate
// recomputed here from the data.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::SolveResult;
using cpkit::Status;
using cpkit::Vec;
using cpkit::lcp::LemkeOptions;
using cpkit::lcp::solve_lemke;

// ||min(z, Mz + q)||_inf, computed here from the data (not with cpkit's residual code).
double natural_residual(const Mat& M, const Vec& q, const Vec& z) {
  double r = 0;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    double wi = q[i];
    for (Eigen::Index j = 0; j < q.size(); ++j) wi += M(i, j) * z[j];
    r = std::max(r, std::abs(std::min(z[i], wi)));
  }
  return r;
}

// Checks y >= 0, M^T y <= 0, q^T y < 0 here, with a small absolute slack.
// y >= 0, M^T y <= 0, q^T y < 0 for integer M, q, checked in long double (64-bit significand):
// the products of small integers with the doubles of y are exact there, and so are the short
// sums of the tests below, so a certificate that holds only by one unit in the last place of a
// double (Lemke may return one, and finalize() proves it exactly) is judged correctly.
bool is_farkas_certificate(const Mat& M, const Vec& q, const Vec& y) {
  if (!(y.cwiseAbs().maxCoeff() > 0) || y.minCoeff() < 0) return false;
  long double qy = 0;
  for (Eigen::Index i = 0; i < q.size(); ++i) qy += static_cast<long double>(q[i]) * y[i];
  if (!(qy < 0)) return false;
  for (Eigen::Index j = 0; j < M.cols(); ++j) {
    long double c = 0;
    for (Eigen::Index i = 0; i < M.rows(); ++i) c += static_cast<long double>(M(i, j)) * y[i];
    if (c > 0) return false;
  }
  return true;
}

// All solutions of a nondegenerate LCP by enumerating the 2^n complementary bases (z_i basic
// for i in the subset, w_i otherwise): solve M_aa z_a = -q_a, accept when z_a >= 0 and
// w = M z + q >= 0. Used for P-matrices, whose solution is unique [CPS 1992, Thm 3.3.7].
std::vector<Vec> enumerate_solutions(const Mat& M, const Vec& q) {
  const Eigen::Index n = q.size();
  std::vector<Vec> out;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<Eigen::Index> a;
    for (Eigen::Index i = 0; i < n; ++i)
      if (mask & (1u << i)) a.push_back(i);
    Vec z = Vec::Zero(n);
    if (!a.empty()) {
      Mat Maa(a.size(), a.size());
      Vec qa(a.size());
      for (size_t r = 0; r < a.size(); ++r) {
        qa[r] = q[a[r]];
        for (size_t c = 0; c < a.size(); ++c) Maa(r, c) = M(a[r], a[c]);
      }
      Eigen::FullPivLU<Mat> lu(Maa);
      if (!lu.isInvertible()) continue;
      const Vec za = lu.solve(-qa);
      for (size_t r = 0; r < a.size(); ++r) z[a[r]] = za[r];
    }
    const Vec w = M * z + q;
    if (z.minCoeff() >= -1e-9 && w.minCoeff() >= -1e-9) out.push_back(z);
  }
  return out;
}

// Random P-matrix: positive definite symmetric part (B B^T / n + I) plus a skew part.
Mat random_p_matrix(Eigen::Index n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat B(n, n), S(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) B(i, j) = u(rng), S(i, j) = u(rng);
  return B * B.transpose() / static_cast<double>(n) + Mat::Identity(n, n) + S - S.transpose();
}

Vec random_vec(Eigen::Index n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

// Murty's example [Murty 1978]: unit diagonal, 2 above it, q_i = -(2^(i+1) + ... + 2^n).
LcpProblem murty(int n) {
  Mat M = Mat::Zero(n, n);
  Vec q(n);
  for (int i = 0; i < n; ++i) {
    M(i, i) = 1;
    for (int j = i + 1; j < n; ++j) M(i, j) = 2;
    double s = 0;
    for (int j = i + 1; j <= n; ++j) s += std::ldexp(1.0, j);
    q[i] = -s;
  }
  return LcpProblem(M, q, "murty");
}

// Plain Lemke with first-index tie-breaking on a full tableau (independent of cpkit's code):
// initial leaving row = smallest index among the most negative q_i; later ties: z0 first,
// otherwise the smallest row index. Returns true when a basis repeats (cycling).
bool plain_lemke_cycles(const Mat& M, const Vec& q, int max_pivots) {
  const int n = static_cast<int>(q.size());
  // Columns: w_0..w_{n-1}, z_0..z_{n-1}, z0, rhs. Rows: w - M z - e z0 = q.
  Mat T = Mat::Zero(n, 2 * n + 2);
  T.leftCols(n) = Mat::Identity(n, n);
  T.block(0, n, n, n) = -M;
  T.col(2 * n) = -Vec::Ones(n);
  T.col(2 * n + 1) = q;
  std::vector<int> basic(n);
  for (int i = 0; i < n; ++i) basic[i] = i;
  auto do_pivot = [&](int r, int col) {
    T.row(r) /= T(r, col);
    for (int i = 0; i < n; ++i)
      if (i != r) T.row(i) -= T(i, col) * T.row(r);
    basic[r] = col;
  };
  int r0 = 0;
  for (int i = 1; i < n; ++i)
    if (q[i] < q[r0] - 1e-12) r0 = i;
  int leaving = basic[r0];
  do_pivot(r0, 2 * n);
  std::set<std::vector<int>> seen;
  for (int p = 1; p < max_pivots; ++p) {
    std::vector<int> key = basic;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) return true;
    const int entering = leaving < n ? leaving + n : leaving - n;
    int r = -1;
    double best = INFINITY;
    for (int i = 0; i < n; ++i) {
      if (T(i, entering) <= 1e-12) continue;
      const double ratio = T(i, 2 * n + 1) / T(i, entering);
      // The first admissible row is taken as is (r = -1 has no basic variable to compare:
      // reading basic[r] there was an out-of-bounds read caught by AddressSanitizer).
      const bool tie = r >= 0 && std::abs(ratio - best) <= 1e-12 * (1 + std::abs(best));
      if (r < 0 || ratio < best - 1e-12 * (1 + std::abs(best)) ||
          (tie && basic[i] == 2 * n && basic[r] != 2 * n)) {
        best = ratio;
        r = i;
      }
    }
    if (r < 0) return false;  // ray
    leaving = basic[r];
    do_pivot(r, entering);
    if (leaving == 2 * n) return false;  // solved
  }
  return false;
}

std::vector<std::string> data_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(CPKIT_TEST_DATA_DIR "/lcp"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("TrivialNoPivot: q >= 0 is solved by z = 0 without pivots", "[lemke]") {
  const LcpProblem p(Mat{{1, 2}, {-3, 4}}, Vec{{0.5, 0.0}});
  const auto r = solve_lemke(p);
  CHECK(r.status == Status::kSolved);
  CHECK(r.iterations == 0);
  CHECK(r.z == Vec::Zero(2));
  CHECK(r.w == p.q);  // recomputed by finalize
  CHECK(r.solver == "lemke");
  CHECK(r.basis == std::vector<int>{~0, ~1});
}

TEST_CASE("Hand-solved 2x2: M = [[2,1],[1,2]], q = (-1,1)", "[lemke]") {
  // z2 = 0: w1 = 2 z1 - 1 = 0 -> z1 = 1/2, w2 = z1 + 1 = 3/2. Pivots: z0 enters (w1 leaves,
  // z0 = 1); z1 enters, z0 = 1 - 2 z1 hits 0 at z1 = 1/2 before w2 = 2 - z1 does: 2 pivots.
  const LcpProblem p(Mat{{2, 1}, {1, 2}}, Vec{{-1, 1}});
  const auto r = solve_lemke(p);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.iterations == 2);
  CHECK(r.z[0] == Approx(0.5).margin(1e-15));
  CHECK(r.z[1] == Approx(0.0).margin(1e-15));
  CHECK(r.w[0] == Approx(0.0).margin(1e-15));
  CHECK(r.w[1] == Approx(1.5).margin(1e-15));
}

TEST_CASE("Hand-solved 3x3 with a degenerate pivot", "[lemke]") {
  // M tridiagonal (2, -1), q = (-1, 2, -1). Solution z = (1/2, 0, 1/2), w = (0, 1, 0).
  // Pivots: rows 0 and 2 tie for z0 (q = -1); the lexicographic rule takes the larger index,
  // w3 leaves (z0 = 1, w1 = 0 degenerate). z3 enters: w1 = -2 z3 blocks at 0, w1 leaves.
  // z1 enters: z0 = 1 - 2 z1 and w2 = 3 - 4 z1, z0 leaves at z1 = 1/2. 3 pivots.
  const LcpProblem p(Mat{{2, -1, 0}, {-1, 2, -1}, {0, -1, 2}}, Vec{{-1, 2, -1}});
  LemkeOptions o;
  o.common.record_trace = true;
  const auto r = solve_lemke(p, o);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.iterations == 3);
  CHECK((r.z - Vec{{0.5, 0, 0.5}}).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((r.w - Vec{{0, 1, 0}}).cwiseAbs().maxCoeff() < 1e-15);
  // Trace: ids 0..2 = z_i, 3 = z0, 4..6 = w_i.
  REQUIRE(r.trace.size() == 3);
  CHECK(r.trace[0].kind == "z0-enters");
  CHECK(r.trace[0].entering == 3);
  CHECK(r.trace[0].leaving == 6);  // w3
  CHECK(r.trace[1].entering == 2);  // z3
  CHECK(r.trace[1].leaving == 4);   // w1
  CHECK(r.trace[1].step == 0.0);    // degenerate
  CHECK(r.trace[2].entering == 0);  // z1
  CHECK(r.trace[2].leaving == 3);   // z0
  CHECK(r.trace[2].kind == "z0-leaves");
  CHECK(r.basis == std::vector<int>{0, ~1, 2});
}

TEST_CASE("MurtyExponential: 2^n pivots counting the z0 pivot", "[lemke]") {
  SECTION("the reference file murty_exp_6.json") {
    const auto p = cpkit::read_lcp_json(CPKIT_TEST_DATA_DIR "/lcp/murty_exp_6.json");
    const auto r = solve_lemke(p);
    REQUIRE(r.status == Status::kSolved);
    CHECK(r.iterations == 64);
    CHECK((r.z - Vec{{0, 0, 0, 0, 0, 64}}).cwiseAbs().maxCoeff() < 1e-12);
  }
  SECTION("generated, n = 2..10") {
    for (int n = 2; n <= 10; ++n) {
      CAPTURE(n);
      const auto r = solve_lemke(murty(n));
      REQUIRE(r.status == Status::kSolved);
      CHECK(r.iterations == (1 << n));
      Vec expected = Vec::Zero(n);
      expected[n - 1] = std::ldexp(1.0, n);
      CHECK((r.z - expected).cwiseAbs().maxCoeff() < 1e-9);
    }
  }
}

TEST_CASE("CyclingExample: plain Lemke cycles, lexicographic Lemke solves in 4 pivots",
          "[lemke]") {
  const auto p = cpkit::read_lcp_json(CPKIT_TEST_DATA_DIR "/lcp/lemke_cycling_circulant.json");
  // The problem really is a cycling example for first-index tie-breaking (independent code).
  CHECK(plain_lemke_cycles(p.M, p.q, 100));
  const auto r = solve_lemke(p);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.iterations == 4);
  CHECK((r.z - Vec::Constant(3, 1.0 / 3.0)).cwiseAbs().maxCoeff() < 1e-14);
  CHECK(natural_residual(p.M, p.q, r.z) < 1e-14);
}

TEST_CASE("Every reference problem: stated Lemke outcome and pivot count", "[lemke][data]") {
  const auto files = data_files();
  REQUIRE(files.size() >= 14);
  for (const auto& file : files) {
    CAPTURE(file);
    std::ifstream in(file);
    const auto j = nlohmann::json::parse(in);
    const auto& expected = j.at("expected");
    const auto& ref = expected.at("lemke_with_covering_ones");
    const auto p = cpkit::read_lcp_json(file);
    const auto r = solve_lemke(p);
    CAPTURE(cpkit::to_string(r.status), r.message);
    CHECK(r.iterations == ref.at("pivots_including_z0").get<int>());
    if (ref.at("outcome") == "solution") {
      REQUIRE(cpkit::is_solution(r.status));
      CHECK(natural_residual(p.M, p.q, r.z) <= 1e-10 * (1 + p.q.cwiseAbs().maxCoeff()));
      if (expected.at("complete").get<bool>() && !expected.at("continuum").get<bool>()) {
        bool listed = false;
        for (const auto& s : expected.at("solutions")) {
          Vec v(p.size());
          for (Eigen::Index i = 0; i < p.size(); ++i) v[i] = s.at(i).get<double>();
          listed = listed || (v - r.z).cwiseAbs().maxCoeff() < 1e-9;
        }
        CHECK(listed);
      }
    } else {
      REQUIRE(ref.at("outcome") == "secondary ray");
      CHECK_FALSE(cpkit::is_solution(r.status));
      REQUIRE(r.ray.has_value());
      CHECK(r.ray->size() == p.size() + 1);
      if (expected.at("status") == "infeasible") {
        // Both infeasible references end with a certificate cpkit finds and verifies.
        REQUIRE(r.status == Status::kInfeasible);
        REQUIRE(r.certificate.has_value());
        CHECK(r.certificate->checked);
        CHECK(is_farkas_certificate(p.M, p.q, r.certificate->y));
      } else {
        CHECK(r.status == Status::kRayTermination);
        CHECK_FALSE(r.certificate.has_value());
      }
    }
  }
}

TEST_CASE("RayTerminationInfeasible: copositive-plus M, certificate checked here", "[lemke]") {
  // M = [[1,-1],[-1,1]] PSD, q = (-1,-1): w1 + w2 = -2 for every z, so no w >= 0.
  const LcpProblem p(Mat{{1, -1}, {-1, 1}}, Vec{{-1, -1}});
  const auto r = solve_lemke(p);
  REQUIRE(r.status == Status::kInfeasible);
  REQUIRE(r.certificate.has_value());
  const Vec& y = r.certificate->y;
  CHECK(is_farkas_certificate(p.M, p.q, y));
  CHECK(y[0] == Approx(y[1]));  // the only certificate direction is (1, 1)
  CHECK(r.certificate->q_dot_y < 0);
}

TEST_CASE("Lemke on copositive-plus problems never ends on an unproven ray", "[lemke]") {
  // PSD M = B B^T (rank deficient) + skew part is copositive-plus: Lemke must solve the LCP
  // or prove it infeasible [CPS 1992, Thm 4.4.13]; both answers are checked here.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> u(-3, 3);
  int solved = 0, infeasible = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 2 + trial % 6;
    const int rank = 1 + (trial / 6) % n;
    Mat B(n, rank), S(n, n);
    Vec q(n);
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < rank; ++c) B(i, c) = u(rng);
      for (int c = 0; c < n; ++c) S(i, c) = u(rng);
      q[i] = u(rng) - 1;
    }
    const Mat skew = trial % 3 == 0 ? Mat(S - S.transpose()) : Mat::Zero(n, n);
    const LcpProblem p(B * B.transpose() + skew, q);
    CAPTURE(trial, p.M, p.q);
    const auto r = solve_lemke(p);
    if (cpkit::is_solution(r.status)) {
      ++solved;
      CHECK(natural_residual(p.M, p.q, r.z) <= 1e-9 * (1 + r.z.cwiseAbs().maxCoeff()));
    } else {
      REQUIRE(r.status == Status::kInfeasible);
      ++infeasible;
      CHECK(is_farkas_certificate(p.M, p.q, r.certificate->y));
    }
  }
  CHECK(solved > 20);
  CHECK(infeasible > 20);
}

TEST_CASE("1x1 traps: M = -1 / M = 0 are never 'solved' when q < 0", "[lemke]") {
  SECTION("M = -1, q = -1: infeasible (w = -z - 1 < 0), never z = -1") {
    const auto r = solve_lemke(LcpProblem(Mat{{-1}}, Vec{{-1}}));
    CHECK_FALSE(cpkit::is_solution(r.status));
    CHECK(r.status == Status::kInfeasible);
    REQUIRE(r.certificate.has_value());
    CHECK(r.certificate->y[0] > 0);
  }
  SECTION("M = 0, q = -1: infeasible") {
    const auto r = solve_lemke(LcpProblem(Mat{{0}}, Vec{{-1}}));
    CHECK(r.status == Status::kInfeasible);
  }
  SECTION("M = 0, q = 0 and q = 1: z = 0 solves") {
    for (double q : {0.0, 1.0}) {
      const auto r = solve_lemke(LcpProblem(Mat{{0}}, Vec{{q}}));
      CHECK(r.status == Status::kSolved);
      CHECK(r.z[0] == 0.0);
    }
  }
  SECTION("M = 1, q = -1: z = 1") {
    const auto r = solve_lemke(LcpProblem(Mat{{1}}, Vec{{-1}}));
    CHECK(r.status == Status::kSolved);
    CHECK(r.z[0] == 1.0);
    CHECK(r.iterations == 2);
  }
}

TEST_CASE("Random P-matrix problems: unique solution, checked by enumeration and residual",
          "[lemke][random]") {
  std::mt19937 rng(20260);
  SECTION("small n against brute-force enumeration") {
    for (int trial = 0; trial < 60; ++trial) {
      const int n = 1 + trial % 8;
      const LcpProblem p(random_p_matrix(n, rng), random_vec(n, rng));
      CAPTURE(trial, n);
      const auto truth = enumerate_solutions(p.M, p.q);
      REQUIRE(truth.size() == 1);
      const auto r = solve_lemke(p);
      REQUIRE(r.status == Status::kSolved);
      CHECK((r.z - truth[0]).cwiseAbs().maxCoeff() < 1e-10);
    }
  }
  SECTION("larger n: residual") {
    for (int n : {20, 60, 150, 300}) {
      CAPTURE(n);
      const LcpProblem p(random_p_matrix(n, rng), random_vec(n, rng));
      const auto r = solve_lemke(p);
      REQUIRE(r.status == Status::kSolved);
      CHECK(r.iterations > n / 4);
      CHECK(natural_residual(p.M, p.q, r.z) < 1e-12 * (1 + r.z.cwiseAbs().maxCoeff()));
    }
  }
  SECTION("forced refactorization gives the same answer") {
    const LcpProblem p(random_p_matrix(80, rng), random_vec(80, rng));
    LemkeOptions o;
    o.refactor_every = 3;
    const auto a = solve_lemke(p);
    const auto b = solve_lemke(p, o);
    REQUIRE(a.status == Status::kSolved);
    REQUIRE(b.status == Status::kSolved);
    CHECK(a.iterations == b.iterations);
    CHECK((a.z - b.z).cwiseAbs().maxCoeff() < 1e-12);
  }
}

TEST_CASE("General random matrices: a claimed solution or certificate holds", "[lemke][random]") {
  // Not copositive-plus in general: every pivot kind occurs (z or w entering, z or w leaving).
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> u(-4, 4);
  int solved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + trial % 7;
    Mat M(n, n);
    Vec q(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) M(i, j) = u(rng);
      q[i] = u(rng);
    }
    const LcpProblem p(M, q);
    CAPTURE(trial, M, q);
    const auto r = solve_lemke(p);
    CHECK(r.status != Status::kNumericalFailure);
    if (cpkit::is_solution(r.status)) {
      ++solved;
      CHECK(natural_residual(M, q, r.z) <= 1e-9 * (1 + r.z.cwiseAbs().maxCoeff()));
    } else if (r.status == Status::kInfeasible) {
      CHECK(is_farkas_certificate(M, q, r.certificate->y));
      CHECK(enumerate_solutions(M, q).empty());
    } else {
      CHECK(r.status == Status::kRayTermination);
    }
  }
  CHECK(solved > 80);
}

TEST_CASE("DimensionMismatchThrows and other bad input", "[lemke][input]") {
  SECTION("size mismatch") {
    const LcpProblem p(Mat::Identity(2, 2), Vec::Ones(3));
    CHECK_THROWS_AS(solve_lemke(p), cpkit::InputError);
    CHECK_THROWS_WITH(solve_lemke(p), Catch::Contains("size mismatch"));
  }
  SECTION("non-square M") {
    const LcpProblem p(Mat::Ones(2, 3), Vec::Ones(2));
    CHECK_THROWS_WITH(solve_lemke(p), Catch::Contains("not square"));
  }
  SECTION("NaN and Inf") {
    CHECK_THROWS_WITH(solve_lemke(LcpProblem(Mat{{1, NAN}, {0, 1}}, Vec{{-1, -1}})),
                      Catch::Contains("non-finite") && Catch::Contains("(0, 1)"));
    CHECK_THROWS_WITH(solve_lemke(LcpProblem(Mat::Identity(2, 2), Vec{{-1, INFINITY}})),
                      Catch::Contains("q has a non-finite entry"));
  }
  SECTION("empty problem") { CHECK_THROWS_AS(solve_lemke(LcpProblem()), cpkit::InputError); }
  SECTION("invalid common options") {
    LemkeOptions o;
    o.common.tol = -1;
    CHECK_THROWS_WITH(solve_lemke(LcpProblem(Mat{{1}}, Vec{{-1}}), o), Catch::Contains("tol"));
  }
}

TEST_CASE("Covering vector: validated, and any d > 0 works", "[lemke][covering]") {
  const LcpProblem p(Mat{{2, 1}, {1, 2}}, Vec{{-5, -6}});
  SECTION("invalid covering vectors throw") {
    LemkeOptions o;
    o.covering = Vec{{1, 0}};
    CHECK_THROWS_WITH(solve_lemke(p, o), Catch::Contains("covering vector entry 1"));
    o.covering = Vec{{1, -2}};
    CHECK_THROWS_AS(solve_lemke(p, o), cpkit::InputError);
    o.covering = Vec{{1, NAN}};
    CHECK_THROWS_AS(solve_lemke(p, o), cpkit::InputError);
    o.covering = Vec{{1, 1, 1}};
    CHECK_THROWS_WITH(solve_lemke(p, o), Catch::Contains("size 3"));
  }
  SECTION("custom covering vectors give the unique solution (4/3, 7/3)") {
    for (const Vec& d : {Vec{{1, 1}}, Vec{{0.1, 10}}, Vec{{5, 6}}, Vec{{1e-3, 1}}}) {
      LemkeOptions o;
      o.covering = d;
      const auto r = solve_lemke(p, o);
      REQUIRE(r.status == Status::kSolved);
      CHECK(r.z[0] == Approx(4.0 / 3.0).epsilon(1e-14));
      CHECK(r.z[1] == Approx(7.0 / 3.0).epsilon(1e-14));
    }
  }
  SECTION("d = -q makes every row tie in the z0 pivot; still solved") {
    std::mt19937 rng(3);
    const LcpProblem big(random_p_matrix(30, rng), -Vec::Ones(30));
    LemkeOptions o;
    o.covering = Vec::Ones(30);
    const auto r = solve_lemke(big, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK(natural_residual(big.M, big.q, r.z) < 1e-12);
  }
}

TEST_CASE("Warm start from a complementary basis", "[lemke][warm]") {
  std::mt19937 rng(11);
  const int n = 40;
  const LcpProblem p(random_p_matrix(n, rng), random_vec(n, rng));
  const auto cold = solve_lemke(p);
  REQUIRE(cold.status == Status::kSolved);
  REQUIRE(cold.basis.size() == static_cast<size_t>(n));
  SECTION("the solution basis of the same problem: no pivot, same z") {
    LemkeOptions o;
    o.warm_basis = cold.basis;
    const auto r = solve_lemke(p, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK(r.iterations == 0);
    CHECK((r.z - cold.z).cwiseAbs().maxCoeff() < 1e-12);
  }
  SECTION("a nearby problem: solved from the previous basis") {
    LcpProblem p2 = p;
    p2.q += 0.05 * random_vec(n, rng);
    LemkeOptions o;
    o.warm_basis = cold.basis;
    const auto warm = solve_lemke(p2, o);
    const auto ref = solve_lemke(p2);
    REQUIRE(warm.status == Status::kSolved);
    REQUIRE(ref.status == Status::kSolved);
    // P-matrix: unique solution, so both runs must agree.
    CHECK((warm.z - ref.z).cwiseAbs().maxCoeff() < 1e-10);
    CHECK(warm.iterations < ref.iterations);
  }
  SECTION("an arbitrary (infeasible) complementary basis still leads to the solution") {
    std::vector<int> basis(n);
    for (int i = 0; i < n; ++i) basis[i] = (i % 3 == 0) ? i : ~i;
    LemkeOptions o;
    o.warm_basis = basis;
    const auto r = solve_lemke(p, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK((r.z - cold.z).cwiseAbs().maxCoeff() < 1e-10);
  }
  SECTION("invalid warm bases throw") {
    LemkeOptions o;
    o.warm_basis = {0, 1};
    CHECK_THROWS_WITH(solve_lemke(p, o), Catch::Contains("warm_basis has size 2"));
    o.warm_basis = cold.basis;
    o.warm_basis[3] = 5;
    CHECK_THROWS_WITH(solve_lemke(p, o), Catch::Contains("warm_basis[3]"));
  }
  SECTION("a singular warm basis is ignored (cold start)") {
    // M(0,0) = 0: the basis {z1 basic} has a singular block.
    const LcpProblem s(Mat{{0, 1}, {-1, 1}}, Vec{{-1, -1}});
    // Hand solution: z = (0, 1)? w1 = z2 - 1 = 0, w2 = z2 - 1 = 0 -> z = (0, 1), w = 0.
    LemkeOptions o;
    o.warm_basis = {0, ~1};
    const auto r = solve_lemke(s, o);
    REQUIRE(cpkit::is_solution(r.status));
    CHECK(r.message.find("warm basis ignored") != std::string::npos);
    CHECK(natural_residual(s.M, s.q, r.z) < 1e-14);
  }
}

TEST_CASE("Pivot limit, time limit and trace", "[lemke][limits]") {
  SECTION("pivot limit") {
    LemkeOptions o;
    o.common.max_iterations = 10;
    const auto r = solve_lemke(murty(6), o);
    CHECK(r.status == Status::kIterationLimit);
    CHECK(r.iterations == 10);
    CHECK(r.z.size() == 6);
  }
  SECTION("time limit") {
    std::mt19937 rng(5);
    const LcpProblem p(random_p_matrix(200, rng), random_vec(200, rng));
    LemkeOptions o;
    o.common.time_limit_s = 1e-9;
    const auto r = solve_lemke(p, o);
    CHECK(r.status == Status::kTimeLimit);
  }
  SECTION("trace: each entering variable is the complement of the previous leaving one") {
    LemkeOptions o;
    o.common.record_trace = true;
    const int n = 5;
    const auto r = solve_lemke(murty(n), o);
    REQUIRE(r.status == Status::kSolved);
    REQUIRE(r.trace.size() == static_cast<size_t>(r.iterations));
    for (size_t t = 1; t < r.trace.size(); ++t) {
      const int prev = r.trace[t - 1].leaving;
      const int complement = prev < n ? prev + n + 1 : prev - n - 1;
      CHECK(r.trace[t].entering == complement);
    }
    CHECK(r.trace.back().leaving == n);  // z0 leaves last
    CHECK(r.trace.back().residual == 0.0);
  }
}

TEST_CASE("Sparse input is densified up to kLemkeMaxDensify", "[lemke][sparse]") {
  const Mat M{{2, 1}, {1, 2}};
  LcpProblem sp;
  sp.M_sparse = M.sparseView();
  sp.q = Vec{{-5, -6}};
  const auto r = solve_lemke(sp);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z[0] == Approx(4.0 / 3.0).epsilon(1e-14));
  LcpProblem big;
  const Eigen::Index n = cpkit::lcp::kLemkeMaxDensify + 1;
  big.M_sparse.resize(n, n);
  big.M_sparse.setIdentity();
  big.q = -Vec::Ones(n);
  const auto u = solve_lemke(big);
  CHECK(u.status == Status::kUnsupported);
  CHECK(u.message.find("densified") != std::string::npos);
}

TEST_CASE("Registry entry 'lemke' runs solve_lemke with the common options", "[lemke]") {
  const auto* e = cpkit::lcp::solvers().find("lemke");
  REQUIRE(e != nullptr);
  CHECK(e->accepts(cpkit::ProblemKind::kLcp));
  cpkit::CommonOptions o;
  o.max_iterations = 3;
  const auto r = e->solve_lcp(murty(4), o);
  CHECK(r.status == Status::kIterationLimit);
  CHECK(r.iterations == 3);
  CHECK(r.solver == "lemke");
}

TEST_CASE("Scale invariance: scaling M and q does not change the path or the verdict",
          "[lemke][scaling]") {
  // Hilbert matrix (positive definite, condition ~1e13 at n = 10) with q = -H 1 - small: the
  // Lemke path (a P-matrix problem) is the same for (a M, b q) in exact arithmetic, z scales by
  // b / a. Tolerances that are not scale-aware break this (they did in development).
  const int n = 10;
  Mat H(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) H(i, j) = 1.0 / (i + j + 1);
  std::mt19937 rng(3);
  const Vec q = -H * Vec::Ones(n) - 0.01 * random_vec(n, rng).cwiseAbs();
  const auto ref = solve_lemke(LcpProblem(H, q));
  REQUIRE(ref.status == Status::kSolved);
  for (double a : {1e-8, 1.0, 1e8}) {
    for (double b : {1e-6, 1.0, 1e6}) {
      CAPTURE(a, b);
      const auto r = solve_lemke(LcpProblem(a * H, b * q));
      REQUIRE(r.status == Status::kSolved);
      CHECK(r.iterations == ref.iterations);
      CHECK(r.basis == ref.basis);
    }
  }
}

TEST_CASE("Per-thread storage: an answer does not depend on the calls made before it",
          "[lemke][reuse]") {
  // solve_lemke keeps the arrays of small runs per thread (issue 27). A thread that has solved
  // nothing yet (std::thread: fresh storage) is the second route: every answer of a long mixed
  // sequence on one thread (sizes 1..12 interleaved, degenerate integer data with ties, rays,
  // n = 70 beyond the reuse bound) must equal it bit for bit.
  std::mt19937 rng(27);
  std::vector<LcpProblem> problems;
  for (int t = 0; t < 120; ++t) {
    const Eigen::Index n = t % 40 == 39 ? 70 : 1 + static_cast<Eigen::Index>(rng() % 12);
    Mat M(n, n);
    Vec q(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      q[i] = static_cast<double>(static_cast<int>(rng() % 6) - 3);
      for (Eigen::Index j = 0; j < n; ++j)
        M(i, j) = t % 2 == 0 ? static_cast<double>(static_cast<int>(rng() % 5) - 2)
                             : static_cast<double>(rng() % 2) + (i == j ? 1.0 : 0.0);
    }
    problems.emplace_back(M, q);
  }
  auto same = [](const SolveResult& a, const SolveResult& b) {
    return a.status == b.status && a.iterations == b.iterations && a.basis == b.basis &&
           a.message == b.message && a.z.size() == b.z.size() &&
           std::equal(a.z.data(), a.z.data() + a.z.size(), b.z.data()) &&
           a.ray.has_value() == b.ray.has_value() && (!a.ray || *a.ray == *b.ray);
  };
  std::vector<SolveResult> sequence;
  for (const auto& p : problems) sequence.push_back(solve_lemke(p));
  int solved = 0, other = 0;
  for (size_t t = 0; t < problems.size(); ++t) {
    SolveResult fresh;
    std::thread([&] { fresh = solve_lemke(problems[t]); }).join();
    CAPTURE(t, problems[t].size());
    CHECK(same(sequence[t], fresh));
    (fresh.status == Status::kSolved ? solved : other) += 1;
  }
  CHECK(solved > 20);  // both kinds of outcome occur in the sequence
  CHECK(other > 20);
  // The closed form after all that: 2 z1 + z2 = 5, z1 + 2 z2 = 6 gives z = (4/3, 7/3).
  const auto r = solve_lemke(LcpProblem(Mat{{2, 1}, {1, 2}}, Vec{{-5, -6}}));
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.z[0] == Approx(4.0 / 3.0).epsilon(1e-15));
  CHECK(r.z[1] == Approx(7.0 / 3.0).epsilon(1e-15));
  // Two threads at once, each with its own storage: the same answers as the sequence.
  std::vector<SolveResult> a(problems.size()), b(problems.size());
  std::thread ta([&] {
    for (size_t t = 0; t < problems.size(); ++t) a[t] = solve_lemke(problems[t]);
  });
  std::thread tb([&] {
    for (size_t t = problems.size(); t-- > 0;) b[t] = solve_lemke(problems[t]);
  });
  ta.join();
  tb.join();
  for (size_t t = 0; t < problems.size(); ++t) {
    CAPTURE(t);
    CHECK(same(a[t], sequence[t]));
    CHECK(same(b[t], sequence[t]));
  }
}
