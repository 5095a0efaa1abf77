// Benchmark of the incremental step and the fretting simulation (docs/benchmarks/step.md).
//
//   bench_step [--cycles N] [--steps-per-cycle N] [--repeat N]
//
// 1. A long fretting run (default 10,000 cycles of 100 steps) with the simulation's default
//    path: the closed-form active-set enumeration of every step, verified by the step NCP
//    residual (no series recorded). Reports steps per second (best and median of --repeat).
// 2. One step through solve_step() with the default chain (active-set first, every claim
//    finalized against the MCP), and through the general solvers alone (fb-newton, ipopt).
// 3. The full all-solutions step: enumerate_step() (pieces, continua, jump detection by the
//    homotopy in the increment) and the allocation-free core enumerate_step_points().
// "Solved" means: StepNcp::residual <= 1e-9 (simulation) or finalize() status solved.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_solve.hpp"

using namespace cpkit::rate;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The one contact point of both parts (k_a: Archard's coefficient of the part).
ContactParameters sample_params(double k_a) {
  ContactParameters c;
  c.a11 = 2.0;
  c.a12 = 0.3;
  c.a22 = 1.5;
  c.mu = 0.5;
  c.C_T = 0.4;
  c.k_a = k_a;
  return c;
}

StepProblem sample_step() {
  StepProblem p;
  p.params = sample_params(0.01);
  p.state = {0.2, 1.0, 0.0};
  p.load = {0.05, 0.01};
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  int cycles = 10000, spc = 100, repeat = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--cycles")) cycles = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--steps-per-cycle")) spc = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: bench_step [--cycles N] [--steps-per-cycle N] [--repeat N]\n");
      return 2;
    }
  }
  // 1. Long fretting run.
  SimulationOptions o;
  o.params = sample_params(3e-6);
  o.params.P_s = 1.0;
  o.record_every = 0;
  FrettingCycle c;
  c.F_N = 1.0;
  c.amplitude = 1.2;
  c.cycles = cycles;
  c.steps_per_cycle = spc;
  const LoadHistory h = fretting_history(c);
  std::vector<double> rates;
  SimulationResult last;
  for (int r = 0; r < repeat; ++r) {
    cpkit::Stopwatch sw;
    last = simulate(h, o);
    const double s = sw.seconds();
    rates.push_back(static_cast<double>(last.steps) / s);
  }
  std::printf("## Fretting run: %d cycles x %d steps (%ld steps), a12 = 0.3, C_T = 0.4, "
              "k_a = 3e-6, gross slip\n\n",
              cycles, spc, last.steps);
  std::printf("| measure | value |\n|---|---|\n");
  std::printf("| outcome | %s |\n", std::string(to_string(last.outcome)).c_str());
  std::printf("| steps/s (best of %d) | %.3g |\n", repeat, *std::max_element(rates.begin(), rates.end()));
  std::printf("| steps/s (median) | %.3g |\n", median(rates));
  std::printf("| branch steps | %ld |\n", last.branch_steps);
  std::printf("| max step residual | %.2e |\n", last.max_residual);
  std::printf("| final wear depth | %.6g (Archard integral %.6g) |\n", last.wear_depth,
              last.wear_integral);
  std::printf("| energy balance error (rel) | %.2e |\n", last.energy_error);
  std::printf("| most negative step dissipation (rel) | %.2e |\n\n", last.min_step_dissipation);

  // 2. One step through solve_step().
  const StepProblem p = sample_step();
  std::printf("## One step (state c -> slip, k_a = 0.01), per call\n\n");
  std::printf("| route | calls | us/call (median of %d) | status |\n|---|---|---|---|\n", repeat);
  auto time_chain = [&](const std::vector<std::string>& chain, int calls) {
    if (chain.size() == 1 && chain[0] != "active-set" &&
        cpkit::lcp::solvers().find(chain[0]) == nullptr) {
      std::printf("| %s | - | not registered | - |\n", chain[0].c_str());
      return;
    }
    StepSolveOptions so;
    so.chain = chain;
    std::vector<double> t;
    StepSolveResult r;
    for (int k = 0; k < repeat; ++k) {
      cpkit::Stopwatch sw;
      for (int i = 0; i < calls; ++i) r = solve_step(p, so);
      t.push_back(sw.seconds() / calls * 1e6);
    }
    std::string name;
    for (const auto& n : chain) name += (name.empty() ? "" : ",") + n;
    std::printf("| solve_step %s | %d | %.3g | %s |\n", name.c_str(), calls, median(t),
                std::string(cpkit::to_string(r.status)).c_str());
  };
  time_chain({"active-set", "lemke", "fb-newton", "ipopt"}, 20000);
  time_chain({"fb-newton"}, 2000);
  time_chain({"ipopt"}, 20);

  // 3. All solutions.
  {
    std::vector<double> t1, t2;
    const StepNcp ncp = build_step_ncp(p);
    StepPoints pts;
    StepSolutionSet set;
    for (int k = 0; k < repeat; ++k) {
      cpkit::Stopwatch sw;
      const int n1 = 2000;
      for (int i = 0; i < n1; ++i) set = enumerate_step(p);
      t1.push_back(sw.seconds() / n1 * 1e6);
      cpkit::Stopwatch sw2;
      const int n2 = 1000000;
      double sink = 0;
      for (int i = 0; i < n2; ++i) {
        enumerate_step_points(p, ncp, pts);
        sink += pts.points[0].DP_N;
      }
      t2.push_back(sw2.seconds() / n2 * 1e6);
      if (sink == 12345.678) std::printf(" ");
    }
    std::printf("| enumerate_step (all solutions + jump detection) | 2000 | %.3g | count %d |\n",
                median(t1), set.count());
    std::printf("| enumerate_step_points (core, allocation-free) | 1000000 | %.3g | count %d |\n",
                median(t2), pts.n);
  }
  return 0;
}
