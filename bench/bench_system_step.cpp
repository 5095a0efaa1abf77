// Benchmark of the N-point step enumeration (system_step.hpp) on the flat punch
// (flat_punch.hpp), docs/simulation.md "N points".
//
//   bench_system_step [--max-points N] [--repeat N]
//
// For N = 2 .. max-points (default 7): one step of the punch under F_N = 1 (from the grazing
// state b) and one from the loaded stick state with a tangential increment, without wear
// (k_a = 0: every active set linear) and with wear (k_a = 0.03: m >= 2 sets by the resultant
// or by continuation). Reports active sets per second and seconds per step (median of
// --repeat), the number of solutions and `complete`.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpkit/rate_problem/simulation/flat_punch.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"

using namespace cpkit::rate;

int main(int argc, char** argv) {
  int max_points = 7, repeat = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max-points")) max_points = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: bench_system_step [--max-points N] [--repeat N]\n");
      return 2;
    }
  }
  if (max_points < 2 || max_points > 8 || repeat < 1) {
    std::fprintf(stderr, "bench_system_step: --max-points in [2, 8], --repeat >= 1\n");
    return 2;
  }
  std::printf("N  k_a   start  sets     median_s   sets_per_s  solutions complete\n");
  for (int N = 2; N <= max_points; ++N) {
    for (double k_a : {0.0, 0.03}) {
      FlatPunch fp;
      fp.n_points = N;
      fp.k_a = k_a;
      const ContactSystem s = flat_punch_system(fp);
      for (int start = 0; start < 2; ++start) {
        SystemStepProblem p;
        p.system = s;
        if (start == 0) {
          p.DF = *s.pattern2;  // normal load 1 from grazing
        } else {
          for (auto& q : p.system.points) {
            q.P_N = 1.0 / N;  // loaded, stuck: the uniform pressure of pattern 2
            q.P_T = 0;
          }
          p.DF = 0.45 * *s.pattern1;  // tangential increment: the edges slip
        }
        std::vector<double> t;
        SystemStepSolutionSet set;
        for (int r = 0; r < repeat; ++r) {
          const auto t0 = std::chrono::steady_clock::now();
          set = enumerate_system_step(p);
          t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        std::sort(t.begin(), t.end());
        const double med = t[t.size() / 2];
        std::printf("%d  %.2f  %-5s  %-7ld  %.3e  %.3e   %-9zu %s\n", N, k_a,
                    start == 0 ? "b" : "stick", set.active_sets, med, set.active_sets / med,
                    set.solutions.size(), set.complete ? "true" : "false");
      }
    }
  }
  return 0;
}
