// Benchmark of whole processes, as a user times them (issue 14), side by side with the peers on
// the same inputs in one run:
//  (1) parse time per MB of a dense problem: the reference JSON reader (nlohmann), the fast one
//      (simdjson) and .npy, in-process, from memory;
//  (2) `cpkit lcp solve` (JSON and .npy input) against a Siconos numerics process that reads the
//      same problem as .dat (linearComplementarity_newFromFilename) and solves it
//      (lcp_newton_FB / lcp_lexicolemke) and prints z and w as cpkit does: fb-newton n = 400,
//      lemke n = 800 (random dense P-matrix LCPs, bench_problems.hpp, seed 2026 per size); whole
//      process wall time and the inner solve time each program reports;
//  (3) all equilibria of random bimatrix games (2 m^2 distinct payoffs from 1..1000, seeded):
//      `cpkit lcp enumerate` against `lrsnash` (lrslib), whole process, counts side by side.
// Times are wall-clock (best and median of the repetitions) plus user+sys CPU of the child; the
// machine load (uptime) is printed before and after. Figures: docs/benchmarks.md.
//
// Usage: bench_process [--quick] [--reps R] [--games-max M]
//   --quick: smaller sizes, 2 repetitions, games up to 12 x 12; --games-max: largest game size
//   (default 20). Internal: bench_process --siconos-solve FILE.dat lemke|fb-newton.
#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"

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

#include "bench_problems.hpp"

#ifndef CPKIT_CLI_PATH
#define CPKIT_CLI_PATH "cpkit"  // without the apps target: the program on PATH
#endif

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// One child process: wall seconds, user+sys CPU seconds, exit status, its stdout.
struct Run {
  double wall = NAN, cpu = NAN;
  int status = -1;
  std::string out;
};

/// Runs argv[0] (found on PATH) with stdout to a scratch file and stderr to /dev/null.
Run run_process(const std::vector<std::string>& args, const fs::path& scratch) {
  const std::string out_path = (scratch / "child.out").string();
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  Run r;
  const auto t0 = Clock::now();
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&fa);
    return r;
  }
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  r.wall = seconds_since(t0);
  posix_spawn_file_actions_destroy(&fa);
  r.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out_path);
  return r;
}

std::string uptime() {
  const std::string s = slurp("/proc/loadavg");
  return "load average " + s.substr(0, s.find(' ', s.find(' ', s.find(' ') + 1) + 1));
}

/// A numpy .npy file (format 1.0, '<f8', C order) of `rows` x `cols` row-major values.
void write_npy(const std::string& path, const double* data, long rows, long cols, bool vector) {
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) +
                     (vector ? ",), }" : ", " + std::to_string(cols) + "), }");
  const size_t total = 10 + dict.size() + 1;
  dict += std::string((64 - total % 64) % 64, ' ') + "\n";
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const char len[2] = {char(dict.size() & 0xff), char(dict.size() >> 8)};
  out.write(len, 2);
  out << dict;
  out.write(reinterpret_cast<const char*>(data), std::streamsize(sizeof(double) * rows * cols));
}

/// p as p.json, p.dat, p.npy + p.q.npy under `dir`.
void write_all_forms(const cpkit::LcpProblem& p, const fs::path& dir) {
  cpkit::write_lcp_json(p, (dir / "p.json").string());
  cpkit::write_lcp_dat(p, (dir / "p.dat").string());
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rm = p.dense_M();
  write_npy((dir / "p.npy").string(), rm.data(), long(rm.rows()), long(rm.cols()), false);
  write_npy((dir / "p.q.npy").string(), p.q.data(), long(p.q.size()), 1, true);
}

template <class F>
double best_of(int reps, F&& f) {
  double best = INFINITY;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, seconds_since(t0));
  }
  return best;
}

// ---------------- (1) parse time per MB ----------------
void bench_parse(const std::vector<int>& sizes, int reps, const fs::path& dir) {
  std::printf("## (1) Reading a dense problem from memory (best of %d)\n\n", reps);
  std::printf("| n | JSON MB | reference JSON ms | ms/MB | fast JSON ms | ms/MB | speed-up | .npy MB | .npy ms | ms/MB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : sizes) {
    std::mt19937 rng(2026);
    const cpkit::LcpProblem p = cpkit::bench::random_p_lcp(n, rng);
    write_all_forms(p, dir);
    const std::string json = slurp((dir / "p.json").string());
    const std::string npy = slurp((dir / "p.npy").string());
    cpkit::LcpProblem a, b;
    const double t_ref = best_of(reps, [&] { a = cpkit::parse_lcp_json_reference(json, "p.json"); });
    const double t_fast = best_of(reps, [&] { b = cpkit::parse_lcp_json(json, "p.json"); });
    cpkit::Mat m;
    const double t_npy = best_of(reps, [&] { m = cpkit::parse_npy_matrix(npy, "p.npy"); });
    if (!(a.M == b.M) || !(m == p.M) || !(a.M == p.M))
      std::printf("(readers disagree at n = %d)\n", n);
    const double mj = double(json.size()) / 1e6, mn = double(npy.size()) / 1e6;
    std::printf("| %d | %.1f | %.1f | %.2f | %.1f | %.2f | %.1fx | %.1f | %.2f | %.3f |\n", n, mj,
                1e3 * t_ref, 1e3 * t_ref / mj, 1e3 * t_fast, 1e3 * t_fast / mj, t_ref / t_fast,
                mn, 1e3 * t_npy, 1e3 * t_npy / mn);
    std::fflush(stdout);
  }
  std::printf("\n");
}

// ---------------- (2) whole process vs Siconos ----------------
struct Summary {
  std::vector<double> wall, cpu, inner;
  bool ok = true;
};

void print_summary(const char* who, const char* input, const Summary& s, const Summary* peer) {
  const double wall = median(s.wall);
  std::printf("| %s | %s | %.1f | %.1f | %.1f | %.1f |", who, input,
              1e3 * *std::min_element(s.wall.begin(), s.wall.end()), 1e3 * wall,
              1e3 * median(s.cpu), 1e3 * median(s.inner));
  if (peer && !peer->wall.empty())
    std::printf(" %.2f | %.2f |", wall / median(peer->wall), median(s.inner) / median(peer->inner));
  else
    std::printf(" - | - |");
  std::printf(" %s |\n", s.ok ? "yes" : "NO");
}

void bench_solve(const char* solver, int n, int reps, const fs::path& dir, const std::string& cpkit,
                 const std::string& self) {
  std::mt19937 rng(2026);
  const cpkit::LcpProblem p = cpkit::bench::random_p_lcp(n, rng);
  write_all_forms(p, dir);
  Summary cj, cn, sic;
  for (int r = 0; r < reps; ++r) {
    const std::pair<Summary*, const char*> inputs[] = {{&cj, "p.json"}, {&cn, "p.npy"}};
    for (const auto& [s, file] : inputs) {
      const Run run =
          run_process({cpkit, "lcp", "solve", "--solver", solver, "--json", (dir / file).string()},
                      dir);
      s->wall.push_back(run.wall);
      s->cpu.push_back(run.cpu);
      try {
        const auto j = nlohmann::json::parse(run.out);
        s->inner.push_back(j.at("seconds").get<double>());
        s->ok = s->ok && run.status == 0 && j.at("status") == "solved";
      } catch (const std::exception&) {
        s->ok = false;
      }
    }
#ifdef CPKIT_HAVE_SICONOS
    const Run run = run_process({self, "--siconos-solve", (dir / "p.dat").string(), solver}, dir);
    sic.wall.push_back(run.wall);
    sic.cpu.push_back(run.cpu);
    double t = NAN;
    int info = -1;
    std::sscanf(run.out.c_str(), "seconds %lf info %d", &t, &info);
    sic.inner.push_back(t);
    sic.ok = sic.ok && run.status == 0 && info == 0;
#else
    (void)self;
#endif
  }
  std::printf("### `lcp solve --solver %s`, n = %d (%d runs each, interleaved)\n\n", solver, n, reps);
  std::printf("| program | input | wall ms (best) | wall ms (median) | CPU ms (median) | inner solve ms (median) | wall / Siconos | solve / Siconos | solved |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const Summary* peer = sic.wall.empty() ? nullptr : &sic;
  print_summary("cpkit", "JSON", cj, peer);
  print_summary("cpkit", ".npy", cn, peer);
  if (peer) print_summary("Siconos", ".dat", sic, nullptr);
  else std::printf("(Siconos numerics not available: libsiconos-numerics-dev)\n");
  std::printf("\n");
  std::fflush(stdout);
}

#ifdef CPKIT_HAVE_SICONOS
/// The peer process: Siconos' own reader, then its solver; prints the solve time, info, z, w.
/// Like `cpkit`, it runs OpenBLAS on one thread (apps/platform/blas_threads.hpp): the same work is compared.
int siconos_solve(const char* file, const std::string& solver) {
  if (!std::getenv("OPENBLAS_NUM_THREADS"))
    if (auto* set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
  LinearComplementarityProblem* lcp = newLCP();
  linearComplementarity_newFromFilename(lcp, file);  // returns 1 when it has read the file
  if (lcp->size <= 0 || !lcp->M || !lcp->q) return 2;
  const int n = lcp->size;
  std::vector<double> z(size_t(n), 0.0), w(size_t(n), 0.0);
  int info = -1;
  const bool fb = solver == "fb-newton";
  SolverOptions* opts = solver_options_create(fb ? SICONOS_LCP_NEWTON_FB_FBLSA : SICONOS_LCP_LEMKE);
  if (fb) {
    opts->dparam[SICONOS_DPARAM_TOL] = 1e-12;  // as bench_fb_newton
    opts->iparam[SICONOS_IPARAM_MAX_ITER] = 1000;
  } else {
    opts->iparam[SICONOS_IPARAM_MAX_ITER] = 50 * (n + 1) + 1000;  // as cpkit's default
  }
  const auto t0 = Clock::now();
  if (fb)
    lcp_newton_FB(lcp, z.data(), w.data(), &info, opts);
  else
    lcp_lexicolemke(lcp, z.data(), w.data(), &info, opts);
  const double t = seconds_since(t0);
  std::printf("seconds %.9f info %d\nz", t, info);
  for (double v : z) std::printf(" %.17g", v);
  std::printf("\nw");
  for (double v : w) std::printf(" %.17g", v);
  std::printf("\n");
  solver_options_delete(opts);
  freeLinearComplementarityProblem(lcp);
  return 0;
}
#endif

// ---------------- (3) bimatrix games vs lrsnash ----------------
void bench_games(const std::vector<int>& sizes, const fs::path& dir, const std::string& cpkit) {
  std::printf("## (3) All equilibria of random m x m bimatrix games (2 m^2 distinct payoffs from 1..1000), whole process\n\n");
  std::printf("(wall: best of 3 runs up to 12 x 12, one run beyond)\n\n");
  std::printf("| game | seed | cpkit equilibria | lrsnash equilibria | equal | cpkit wall s | lrsnash wall s | ratio cpkit/lrsnash | cpkit polytope vertices |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int m : sizes) {
    const int games = m <= 12 ? 3 : m <= 14 ? 2 : 1;
    for (int g = 1; g <= games; ++g) {
      std::mt19937 rng(unsigned(1000 * m + g));
      std::vector<int> pool(1000);
      for (int v = 0; v < 1000; ++v) pool[size_t(v)] = v + 1;
      std::shuffle(pool.begin(), pool.end(), rng);
      const int n = 2 * m;
      cpkit::Mat M = cpkit::Mat::Zero(n, n);
      std::ostringstream lrs;
      lrs << m << ' ' << m << "\n\n";
      for (int player = 0; player < 2; ++player) {
        for (int i = 0; i < m; ++i) {
          for (int j = 0; j < m; ++j) {
            const int v = pool[size_t(player * m * m + i * m + j)];
            lrs << v << ' ';
            if (player == 0) M(i, m + j) = -v; else M(m + j, i) = -v;
          }
          lrs << '\n';
        }
        lrs << '\n';
      }
      cpkit::write_lcp_json(cpkit::LcpProblem(M, cpkit::Vec::Ones(n)), (dir / "game.json").string());
      std::ofstream((dir / "game.lrs").string()) << lrs.str();
      // best of 3 runs up to 12 x 12 (a load spike on the shared machine can triple a 0.1 s
      // run), one run beyond
      const int reps = m <= 12 ? 3 : 1;
      Run c, l;
      for (int r = 0; r < reps; ++r) {
        const Run cr = run_process({cpkit, "lcp", "enumerate", "--json", "--time-limit", "3600",
                                    (dir / "game.json").string()}, dir);
        if (r == 0 || cr.wall < c.wall) c = cr;
        const Run lr = run_process({"lrsnash", (dir / "game.lrs").string()}, dir);
        if (r == 0 || lr.wall < l.wall) l = lr;
      }
      int count = -1;
      long long nodes = -1;
      try {
        const auto j = nlohmann::json::parse(c.out);
        if (j.at("complete").get<bool>()) count = j.at("count").get<int>() - 1;  // minus z = 0
        nodes = j.at("nodes").get<long long>();
      } catch (const std::exception&) {
      }
      int theirs = -1;
      const auto at = l.out.find("Number of equilibria found:");
      if (at != std::string::npos) theirs = std::atoi(l.out.c_str() + at + 27);
      std::printf("| %d x %d | %d | %d | %s | %s | %.3f | %s | %s | %lld |\n", m, m, 1000 * m + g,
                  count, theirs >= 0 ? std::to_string(theirs).c_str() : "-",
                  theirs < 0 ? "-" : count == theirs ? "yes" : "NO", c.wall,
                  theirs >= 0 ? std::to_string(l.wall).substr(0, 6).c_str() : "-",
                  theirs >= 0 ? std::to_string(c.wall / l.wall).substr(0, 5).c_str() : "-", nodes);
      std::fflush(stdout);
    }
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int reps = 5, games_max = 20;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--siconos-solve") && a + 2 < argc) {
#ifdef CPKIT_HAVE_SICONOS
      return siconos_solve(argv[a + 1], argv[a + 2]);
#else
      return 2;
#endif
    }
    if (!std::strcmp(argv[a], "--quick")) quick = true;
    else if (!std::strcmp(argv[a], "--reps") && a + 1 < argc) reps = std::atoi(argv[++a]);
    else if (!std::strcmp(argv[a], "--games-max") && a + 1 < argc) games_max = std::atoi(argv[++a]);
    else {
      std::fprintf(stderr, "usage: bench_process [--quick] [--reps R] [--games-max M]\n");
      return 2;
    }
  }
  if (quick) {
    reps = std::min(reps, 2);
    games_max = std::min(games_max, 12);
  }
  const std::string cpkit = CPKIT_CLI_PATH;
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::random_device rd;
  const fs::path dir = fs::temp_directory_path() / ("cpkit_bench_process_" + std::to_string(rd()));
  fs::create_directories(dir);
  std::printf("# Whole-process benchmark (cpkit %s), %s, %u hardware threads\n\n", CPKIT_VERSION_TEXT,
              uptime().c_str(), std::max(1u, unsigned(sysconf(_SC_NPROCESSORS_ONLN))));
  bench_parse(quick ? std::vector<int>{400, 800} : std::vector<int>{400, 800, 1600}, reps, dir);
  std::printf("## (2) `cpkit lcp solve` vs a Siconos process on the same problem\n\n");
  bench_solve("fb-newton", 400, reps, dir, cpkit, self);
  bench_solve("lemke", 800, reps, dir, cpkit, self);
  std::vector<int> sizes;
  for (int m = 10; m <= games_max; m += 2) sizes.push_back(m);
  bench_games(sizes, dir, cpkit);
  std::printf("Machine after the run: %s\n", uptime().c_str());
  fs::remove_all(dir);
  return 0;
}
