// Cells per second of the sphere map of one 3-D point (sphere_map_3d.hpp): the exact route and
// the faceted one with k = 16, one thread and all threads. The point is that of
// docs/examples/sphere_point_3d.json (state b, strong coupling, a region of three solutions).
// usage: bench_sphere_map_3d [--n N] (rows of the exact map; columns 2N)
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <thread>

#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"

using namespace cpkit::rate3d;

int main(int argc, char** argv) {
  int n = 91;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--n") == 0 && i + 1 < argc) {
      n = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: bench_sphere_map_3d [--n N]\n");
      return 2;
    }
  }
  if (n < 2) {
    std::fprintf(stderr, "bench_sphere_map_3d: --n must be >= 2\n");
    return 2;
  }
  ContactSystem3d sys;
  sys.A.resize(3, 3);
  sys.A << 1.0, 0.0, 0.9, 0.0, 1.0, 0.6, 0.9, 0.6, 1.6;
  SystemPoint3d p;
  p.mu = 4;
  p.C_T = 0.1;
  p.alpha = {0.6, 1.0};
  sys.points = {p};
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("sphere map of one 3-D point (state b), cells per second\n");
  std::printf("%-18s %10s %8s %10s %12s %12s\n", "route", "grid", "threads", "seconds", "cells/s",
              "incomplete");
  struct Run {
    const char* name;
    int facets, rows;
  };
  for (const Run r : {Run{"exact", 0, n}, Run{"faceted k = 16", 16, n / 3 + 1}}) {
    SphereGrid g;
    g.n_beta = r.rows;
    g.n_gamma = 2 * r.rows;
    for (int threads : {1, cores}) {
      Map3dOptions o;
      o.facets = r.facets;
      o.threads = threads;
      const cpkit::Stopwatch clock;
      const Map3d m = compute_sphere_map_3d(sys, g, o);
      const double s = clock.seconds();
      char grid[32];
      std::snprintf(grid, sizeof grid, "%dx%d", g.n_beta, g.n_gamma);
      std::printf("%-18s %10s %8d %10.3f %12.0f %12lld\n", r.name, grid, m.threads, s,
                  static_cast<double>(m.cells()) / s, static_cast<long long>(m.incomplete_cells));
      if (cores == 1) break;
    }
  }
  return 0;
}
