// Benchmark: cpkit's nsgs and auto against Siconos' NSGS (its C driver, fc3d_driver, with W in
// its sparse-block storage) on seeded granular packings of 1e3 to 1e5 contacts (issue 35):
// spheres in a box and brick-bond walls of boxes (packing.hpp), the same problem for both.
//
// Every solve runs in a child process of its own (fork), so that its peak memory is its own:
// the child returns free heap pages (malloc_trim), resets the peak (clear_refs), solves, and
// reports VmHWM - VmRSS at its start: the memory the solve added to the problem's. Then
// the child re-judges the answer twice, independently of the solver that found it:
//   |F|/|q| cpkit    cpkit's verdict library (friction_errors' relative_q, u = W r + q recomputed)
//   |F|/|q| siconos  Siconos' fc3d_compute_error over its own copy of the problem, / ||q||_2
// cpkit solves in the field's measure (solve_in_measure, relative_q, as `fc solve --measure
// relative_q`; --measure chooses another); Siconos' NSGS with dparam[TOL] = --tol (its defaults otherwise; it stops on its
// own error, relative to ||q||). A run is ok when it says solved and both re-judged numbers are
// <= --tol. A child that passes --time-limit is killed (Siconos' NSGS has no time limit).
// Printed per size and solver: contacts, W's nonzeros, status, sweeps (iterations for auto),
// total seconds, ms per sweep, ns per sweep and contact, peak memory, both residuals; then per
// solver the exponent p of time per sweep ~ contacts^p (least squares over the sizes run).
// --solvers verdict times one check of r = 0 by cpkit's verdict (friction_errors) instead.
// --sweeps N (default 250) times exactly N sweeps of nsgs and NSGS (tolerance 1e-30: the cost of
// a sweep as each solver runs it, its convergence tests included, whatever the convergence);
// --sweeps 0 solves to --tol instead (nsgs, auto and NSGS), at most --max-sweeps sweeps.
// Usage: bench_fc_packings [--kind spheres|boxes|all] [--sizes 1000,3000,10000] [--tol 1e-8]
//          [--time-limit 300] [--max-sweeps 20000] [--seed 2026] [--solvers nsgs,auto,NSGS]
//          [--sweeps 250] [--measure relative_q|unit_free|relative_max]
#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "packing.hpp"
#include "peak_memory.hpp"
#include "siconos_friction.hpp"

namespace {

using cpkit::bench::Packing;

// What a child reports (plain data through a pipe).
struct Outcome {
  bool finished = false;  // false: killed at the time limit, or crashed
  bool solved = false;    // the solver's own verdict
  int sweeps = 0;
  double seconds = NAN;
  double rel_q_cpkit = NAN, rel_q_siconos = NAN;
  long peak_kb = -1;
  char message[200] = "";
};

// What a solve returns inside the child.
struct Answer {
  bool solved = false;
  int sweeps = 0;
  double seconds = NAN;
  Eigen::VectorXd r;
  std::string message;
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Runs `solve` in a child; judges its answer there with `judge`. Kills it after limit_s.
Outcome in_child(const std::function<Answer()>& solve,
                 const std::function<void(const Eigen::VectorXd&, Outcome&)>& judge,
                 double limit_s) {
  Outcome out;
  int fd[2];
  if (pipe(fd) != 0) return out;
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0) return out;
  if (pid == 0) {
    close(fd[0]);
    // Free heap pages the parent kept go back to the system, so that the solve's allocations
    // count in VmHWM even where malloc reuses them (without it, a solve reusing the generator's
    // freed memory measured 1.4 MB at every size).
    malloc_trim(0);
    cpkit::bench::reset_peak_memory();
    const long base = cpkit::bench::resident_kb();
    const Answer a = solve();
    Outcome o;
    o.peak_kb = cpkit::bench::peak_resident_kb() - base;
    o.finished = true;
    o.solved = a.solved;
    o.sweeps = a.sweeps;
    o.seconds = a.seconds;
    std::snprintf(o.message, sizeof o.message, "%s", a.message.c_str());
    if (a.r.size()) judge(a.r, o);
    const char* p = reinterpret_cast<const char*>(&o);
    for (size_t left = sizeof o; left > 0;) {
      const ssize_t w = write(fd[1], p, left);
      if (w <= 0) break;
      p += w;
      left -= static_cast<size_t>(w);
    }
    _exit(0);
  }
  close(fd[1]);
  char* p = reinterpret_cast<char*>(&out);
  size_t got = 0;
  const double deadline = now() + limit_s;
  while (got < sizeof out) {
    pollfd pf{fd[0], POLLIN, 0};
    const double left = deadline - now();
    if (left <= 0 || poll(&pf, 1, static_cast<int>(left * 1000) + 1) <= 0) break;
    const ssize_t r = read(fd[0], p + got, sizeof out - got);
    if (r <= 0) break;
    got += static_cast<size_t>(r);
  }
  if (got < sizeof out) {
    kill(pid, SIGKILL);  // our own child, past its time
    out = Outcome{};
    std::snprintf(out.message, sizeof out.message, "killed after %.0f s", limit_s);
  }
  close(fd[0]);
  waitpid(pid, nullptr, 0);
  return out;
}

// Packings of about `target` contacts: spheres on an n x n x 10 lattice (about 30 n^2 contacts),
// boxes in rows of 20 columns and 10 layers (1,448 contacts a row).
Packing make_packing(const std::string& kind, long target, unsigned seed) {
  if (kind == "spheres") {
    cpkit::bench::SpherePackingOptions o;
    o.nx = o.ny = std::max(1, static_cast<int>(std::lround(std::sqrt(target / 30.0))));
    o.nz = 10;
    o.seed = seed;
    return cpkit::bench::sphere_packing(o);
  }
  cpkit::bench::BoxStackOptions o;
  o.columns = 20;
  o.layers = 10;
  o.rows = std::max(1, static_cast<int>(std::lround(target / 1448.0)));
  o.seed = seed;
  return cpkit::bench::box_stack(o);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// Least-squares slope of log y against log x.
double exponent(const std::vector<std::pair<double, double>>& xy) {
  if (xy.size() < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : xy) {
    const double lx = std::log(x), ly = std::log(y);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double n = static_cast<double>(xy.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  double tol = 1e-8, time_limit = 300;
  int max_sweeps = 20000, fixed_sweeps = 250;
  cpkit::FrictionMeasure measure = cpkit::FrictionMeasure::kRelativeQ;
  unsigned seed = 2026;
  std::vector<std::string> kinds = {"spheres", "boxes"};
  std::vector<std::string> sizes = {"1000", "3000", "10000"};  // ~1 min; docs: up to 100000
  std::vector<std::string> solvers = {"nsgs", "auto", "NSGS"};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has = i + 1 < argc;
    if (a == "--tol" && has) tol = std::atof(argv[++i]);
    else if (a == "--time-limit" && has) time_limit = std::atof(argv[++i]);
    else if (a == "--max-sweeps" && has) max_sweeps = std::atoi(argv[++i]);
    else if (a == "--measure" && has) {
      const auto m = cpkit::friction_measure_from_string(argv[++i]);
      if (!m) {
        std::fprintf(stderr, "cpkit: bad input: --measure must be one of %s\n",
                     cpkit::friction_measure_names().c_str());
        return 2;
      }
      measure = *m;
    } else if (a == "--sweeps" && has) fixed_sweeps = std::atoi(argv[++i]);
    else if (a == "--seed" && has) seed = static_cast<unsigned>(std::atol(argv[++i]));
    else if (a == "--kind" && has) {
      const std::string k = argv[++i];
      kinds = k == "all" ? std::vector<std::string>{"spheres", "boxes"} : split(k);
    } else if (a == "--sizes" && has) sizes = split(argv[++i]);
    else if (a == "--solvers" && has) solvers = split(argv[++i]);
    else {
      std::fprintf(stderr, "cpkit: bad input: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  for (const std::string& k : kinds)
    if (k != "spheres" && k != "boxes") {
      std::fprintf(stderr, "cpkit: bad input: --kind must be spheres, boxes or all\n");
      return 2;
    }
#ifndef CPKIT_HAVE_SICONOS
  std::printf("# Siconos numerics not found at build time: its NSGS is not run\n");
#endif
  if (fixed_sweeps > 0) {
    std::printf("# %d sweeps of each solver (tolerance 1e-30), seed %u\n", fixed_sweeps, seed);
    tol = 1e-30;
    max_sweeps = fixed_sweeps;
    solvers.erase(std::remove(solvers.begin(), solvers.end(), "auto"), solvers.end());
  } else {
    std::printf("# tol %g in |F_nat|/|q|, time limit %g s a solve, at most %d sweeps, seed %u\n",
                tol, time_limit, max_sweeps, seed);
  }
  std::printf("%-8s %7s %9s %7s | %-5s %-6s %6s %9s %9s %9s %8s | %9s %9s\n", "kind", "nc",
              "nnz(W)", "W MB", "solver", "status", "sweeps", "total s", "ms/sweep", "ns/sw/nc",
              "peak MB", "|F|/|q|c", "|F|/|q|s");
  std::map<std::string, std::vector<std::pair<double, double>>> per_sweep;  // kind/solver
  for (const std::string& kind : kinds)
    for (const std::string& size : sizes) {
      const double t0 = now();
      const Packing packing = make_packing(kind, std::atol(size.c_str()), seed);
      const cpkit::FrictionContactProblem p = cpkit::bench::packing_problem(packing);
      const double t_build = now() - t0;
      const long nc = static_cast<long>(p.contacts());
      const double w_mb = (static_cast<double>(p.W.nonZeros()) * 12 + 4.0 * p.W.cols()) / 1e6;
#ifdef CPKIT_HAVE_SICONOS
      cpkit::bench::SiconosFriction siconos(p);
      auto siconos_error = [&siconos](const Eigen::VectorXd& r) { return siconos.error(r); };
      const double sbm_mb = static_cast<double>(siconos.w_bytes()) / 1e6;
#else
      auto siconos_error = [](const Eigen::VectorXd&) { return NAN; };
      const double sbm_mb = NAN;
#endif
      std::printf("# %s: %zu bodies, %ld contacts, built in %.2f s; W %.1f MB in cpkit (CSC), "
                  "%.1f MB in Siconos (sparse blocks)\n",
                  packing.name.c_str(), packing.bodies.size(), nc, t_build, w_mb, sbm_mb);
      auto judge = [&](const Eigen::VectorXd& r, Outcome& o) {
        o.rel_q_cpkit = cpkit::friction_errors(p, r).relative_q;
        o.rel_q_siconos = siconos_error(r);
      };
      for (const std::string& solver : solvers) {
        std::function<Answer()> solve;
        if (solver == "NSGS") {
#ifdef CPKIT_HAVE_SICONOS
          solve = [&]() {
            Answer a;
            Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u = r;
            SolverOptions* so = solver_options_create(SICONOS_FRICTION_3D_NSGS);
            so->dparam[SICONOS_DPARAM_TOL] = tol;
            so->iparam[SICONOS_IPARAM_MAX_ITER] = max_sweeps;
            const double t = now();
            const int info = fc3d_driver(siconos.get(), r.data(), u.data(), so);
            a.seconds = now() - t;
            a.sweeps = so->iparam[SICONOS_IPARAM_ITER_DONE];
            a.solved = info == 0;
            a.message = "info " + std::to_string(info);
            solver_options_delete(so);
            a.r = r;
            return a;
          };
#else
          continue;
#endif
        } else if (solver == "verdict") {
          // Not a solver: one full check of r = 0 by cpkit's verdict (friction_errors), the
          // cost nsgs pays at each convergence test and in finalize().
          solve = [&]() {
            Answer a;
            const double t = now();
            const cpkit::FrictionErrors e = cpkit::friction_errors(p, Eigen::VectorXd::Zero(p.q.size()));
            a.seconds = now() - t;
            a.sweeps = 1;
            a.message = "unit-free " + std::to_string(e.unit_free);
            return a;
          };
        } else {
          const cpkit::SolverEntry* e = cpkit::lcp::solvers().find(solver);
          if (!e || !e->solve_fc) {
            std::fprintf(stderr, "cpkit: bad input: no friction solver '%s'\n", solver.c_str());
            return 2;
          }
          solve = [&, e]() {
            cpkit::CommonOptions o;
            o.tol = tol;
            o.time_limit_s = time_limit;
            o.max_iterations = max_sweeps;
            const double t = now();
            const cpkit::SolveResult r =
                fixed_sweeps > 0 ? e->solve_fc(p, o)
                                 : cpkit::lcp::friction::solve_in_measure(p, *e, o, measure);
            Answer a;
            a.seconds = now() - t;
            a.sweeps = r.iterations;
            a.solved = r.status == cpkit::Status::kSolved;
            a.message = std::string(cpkit::to_string(r.status)) + " " + r.solver + " " + r.message;
            a.r = r.z;
            return a;
          };
        }
        const Outcome o = in_child(solve, judge, time_limit + 5);
        const bool ok = o.finished && o.solved && o.rel_q_cpkit <= tol && o.rel_q_siconos <= tol;
        const double ms_sweep = o.sweeps > 0 ? 1e3 * o.seconds / o.sweeps : NAN;
        std::printf("%-8s %7ld %9ld %7.1f | %-5s %-6s %6d %9.3f %9.3f %9.1f %8.1f | %9.1e %9.1e  %s\n",
                    kind.c_str(), nc, static_cast<long>(p.W.nonZeros()), w_mb, solver.c_str(),
                    !o.finished ? "killed" : fixed_sweeps > 0 ? "fixed" : ok ? "ok" : "FAIL", o.sweeps, o.seconds, ms_sweep,
                    1e6 * ms_sweep / static_cast<double>(nc), o.peak_kb / 1024.0, o.rel_q_cpkit,
                    o.rel_q_siconos, o.message);
        std::fflush(stdout);
        if (o.finished && o.sweeps > 0) per_sweep[kind + " " + solver].emplace_back(nc, ms_sweep);
      }
    }
  std::printf("# time per sweep ~ contacts^p, least squares over the sizes run:\n");
  for (const auto& [name, xy] : per_sweep)
    std::printf("#   %-14s p = %.2f over %zu sizes\n", name.c_str(), exponent(xy), xy.size());
  return 0;
}
