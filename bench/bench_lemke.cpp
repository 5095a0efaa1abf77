// Benchmark: cpkit's Lemke (lexicographic, block basis inverse) against Siconos numerics'
// lcp_lexicolemke on the same problems: random dense P-matrix LCPs (fixed seed), n = 10 ... 500,
// and degenerate families (M = I, q = -1; M = I with many equal q_i; block-diagonal contact
// LCPs), n = 300 ... 1000, where every pivot has ties.
// Success of both is decided by cpkit's own residual check (finalize on the returned z), never
// by the solver's own flag. Usage: bench_lemke [--quick] [--reps R] [--random | --degenerate]
// Output: a Markdown table (docs/benchmarks/lemke.md records a run).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/lcp/lemke.hpp"

#ifdef CPKIT_HAVE_SICONOS
#include "siconos_lcp.hpp"
#endif

#include "bench_problems.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;
using Clock = std::chrono::steady_clock;

// The random dense P-matrix LCPs shared with bench_lemke / bench_fb_newton (bench_problems.hpp).
using cpkit::bench::random_p_lcp;

struct Outcome {
  bool verified = false;  // cpkit's finalize accepts z
  int pivots = 0;
  double seconds = 0;     // best of the repetitions
};

// cpkit's verdict on a z returned by any solver.
bool verified(const LcpProblem& p, const Vec& z) {
  cpkit::SolveResult claim;
  claim.status = cpkit::Status::kSolved;
  claim.z = z;
  return cpkit::is_solution(cpkit::finalize(p, claim, {}).status);
}

Outcome run_cpkit(const LcpProblem& p, int reps) {
  Outcome o;
  o.seconds = INFINITY;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    const auto res = cpkit::lcp::solve_lemke(p);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    o.seconds = std::min(o.seconds, s);
    o.pivots = res.iterations;
    o.verified = verified(p, res.z) && cpkit::is_solution(res.status);
  }
  return o;
}

#ifdef CPKIT_HAVE_SICONOS
Outcome run_siconos(const LcpProblem& p, int reps) {
  const int n = static_cast<int>(p.size());
  Outcome o;
  o.seconds = INFINITY;
  for (int r = 0; r < reps; ++r) {
    SiconosLcp sl(p.M, p.q);  // setup (copy of M and q) is not timed
    LinearComplementarityProblem& lcp = sl.lcp;
    std::vector<double> z(n, 0.0), w(n, 0.0);
    SolverOptions* opts = solver_options_create(SICONOS_LCP_LEMKE);
    opts->iparam[SICONOS_IPARAM_MAX_ITER] = 50 * (n + 1) + 1000;  // as cpkit's default
    int info = -1;
    const auto t0 = Clock::now();
    lcp_lexicolemke(&lcp, z.data(), w.data(), &info, opts);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    o.seconds = std::min(o.seconds, s);
    o.pivots = opts->iparam[SICONOS_IPARAM_ITER_DONE];
    o.verified = verified(p, Eigen::Map<const Vec>(z.data(), n));
    solver_options_delete(opts);
  }
  return o;
}
#endif

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void print_row(const char* family, int n, int count, int okc, int oks, double pivc, double pivs,
               const std::vector<double>& tc, const std::vector<double>& ts) {
#ifdef CPKIT_HAVE_SICONOS
  std::printf("| %s | %d | %d | %d | %d | %.1f | %.1f | %.4g | %.4g | %.3f |\n", family, n, count,
              okc, oks, pivc / count, pivs / count, median(tc), median(ts),
              median(tc) / median(ts));
#else
  (void)oks, (void)pivs, (void)ts;
  std::printf("| %s | %d | %d | %d | - | %.1f | - | %.4g | - | - |\n", family, n, count, okc,
              pivc / count, median(tc));
#endif
  std::fflush(stdout);
}

// Runs both solvers on `count` problems drawn by `make` and prints one table row.
template <class Make>
void run_family(const char* family, int n, int count, int reps, Make make) {
  std::vector<double> tc, ts;
  int okc = 0, oks = 0;
  double pivc = 0, pivs = 0;
  for (int k = 0; k < count; ++k) {
    const LcpProblem p = make();
    const Outcome c = run_cpkit(p, reps);
    okc += c.verified;
    pivc += c.pivots;
    tc.push_back(c.seconds * 1e3);
#ifdef CPKIT_HAVE_SICONOS
    const Outcome s = run_siconos(p, reps);
    oks += s.verified;
    pivs += s.pivots;
    ts.push_back(s.seconds * 1e3);
#endif
  }
  print_row(family, n, count, okc, oks, pivc, pivs, tc, ts);
}

const char* kHeader =
    "| family | n | problems | cpkit ok | Siconos ok | cpkit pivots (mean) | Siconos pivots "
    "(mean) | cpkit median ms | Siconos median ms | ratio cpkit/Siconos |\n"
    "|---|---|---|---|---|---|---|---|---|---|\n";

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, random = true, degenerate = true;
  int reps = 3;
  for (int a = 1; a < argc; ++a) {
    if (std::strcmp(argv[a], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[a], "--random") == 0) degenerate = false;
    else if (std::strcmp(argv[a], "--degenerate") == 0) random = false;
    else if (std::strcmp(argv[a], "--reps") == 0 && a + 1 < argc) reps = std::atoi(argv[++a]);
  }
#ifndef CPKIT_HAVE_SICONOS
  std::printf("bench_lemke: Siconos numerics not available (libsiconos-numerics-dev); "
              "peer comparison skipped, cpkit only.\n");
#endif
  if (random) {
    std::printf("# Lemke: cpkit vs Siconos lcp_lexicolemke, random dense P-matrix LCPs "
                "(seed 2026, best of %d runs per problem)\n\n%s", reps, kHeader);
    std::mt19937 rng(2026);
    for (int n : {10, 50, 100, 200, 500}) {
      const int count = quick ? 3 : (n <= 50 ? 40 : n <= 100 ? 20 : n <= 200 ? 10 : 6);
      run_family("random P", n, count, reps, [&] { return random_p_lcp(n, rng); });
    }
  }
  if (degenerate) {
    std::printf("\n# Lemke: degenerate families (ties at every pivot; seed 7, best of %d runs)"
                "\n\n%s", reps, kHeader);
    std::mt19937 rng(7);
    for (int n : {300, 600, 1000}) {
      if (quick && n > 300) break;
      run_family("M = I, q = -1", n, 1, reps, [&] { return cpkit::bench::identity_lcp(n); });
      run_family("M = I, q in {-2,-1,0,1}", n, 3, reps,
                 [&] { return cpkit::bench::identity_ties_lcp(n, rng); });
      const int bodies = n / 12;
      run_family("contact (2 per body)", 12 * bodies, 3, reps,
                 [&] { return cpkit::bench::contact_lcp(bodies, rng); });
    }
  }
  return 0;
}
