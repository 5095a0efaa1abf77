// Map throughput: cells per second of a 1000 x 1000 mu x direction map (state b: the Fig. 5
// model; state d: the state-d preset, where Lambda changes sign), enumeration route, 1 thread and
// all threads; plus the cost of one summarize_rate_problem call per route.
// Results: docs/benchmarks/maps.md. Run: build/bench/bench_maps [n] [repeats]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
  const Case cases[] = {{"b", "fig5b", MapAxis{MapParameter::kMu, 0.1, 4.0, n}},
                        {"d", "state-d", MapAxis{MapParameter::kMu, 0.2, 2.5, n}}};
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
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    char buf[128] = {};
    if (std::fgets(buf, sizeof buf, f)) std::printf("load average (1/5/15 min, ...): %s", buf);
    std::fclose(f);
  }
  return 0;
}
