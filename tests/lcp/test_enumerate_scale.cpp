// Scale invariance of the enumeration (issue 11, part 2): the same LCP in other units,
// q -> a q and (M, q) -> b (M, q) for a, b in {1e-12, 1e-6, 1, 1e6, 1e12}, must give the same
// verdicts - the same count, the same zero patterns of z and w, the same pieces and rays - with
// the solutions scaled (z -> a z, w -> a b w). The reference at a = b = 1 is itself checked
// against the exact brute force of enumerate_brute_force.hpp (rational arithmetic), so the
// scaled answers are compared with an independent source, not with themselves only.
// Families (seeded): P-matrices, non-P matrices with several solutions, degenerate ties (zero
// entries of q, repeated columns), singular blocks and continua, a bimatrix game (structured
// path), and every reference problem in tests/data/lcp. Both enumerate_all and the fixed-size
// enumerate_small / SmallPreparedLcp (used directly by the maps, without normalisation) are
// covered.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "cpkit/core/io.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/enumerate_small_prepared.hpp"
#include "lcp/enumerate_brute_force.hpp"
#include "lcp/enumeration_checks.hpp"

using cpkit::lcp::enumerate_all;
using cpkit::lcp::SolutionSet;

namespace {

using enumeration_checks::require_verified;
using enumeration_checks::to_found;

const double kFactors[] = {1e-12, 1e-6, 1.0, 1e6, 1e12};

struct IntLcp {
  std::vector<std::vector<int>> M;
  std::vector<int> q;
  cpkit::Mat Md() const {
    const int n = int(q.size());
    cpkit::Mat A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = M[i][j];
    return A;
  }
  cpkit::Vec qd() const {
    cpkit::Vec v(int(q.size()));
    for (size_t i = 0; i < q.size(); ++i) v(int(i)) = q[i];
    return v;
  }
};

/// s (the problem scaled by a, b) equals ref (a = b = 1) with z -> a z, w -> a b w.
void require_scaled_equal(const SolutionSet& ref, const SolutionSet& s, double a, double b) {
  REQUIRE(s.complete == ref.complete);
  REQUIRE(s.infinite == ref.infinite);
  REQUIRE(s.ambiguous == ref.ambiguous);
  REQUIRE(s.unrepresentable == ref.unrepresentable);
  REQUIRE(s.solutions.size() == ref.solutions.size());
  for (size_t p = 0; p < s.solutions.size(); ++p) {
    const auto& e = s.solutions[p];
    const auto& r = ref.solutions[p];
    CAPTURE(p, e.z.transpose(), r.z.transpose());
    const double zn = r.z.cwiseAbs().maxCoeff(), wn = r.w.cwiseAbs().maxCoeff();
    for (int j = 0; j < int(e.z.size()); ++j) {
      REQUIRE((e.z(j) == 0) == (r.z(j) == 0));  // the same zero verdicts
      REQUIRE((e.w(j) == 0) == (r.w(j) == 0));
      REQUIRE(std::abs(e.z(j) - a * r.z(j)) <= 1e-10 * a * zn);
      REQUIRE(std::abs(e.w(j) - a * b * r.w(j)) <= 1e-10 * a * b * wn);
    }
    REQUIRE(e.basis == r.basis);
  }
  REQUIRE(s.pieces.size() == ref.pieces.size());
  for (size_t k = 0; k < s.pieces.size(); ++k) {
    REQUIRE(s.pieces[k].support == ref.pieces[k].support);
    REQUIRE(s.pieces[k].vertices == ref.pieces[k].vertices);
    REQUIRE(s.pieces[k].rays.size() == ref.pieces[k].rays.size());
    for (size_t r = 0; r < s.pieces[k].rays.size(); ++r)
      REQUIRE((s.pieces[k].rays[r] - ref.pieces[k].rays[r]).cwiseAbs().maxCoeff() <= 1e-10);
  }
  REQUIRE(s.directions.size() == ref.directions.size());
}

void check_all_scales(const cpkit::Mat& M, const cpkit::Vec& q, const SolutionSet& ref) {
  for (double a : kFactors)
    for (double b : kFactors) {
      CAPTURE(a, b);
      const cpkit::Mat Ms = b * M;
      const cpkit::Vec qs = (a * b) * q;
      const SolutionSet s = enumerate_all(cpkit::LcpProblem(Ms, qs));
      require_verified(s, Ms, qs);
      require_scaled_equal(ref, s, a, b);
    }
}

/// The seeded family (integer data, so that the exact brute force applies).
std::vector<IntLcp> family() {
  std::vector<IntLcp> out;
  std::mt19937 rng(20261123);
  auto rnd = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (int t = 0; t < 6; ++t) {  // P-matrices: strictly diagonally dominant, positive diagonal
    const int n = 2 + t % 5;
    IntLcp p{std::vector<std::vector<int>>(n, std::vector<int>(n)), std::vector<int>(n)};
    for (int i = 0; i < n; ++i) {
      int off = 0;
      for (int j = 0; j < n; ++j)
        if (j != i) off += std::abs(p.M[i][j] = rnd(-2, 2));
      p.M[i][i] = off + rnd(1, 3);
      p.q[i] = rnd(-5, 5);
    }
    out.push_back(p);
  }
  for (int t = 0; t < 10; ++t) {  // general integer matrices: non-P, several solutions
    const int n = 2 + t % 5;
    IntLcp p{std::vector<std::vector<int>>(n, std::vector<int>(n)), std::vector<int>(n)};
    for (int i = 0; i < n; ++i) {
      p.q[i] = rnd(-3, 3);
      for (int j = 0; j < n; ++j) p.M[i][j] = rnd(-3, 3);
    }
    out.push_back(p);
  }
  for (int t = 0; t < 10; ++t) {  // degenerate: zeros in q, sparse M, repeated columns
    const int n = 3 + t % 4;
    IntLcp p{std::vector<std::vector<int>>(n, std::vector<int>(n)), std::vector<int>(n)};
    for (int i = 0; i < n; ++i) {
      p.q[i] = rnd(0, 2) == 0 ? 0 : rnd(-2, 2);
      for (int j = 0; j < n; ++j) p.M[i][j] = rnd(0, 1) ? 0 : rnd(-2, 2);
    }
    for (int i = 0; i < n; ++i) p.M[i][n - 1] = p.M[i][0];  // a tie: z_0 and z_{n-1} alike
    out.push_back(p);
  }
  // continua: CPS Remark 4.1.14 (a segment), CPS Example 4.4.16 (a ray), and M = 0, q = 0
  out.push_back({{{1, 1}, {1, 1}}, {-1, -1}});
  out.push_back({{{1, -1}, {-1, 1}}, {1, -1}});
  out.push_back({{{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}},
                 {0, 1, 0, 2, 0}});
  // the two regressions of test_enumerate.cpp (a singular piece, a constant constraint)
  out.push_back({{{2, 2, 3, 1, -2}, {0, 0, -3, -3, 1}, {0, 0, 0, -1, 0}, {1, -1, 0, 0, 0}, {0, 2, -2, 3, 0}},
                 {-2, 0, 0, 0, 3}});
  out.push_back({{{1, 2, 0, -2, 0}, {0, 1, -2, 0, 0}, {0, 1, 2, 0, 0}, {0, 1, 2, 2, 1}, {0, 0, -2, 0, 0}},
                 {0, 0, 0, -2, 0}});
  // a 3x3 bimatrix game (battle-of-the-sexes extended; the block-bipartite path)
  out.push_back({{{0, 0, 0, -3, -1, -2},
                  {0, 0, 0, -1, -2, -1},
                  {0, 0, 0, -2, -1, -3},
                  {-2, -1, -1, 0, 0, 0},
                  {-1, -3, -2, 0, 0, 0},
                  {-3, -1, -2, 0, 0, 0}},
                 {1, 1, 1, 1, 1, 1}});
  return out;
}

template <int N>
void small_scale_check(const IntLcp& p) {
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;
  const MatN M = p.Md();
  const VecN q = p.qd();
  cpkit::lcp::SmallSolutionSet<N> ref, s, sp;
  cpkit::lcp::enumerate_small<N>(M, q, ref);
  REQUIRE(ref.ambiguous == 0);
  REQUIRE(ref.dropped == 0);
  for (double a : kFactors)
    for (double b : kFactors) {
      CAPTURE(a, b);
      const MatN Ms = b * M;
      const VecN qs = (a * b) * q;
      cpkit::lcp::enumerate_small<N>(Ms, qs, s);
      const cpkit::lcp::SmallPreparedLcp<N> prep(Ms);
      prep.enumerate(qs, sp);
      for (const auto* o : {&s, &sp}) {
        REQUIRE(o->num_points == ref.num_points);
        REQUIRE(o->num_pieces == ref.num_pieces);
        REQUIRE(o->infinite == ref.infinite);
        REQUIRE(o->ambiguous == ref.ambiguous);
        REQUIRE(o->dropped == 0);
        for (int k = 0; k < ref.num_points; ++k) {
          REQUIRE(o->support[k] == ref.support[k]);
          for (int j = 0; j < N; ++j) {
            REQUIRE((o->w[k](j) == 0) == (ref.w[k](j) == 0));
            REQUIRE(std::abs(o->z[k](j) - a * ref.z[k](j)) <= 1e-10 * a * ref.z[k].cwiseAbs().maxCoeff());
          }
        }
        for (int k = 0; k < ref.num_pieces; ++k) {
          REQUIRE(o->pieces[k].support == ref.pieces[k].support);
          REQUIRE(o->pieces[k].vertex_mask == ref.pieces[k].vertex_mask);
          REQUIRE(o->pieces[k].num_rays == ref.pieces[k].num_rays);
        }
      }
    }
}

}  // namespace

TEST_CASE("enumerate_all: the same verdicts under q -> a q and (M, q) -> b (M, q)", "[enumerate][scale]") {
  int index = 0;
  for (const IntLcp& p : family()) {
    CAPTURE(index++, p.M, p.q);
    const cpkit::Mat M = p.Md();
    const cpkit::Vec q = p.qd();
    cpkit::lcp::EnumerationOptions opt;
    const SolutionSet ref = enumerate_all(cpkit::LcpProblem(M, q), opt);
    REQUIRE(ref.complete);
    REQUIRE(ref.ambiguous == 0);
    brute::check(p.M, p.q, to_found(ref));  // the reference is exact (independent brute force)
    check_all_scales(M, q, ref);
  }
}

TEST_CASE("enumerate_small and SmallPreparedLcp: the same verdicts in other units", "[enumerate_small][scale]") {
  for (const IntLcp& p : family()) {
    CAPTURE(p.M, p.q);
    switch (p.q.size()) {
      case 2: small_scale_check<2>(p); break;
      case 3: small_scale_check<3>(p); break;
      case 4: small_scale_check<4>(p); break;
      default: break;  // larger problems are covered by enumerate_all above
    }
  }
}

TEST_CASE("enumerate_all: reference problems in other units", "[enumerate][scale][data]") {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CPKIT_TEST_DATA_DIR "/lcp")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const cpkit::LcpProblem p = cpkit::read_lcp_json(entry.path().string());
    CAPTURE(entry.path().filename().string());
    const SolutionSet ref = enumerate_all(p);
    REQUIRE(ref.complete);
    check_all_scales(p.dense_M(), p.q, ref);
  }
  CHECK(files >= 14);
}
