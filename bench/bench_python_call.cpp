// Benchmark: the overhead of a Python call. The same tiny LCP (M = [[2, 1], [1, 2]],
// q = (-5, -6), Lemke: 2 pivots) solved through the solver registry in C++ (the path the Python
// binding takes) and from Python: cpkit.solve(M, q, "lemke") (argument checks, numpy <-> Eigen,
// the result object) and the bare extension call cpkit._cpkit.solve_dense_fast (no
// pure-Python layer). bench/bench_python_siconos.py compares with Siconos' module. Each figure is
// the median per-call time of 15 batches. The heap allocations per C++ call are counted (this
// program's own malloc/calloc/realloc forward to glibc's and count; not under AddressSanitizer,
// which has its own) for n = 2 and n = 10 after a first call (issue 27: the Lemke arrays are
// reused per thread).
// Usage: bench_python_call [--quick]. Needs the Python module of this build
// (CPKIT_PYTHON_DIR; skipped with a message otherwise). Numbers: docs/python.md.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cpkit/lcp/solvers.hpp"

#if defined(__has_feature)  // clang spells the AddressSanitizer test this way
#if __has_feature(address_sanitizer)
#define CPKIT_UNDER_ASAN 1
#endif
#endif
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(CPKIT_UNDER_ASAN)
#define CPKIT_COUNT_ALLOCATIONS 1
namespace {
std::atomic<unsigned long long> g_allocations{0};
}
// glibc's allocator under its internal names; the definitions below replace malloc & co for
// the whole process (Eigen's arrays and operator new both end in malloc).
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t k, std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(k, n);
}
void* realloc(void* p, std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
}
#endif

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Median seconds per call of the registry's Lemke on the tiny LCP.
double cpp_call(int calls) {
  const cpkit::LcpProblem p(cpkit::Mat{{2, 1}, {1, 2}}, cpkit::Vec{{-5, -6}});
  const cpkit::SolverEntry* lemke = cpkit::lcp::solvers().find("lemke");
  std::vector<double> batches;
  double sink = 0;
  for (int b = 0; b < 15; ++b) {
    const auto t0 = Clock::now();
    for (int i = 0; i < calls; ++i) sink += lemke->solve_lcp(p, {}).z[0];
    batches.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / calls);
  }
  if (sink < 0) std::printf("unexpected\n");  // keeps the calls from being optimised away
  return median(batches);
}

/// Heap allocations per call of the registry's Lemke on an n x n SPD LCP (after one call, so
/// per-thread storage is in place); -1 when not counted.
double allocations_per_call(Eigen::Index n) {
#ifdef CPKIT_COUNT_ALLOCATIONS
  cpkit::Mat M = cpkit::Mat::Constant(n, n, 1.0) + cpkit::Mat::Identity(n, n) * double(n);
  const cpkit::LcpProblem p(M, cpkit::Vec::LinSpaced(n, -5.0, -6.0));
  const cpkit::SolverEntry* lemke = cpkit::lcp::solvers().find("lemke");
  const cpkit::CommonOptions o;
  double sink = lemke->solve_lcp(p, o).z[0];
  constexpr int kCalls = 100;
  const unsigned long long before = g_allocations.load();
  for (int i = 0; i < kCalls; ++i) sink += lemke->solve_lcp(p, o).z[0];
  const unsigned long long after = g_allocations.load();
  if (sink < 0) std::printf("unexpected\n");
  return static_cast<double>(after - before) / kCalls;
#else
  (void)n;
  return -1;
#endif
}

/// Runs the Python side; fills {wrapper, bare} seconds per call. False when it cannot run.
bool python_calls(int calls, double& wrapper, double& bare) {
#ifndef CPKIT_PYTHON_DIR
  (void)calls, (void)wrapper, (void)bare;
  return false;
#else
  const std::string code =
      "import timeit, statistics, numpy as np, cpkit\n"
      "M = np.array([[2.0, 1.0], [1.0, 2.0]]); q = np.array([-5.0, -6.0]); n = " +
      std::to_string(calls) +
      "\n"
      "assert cpkit.solve(M, q, 'lemke').status == 'solved'\n"
      "inf = float('inf')\n"
      "w = [timeit.timeit(lambda: cpkit.solve(M, q, 'lemke'), number=n) / n for _ in range(15)]\n"
      "b = [timeit.timeit(lambda: cpkit._cpkit.solve_dense_fast(M, q, 'lemke', 1e-10, 1e-6, 0, inf),"
      " number=n) / n for _ in range(15)]\n"
      "print(statistics.median(w), statistics.median(b))\n";
  const std::string cmd = std::string("PYTHONPATH=") + CPKIT_PYTHON_DIR + " " +
                          CPKIT_PYTHON_EXECUTABLE + " -c \"" + [&] {
                            std::string e;
                            for (char c : code) e += (c == '"' ? std::string("\\\"") : std::string(1, c));
                            return e;
                          }() + "\"";
  FILE* f = popen(cmd.c_str(), "r");
  if (f == nullptr) return false;
  std::array<char, 256> buf{};
  const bool got = std::fgets(buf.data(), buf.size(), f) != nullptr;
  const int rc = pclose(f);
  return got && rc == 0 && std::sscanf(buf.data(), "%lf %lf", &wrapper, &bare) == 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int calls = quick ? 2000 : 20000;
  const double cpp = cpp_call(calls);
  std::printf("tiny LCP (n = 2, Lemke), median seconds per call over 15 batches of %d calls\n",
              calls);
  std::printf("| path | per call | vs C++ |\n|---|---|---|\n");
  std::printf("| C++: solvers().find(\"lemke\")->solve_lcp | %.2f us | 1.0x |\n", cpp * 1e6);
  const double a2 = allocations_per_call(2), a10 = allocations_per_call(10);
  if (a2 >= 0)
    std::printf("heap allocations per C++ call (the result's arrays included): n = 2: %.1f, "
                "n = 10: %.1f\n", a2, a10);
  double wrapper = 0, bare = 0;
  if (!python_calls(calls, wrapper, bare)) {
    std::printf("Python module not available in this build: Python rows skipped\n");
    return 0;
  }
  std::printf("| Python: cpkit._cpkit.solve_dense_fast (extension only) | %.2f us | %.1fx |\n",
              bare * 1e6, bare / cpp);
  std::printf("| Python: cpkit.solve(M, q, \"lemke\") | %.2f us | %.1fx |\n", wrapper * 1e6,
              wrapper / cpp);
  std::printf("overhead of a Python call: %.2f us (extension only: %.2f us)\n",
              (wrapper - cpp) * 1e6, (bare - cpp) * 1e6);
  return 0;
}
