// Time per solve of one 3-D implicit step (step_solvers_3d.hpp): the exact enumeration, FB-SOC
// Newton from the start state, Ipopt (MPCC + Newton polish) and the faceted LCP with k = 8, 16,
// 32, on random generic steps (elliptic points, strong tangential-normal coupling, states a-d,
// no wear so that the faceted LCP applies). Prints success rates, Newton iterations and how
// often the faceted count equals the exact count.
//   bench_step_3d [n_problems=500] [ipopt_every=10]
#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"

using namespace cpkit::rate;

namespace {
constexpr double kPi = 3.14159265358979323846;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Step3dProblem random_problem(std::mt19937& rng, int c) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  Step3dProblem p;
  Eigen::Matrix2d L;
  L << 0.5 + pos(rng), 0, u(rng), 0.5 + pos(rng);
  const Eigen::Matrix2d ATT = L * L.transpose();
  const Eigen::Vector2d ATN = 3.0 * Eigen::Vector2d(u(rng), u(rng));
  p.params.A.topLeftCorner<2, 2>() = ATT;
  p.params.A.topRightCorner<2, 1>() = ATN;
  p.params.A.bottomLeftCorner<1, 2>() = ATN.transpose();
  p.params.A(2, 2) = ATN.dot(ATT.ldlt().solve(ATN)) + 0.05 + pos(rng);
  p.params.mu = 0.5 + 4 * pos(rng);
  p.params.C_T = c % 2 ? 0 : pos(rng);
  p.params.alpha = Eigen::Vector2d(0.4 + pos(rng), 0.4 + pos(rng));
  const double th = kPi * u(rng);
  const Eigen::Vector2d t = p.params.alpha.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th));
  switch (c % 4) {
    case 0: break;
    case 1: p.state.g0 = -0.3 * pos(rng); break;
    case 2: p.state.P_N0 = 2 * pos(rng); p.state.P_T0 = 0.9 * pos(rng) * p.params.mu * p.state.P_N0 * t; break;
    default: p.state.P_N0 = 2 * pos(rng); p.state.P_T0 = p.params.mu * p.state.P_N0 * t;
  }
  p.DF = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return p;
}
}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 500;
  const int ipopt_every = argc > 2 ? std::atoi(argv[2]) : 10;
  std::mt19937 rng(2026);
  double t_exact = 0, t_fb = 0, t_ip = 0, t_fac[3] = {0, 0, 0};
  int complete = 0, multi = 0, fb_ok = 0, fb_it = 0, ip_ok = 0, ip_runs = 0, agree[3] = {0, 0, 0};
  const int ks[3] = {8, 16, 32};
  for (int c = 0; c < n; ++c) {
    const Step3dProblem p = random_problem(rng, c);
    double t0 = now();
    const Step3dSolutionSet ex = enumerate_step_3d(p);
    t_exact += now() - t0;
    complete += ex.complete;
    multi += ex.count() > 1;
    const Step3dSolveResult r = solve_step_3d_fb_soc(p);
    t_fb += r.seconds;
    fb_ok += (r.status == cpkit::Status::kSolved);
    fb_it += r.iterations;
    if (ipopt_every > 0 && c % ipopt_every == 0) {
      const Step3dSolveResult q = solve_step_3d_ipopt(p);
      t_ip += q.seconds;
      ip_ok += (q.status == cpkit::Status::kSolved);
      ++ip_runs;
    }
    for (int j = 0; j < 3; ++j) {
      t0 = now();
      const FacetedStep3dResult f = solve_step_3d_faceted(p, ks[j]);
      t_fac[j] += now() - t0;
      agree[j] += ex.complete && f.set.count() == ex.count();
    }
  }
  std::printf("%d random steps (%d proved complete, %d with several solutions)\n", n, complete, multi);
  std::printf("%-12s %14s %s\n", "route", "us per solve", "outcome");
  std::printf("%-12s %14.1f %d/%d complete\n", "exact", 1e6 * t_exact / n, complete, n);
  std::printf("%-12s %14.1f %d/%d verified, %.2f Newton iterations\n", "fb-soc", 1e6 * t_fb / n,
              fb_ok, n, static_cast<double>(fb_it) / n);
  if (ip_runs > 0)
    std::printf("%-12s %14.1f %d/%d verified\n", "ipopt", 1e6 * t_ip / ip_runs, ip_ok, ip_runs);
  for (int j = 0; j < 3; ++j)
    std::printf("faceted k=%-2d %14.1f count = exact count %d/%d\n", ks[j], 1e6 * t_fac[j] / n,
                agree[j], complete);
  return 0;
}
