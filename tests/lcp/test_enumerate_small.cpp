// Tests of the fixed-size enumerator (enumerate_small.hpp) against the independent exact brute
// force of enumerate_brute_force.hpp (rational arithmetic over integer data), against the closed
// form of the state-b rate problem (docs/model.md, Sec. 2) and against known game equilibria.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "lcp/enumerate_brute_force.hpp"
#include "lcp/enumerate_small_found.hpp"

namespace {

template <int N>
void compare(const std::vector<std::vector<int>>& Mi, const std::vector<int>& qi) {
  Eigen::Matrix<double, N, N> M;
  Eigen::Matrix<double, N, 1> q;
  for (int i = 0; i < N; ++i) {
    q(i) = qi[i];
    for (int j = 0; j < N; ++j) M(i, j) = Mi[i][j];
  }
  cpkit::lcp::SmallSolutionSet<N> out;
  cpkit::lcp::enumerate_small<N>(M, q, out);
  CAPTURE(M, q.transpose());
  REQUIRE(out.ambiguous == 0);
  REQUIRE(out.dropped == 0);
  // the support is the set of positive z entries
  for (int p = 0; p < out.num_points; ++p)
    for (int j = 0; j < N; ++j) REQUIRE(bool((out.support[p] >> j) & 1u) == (out.z[p](j) > 0));
  brute::check(Mi, qi, to_found(out));
}

template <int N>
void random_sweep(unsigned seed, int count, int range, double zero_prob) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> val(-range, range);
  std::uniform_real_distribution<double> u(0, 1);
  for (int t = 0; t < count; ++t) {
    std::vector<std::vector<int>> M(N, std::vector<int>(N));
    std::vector<int> q(N);
    for (int i = 0; i < N; ++i) {
      q[i] = u(rng) < zero_prob ? 0 : val(rng);
      for (int j = 0; j < N; ++j) M[i][j] = u(rng) < zero_prob ? 0 : val(rng);
    }
    compare<N>(M, q);
  }
}

// ---- the state-b rate LCP of the one-point problem (docs/model.md, Sec. 2) ----
struct RateData {
  double a11, a12, a22, CT, mu, dFT, dFN;
};
struct Rates {
  double dPT, dPN, dwT, dwN;
};

void rate_lcp(const RateData& p, Eigen::Matrix3d& M, Eigen::Vector3d& q) {
  const double detA = p.a11 * p.a22 - p.a12 * p.a12, D0 = p.a22 + p.CT * detA;
  const double S = (1 + p.a11 * p.CT) * p.dFN - p.a12 * p.CT * p.dFT;
  M << 1 + p.a11 * p.CT, p.a12, -p.a12, p.mu * D0 - p.a12, detA, -detA, p.mu * D0 + p.a12, -detA,
      detA;
  const double t = p.a22 * p.dFT - p.a12 * p.dFN;
  q << -S, -t, t;
}

Rates to_rates(const RateData& p, const Eigen::Vector3d& z) {
  const double detA = p.a11 * p.a22 - p.a12 * p.a12, D0 = p.a22 + p.CT * detA;
  const double S = (1 + p.a11 * p.CT) * p.dFN - p.a12 * p.CT * p.dFT;
  const double xi = z(1) - z(2);
  Rates r;
  r.dPN = z(0);
  r.dPT = (p.a22 * p.dFT - p.a12 * p.dFN + p.a12 * r.dPN - detA * xi) / D0;
  r.dwN = (S - (1 + p.a11 * p.CT) * r.dPN - p.a12 * xi) / D0;
  r.dwT = p.CT * r.dPT + xi;
  return r;
}

/// Closed-form solutions of the state-b rate problem (model.md "Solution types", b).
std::vector<Rates> closed_form(const RateData& p) {
  const double detA = p.a11 * p.a22 - p.a12 * p.a12;
  const double N = p.a11 * p.dFN - p.a12 * p.dFT;
  const double S = (1 + p.a11 * p.CT) * p.dFN - p.a12 * p.CT * p.dFT;
  auto L = [&](double s) { return (s + p.mu * p.a12 * p.CT) * p.dFT - p.mu * (1 + p.a11 * p.CT) * p.dFN; };
  std::vector<Rates> sol;
  // dw from dF - dP = A dw (A^-1 by the 2x2 formula), dw_T = C_T dP_T + dw_T^i
  auto with_dP = [&](double dPT, double dPN) {
    const double fT = p.dFT - dPT, fN = p.dFN - dPN;
    Rates r{dPT, dPN, (p.a22 * fT - p.a12 * fN) / detA, (p.a11 * fN - p.a12 * fT) / detA};
    return r;
  };
  if (N < 0) sol.push_back(with_dP(0, 0));  // separation
  if (S >= 0 && L(1) <= 0 && L(-1) <= 0)
    sol.push_back(with_dP(p.dFT / (1 + p.a11 * p.CT), S / (1 + p.a11 * p.CT)));  // stick
  for (double s : {1.0, -1.0}) {
    const double Ds = p.a11 - s * p.mu * p.a12;
    if (Ds == 0) continue;
    const double dPN = N / Ds, lambda = L(s) / Ds;
    if (dPN >= 0 && lambda > 0) sol.push_back(with_dP(s * p.mu * dPN, dPN));
  }
  return sol;
}

bool same(const Rates& a, const Rates& b) {
  return std::abs(a.dPT - b.dPT) < 1e-9 && std::abs(a.dPN - b.dPN) < 1e-9 &&
         std::abs(a.dwT - b.dwT) < 1e-9 && std::abs(a.dwN - b.dwN) < 1e-9;
}

/// The physical solutions reached by the enumeration: images of the extreme solutions (a ray
/// (0, 1, 1) leaves the rates unchanged, every other ray would add a continuum).
std::vector<Rates> physical(const RateData& p, const cpkit::lcp::SmallSolutionSet<3>& out) {
  std::vector<Rates> phys;
  for (int k = 0; k < out.num_points; ++k) {
    const Rates r = to_rates(p, out.z[k]);
    bool dup = false;
    for (const Rates& s : phys) dup = dup || same(r, s);
    if (!dup) phys.push_back(r);
  }
  return phys;
}

/// enumerate_small of the rate LCP of p.
cpkit::lcp::SmallSolutionSet<3> enumerate_rate(const RateData& p) {
  Eigen::Matrix3d M;
  Eigen::Vector3d q;
  rate_lcp(p, M, q);
  cpkit::lcp::SmallSolutionSet<3> out;
  cpkit::lcp::enumerate_small<3>(M, q, out);
  return out;
}

}  // namespace

TEST_CASE("enumerate_small: 1x1 textbook cases", "[enumerate_small]") {
  cpkit::lcp::SmallSolutionSet<1> out;
  using M1 = Eigen::Matrix<double, 1, 1>;
  // M = -1, q = -1: no solution (Siconos' 1x1 fast path claims z = -1)
  cpkit::lcp::enumerate_small<1>(M1(-1.0), M1(-1.0), out);
  CHECK(out.num_points == 0);
  CHECK_FALSE(out.infinite);
  // M = -1, q = 1: z = 0 and z = 1
  cpkit::lcp::enumerate_small<1>(M1(-1.0), M1(1.0), out);
  CHECK(out.num_points == 2);
  // M = 0, q = 0: the whole half-line z >= 0
  cpkit::lcp::enumerate_small<1>(M1(0.0), M1(0.0), out);
  REQUIRE(out.num_points == 1);
  CHECK(out.z[0](0) == 0);
  CHECK(out.infinite);
  REQUIRE(out.num_pieces == 1);
  REQUIRE(out.pieces[0].num_rays == 1);
  CHECK(out.pieces[0].rays[0](0) == 1);
}

TEST_CASE("enumerate_small: bad input throws", "[enumerate_small]") {
  cpkit::lcp::SmallSolutionSet<2> out;
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
  Eigen::Vector2d q(1, std::nan(""));
  CHECK_THROWS_AS(cpkit::lcp::enumerate_small<2>(M, q, out), cpkit::InputError);
  q(1) = 1;
  CHECK_THROWS_AS(cpkit::lcp::enumerate_small<2>(M, q, out, -1.0), cpkit::InputError);
}

TEST_CASE("enumerate_small: battle of the sexes has 3 equilibria", "[enumerate_small]") {
  // A = [[3,1],[0,2]]-ish positive payoffs; M = [[0,-A],[-B^T,0]], q = 1: nontrivial solutions
  // are the equilibria, plus the trivial z = 0 (x = 0, y = 0) [von Stengel 2002, Sec. 3].
  Eigen::Matrix2d A, B;
  A << 3, 1, 1, 2;  // row player prefers (0,0) most
  B << 2, 1, 1, 3;
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  M.topRightCorner<2, 2>() = -A;
  M.bottomLeftCorner<2, 2>() = -B.transpose();
  const Eigen::Vector4d q = Eigen::Vector4d::Ones();
  cpkit::lcp::SmallSolutionSet<4> out;
  cpkit::lcp::enumerate_small<4>(M, q, out);
  CHECK(out.num_points == 4);  // z = 0 and three equilibria
  CHECK_FALSE(out.infinite);
}

TEST_CASE("enumerate_small: random integer LCPs against an exact brute force", "[enumerate_small]") {
  SECTION("n = 1") { random_sweep<1>(1, 200, 2, 0.3); }
  SECTION("n = 2") { random_sweep<2>(2, 1500, 2, 0.35); }
  SECTION("n = 3") { random_sweep<3>(3, 1500, 2, 0.4); }
  SECTION("n = 4") { random_sweep<4>(4, 600, 2, 0.45); }
  SECTION("n = 3, entries in {-1, 0, 1}") { random_sweep<3>(5, 1500, 1, 0.3); }
}

TEST_CASE("enumerate_small: rate LCP, state b, a11 > mu |a12| (unique rates)", "[enumerate_small][rate]") {
  // A = [[2, 0.5], [0.5, 1]], mu = 0.3, C_T = 0.1: a11 = 2 > mu |a12| = 0.15
  for (auto [dFT, dFN] : std::vector<std::pair<double, double>>{
           {0.5, -1}, {0.1, 1}, {1, 1}, {-1, 1}, {-0.3, -0.2}, {0, 0.7}, {2, 0.5}}) {
    const RateData p{2, 0.5, 1, 0.1, 0.3, dFT, dFN};
    CAPTURE(dFT, dFN);
    const auto out = enumerate_rate(p);
    CHECK(out.ambiguous == 0);
    const auto cf = closed_form(p);
    REQUIRE(cf.size() == 1);
    const auto ph = physical(p, out);
    REQUIRE(ph.size() == 1);
    CHECK(same(ph[0], cf[0]));
    // dP_N = 0 (separation) is a ray of z along (0, 1, 1); dP_N > 0 is a single point
    const bool sep = cf[0].dPN == 0;
    CHECK(out.infinite == sep);
    if (sep) {
      REQUIRE(out.num_pieces == 1);
      REQUIRE(out.pieces[0].num_rays == 1);
      CHECK((out.pieces[0].rays[0] - Eigen::Vector3d(0, 1, 1)).norm() < 1e-12);
    }
  }
}

TEST_CASE("enumerate_small: rate LCP, state b, a11 < mu |a12| (several rates)", "[enumerate_small][rate]") {
  // A = [[1, 2], [2, 5]], C_T = 0.2, mu = 0.6: a11 = 1 < mu a12 = 1.2, D_+ < 0
  for (auto [dFT, dFN] : std::vector<std::pair<double, double>>{
           {1, 1.5}, {1, 1}, {0.3, 0.2}, {-1, 0.5}, {1, -1}, {0.6, 1.1}}) {
    const RateData p{1, 2, 5, 0.2, 0.6, dFT, dFN};
    CAPTURE(dFT, dFN);
    const auto out = enumerate_rate(p);
    CHECK(out.ambiguous == 0);
    const auto cf = closed_form(p);
    const auto ph = physical(p, out);
    REQUIRE(ph.size() == cf.size());
    for (const Rates& r : cf) {
      bool found = false;
      for (const Rates& s : ph) found = found || same(r, s);
      CHECK(found);
    }
  }
}

TEST_CASE("enumerate_small: rate LCP, degenerate a11 = mu |a12| gives a segment", "[enumerate_small][rate]") {
  // a11 = 1, a12 = 2, mu = 0.5: D_+ = 0. On N = a11 dF_N - a12 dF_T = 0 with dF_N > 0 the
  // solutions form a segment from stick to zero-force slip (model.md, state b).
  const RateData p{1, 2, 5, 0.2, 0.5, 0.5, 1};
  Eigen::Matrix3d M;
  Eigen::Vector3d q;
  rate_lcp(p, M, q);
  cpkit::lcp::SmallSolutionSet<3> out;
  cpkit::lcp::enumerate_small<3>(M, q, out);
  CHECK(out.ambiguous == 0);
  REQUIRE(out.infinite);
  // the ends: stick (closed form) and zero-force slip (dP = 0)
  const double S = (1 + p.a11 * p.CT) * p.dFN - p.a12 * p.CT * p.dFT;
  const Rates stick{p.dFT / (1 + p.a11 * p.CT), S / (1 + p.a11 * p.CT), 0, 0};
  int stick_k = -1, slip_k = -1;
  for (int k = 0; k < out.num_points; ++k) {
    const Rates r = to_rates(p, out.z[k]);
    if (std::abs(r.dPT - stick.dPT) < 1e-9 && std::abs(r.dPN - stick.dPN) < 1e-9) stick_k = k;
    if (std::abs(r.dPT) < 1e-9 && std::abs(r.dPN) < 1e-9) slip_k = k;
  }
  REQUIRE(stick_k >= 0);
  REQUIRE(slip_k >= 0);
  CHECK(out.z[slip_k](1) - out.z[slip_k](2) > 0);  // slip+: positive xi
  // one piece holds both ends: the segment of physical solutions
  bool segment = false;
  for (int k = 0; k < out.num_pieces; ++k) {
    const unsigned m = out.pieces[k].vertex_mask;
    segment = segment || ((m >> stick_k) & 1u && (m >> slip_k) & 1u);
  }
  CHECK(segment);
  // just off the degenerate value (a11 > mu |a12|) the same load has one physical solution
  const RateData p2{1, 2, 5, 0.2, 0.49, 0.5, 1};
  rate_lcp(p2, M, q);
  cpkit::lcp::enumerate_small<3>(M, q, out);
  const auto cf = closed_form(p2);
  REQUIRE(cf.size() == 1);
  const auto ph = physical(p2, out);
  REQUIRE(ph.size() == 1);
  CHECK(same(ph[0], cf[0]));
  // here N = 0: the unique solution is zero-force slip (dP_N = 0), a ray of z, not a segment
  CHECK(cf[0].dPN == 0);
  REQUIRE(out.num_pieces == 1);
  CHECK(out.pieces[0].num_rays == 1);
  CHECK(__builtin_popcount(out.pieces[0].vertex_mask) == 1);
}

// Issue 24 (the bands of enumerate_small): the near-singular band (|det| <= 1e4 tol perm sends a
// block to the elimination path) and the sign bands are relative to the terms, so the verdict of
// a near-degenerate state-b rate LCP (a11 = mu a12 (1 + delta)) and of the 1x1 LCP of a state-d
// point must not change under q -> a q and (M, q) -> b (M, q), a, b in 1e-12..1e12. Reference:
// the unscaled problem's closed form (closed_form above; the 1x1 LCP by hand), not the code.
TEST_CASE("enumerate_small: near-singular and 1x1 rate LCPs keep their verdict in other units",
          "[enumerate_small][rate][scale]") {
  const double kF[] = {1e-12, 1e-6, 1.0, 1e6, 1e12};
  for (double delta : {1e-2, 1e-5, 1e-7, 1e-9, -1e-9, -1e-7, -1e-5, -1e-2}) {
    for (auto [dFT, dFN] : std::vector<std::pair<double, double>>{{1, 1.5}, {0.3, 1}, {-1, 0.5}, {1, -1}}) {
      // a12 = 2, mu = 0.5: D_+ = a11 - mu a12 = delta (relative to mu a12 = 1)
      const RateData p{1 + delta, 2, 5, 0.2, 0.5, dFT, dFN};
      CAPTURE(delta, dFT, dFN);
      Eigen::Matrix3d M;
      Eigen::Vector3d q;
      rate_lcp(p, M, q);
      const auto cf = closed_form(p);
      int ref_count = -2, ref_amb = -1;
      bool ref_inf = false;
      for (double a : kF) {
        for (double b : kF) {
          CAPTURE(a, b);
          const Eigen::Matrix3d Mb = b * M;
          const Eigen::Vector3d qb = (a * b) * q;
          cpkit::lcp::SmallSolutionSet<3> out;
          cpkit::lcp::enumerate_small<3>(Mb, qb, out);
          // the physical points of z / a (the unscaled problem's z)
          cpkit::lcp::SmallSolutionSet<3> back = out;
          for (int k = 0; k < back.num_points; ++k) back.z[k] /= a;
          const int count = static_cast<int>(physical(p, back).size());
          if (ref_count == -2) {
            ref_count = count;
            ref_amb = out.ambiguous;
            ref_inf = out.infinite;
            // decided and finite in the reference units: the closed form's set
            if (ref_amb == 0 && (!ref_inf || cf.size() == 1)) CHECK(count == static_cast<int>(cf.size()));
          }
          CHECK(out.ambiguous == ref_amb);
          CHECK(out.infinite == ref_inf);
          CHECK(count == ref_count);
        }
      }
    }
  }
  // 1x1 (a state-d point): m z + q = w, z, w >= 0, z w = 0. m > 0: one solution; m < 0: two
  // when q > 0, none when q < 0; m = 0: z = 0 when q > 0, a ray when q = 0, none when q < 0.
  struct Case { double m, q; int count; bool infinite; };
  for (const Case c : {Case{1, -2, 1, false}, Case{1, 3, 1, false}, Case{-1, 2, 2, false},
                       Case{-1, -2, 0, false}, Case{0, 1, 1, false}, Case{0, 0, 1, true},
                       Case{0, -1, 0, false}, Case{3e-9, -1, 1, false}, Case{-3e-9, 1, 2, false}}) {
    for (double a : kF) {
      for (double b : kF) {
        CAPTURE(c.m, c.q, a, b);
        cpkit::lcp::SmallSolutionSet<1> out;
        cpkit::lcp::enumerate_small<1>(Eigen::Matrix<double, 1, 1>(b * c.m),
                                       Eigen::Matrix<double, 1, 1>(a * b * c.q), out);
        CHECK(out.ambiguous == 0);
        CHECK(out.num_points == c.count);
        CHECK(out.infinite == c.infinite);
      }
    }
  }
}
