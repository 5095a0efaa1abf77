// Map throughput: cells per second of a 1000 x 1000 mu x direction map (state b: the Fig. 5
// model; state d: the state-d preset, where Lambda changes sign), enumeration route, 1 thread and
// all threads; plus the cost of one summarize_rate_problem call per route; then the WHOLE
// `cpkit map` process (start, estimate, cells, streamed .npy or CSV output, exit) for the
// 1000 x 1000 mu x direction map and an 800 x 800 param-param map.
// Results: docs/benchmarks/maps.md. Run: build/bench/bench_maps [n] [repeats]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"

using namespace cpkit::rate;

namespace {
double best_map_seconds(const MapPreset& p, const MapAxis& axis, int theta_n, int threads,
                        RateMethod method, int repeats, int64_t& checksum) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    MapOptions o;
    o.threads = threads;
    o.method = method;
    const auto t0 = std::chrono::steady_clock::now();
    const ParamDirectionMap m = compute_param_direction_map(p.params, p.state, axis, theta_n, o);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
    checksum = 0;
    for (const auto c : m.count) checksum += c;
  }
  return best;
}

/// ns per summarize_rate_problem call; `pre` selects the precomputed overload (the maps' route).
double ns_per_summary(const MapPreset& p, RateMethod method, int calls, bool use_pre) {
  int64_t sink = 0;
  const RatePrecomputed pre = precompute_rate_problem(p.params, p.state);
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < calls; ++k) {
    const double th = 6.283185307179586 * (k + 0.5) / calls;
    const LoadRate load{std::cos(th), std::sin(th)};
    const RateSummary s = use_pre ? summarize_rate_problem(pre, load, method)
                                  : summarize_rate_problem(p.params, p.state, load, method);
    sink += s.count + static_cast<int>(s.types);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (sink == 42) std::printf(" ");
  return 1e9 * s / calls;
}
/// Best wall time of `command` (run through /bin/sh; its start, about 1 ms, is included).
double best_process_seconds(const std::string& command, int repeats) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(command.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (rc != 0) {
      std::printf("  command failed (%d): %s\n", rc, command.c_str());
      return -1;
    }
    best = std::min(best, s);
  }
  return best;
}

void whole_process(const char* argv0, int repeats) {
  namespace fs = std::filesystem;
  const fs::path cpkit = fs::absolute(fs::path(argv0)).parent_path().parent_path() / "apps" / "cpkit";
  if (!fs::exists(cpkit)) {
    std::printf("\nwhole process: skipped (%s not built)\n", cpkit.string().c_str());
    return;
  }
  const fs::path dir = fs::temp_directory_path() / "cpkit_bench_maps";
  fs::create_directories(dir);
  const std::string map = cpkit.string() +
                          " map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 "
                          "--n 1000 --theta-n 1000";
  std::printf("\nwhole process, 1000 x 1000 mu x direction (fig5b), all threads, best of %d:\n",
              repeats);
  struct Job {
    const char* label;
    std::string args;
    double cells;
  };
  const Job jobs[] = {
      {"--out, npy (default)", " --out " + (dir / "npy").string(), 1e6},
      {"--out, --format csv", " --out " + (dir / "csv").string() + " --format csv", 1e6},
      {"no --out (summary only)", "", 1e6},
  };
  for (const Job& j : jobs) {
    const double s = best_process_seconds(map + j.args + " >/dev/null", repeats);
    if (s > 0) std::printf("  %-26s %8.3f s %12.3e cells/s\n", j.label, s, j.cells / s);
  }
  const std::string pp = cpkit.string() + " map --preset state-d-mu-kappa --n 800 --n2 800 --out " +
                         (dir / "pp").string() + " >/dev/null 2>&1";
  const double s = best_process_seconds(pp, 1);
  if (s > 0)
    std::printf("  %-26s %8.3f s %12.3e cells/s (cells + threaded critical curves)\n",
                "param-param 800 x 800", s, 640000.0 / s);
  fs::remove_all(dir);
}
}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("bench_maps: %d x %d mu x direction maps, best of %d, %d hardware threads\n", n, n,
              repeats, cores);
  std::printf("%-8s %-10s %8s %10s %14s %16s %10s\n", "state", "route", "threads", "seconds",
              "cells/s", "ns/cell/thread", "checksum");
  struct Case {
    const char* label;
    const char* preset;
    MapAxis axis;
  };
  const Case cases[] = {{"b", "fig5b", MapAxis{map_parameter("mu"), 0.1, 4.0, n}},
                        {"d", "state-d", MapAxis{map_parameter("mu"), 0.2, 2.5, n}}};
  for (const Case& c : cases) {
    const MapPreset p = *find_map_preset(c.preset);
    for (const RateMethod method : {RateMethod::kEnumerate, RateMethod::kAnalytic}) {
      for (const int threads : {1, cores}) {
        int64_t checksum = 0;
        const double s = best_map_seconds(p, c.axis, n, threads, method, repeats, checksum);
        const double cells = static_cast<double>(n) * n;
        // kAnalytic maps also run the enumeration route on every cell (cross-check).
        std::printf("%-8s %-10s %8d %10.4f %14.3e %16.1f %10lld\n", c.label,
                    method == RateMethod::kEnumerate ? "enumerate" : "analytic+x", threads, s,
                    cells / s, 1e9 * s * threads / cells, static_cast<long long>(checksum));
      }
    }
  }
  std::printf("\none summarize_rate_problem call (1 thread, 10^6 directions, incl. cos/sin):\n");
  for (const char* preset : {"fig5b", "state-d"}) {
    const MapPreset p = *find_map_preset(preset);
    std::printf("  %-8s enumerate %7.1f ns (precomputed %7.1f ns)   analytic %7.1f ns\n", preset,
                ns_per_summary(p, RateMethod::kEnumerate, 1000000, false),
                ns_per_summary(p, RateMethod::kEnumerate, 1000000, true),
                ns_per_summary(p, RateMethod::kAnalytic, 1000000, false));
  }
  whole_process(argv[0], repeats);
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    char buf[128] = {};
    if (std::fgets(buf, sizeof buf, f)) std::printf("load average (1/5/15 min, ...): %s", buf);
    std::fclose(f);
  }
  return 0;
}
