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
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

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

/// A random N-point system: SPD A with coupling, points in states b and d (half each).
ContactSystem make_system(int N, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> G(0, 1);
  ContactSystem s;
  Eigen::MatrixXd B(2 * N, 2 * N);
  for (int i = 0; i < 2 * N; ++i)
    for (int j = 0; j < 2 * N; ++j) B(i, j) = G(rng);
  s.A = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(2 * N, 2 * N);
  for (int i = 0; i < N; ++i) {
    SystemPoint p;
    p.mu = 0.1 + 2 * U(rng);
    p.C_T = U(rng);
    p.k_a = U(rng);
    if (i % 2 == 1) {
      p.state.label = StateLabel::kD;
      p.state.P_N = p.P_N = 0.5 + U(rng);
      p.state.sgn_PT = U(rng) < 0.5 ? 1 : -1;
      p.P_T = p.state.sgn_PT * p.mu * p.P_N;
    }
    s.points.push_back(p);
  }
  return s;
}

/// Cost of one N-point rate solve (full set) and one summary (precomputed), N = 1..5.
void bench_system(int reps) {
  std::printf("\n# N-point rate problem (states b, d alternating; LCP size 3 n_b + n_d)\n");
  std::printf("%-3s %-5s %16s %16s %s\n", "N", "m", "full solves/s", "summaries/s", "counts 0/1/2/3+/inf");
  for (int N = 1; N <= 5; ++N) {
    std::mt19937_64 rng(100 + N);
    const int ns = 20;
    std::vector<ContactSystem> sys;
    std::vector<SystemRatePrecomputed> pre;
    std::vector<Eigen::VectorXd> loads;
    for (int k = 0; k < ns; ++k) {
      sys.push_back(make_system(N, rng));
      pre.push_back(precompute_system_rate(sys.back()));
    }
    const int nl = N <= 3 ? 200 : 40;
    std::normal_distribution<double> G(0, 1);
    for (int k = 0; k < nl; ++k) {
      Eigen::VectorXd f(2 * N);
      for (int j = 0; j < 2 * N; ++j) f(j) = G(rng);
      loads.push_back(f);
    }
    int hist[5] = {};
    const double rf = best_rate(reps, ns * nl, [&] {
      for (int a = 0; a < ns; ++a)
        for (const auto& f : loads) (void)solve_rate_problem(sys[static_cast<std::size_t>(a)], f);
    });
    const double rs = best_rate(reps, ns * nl, [&] {
      for (auto& h : hist) h = 0;
      for (const auto& p : pre)
        for (const auto& f : loads) {
          const int c = summarize_rate_problem(p, f).count;
          ++hist[c < 0 ? 4 : std::min(c, 3)];
        }
    });
    std::printf("%-3d %-5d %16.0f %16.0f %d/%d/%d/%d/%d\n", N, pre[0].m, rf, rs, hist[0], hist[1],
                hist[2], hist[3], hist[4]);
  }
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
  bench_system(reps);
  return 0;
}
