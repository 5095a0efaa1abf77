// The block basis of Lemke's method (lcp/src/lemke_basis.hpp, private): after any sequence of
// the four kinds of pivots, the rows of the basis inverse it reports (from H^{-1}, and from the
// updated rows X = G(:, Z) H^{-1} of the basic w's used by the lexicographic tie-break) equal
// the rows of B^{-1} computed here from scratch with a dense LU of the basis matrix B.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "../../lcp/src/lemke_basis.hpp"

namespace {

using cpkit::lcp::detail::LemkeBasis;
using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

// B^{-1} row of basic variable `var` for the system I w - G x = q (G = [M | c]), from a dense
// LU of B (columns: e_i for a basic w_i, -G(:, j) for a basic x_j).
Vec reference_row(const Mat& M, const Vec& c, const LemkeBasis& b, int var) {
  const Eigen::Index n = M.rows();
  std::vector<int> basic;
  for (int v = 0; v < 2 * n + 1; ++v)
    if (b.is_basic(v)) basic.push_back(v);
  REQUIRE(static_cast<Eigen::Index>(basic.size()) == n);
  Mat B(n, n);
  int slot = -1;
  for (Eigen::Index s = 0; s < n; ++s) {
    const int v = basic[static_cast<size_t>(s)];
    if (v == var) slot = static_cast<int>(s);
    if (v > n) B.col(s) = Vec::Unit(n, v - n - 1);
    else B.col(s) = v < n ? Vec(-M.col(v)) : Vec(-c);
  }
  REQUIRE(slot >= 0);
  const Mat Binv = Eigen::FullPivLU<Mat>(B).inverse();
  return Binv.row(slot).transpose();
}

}  // namespace

TEST_CASE("LemkeBasis: inverse rows stay exact through every kind of pivot, with and without X",
          "[lemke][basis]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 7;
  for (int trial = 0; trial < 20; ++trial) {
    Mat M(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = u(rng) + (i == j ? 3.0 : 0.0);
    Vec q(n), c(n);
    for (int i = 0; i < n; ++i) q[i] = u(rng), c[i] = 1.0 + u(rng) * 0.5;
    LemkeBasis b(M, q);
    b.set_artificial_column(c);
    REQUIRE(b.reset({}));
    Vec dxz = Vec::Zero(n + 1), dw = Vec::Zero(n), row(n);
    int kinds[4] = {0, 0, 0, 0};
    for (int step = 0; step < 40; ++step) {
      if (step == 10 + trial % 7) b.enable_lexico_rows();  // X built mid-run, then updated
      // A random nonbasic entering variable (z_j, z0 or w_i) and a basic leaving variable with
      // a pivot entry of size >= 0.2 (keeps the basis well conditioned).
      std::vector<int> nonbasic;
      for (int v = 0; v < 2 * n + 1; ++v)
        if (!b.is_basic(v)) nonbasic.push_back(v);
      const int entering = nonbasic[rng() % nonbasic.size()];
      b.direction(entering, dxz, dw);
      std::vector<int> leave;
      for (int v = 0; v < 2 * n + 1; ++v) {
        if (!b.is_basic(v)) continue;
        const double rate = v <= n ? dxz[b.zpos(v)] : dw[v - n - 1];
        if (std::abs(rate) >= 0.2) leave.push_back(v);
      }
      if (leave.empty()) continue;
      const int leaving = leave[rng() % leave.size()];
      kinds[(entering <= n ? 0 : 2) + (leaving <= n ? 1 : 0)]++;
      b.pivot(entering, leaving, 0.0, dxz, dw);
      for (int v = 0; v < 2 * n + 1; ++v) {
        if (!b.is_basic(v)) continue;
        CAPTURE(trial, step, entering, leaving, v, b.lexico_rows_enabled());
        b.inverse_row(v, row);
        const Vec ref = reference_row(M, c, b, v);
        const double tol = 1e-9 * (1 + ref.cwiseAbs().maxCoeff());
        CHECK((row - ref).cwiseAbs().maxCoeff() <= tol);
        if (b.lexico_rows_enabled() || v <= n)
          for (Eigen::Index j = 0; j < n; ++j) CHECK(std::abs(b.inverse_entry(v, j) - ref[j]) <= tol);
      }
    }
    // Every kind of pivot occurred: z enters / w leaves, z / x, w / w, w / x.
    CAPTURE(kinds[0], kinds[1], kinds[2], kinds[3]);
    CHECK(kinds[0] > 0);
    CHECK(kinds[1] > 0);
    CHECK(kinds[2] > 0);
    CHECK(kinds[3] > 0);
  }
}
