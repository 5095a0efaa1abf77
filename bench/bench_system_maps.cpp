// Cells per second of N-point parameter x direction maps (issue 12's benchmark): a 500 x 500
// mu x direction map of a 2-point and a 4-point system, enumeration route, 1 and 2 threads.
// Usage: bench_system_maps [n] [theta_n]   (default 500 500)
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cpkit/rate_problem/maps/system_grid_map.hpp"

using namespace cpkit::rate;

namespace {

SystemPoint point(StateLabel label, double P_N = 0) {
  SystemPoint p;
  p.mu = 1;
  p.C_T = 0.25;
  p.k_a = 0.1;
  p.state.label = label;
  p.state.P_N = P_N;
  p.P_N = P_N;
  p.P_T = label == StateLabel::kD ? p.mu * P_N : 0.0;
  return p;
}

/// A chain of N points, neighbours coupled (T-T 0.2, N-N 0.25, T-N 0.1); point 2 sliding (d),
/// the others grazing (b): LCP size 3 (N - 1) + 1.
ContactSystem chain(int N) {
  ContactSystem S;
  S.name = std::to_string(N) + "-point chain";
  S.A = Eigen::MatrixXd::Zero(2 * N, 2 * N);
  for (int i = 0; i < N; ++i) {
    S.A(2 * i, 2 * i) = 2;
    S.A(2 * i + 1, 2 * i + 1) = 2.5;
    S.A(2 * i, 2 * i + 1) = S.A(2 * i + 1, 2 * i) = 0.3;
    if (i + 1 < N) {
      S.A(2 * i, 2 * i + 2) = S.A(2 * i + 2, 2 * i) = -0.2;
      S.A(2 * i + 1, 2 * i + 3) = S.A(2 * i + 3, 2 * i + 1) = -0.25;
      S.A(2 * i, 2 * i + 3) = S.A(2 * i + 3, 2 * i) = 0.1;
    }
    S.points.push_back(point(i == 1 ? StateLabel::kD : StateLabel::kB, i == 1 ? 1.0 : 0.0));
  }
  return S;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 500;
  const int theta_n = argc > 2 ? std::atoi(argv[2]) : 500;
  std::printf("N-point mu x direction maps, %d x %d cells, mu in [0.2, 4], enumeration route\n",
              n, theta_n);
  std::printf("%-16s %4s %8s %9s %12s %14s\n", "system", "m", "threads", "seconds", "cells/s",
              "cells (count>1)");
  for (int N : {2, 4}) {
    const ContactSystem S = chain(N);
    for (int threads : {1, 2}) {
      SystemMapAxis axis;
      axis.param = parse_system_map_parameter("mu", N);
      axis.from = 0.2;
      axis.to = 4;
      axis.n = n;
      MapOptions options;
      options.threads = threads;
      const SystemParamDirectionMap m =
          compute_system_param_direction_map(S, axis, theta_n, options);
      long multi = 0;
      for (auto c : m.count) multi += c > 1 || c < 0;
      std::printf("%-16s %4d %8d %9.3f %12.0f %14ld\n", S.name.c_str(), m.m_max, m.threads,
                  m.seconds, static_cast<double>(m.cells()) / m.seconds, multi);
    }
  }
  return 0;
}
