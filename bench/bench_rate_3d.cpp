// The 3-D one-point rate problem in state b (docs/benchmarks/rate.md, "3-D points"):
//
//   bench_rate_3d [--n N] [--reps R]
//
// Exact route (solve_rate_3d: quartic via the companion matrix, Newton, certificate) and the
// faceted route (solve_rate_3d_faceted: an LCP of size k by complete enumeration) with
// k = 8, 16, 32, 64 on the same random problems (fixed seed, generic directions, strong
// tangential-normal coupling so that some have several solutions). Prints solves per second,
// and how often the faceted count equals the exact one. Best of R repetitions.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include <Eigen/Cholesky>

#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"

using namespace cpkit::rate;

namespace {
struct Case {
  ContactParameters3d p;
  Eigen::Vector3d dF;
};

std::vector<Case> make_cases(int n) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  std::vector<Case> v(static_cast<std::size_t>(n));
  for (auto& c : v) {
    Eigen::Matrix2d L;
    L << 0.5 + pos(rng), 0, u(rng), 0.5 + pos(rng);
    const Eigen::Matrix2d ATT = L * L.transpose();
    const Eigen::Vector2d ATN(u(rng), u(rng));
    c.p.A.topLeftCorner<2, 2>() = ATT;
    c.p.A.topRightCorner<2, 1>() = ATN;
    c.p.A.bottomLeftCorner<1, 2>() = ATN.transpose();
    c.p.A(2, 2) = ATN.dot(ATT.ldlt().solve(ATN)) + 0.05 + pos(rng);
    c.p.mu = 0.2 + 4 * pos(rng);
    c.p.C_T = pos(rng);
    c.p.alpha = {0.4 + pos(rng), 0.4 + pos(rng)};
    c.dF = {u(rng), u(rng), u(rng)};
  }
  return v;
}

template <class F>
double best_seconds(int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  int n = 2000, reps = 3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--n") && i + 1 < argc) n = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: bench_rate_3d [--n N] [--reps R]\n");
      return 2;
    }
  }
  if (n < 1 || reps < 1) {
    std::fprintf(stderr, "bench_rate_3d: --n and --reps must be >= 1\n");
    return 2;
  }
  const std::vector<Case> cases = make_cases(n);
  std::vector<int> exact_count(cases.size());
  int incomplete = 0, several = 0;
  const double t_exact = best_seconds(reps, [&] {
    incomplete = several = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const RateSolutionSet3d s = solve_rate_3d(cases[i].p, {}, cases[i].dF);
      exact_count[i] = s.count();
      incomplete += !s.complete;
      several += s.count() > 1;
    }
  });
  std::printf("3-D one-point rate problem, state b, %d random problems (%d with several solutions, "
              "%d not proved complete)\n", n, several, incomplete);
  std::printf("%-22s %12s %14s %16s\n", "route", "us/solve", "solves/s", "count = exact");
  std::printf("%-22s %12.2f %14.0f %16s\n", "exact (quartic)", 1e6 * t_exact / n, n / t_exact, "-");
  for (int k : {8, 16, 32, 64}) {
    int agree = 0;
    long long nodes = 0;
    const double t = best_seconds(reps, [&] {
      agree = 0;
      nodes = 0;
      for (std::size_t i = 0; i < cases.size(); ++i) {
        const RateSolutionSet3d f = solve_rate_3d_faceted(cases[i].p, cases[i].dF, k);
        agree += f.count() == exact_count[i];
        nodes += f.nodes;
      }
    });
    char name[32];
    std::snprintf(name, sizeof name, "faceted k = %d", k);
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%d/%d", agree, n);
    std::printf("%-22s %12.2f %14.0f %16s   (%.0f search nodes/solve)\n", name, 1e6 * t / n,
                n / t, ratio, static_cast<double>(nodes) / n);
  }
  return 0;
}
