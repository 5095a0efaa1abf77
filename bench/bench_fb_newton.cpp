// Benchmark: cpkit fb-newton against Siconos numerics' lcp_newton_FB (SICONOS_LCP_NEWTON_FB_FBLSA)
// on random dense P-matrix LCPs, and cpkit fb-newton alone on the sparse 2-D obstacle problem.
// Success of both solvers is judged by cpkit's residual check (finalize's scaled natural
// residual), never by the peer's own flag. Figures: docs/benchmarks/fb_newton.md.
//
// Usage: bench_fb_newton [--quick]   (--quick: fewer repetitions, obstacle n = 10^4 only)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/lcp/fb_newton.hpp"

#ifdef CPKIT_HAVE_SICONOS
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "lcp_cst.h"
#pragma GCC diagnostic pop
#endif

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::SparseMat;
using cpkit::Vec;
using Clock = std::chrono::steady_clock;

/// Random P-matrix LCP (fixed seed): M = A A^T / n + (S - S^T) / sqrt(n) + 0.1 I with A, S
/// standard normal, so x^T M x >= 0.1 ||x||^2 (positive definite, hence a P-matrix: unique
/// solution); q standard normal. The same idea as the Lemke benchmark (positive definite,
/// non-symmetric, seeded std::mt19937).
LcpProblem random_p_lcp(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  Mat A(n, n), S(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      A(i, j) = N(gen);
      S(i, j) = N(gen);
    }
  Mat M = A * A.transpose() / n + (S - S.transpose()) / std::sqrt(double(n)) +
          0.1 * Mat::Identity(n, n);
  Vec q(n);
  for (int i = 0; i < n; ++i) q[i] = N(gen);
  return LcpProblem(std::move(M), std::move(q), "random_p_" + std::to_string(n));
}

/// 2-D obstacle problem on the unit square, m x m interior grid (n = m^2): membrane u = 0 on
/// the boundary under a downward load f = -20, obstacle psi(x, y) = -0.2 - ((x - .5)^2 +
/// (y - .5)^2) below it. With z = u - psi >= 0: M = 5-point Laplacian (4 on the diagonal, -1 off,
/// i.e. h^2 (-Delta)), q = M psi - h^2 f (boundary values of psi enter q through u = 0 there).
LcpProblem obstacle(int m) {
  const int n = m * m;
  const double h = 1.0 / (m + 1);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(5 * static_cast<size_t>(n));
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0);
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
  // u = z + psi: A u - h^2 f >= 0 with u = 0 on the boundary  =>  M z + (M psi - h^2 f) >= 0.
  p.q = p.M_sparse * psi - Vec::Constant(n, h * h * (-20.0));
  p.name = "obstacle_" + std::to_string(n);
  return p;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct RunStats {
  double seconds = 0;
  int iterations = 0;
  bool success = false;
  double residual = 0;
};

RunStats run_cpkit(const LcpProblem& p, int reps) {
  RunStats s;
  std::vector<double> times;
  for (int k = 0; k < reps; ++k) {
    const auto t0 = Clock::now();
    const auto r = cpkit::lcp::solve_fb_newton(p);
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    s.iterations = r.iterations;
    s.success = cpkit::is_solution(r.status);
    s.residual = r.residuals.natural;
  }
  s.seconds = median(times);
  return s;
}

#ifdef CPKIT_HAVE_SICONOS
RunStats run_siconos(const LcpProblem& p, int reps) {
  RunStats s;
  const int n = static_cast<int>(p.size());
  Mat Mcopy = p.M;  // column-major, as Siconos' NM_DENSE expects
  Vec qcopy = p.q;
  NumericsMatrix* M = NM_create_from_data(NM_DENSE, n, n, Mcopy.data());
  LinearComplementarityProblem lcp;
  lcp.size = n;
  lcp.M = M;
  lcp.q = qcopy.data();
  std::vector<double> times;
  for (int k = 0; k < reps; ++k) {
    SolverOptions* opt = solver_options_create(SICONOS_LCP_NEWTON_FB_FBLSA);
    opt->dparam[SICONOS_DPARAM_TOL] = 1e-12;
    opt->iparam[SICONOS_IPARAM_MAX_ITER] = 1000;
    Vec z = Vec::Zero(n), w = Vec::Zero(n);
    int info = 0;
    const auto t0 = Clock::now();
    lcp_newton_FB(&lcp, z.data(), w.data(), &info, opt);
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    s.iterations = opt->iparam[SICONOS_IPARAM_ITER_DONE];
    // Judged by cpkit: finalize() on the returned z (status claimed as "solved").
    cpkit::SolveResult claim;
    claim.status = cpkit::Status::kSolved;
    claim.z = z;
    const auto r = cpkit::finalize(p, claim, cpkit::CommonOptions{});
    s.success = cpkit::is_solution(r.status);
    s.residual = r.residuals.natural;
    solver_options_delete(opt);
  }
  // The matrix data belong to Mcopy: detach before freeing the NumericsMatrix.
  NM_free_not_dense(M);
  s.seconds = median(times);
  return s;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf(
      "# fb-newton benchmark (median wall time per solve; success = cpkit's residual check)\n");
  std::printf("## random dense P-matrix LCPs (seed 20261122 + n, %s)\n",
#ifdef CPKIT_HAVE_SICONOS
              "peer: Siconos numerics lcp_newton_FB"
#else
              "Siconos not found: no peer column"
#endif
  );
  std::printf("%6s %4s | %12s %5s %4s %10s | %12s %5s %4s %10s | %6s\n", "n", "prob", "cpkit ms",
              "iter", "ok", "resid", "siconos ms", "iter", "ok", "resid", "ratio");
  std::map<int, std::vector<double>> ratios;
  for (const int n : {10, 50, 100, 200, 500}) {
    const int problems = quick ? 2 : (n <= 100 ? 5 : 3);
    const int reps = quick ? 3 : (n <= 100 ? 21 : (n <= 200 ? 11 : 5));
    for (int k = 0; k < problems; ++k) {
      const auto p = random_p_lcp(n, 20261122u + static_cast<unsigned>(n) + 1000u * k);
#ifdef CPKIT_HAVE_SICONOS
      // Interleaved repetitions (cpkit, Siconos, cpkit, ...) so that load changes on the shared
      // machine hit both alike; medians of each.
      std::vector<double> ta, tb;
      RunStats a, b;
      for (int k2 = 0; k2 < reps; ++k2) {
        a = run_cpkit(p, 1);
        b = run_siconos(p, 1);
        ta.push_back(a.seconds);
        tb.push_back(b.seconds);
      }
      a.seconds = median(ta);
      b.seconds = median(tb);
      std::printf("%6d %4d | %12.4f %5d %4s %10.2e | %12.4f %5d %4s %10.2e | %6.2f\n", n, k,
                  a.seconds * 1e3, a.iterations, a.success ? "yes" : "NO", a.residual,
                  b.seconds * 1e3, b.iterations, b.success ? "yes" : "NO", b.residual,
                  a.seconds / b.seconds);
      ratios[n].push_back(a.seconds / b.seconds);
#else
      const auto a = run_cpkit(p, reps);
      std::printf("%6d %4d | %12.4f %5d %4s %10.2e |\n", n, k, a.seconds * 1e3, a.iterations,
                  a.success ? "yes" : "NO", a.residual);
#endif
    }
  }
  for (auto& [n, v] : ratios)
    std::printf("summary n = %d: median time ratio cpkit/Siconos %.2f over %zu problems\n", n,
                median(v), v.size());
  std::printf("## sparse 2-D obstacle problem (5-point Laplacian; symmetric: sparse LDL^T)\n");
  std::printf("%8s | %10s %5s %6s %4s %10s\n", "n", "seconds", "iter", "ls", "ok", "resid");
  std::vector<int> sides = quick ? std::vector<int>{100} : std::vector<int>{100, 316};
  for (const int m : sides) {
    const auto p = obstacle(m);
    std::vector<double> times;
    cpkit::SolveResult r;
    for (int k = 0; k < (quick || m > 200 ? 1 : 3); ++k) {
      const auto t0 = Clock::now();
      r = cpkit::lcp::solve_fb_newton(p);
      times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
    std::printf("%8lld | %10.3f %5d %6d %4s %10.2e\n", static_cast<long long>(p.size()),
                median(times), r.iterations, r.line_search_steps,
                cpkit::is_solution(r.status) ? "yes" : "NO", r.residuals.natural);
  }
  return 0;
}
