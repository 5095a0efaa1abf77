// Rate problems per second for each route of the rate problem (docs/benchmarks/rate.md).
//
//   bench_rate [--n N] [--reps R] [--show-outside]
//
// Random parameter sets and load directions (fixed seed), states b and d. Routes: the
// allocation-free summaries (count + types) through the enumeration and the closed forms, the
// full solution sets (with rates, segments, rays), and one solution by each registered single
// LCP solver (lemke, fb-newton, ipopt). Best of R repetitions (the machine is shared).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/one_point/analytic.hpp"
#include "cpkit/rate_problem/one_point/rate_lcp.hpp"
#include "cpkit/rate_problem/one_point/rate_problem.hpp"

using namespace cpkit::rate;

namespace {

struct Case {
  ContactParameters p;
  ContactState st;
  LoadRate f;
};

std::vector<Case> make_cases(int n, StateLabel label, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Case> v(n);
  for (auto& c : v) {
    c.p.a11 = 0.1 + 3 * U(rng);
    c.p.a22 = 0.1 + 3 * U(rng);
    c.p.a12 = (2 * U(rng) - 1) * 0.97 * std::sqrt(c.p.a11 * c.p.a22);
    c.p.mu = 0.05 + 2 * U(rng);
    c.p.C_T = U(rng);
    c.p.k_a = U(rng);
    c.p.P_s = 1;
    c.st.label = label;
    c.st.P_N = label == StateLabel::kD ? 0.1 + 3 * U(rng) : 0.0;
    c.st.sgn_PT = U(rng) < 0.5 ? 1 : -1;
    const double th = 2 * M_PI * U(rng);
    c.f = LoadRate{std::cos(th), std::sin(th)};
  }
  return v;
}

template <class F>
double best_rate(int reps, int n, F&& run) {
  double best = 0;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::max(best, n / s);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 200000, reps = 5;
  bool show_outside = false;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--show-outside")) show_outside = true;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--n")) n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--reps")) reps = std::atoi(argv[i + 1]);
  }
  std::printf("# bench_rate: rate problems per second (best of %d), %d random problems per state\n",
              reps, n);
  std::printf("%-8s %-34s %14s %s\n", "state", "route", "problems/s", "check");
  const auto& reg = cpkit::lcp::solvers();
  for (StateLabel label : {StateLabel::kB, StateLabel::kD}) {
    const auto cases = make_cases(n, label, label == StateLabel::kB ? 1u : 2u);
    const char* st = label == StateLabel::kB ? "b" : "d";
    long sum_e = 0, sum_a = 0, unreliable = 0;
    const double re = best_rate(reps, n, [&] {
      sum_e = 0;
      for (const auto& c : cases) {
        const RateSummary s = summarize_rate_problem(c.p, c.st, c.f, RateMethod::kEnumerate);
        sum_e += s.count * 31 + static_cast<long>(s.types);
        unreliable += !s.reliable;
      }
    });
    const double ra = best_rate(reps, n, [&] {
      sum_a = 0;
      for (const auto& c : cases) {
        const RateSummary s = summarize_rate_problem(c.p, c.st, c.f, RateMethod::kAnalytic);
        sum_a += s.count * 31 + static_cast<long>(s.types);
      }
    });
    std::vector<RatePrecomputed> pres;
    pres.reserve(cases.size());
    for (const auto& c : cases) pres.push_back(precompute_rate_problem(c.p, c.st));
    long sum_p = 0;
    const double rp = best_rate(reps, n, [&] {
      sum_p = 0;
      for (std::size_t i = 0; i < cases.size(); ++i) {
        const RateSummary s = summarize_rate_problem(pres[i], cases[i].f);
        sum_p += s.count * 31 + static_cast<long>(s.types);
      }
    });
    std::printf("%-8s %-34s %14.0f %s\n", st, "enumerate summary (count+types)", re,
                sum_e == sum_a ? "agrees with analytic" : "DISAGREES with analytic");
    std::printf("%-8s %-34s %14.0f %s\n", st, "enumerate summary, precomputed", rp,
                sum_p == sum_a ? "agrees with analytic" : "DISAGREES with analytic");
    std::printf("%-8s %-34s %14.0f\n", st, "analytic summary (count+types)", ra);
    const int nf = std::min(n, 50000);
    const double rfe = best_rate(reps, nf, [&] {
      for (int i = 0; i < nf; ++i)
        (void)solve_rate_problem(cases[i].p, cases[i].st, cases[i].f, RateMethod::kEnumerate);
    });
    const double rfa = best_rate(reps, nf, [&] {
      for (int i = 0; i < nf; ++i)
        (void)solve_rate_problem(cases[i].p, cases[i].st, cases[i].f, RateMethod::kAnalytic);
    });
    std::printf("%-8s %-34s %14.0f\n", st, "enumerate full set (rates, pieces)", rfe);
    std::printf("%-8s %-34s %14.0f\n", st, "analytic full set (rates, pieces)", rfa);
    for (const char* name : {"lemke", "fb-newton", "ipopt"}) {
      if (reg.find(name) == nullptr) {
        std::printf("%-8s %-34s %14s\n", st, name, "not registered");
        continue;
      }
      const int ns = std::string(name) == "ipopt" ? std::min(n, 100) : std::min(n, 20000);
      int solved = 0, inside = 0;
      const double rs = best_rate(std::string(name) == "ipopt" ? 1 : reps, ns, [&] {
        solved = inside = 0;
        for (int i = 0; i < ns; ++i) {
          const RateSolutionSet one = solve_rate_single(cases[i].p, cases[i].st, cases[i].f, name);
          solved += !one.solutions.empty();
        }
      });
      for (int i = 0; i < ns; ++i) {
        const RateSolutionSet one = solve_rate_single(cases[i].p, cases[i].st, cases[i].f, name);
        if (one.solutions.empty()) continue;
        const RateSolutionSet all = solve_rate_problem(cases[i].p, cases[i].st, cases[i].f,
                                                       RateMethod::kAnalytic);
        const bool in = contains(all, one.solutions.front().start, std::max(1e-6, 1e3 * one.residual));
        inside += in;
        if (!in && show_outside) {
          const Case& c = cases[i];
          const Rates& r = one.solutions.front().start;
          std::printf("# outside: %s state %s a=(%.17g,%.17g,%.17g) mu=%.17g C_T=%.17g k_a=%.17g "
                      "P_N=%.17g s=%d dF=(%.17g,%.17g): dP=(%.6g,%.6g) dw_Ti=%.6g [%s]\n",
                      name, st, c.p.a11, c.p.a12, c.p.a22, c.p.mu, c.p.C_T, c.p.k_a, c.st.P_N,
                      c.st.sgn_PT, c.f.dF_T, c.f.dF_N, r.dP_T, r.dP_N, r.dw_Ti,
                      one.message.c_str());
          for (const auto& x : all.solutions)
            std::printf("#   set: %s dP=(%.6g,%.6g) dw_Ti=%.6g\n", std::string(to_string(x.type)).c_str(),
                        x.start.dP_T, x.start.dP_N, x.start.dw_Ti);
        }
      }
      std::printf("%-8s %-34s %14.0f solved %d/%d, inside the set %d/%d\n", st,
                  (std::string(name) + " (one solution)").c_str(), rs, solved, ns, inside, solved);
    }
    if (unreliable) std::printf("# %s: %ld summaries flagged unreliable\n", st, unreliable);
  }
  return 0;
}
