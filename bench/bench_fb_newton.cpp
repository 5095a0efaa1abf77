// Benchmark: cpkit fb-newton against Siconos numerics' lcp_newton_FB (SICONOS_LCP_NEWTON_FB_FBLSA)
// on random dense P-matrix LCPs, and cpkit fb-newton alone on the sparse 2-D obstacle problem.
// Success of both solvers is judged by cpkit's residual check (finalize's scaled natural
// residual), never by the peer's own flag. Figures: docs/benchmarks/fb_newton.md.
//
// Usage: bench_fb_newton [--quick] [--sparse-only]
//   --quick: fewer problems and repetitions, obstacle n = 10^4 only; --sparse-only: obstacle only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/lcp/fb_newton.hpp"

#include "siconos_lcp.hpp"

#include "bench_problems.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::SparseMat;
using cpkit::Vec;
using Clock = std::chrono::steady_clock;

// The random dense P-matrix LCPs shared with bench_lemke / bench_fb_newton (bench_problems.hpp).
using cpkit::bench::random_p_lcp;

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
  SiconosLcp sl(p.M, p.q);
  LinearComplementarityProblem& lcp = sl.lcp;
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
  s.seconds = median(times);
  return s;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, sparse_only = false;
  for (int a = 1; a < argc; ++a) {
    quick = quick || std::strcmp(argv[a], "--quick") == 0;
    sparse_only = sparse_only || std::strcmp(argv[a], "--sparse-only") == 0;
  }
  std::printf(
      "# fb-newton benchmark (median wall time per solve; success = cpkit's residual check)\n");
  std::printf("## random dense P-matrix LCPs of bench_lemke (seed 2026), %s\n\n",
#ifdef CPKIT_HAVE_SICONOS
              "peer: Siconos numerics lcp_newton_FB"
#else
              "Siconos not found: no peer column"
#endif
  );
  std::printf(
      "| n | problems | cpkit ok | Siconos ok | cpkit iter (mean) | Siconos iter (mean) | "
      "cpkit median ms | Siconos median ms | ratio median (min-max) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::mt19937 rng(2026);
  for (const int n : {10, 50, 100, 200, 500}) {
    if (sparse_only) break;
    const int count = quick ? 3 : (n <= 50 ? 40 : n <= 100 ? 20 : n <= 200 ? 10 : 6);
    const int reps = quick ? 3 : (n <= 100 ? 15 : (n <= 200 ? 7 : 5));
    std::vector<double> tc, ts, ratio;
    int okc = 0, oks = 0;
    double itc = 0, its = 0;
    for (int k = 0; k < count; ++k) {
      const auto p = random_p_lcp(n, rng);
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
      oks += b.success;
      its += b.iterations;
      ts.push_back(b.seconds * 1e3);
      ratio.push_back(a.seconds / b.seconds);
#else
      const auto a = run_cpkit(p, reps);
#endif
      okc += a.success;
      itc += a.iterations;
      tc.push_back(a.seconds * 1e3);
    }
#ifdef CPKIT_HAVE_SICONOS
    std::printf("| %d | %d | %d | %d | %.1f | %.1f | %.4g | %.4g | %.2f (%.2f-%.2f) |\n", n, count,
                okc, oks, itc / count, its / count, median(tc), median(ts), median(ratio),
                *std::min_element(ratio.begin(), ratio.end()),
                *std::max_element(ratio.begin(), ratio.end()));
#else
    std::printf("| %d | %d | %d | - | %.1f | - | %.4g | - | - |\n", n, count, okc, itc / count,
                median(tc));
#endif
    std::fflush(stdout);
  }
  std::printf("\n");
  std::printf("## sparse 2-D obstacle problem (5-point Laplacian; symmetric: sparse LDL^T)\n");
  std::printf("%8s %6s | %10s %5s %6s %4s %10s\n", "n", "z0", "seconds", "iter", "ls", "ok",
              "resid");
  std::vector<int> sides = quick ? std::vector<int>{100} : std::vector<int>{100, 316};
  for (const int m : sides) {
    const auto p = obstacle(m);
    // z0 = 0 (membrane on the obstacle everywhere) and z0 = 1 (above it everywhere).
    for (const double start : {0.0, 1.0}) {
      cpkit::lcp::FbNewtonOptions o;
      o.x0 = Vec::Constant(p.size(), start);
      std::vector<double> times;
      cpkit::SolveResult r;
      for (int k = 0; k < (quick || m > 200 ? 1 : 3); ++k) {
        const auto t0 = Clock::now();
        r = cpkit::lcp::solve_fb_newton(p, o);
        times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
      }
      std::printf("%8lld %6.1f | %10.3f %5d %6d %4s %10.2e\n", static_cast<long long>(p.size()),
                  start, median(times), r.iterations, r.line_search_steps,
                  cpkit::is_solution(r.status) ? "yes" : "NO", r.residuals.natural);
      std::fflush(stdout);
    }
  }
  return 0;
}
