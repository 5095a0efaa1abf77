// Per-call cost of the C API (capi/include/cpkit/cpkit.h) against Siconos numerics' C calls, in
// one process (issue 37): the tiny LCP M = [[2, 1], [1, 2]], q = (-5, -6) (z = (4/3, 7/3)) by
// Siconos' lcp_lexicolemke and by cpkit_lcp_solve ("lemke", "auto") and cpkit_lcp_solve_batch
// (per problem); one contact W = I, q = (-1, 0.2, 0), mu = 0.5 (stick, r = (1, -0.2, 0)) by
// Siconos' fc3d_driver (NSGS) and by cpkit_fc3d_solve ("nsgs", "auto") and
// cpkit_fc3d_solve_batch. Every answer is checked against the hand answer first. Times: the best
// of 7 rounds of back-to-back calls (microseconds per call); Siconos' NSGS starts from r = 0 at
// every call (as cpkit does), so that it does not profit from its previous answer.
//   bench_capi_call [rounds]     (Siconos numerics: scripts/setup-deps.sh --bench)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpkit/cpkit.h"
#include "siconos_lcp.hpp"
#ifdef CPKIT_HAVE_SICONOS
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "FrictionContactProblem.h"
#include "Friction_cst.h"
#pragma GCC diagnostic pop
#endif

namespace {

using Clock = std::chrono::steady_clock;

/// Microseconds per call of f (calls back-to-back), the best of `rounds` rounds of ~0.1 s.
template <class F>
double us_per_call(F&& f, int rounds, int per_call_problems = 1) {
  int calls = 1;
  for (;;) {  // calibrate: a round of about 0.1 s
    const auto t0 = Clock::now();
    for (int i = 0; i < calls; ++i) f();
    if (std::chrono::duration<double>(Clock::now() - t0).count() > 0.05) break;
    calls *= 2;
  }
  double best = INFINITY;
  for (int r = 0; r < rounds; ++r) {
    const auto t0 = Clock::now();
    for (int i = 0; i < calls; ++i) f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return 1e6 * best / calls / per_call_problems;
}

bool near(const double* x, const double* y, int n) {
  for (int i = 0; i < n; ++i)
    if (!(std::abs(x[i] - y[i]) <= 1e-12)) return false;
  return true;
}

void row(const char* what, double us, double peer) {
  if (std::isfinite(peer))
    std::printf("| %-50s | %9.4f | %6.2fx |\n", what, us, us / peer);
  else
    std::printf("| %-50s | %9.4f | %7s |\n", what, us, "-");
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  bool ok = true;
  // The tiny LCP (column-major) and its hand answer.
  const double M[4] = {2, 1, 1, 2}, q[2] = {-5, -6}, z_hand[2] = {4.0 / 3, 7.0 / 3};
  // One contact, W = I in CSC, and its hand answer (stick).
  const int col[4] = {0, 1, 2, 3}, rowi[3] = {0, 1, 2};
  const double Wv[3] = {1, 1, 1}, Wd[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, qc[3] = {-1, 0.2, 0},
               mu[1] = {0.5}, r_hand[3] = {1, -0.2, 0};
  double z[2], w[2], r[3], u[3];
  cpkit_info info;

  double sic_lcp = NAN, sic_fc = NAN;
#ifdef CPKIT_HAVE_SICONOS
  {
    const Eigen::MatrixXd Md = Eigen::Map<const Eigen::Matrix2d>(M);
    const Eigen::VectorXd qd = Eigen::Map<const Eigen::Vector2d>(q);
    SiconosLcp sl(Md, qd);
    SolverOptions* opts = solver_options_create(SICONOS_LCP_LEMKE);
    int status = -1;
    lcp_lexicolemke(&sl.lcp, z, w, &status, opts);
    ok = ok && status == 0 && near(z, z_hand, 2);
    std::printf("siconos lcp_lexicolemke: info %d, z = (%.15g, %.15g)\n", status, z[0], z[1]);
    sic_lcp = us_per_call([&] { lcp_lexicolemke(&sl.lcp, z, w, &status, opts); }, rounds);
    solver_options_delete(opts);
  }
  {
    // Siconos owns (and would free) the problem's arrays: malloc'd copies, kept to the end.
    auto* Ws = static_cast<double*>(std::malloc(sizeof Wd));
    auto* qs = static_cast<double*>(std::malloc(sizeof qc));
    auto* ms = static_cast<double*>(std::malloc(sizeof mu));
    std::memcpy(Ws, Wd, sizeof Wd);
    std::memcpy(qs, qc, sizeof qc);
    std::memcpy(ms, mu, sizeof mu);
    FrictionContactProblem* fc = frictionContactProblem_new_with_data(
        3, 1, NM_create_from_data(NM_DENSE, 3, 3, Ws), qs, ms);
    SolverOptions* opts = solver_options_create(SICONOS_FRICTION_3D_NSGS);
    opts->dparam[SICONOS_DPARAM_TOL] = 1e-10;
    std::fill(r, r + 3, 0.0);
    std::fill(u, u + 3, 0.0);
    const int status = fc3d_driver(fc, r, u, opts);
    ok = ok && status == 0 && near(r, r_hand, 3);
    std::printf("siconos fc3d_driver (NSGS): info %d, r = (%.15g, %.15g, %.15g)\n", status, r[0],
                r[1], r[2]);
    sic_fc = us_per_call([&] {
      r[0] = r[1] = r[2] = u[0] = u[1] = u[2] = 0;
      fc3d_driver(fc, r, u, opts);
    }, rounds);
    solver_options_delete(opts);
  }
#else
  std::printf("Siconos numerics not found: cpkit only (scripts/setup-deps.sh --bench)\n");
#endif

  // cpkit: first the answers, then the timings.
  for (const char* s : {"lemke", "auto"}) {
    const int code = cpkit_lcp_solve(2, M, q, s, nullptr, z, w, &info);
    ok = ok && code == 0 && near(z, z_hand, 2);
    std::printf("cpkit_lcp_solve(%s): status %d, z = (%.15g, %.15g)\n", s, code, z[0], z[1]);
  }
  for (const char* s : {"nsgs", "auto"}) {
    const int code = cpkit_fc3d_solve(1, 3, col, rowi, Wv, qc, mu, s, nullptr, r, u, &info);
    ok = ok && code == 0 && near(r, r_hand, 3);
    std::printf("cpkit_fc3d_solve(%s): status %d, r = (%.15g, %.15g, %.15g)\n", s, code, r[0], r[1],
                r[2]);
  }
  const int batch = 1000;
  std::vector<double> Ms(4 * batch), qs(2 * batch), zs(2 * batch), ws(2 * batch);
  std::vector<double> Wb(9 * batch), qb(3 * batch), mub(batch), rb(3 * batch), ub(3 * batch);
  std::vector<int> st(batch);
  for (int k = 0; k < batch; ++k) {
    std::copy(M, M + 4, &Ms[4 * k]);
    std::copy(q, q + 2, &qs[2 * k]);
    std::copy(Wd, Wd + 9, &Wb[9 * k]);
    std::copy(qc, qc + 3, &qb[3 * k]);
    mub[k] = mu[0];
  }
  ok = ok && cpkit_lcp_solve_batch(batch, 2, Ms.data(), qs.data(), "lemke", nullptr, zs.data(),
                                   ws.data(), st.data(), &info) == 0 &&
       near(&zs[2 * (batch - 1)], z_hand, 2);
  ok = ok && cpkit_fc3d_solve_batch(batch, 1, Wb.data(), qb.data(), mub.data(), "auto", nullptr,
                                    rb.data(), ub.data(), st.data(), &info) == 0 &&
       near(&rb[3 * (batch - 1)], r_hand, 3);
  if (!ok) {
    std::printf("WRONG ANSWER: some solver missed the hand answer; no timings\n");
    return 1;
  }

  std::printf("\n| call (one problem unless per problem) | us/call | vs Siconos |\n|---|---|---|\n");
  row("siconos lcp_lexicolemke", sic_lcp, sic_lcp);
  for (const char* s : {"lemke", "auto"}) {
    char name[64];
    std::snprintf(name, sizeof name, "cpkit_lcp_solve(\"%s\")", s);
    row(name, us_per_call([&] { cpkit_lcp_solve(2, M, q, s, nullptr, z, w, &info); }, rounds),
        sic_lcp);
  }
  row("cpkit_lcp_solve(\"lemke\"), info NULL",
      us_per_call([&] { cpkit_lcp_solve(2, M, q, "lemke", nullptr, z, w, nullptr); }, rounds),
      sic_lcp);
  row("cpkit_lcp_solve_batch(1000, \"lemke\") per problem",
      us_per_call([&] {
        cpkit_lcp_solve_batch(batch, 2, Ms.data(), qs.data(), "lemke", nullptr, zs.data(),
                              ws.data(), st.data(), &info);
      }, rounds, batch),
      sic_lcp);
  row("siconos fc3d_driver (NSGS)", sic_fc, sic_fc);
  for (const char* s : {"nsgs", "auto"}) {
    char name[64];
    std::snprintf(name, sizeof name, "cpkit_fc3d_solve(\"%s\")", s);
    row(name, us_per_call([&] {
          cpkit_fc3d_solve(1, 3, col, rowi, Wv, qc, mu, s, nullptr, r, u, &info);
        }, rounds),
        sic_fc);
  }
  row("cpkit_fc3d_solve_batch(1000, \"auto\") per problem",
      us_per_call([&] {
        cpkit_fc3d_solve_batch(batch, 1, Wb.data(), qb.data(), mub.data(), "auto", nullptr,
                               rb.data(), ub.data(), st.data(), &info);
      }, rounds, batch),
      sic_fc);
  return 0;
}
