// Tests of the fixed-size enumerator (enumerate_small.hpp) against an independent exact
// brute force written here: rational arithmetic over integer data, vertices as complementary
// basic feasible solutions of [-M | I] (all C(2n, n) column bases), rays of each piece as the
// minimal-support (circuit) nonnegative null vectors of its cone [Rockafellar 1970, Sec. 19].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"

namespace {

// ---------- exact rationals ----------
struct Q {
  std::int64_t n = 0, d = 1;
  Q() = default;
  Q(std::int64_t a, std::int64_t b = 1) : n(a), d(b) { norm(); }
  void norm() {
    if (d < 0) { n = -n; d = -d; }
    const std::int64_t g = std::gcd(n < 0 ? -n : n, d);
    if (g > 1) { n /= g; d /= g; }
  }
  double val() const { return double(n) / double(d); }
};
Q operator+(Q a, Q b) { return Q(a.n * b.d + b.n * a.d, a.d * b.d); }
Q operator-(Q a, Q b) { return Q(a.n * b.d - b.n * a.d, a.d * b.d); }
Q operator*(Q a, Q b) { return Q(a.n * b.n, a.d * b.d); }
Q operator/(Q a, Q b) { return Q(a.n * b.d, a.d * b.n); }
bool operator==(Q a, Q b) { return a.n == b.n && a.d == b.d; }
bool operator<(Q a, Q b) { return a.n * b.d < b.n * a.d; }

using QVec = std::vector<Q>;
using QMat = std::vector<QVec>;

/// Gauss-Jordan over Q: rank and reduced row echelon form (in place), pivot columns.
/// Pivots are searched only in the first `pivot_cols` columns (the rest is a right-hand side).
int rref(QMat& a, std::vector<int>& pivots, int pivot_cols) {
  const int rows = int(a.size()), cols = rows ? int(a[0].size()) : 0;
  int r = 0;
  pivots.clear();
  for (int c = 0; c < pivot_cols && r < rows; ++c) {
    int p = -1;
    for (int i = r; i < rows; ++i)
      if (a[i][c].n != 0) { p = i; break; }
    if (p < 0) continue;
    std::swap(a[p], a[r]);
    const Q inv = Q(1) / a[r][c];
    for (auto& x : a[r]) x = x * inv;
    for (int i = 0; i < rows; ++i)
      if (i != r && a[i][c].n != 0) {
        const Q f = a[i][c];
        for (int j = 0; j < cols; ++j) a[i][j] = a[i][j] - f * a[r][j];
      }
    pivots.push_back(c);
    ++r;
  }
  return r;
}

struct Exact {
  int n;
  std::vector<QVec> vertices;  // z of every complementary vertex
  std::vector<QVec> vertex_w;
  // per support S: the extreme rays of its recession cone (normalised to max entry 1)
  std::vector<std::vector<QVec>> rays;
};

Exact brute_force(const std::vector<std::vector<int>>& M, const std::vector<int>& q) {
  const int n = int(q.size());
  Exact ex;
  ex.n = n;
  std::set<std::vector<std::pair<std::int64_t, std::int64_t>>> seen;
  // columns 0..n-1: z (coefficient -M), n..2n-1: w (identity); A x = q.
  for (unsigned B = 0; B < (1u << (2 * n)); ++B) {
    if (__builtin_popcount(B) != n) continue;
    std::vector<int> cols;
    for (int j = 0; j < 2 * n; ++j)
      if (B & (1u << j)) cols.push_back(j);
    QMat a(n, QVec(n + 1));
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < n; ++c) {
        const int j = cols[c];
        a[i][c] = j < n ? Q(-M[i][j]) : Q(j - n == i ? 1 : 0);
      }
      a[i][n] = Q(q[i]);
    }
    std::vector<int> piv;
    if (rref(a, piv, n) < n) continue;
    QVec x(2 * n, Q(0));
    for (int c = 0; c < n; ++c) x[cols[c]] = a[c][n];
    bool ok = true;
    for (int j = 0; j < 2 * n; ++j) ok = ok && !(x[j] < Q(0));
    for (int i = 0; i < n; ++i) ok = ok && (x[i].n == 0 || x[n + i].n == 0);
    if (!ok) continue;
    std::vector<std::pair<std::int64_t, std::int64_t>> key;
    for (int j = 0; j < n; ++j) key.emplace_back(x[j].n, x[j].d);
    if (!seen.insert(key).second) continue;
    ex.vertices.emplace_back(x.begin(), x.begin() + n);
    ex.vertex_w.emplace_back(x.begin() + n, x.end());
  }
  // rays of piece S: cone {(d, e) >= 0 : e - M d = 0, d_i = 0 (i not in S), e_i = 0 (i in S)};
  // the allowed variables are d_i (i in S) and e_i (i not in S). Extreme rays are the
  // nonnegative null vectors whose support J is minimal: null space of the J columns is
  // one-dimensional and the null vector has no zero entry.
  ex.rays.resize(1u << n);
  for (unsigned S = 0; S < (1u << n); ++S) {
    std::set<std::vector<std::pair<std::int64_t, std::int64_t>>> rs;
    for (unsigned J = 1; J < (1u << n); ++J) {
      std::vector<int> vars;  // index i: d_i if i in S else e_i
      for (int i = 0; i < n; ++i)
        if (J & (1u << i)) vars.push_back(i);
      const int k = int(vars.size());
      QMat a(n, QVec(k));
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < k; ++c) {
          const int i = vars[c];
          a[r][c] = (S & (1u << i)) ? Q(-M[r][i]) : Q(r == i ? 1 : 0);
        }
      std::vector<int> piv;
      if (rref(a, piv, k) != k - 1) continue;
      int free_c = -1;
      for (int c = 0; c < k; ++c)
        if (std::find(piv.begin(), piv.end(), c) == piv.end()) free_c = c;
      QVec x(k, Q(0));
      x[free_c] = Q(1);
      for (int p = 0; p < int(piv.size()); ++p) x[piv[p]] = Q(0) - a[p][free_c];
      bool all_pos = true, all_neg = true;
      for (const Q& v : x) { all_pos = all_pos && Q(0) < v; all_neg = all_neg && v < Q(0); }
      if (!all_pos && !all_neg) continue;
      // d in z-space
      QVec d(n, Q(0));
      for (int c = 0; c < k; ++c)
        if (S & (1u << vars[c])) d[vars[c]] = all_neg ? Q(0) - x[c] : x[c];
      Q big(0);
      for (const Q& v : d) big = big < v ? v : big;
      if (big.n == 0) continue;  // pure e-direction: impossible (e = M d = 0)
      std::vector<std::pair<std::int64_t, std::int64_t>> key;
      for (Q& v : d) { v = v / big; key.emplace_back(v.n, v.d); }
      rs.insert(key);
    }
    for (const auto& key : rs) {
      QVec d;
      for (auto [a, b] : key) d.emplace_back(a, b);
      ex.rays[S].push_back(d);
    }
  }
  return ex;
}

bool in_piece(const Exact& ex, int v, unsigned S) {
  for (int i = 0; i < ex.n; ++i) {
    if ((S & (1u << i)) && ex.vertex_w[v][i].n != 0) return false;
    if (!(S & (1u << i)) && ex.vertices[v][i].n != 0) return false;
  }
  return true;
}

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
  const Exact ex = brute_force(Mi, qi);
  CAPTURE(M, q.transpose());
  REQUIRE(out.ambiguous == 0);
  REQUIRE(out.dropped == 0);
  // vertices: same set
  REQUIRE(out.num_points == int(ex.vertices.size()));
  std::vector<int> to_exact(out.num_points, -1);
  for (int p = 0; p < out.num_points; ++p) {
    for (int v = 0; v < int(ex.vertices.size()); ++v) {
      double d = 0;
      for (int j = 0; j < N; ++j) d = std::max(d, std::abs(out.z[p](j) - ex.vertices[v][j].val()));
      if (d < 1e-9) to_exact[p] = v;
    }
    REQUIRE(to_exact[p] >= 0);
    const Eigen::Matrix<double, N, 1> w = M * out.z[p] + q;
    REQUIRE((out.w[p] - w).cwiseAbs().maxCoeff() < 1e-9);
  }
  // positive-dimensional nonempty pieces of the brute force
  bool infinite = false;
  for (unsigned S = 0; S < (1u << N); ++S) {
    std::vector<int> members;
    for (int v = 0; v < int(ex.vertices.size()); ++v)
      if (in_piece(ex, v, S)) members.push_back(v);
    if (members.empty()) continue;
    if (members.size() < 2 && ex.rays[S].empty()) continue;
    infinite = true;
    // some listed piece contains it: its support S' holds every vertex and ray of P_S
    bool covered = false;
    for (int k = 0; k < out.num_pieces && !covered; ++k) {
      const unsigned T = out.pieces[k].support;
      bool ok = true;
      for (int v : members) ok = ok && in_piece(ex, v, T);
      for (const QVec& d : ex.rays[S]) {
        bool found = false;
        for (const QVec& e : ex.rays[T]) found = found || d == e;
        // a ray of P_S need not be extreme in the larger cone; check cone membership directly
        if (!found) {
          for (int i = 0; i < N; ++i) {
            Q md(0);
            for (int j = 0; j < N; ++j) md = md + Q(Mi[i][j]) * d[j];
            if ((T & (1u << i)) && md.n != 0) ok = false;
            if (!(T & (1u << i)) && d[i].n != 0) ok = false;
          }
        }
      }
      covered = ok;
    }
    CAPTURE(S);
    REQUIRE(covered);
  }
  REQUIRE(out.infinite == infinite);
  // every listed piece: its vertices and rays are exactly those of the brute force
  for (int k = 0; k < out.num_pieces; ++k) {
    const auto& pc = out.pieces[k];
    CAPTURE(k, pc.support);
    for (int p = 0; p < out.num_points; ++p)
      REQUIRE(bool(pc.vertex_mask & (1u << p)) == in_piece(ex, to_exact[p], pc.support));
    REQUIRE(pc.num_rays == int(ex.rays[pc.support].size()));
    for (int r = 0; r < pc.num_rays; ++r) {
      bool found = false;
      for (const QVec& e : ex.rays[pc.support]) {
        double d = 0;
        for (int j = 0; j < N; ++j) d = std::max(d, std::abs(pc.rays[r](j) - e[j].val()));
        found = found || d < 1e-9;
      }
      REQUIRE(found);
    }
    REQUIRE((pc.vertex_mask != 0));
    REQUIRE((pc.num_rays > 0 || __builtin_popcount(pc.vertex_mask) >= 2));
  }
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
    Eigen::Matrix3d M;
    Eigen::Vector3d q;
    rate_lcp(p, M, q);
    cpkit::lcp::SmallSolutionSet<3> out;
    cpkit::lcp::enumerate_small<3>(M, q, out);
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
    Eigen::Matrix3d M;
    Eigen::Vector3d q;
    rate_lcp(p, M, q);
    cpkit::lcp::SmallSolutionSet<3> out;
    cpkit::lcp::enumerate_small<3>(M, q, out);
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
