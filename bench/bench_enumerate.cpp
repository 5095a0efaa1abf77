// Benchmark of the LCP enumeration (enumerate_small, enumerate_all):
//  (1) tiny problems: all solutions of 3x3 state-b rate LCPs (docs/model.md) per second, per
//      call of enumerate_small<3> and with one SmallPreparedLcp<3> per parameter set;
//  (2) random LCPs n = 8, 12, 16, 20 (M, q uniform in [-1, 1]) against Siconos' lcp_enum
//      restarted (iparam SEED = last CURRENT_ENUM + 1) until it has scanned every basis;
//      counts compared, time ratio;
//  (3) random nondegenerate bimatrix games 6x6, 8x8, 10x10 (payoffs uniform in 1..100,
//      LCP z = (x, y), M = [[0, -A], [-B^T, 0]], q = 1) against lrsnash (exact arithmetic):
//      equilibrium counts (must agree) and time ratio.
// Times are CPU times (CLOCK_THREAD_CPUTIME_ID for in-process work, getrusage(RUSAGE_CHILDREN)
// user+sys for lrsnash, which includes its process start), best of the repetitions, so that
// other jobs on the shared machine disturb them less than wall-clock times.
// Usage: bench_enumerate [--quick] [--tiny] (--tiny: section (1) only). Output: Markdown
// (docs/benchmarks/enumeration.md).
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/enumerate_small_prepared.hpp"

#ifdef CPKIT_HAVE_SICONOS
#include "siconos_lcp.hpp"
#endif

namespace {

using cpkit::Mat;
using cpkit::Vec;

double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double children_cpu() {
  rusage u;
  getrusage(RUSAGE_CHILDREN, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// enumerate_all(p) into s, timed: the best CPU seconds of 3 runs.
double timed_enumerate_all(const cpkit::LcpProblem& p, cpkit::lcp::SolutionSet& s) {
  double best = INFINITY;
  for (int rep = 0; rep < 3; ++rep) {
    const double t0 = cpu_now();
    s = cpkit::lcp::enumerate_all(p);
    best = std::min(best, cpu_now() - t0);
  }
  return best;
}

// ---------------- (1) tiny rate LCPs ----------------
void bench_tiny(bool quick) {
  // state b, A = [[2, .5], [.5, 1]], C_T = .1, mu = .3; load directions around the circle
  const double a11 = 2, a12 = 0.5, a22 = 1, CT = 0.1, mu = 0.3;
  const double detA = a11 * a22 - a12 * a12, D0 = a22 + CT * detA;
  Eigen::Matrix3d M;
  M << 1 + a11 * CT, a12, -a12, mu * D0 - a12, detA, -detA, mu * D0 + a12, -detA, detA;
  const int K = 1000;
  std::vector<Eigen::Vector3d> qs(K);
  for (int k = 0; k < K; ++k) {
    const double th = 2 * M_PI * (k + 0.5) / K, dFT = std::cos(th), dFN = std::sin(th);
    const double S = (1 + a11 * CT) * dFN - a12 * CT * dFT, t = a22 * dFT - a12 * dFN;
    qs[k] << -S, -t, t;
  }
  // the degenerate member a11 = mu |a12| (segments) as a second family
  const double b11 = 1, b12 = 2, b22 = 5, bmu = 0.5;
  const double bdet = b11 * b22 - b12 * b12, bD0 = b22 + CT * bdet;
  Eigen::Matrix3d Md;
  Md << 1 + b11 * CT, b12, -b12, bmu * bD0 - b12, bdet, -bdet, bmu * bD0 + b12, -bdet, bdet;
  std::printf("## (1) Tiny problems: all solutions of a 3x3 state-b rate LCP (enumerate_small<3>)\n\n");
  std::printf("| family | path | problems | points (mean) | infinite (share) | ns per problem (best of 5) | problems per second |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  cpkit::lcp::SmallSolutionSet<3> out;
  const int sweeps = quick ? 200 : 2000;
  for (int run = 0; run < 4; ++run) {
    // run 0, 1: enumerate_small per call; run 2, 3: the maps' use, one SmallPreparedLcp per
    // parameter set (built inside the timed sweep, once per sweep of K load directions)
    const int fam = run % 2;
    const bool prepared = run >= 2;
    const Eigen::Matrix3d& MM = fam == 0 ? M : Md;
    double best = INFINITY, pts = 0, inf = 0;
    for (int rep = 0; rep < 5; ++rep) {
      long long acc = 0, ninf = 0;
      const double t0 = cpu_now();
      for (int s = 0; s < sweeps; ++s) {
        if (prepared) {
          const cpkit::lcp::SmallPreparedLcp<3> prep(MM);
          for (int k = 0; k < K; ++k) {
            prep.enumerate(qs[k], out);
            acc += out.num_points;
            ninf += out.infinite;
          }
          continue;
        }
        for (int k = 0; k < K; ++k) {
          cpkit::lcp::enumerate_small<3>(MM, qs[k], out);
          acc += out.num_points;
          ninf += out.infinite;
        }
      }
      const double dt = cpu_now() - t0;
      best = std::min(best, dt / (double(sweeps) * K));
      pts = double(acc) / (double(sweeps) * K);
      inf = double(ninf) / (double(sweeps) * K);
    }
    std::printf("| %s | %s | %d directions | %.3f | %.3f | %.0f | %.2e |\n",
                fam == 0 ? "a11 > mu abs(a12) (A=[[2,.5],[.5,1]], mu=.3)" : "a11 = mu abs(a12) (A=[[1,2],[2,5]], mu=.5)",
                prepared ? "SmallPreparedLcp<3> (one per parameter set)" : "enumerate_small<3> per call",
                K, pts, inf, best * 1e9, 1.0 / best);
  }
  {  // the one-off cost of the preparation (M-only work), included in the rows above
    double best = INFINITY, sink = 0;
    const int builds = quick ? 20000 : 200000;
    for (int rep = 0; rep < 5; ++rep) {
      const double t0 = cpu_now();
      for (int b = 0; b < builds; ++b) {
        const cpkit::lcp::SmallPreparedLcp<3> prep(b % 2 ? M : Md);
        sink += prep.matrix()(0, 0);
      }
      best = std::min(best, (cpu_now() - t0) / builds);
    }
    std::printf("\nConstruction of one SmallPreparedLcp<3> (either family): %.0f ns (best of 5; checksum %.0f).\n",
                best * 1e9, sink);
  }
  std::printf("\n");
}

// ---------------- (2) random LCPs vs Siconos lcp_enum ----------------
#ifdef CPKIT_HAVE_SICONOS
/// Siconos lcp_enum restarted after every solution until it has scanned all 2^n bases (its
/// scan starts at iparam SEED and wraps around cyclically, so it stops at the first wrap).
/// Returns the number of solutions it reported (each feasible basis once).
int siconos_all(const Mat& Mm, const Vec& q, double& seconds) {
  const int n = static_cast<int>(q.size());
  SiconosLcp sl(Mm, q);
  LinearComplementarityProblem& lcp = sl.lcp;
  std::vector<double> z(n), w(n);
  SolverOptions* opts = solver_options_create(SICONOS_LCP_ENUM);
  opts->dparam[SICONOS_DPARAM_TOL] = 1e-12;
  int count = 0;
  long seed = 0;
  const double t0 = cpu_now();
  while (true) {
    opts->iparam[SICONOS_LCP_IPARAM_ENUM_SEED] = static_cast<int>(seed);
    opts->iparam[SICONOS_LCP_IPARAM_ENUM_MULTIPLE_SOLUTIONS] = 0;
    int info = 1;
    lcp_enum(&lcp, z.data(), w.data(), &info, opts);
    if (info != 0) break;
    const long current = opts->iparam[SICONOS_LCP_IPARAM_ENUM_CURRENT_ENUM];
    if (current < seed) break;  // the scan wrapped around to a basis already counted
    ++count;
    seed = current + 1;
    if (seed >= (1L << n)) break;
  }
  seconds = cpu_now() - t0;
  lcp_enum_reset(&lcp, opts, 1);
  solver_options_delete(opts);
  return count;
}
#endif

void bench_random(bool quick) {
  std::printf("## (2) Random LCPs (M, q uniform in [-1, 1]): all solutions\n\n");
  std::printf("| n | problems | solutions (total) | Siconos count (total) | counts agree | cpkit nodes (median) | cpkit ms (median) | Siconos ms (median) | ratio Siconos/cpkit |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n : {8, 12, 16, 20}) {
    const int probs = n == 20 ? 1 : (quick ? 2 : 5);
    std::vector<double> tc, ts, nodes;
    long total = 0, stotal = 0;
    bool agree = true;
    for (int t = 0; t < probs; ++t) {
      Mat M(n, n);
      Vec q(n);
      for (int i = 0; i < n; ++i) {
        q(i) = u(rng);
        for (int j = 0; j < n; ++j) M(i, j) = u(rng);
      }
      cpkit::lcp::SolutionSet s;
      tc.push_back(timed_enumerate_all(cpkit::LcpProblem(M, q), s) * 1e3);
      nodes.push_back(double(s.nodes));
      total += s.count();
#ifdef CPKIT_HAVE_SICONOS
      if (!quick || n <= 16) {
        double sec = 0;
        const int c = siconos_all(M, q, sec);
        ts.push_back(sec * 1e3);
        stotal += c;
        agree = agree && c == s.count();
      }
#endif
    }
    const double mc = median(tc), ms = median(ts);
    std::printf("| %d | %d | %ld | %s | %s | %.0f | %.2f | %s | %s |\n", n, probs, total,
                ts.empty() ? "-" : std::to_string(stotal).c_str(),
                ts.empty() ? "-" : (agree ? "yes" : "NO"), median(nodes), mc,
                ts.empty() ? "-" : std::to_string(ms).c_str(),
                ts.empty() ? "-" : std::to_string(ms / mc).c_str());
    std::fflush(stdout);
  }
  std::printf("\n");
}

// ---------------- (3) bimatrix games vs lrsnash ----------------
/// Runs lrsnash on the game; returns its equilibrium count (-1 when it could not run) and the
/// children's CPU seconds.
int lrsnash_count(const std::vector<std::vector<int>>& A, const std::vector<std::vector<int>>& B,
                  double& seconds) {
  const int m = int(A.size()), k = int(A[0].size());
  char path[] = "/tmp/cpkit_bench_game_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) return -1;
  FILE* f = fdopen(fd, "w");
  std::fprintf(f, "%d %d\n\n", m, k);
  for (const auto* P : {&A, &B}) {
    for (const auto& row : *P) {
      for (int v : row) std::fprintf(f, "%d ", v);
      std::fprintf(f, "\n");
    }
    std::fprintf(f, "\n");
  }
  std::fclose(f);
  const std::string cmd = std::string("lrsnash ") + path + " 2>/dev/null";
  const double c0 = children_cpu();
  FILE* p = popen(cmd.c_str(), "r");
  int count = -1;
  if (p) {
    char line[4096];
    while (std::fgets(line, sizeof line, p)) {
      const char* key = std::strstr(line, "Number of equilibria found:");
      if (key) count = std::atoi(key + std::strlen("Number of equilibria found:"));
    }
    pclose(p);
  }
  seconds = children_cpu() - c0;
  std::remove(path);
  return count;
}

void bench_games(bool quick) {
  std::printf("## (3) Random bimatrix games (payoffs uniform in 1..100): equilibria vs lrsnash\n\n");
  std::printf("| game | LCP n | games | equilibria (total) | lrsnash (total) | counts agree | structured path (games) | cpkit ms (median) | general engine ms (median) | lrsnash ms (median, incl. process start) | ratio lrsnash/cpkit |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pay(1, 100);
  for (int m : {6, 8, 10}) {
    const int games = quick ? 2 : (m == 10 ? 5 : 10);
    std::vector<double> tc, tl, tg;
    long eq = 0, leq = 0, nstruct = 0;
    bool agree = true, have_lrs = true;
    for (int g = 0; g < games; ++g) {
      std::vector<std::vector<int>> A(m, std::vector<int>(m)), B = A;
      Mat M = Mat::Zero(2 * m, 2 * m);
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          A[i][j] = pay(rng);
          B[i][j] = pay(rng);
          M(i, m + j) = -A[i][j];
          M(m + j, i) = -B[i][j];
        }
      const cpkit::LcpProblem p(M, Vec::Ones(2 * m));
      cpkit::lcp::SolutionSet s;
      tc.push_back(timed_enumerate_all(p, s) * 1e3);
      nstruct += s.structured;
      {
        cpkit::lcp::EnumerationOptions gen;
        gen.use_structure = false;
        const double t0 = cpu_now();
        const cpkit::lcp::SolutionSet gs = cpkit::lcp::enumerate_all(p, gen);
        tg.push_back((cpu_now() - t0) * 1e3);
        if (gs.count() != s.count()) agree = false;
      }
      const int mine = s.count() - 1;  // z = 0 is not an equilibrium
      eq += mine;
      double sec = 0;
      const int theirs = lrsnash_count(A, B, sec);
      if (theirs < 0) {
        have_lrs = false;
        continue;
      }
      tl.push_back(sec * 1e3);
      leq += theirs;
      agree = agree && theirs == mine;
    }
    const double mc = median(tc), ml = median(tl);
    std::printf("| %dx%d | %d | %d | %ld | %s | %s | %ld | %.2f | %.2f | %s | %s |\n", m, m, 2 * m,
                games, eq, have_lrs ? std::to_string(leq).c_str() : "-",
                have_lrs ? (agree ? "yes" : "NO") : "-", nstruct, mc, median(tg),
                have_lrs ? std::to_string(ml).c_str() : "-",
                have_lrs ? std::to_string(ml / mc).c_str() : "-");
    std::fflush(stdout);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, tiny_only = false;
  for (int a = 1; a < argc; ++a) {
    if (std::strcmp(argv[a], "--quick") == 0) quick = true;
    if (std::strcmp(argv[a], "--tiny") == 0) tiny_only = true;
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::printf("# LCP enumeration benchmark%s\n\n", quick ? " (--quick)" : "");
  bench_tiny(quick);
  if (tiny_only) return 0;
  bench_random(quick);
  bench_games(quick);
  return 0;
}
