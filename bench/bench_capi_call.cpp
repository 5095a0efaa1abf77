// Per-call cost of the C API (capi/include/cpkit/cpkit.h) against Siconos numerics' C calls, in
// one process (issue 37):
// - the tiny LCP M = [[2, 1], [1, 2]], q = (-5, -6) (z = (4/3, 7/3)) by Siconos' lcp_lexicolemke
//   and by cpkit_lcp_solve ("lemke", "auto") and cpkit_lcp_solve_batch (per problem);
// - one contact W = I, mu = 0.5, stick q = (-1, 0.2, 0) (r = (1, -0.2, 0)) and slip
//   q = (-1, 1, 0) (r = (1, -0.5, 0)), and a coupled contact (W = [[2, .5, .3], [.5, 1.5, .2],
//   [.3, .2, 1]], q = (-1, .4, -.3), mu = 0.3: cpkit's answer checked against Siconos'), by
//   Siconos' fc3d_driver (NSGS) and by cpkit_fc3d_solve ("auto") and cpkit_fc3d_solve_batch.
// Every answer is checked first (hand answers, or Siconos'). Times: the CPU time of the thread
// (robust to the machine's load, as bench_python_siconos.py) over rounds of back-to-back calls
// (about 0.05 s each), the MEDIAN over the rounds in microseconds per call (the minimum in
// brackets); the two libraries alternate round by round, so that what load remains (caches,
// frequency) hits both alike. Siconos' NSGS starts from r = 0 at every call (as cpkit does). cpkit's calls pass a
// cpkit_info (so they read the wall clock twice for info.seconds) and verify every answer.
//   bench_capi_call [rounds]     (default 15; Siconos numerics: scripts/setup-deps.sh --bench)
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <utility>
#include <string>
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

/// The CPU time of this thread in seconds: what a call costs, without the time the machine's
/// load (other processes on the same cores) takes away from it.
double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// A timed call and its calls per round (calibrated to about 0.05 s).
struct Timed {
  explicit Timed(std::function<void()> call, int problems = 1)
      : f(std::move(call)), per_call_problems(problems) {}
  std::function<void()> f;
  int per_call_problems = 1;
  long calls = 1;
  std::vector<double> us;  ///< microseconds per problem, one per round
};

void calibrate(Timed& t) {
  for (;;) {
    const double t0 = cpu_seconds();
    for (long i = 0; i < t.calls; ++i) t.f();
    if (cpu_seconds() - t0 > 0.05) return;
    t.calls *= 2;
  }
}

void round_of(Timed& t) {
  const double t0 = cpu_seconds();
  for (long i = 0; i < t.calls; ++i) t.f();
  const double s = cpu_seconds() - t0;
  t.us.push_back(1e6 * s / static_cast<double>(t.calls) / t.per_call_problems);
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double minimum(const std::vector<double>& v) {
  return v.empty() ? NAN : *std::min_element(v.begin(), v.end());
}

bool near(const double* x, const double* y, int n, double tol = 1e-12) {
  for (int i = 0; i < n; ++i)
    if (!(std::abs(x[i] - y[i]) <= tol)) return false;
  return true;
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

void row(const char* what, const Timed& t, const Timed* peer) {
  const double us = median(t.us);
  if (peer != nullptr)
    std::printf("| %-52s | %8.4f [%7.4f] | %6.2fx |\n", what, us, minimum(t.us),
                us / median(peer->us));
  else
    std::printf("| %-52s | %8.4f [%7.4f] | %7s |\n", what, us, minimum(t.us), "-");
}

#ifdef CPKIT_HAVE_SICONOS
/// Siconos' one-contact problem (it owns and frees the arrays: malloc'd copies).
FrictionContactProblem* siconos_contact(const double* W, const double* q, double mu) {
  auto* Ws = static_cast<double*>(std::malloc(9 * sizeof(double)));
  auto* qs = static_cast<double*>(std::malloc(3 * sizeof(double)));
  auto* ms = static_cast<double*>(std::malloc(sizeof(double)));
  std::memcpy(Ws, W, 9 * sizeof(double));
  std::memcpy(qs, q, 3 * sizeof(double));
  *ms = mu;
  return frictionContactProblem_new_with_data(3, 1, NM_create_from_data(NM_DENSE, 3, 3, Ws), qs,
                                              ms);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
  std::printf("load average before: %s\n", load_average().c_str());
  bool ok = true;
  // The tiny LCP (column-major) and its hand answer.
  const double M[4] = {2, 1, 1, 2}, q[2] = {-5, -6}, z_hand[2] = {4.0 / 3, 7.0 / 3};
  // One contact: W = I (CSC and dense), stick and slip by hand; a coupled W (dense, all 9 stored).
  const int col_I[4] = {0, 1, 2, 3}, row_I[3] = {0, 1, 2};
  const int col_full[4] = {0, 3, 6, 9}, row_full[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
  const double W_I_values[3] = {1, 1, 1}, W_I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double q_stick[3] = {-1, 0.2, 0}, r_stick[3] = {1, -0.2, 0};
  const double q_slip[3] = {-1, 1, 0}, r_slip[3] = {1, -0.5, 0};
  const double mu[1] = {0.5};
  const double W_c[9] = {2, 0.5, 0.3, 0.5, 1.5, 0.2, 0.3, 0.2, 1}, q_c[3] = {-1, 0.4, -0.3},
               mu_c[1] = {0.3};
  double z[2], w[2], r[3], u[3], r_c_siconos[3] = {NAN, NAN, NAN};
  cpkit_info info;
  std::vector<Timed*> all;  // every timing, in the order the rounds alternate

#ifdef CPKIT_HAVE_SICONOS
  const Eigen::MatrixXd Md = Eigen::Map<const Eigen::Matrix2d>(M);
  const Eigen::VectorXd qd = Eigen::Map<const Eigen::Vector2d>(q);
  SiconosLcp sl(Md, qd);
  SolverOptions* lcp_opts = solver_options_create(SICONOS_LCP_LEMKE);
  int lcp_status = -1;
  lcp_lexicolemke(&sl.lcp, z, w, &lcp_status, lcp_opts);
  ok = ok && lcp_status == 0 && near(z, z_hand, 2);
  std::printf("siconos lcp_lexicolemke: info %d, z = (%.15g, %.15g)\n", lcp_status, z[0], z[1]);
  FrictionContactProblem* fc_stick = siconos_contact(W_I, q_stick, mu[0]);
  FrictionContactProblem* fc_slip = siconos_contact(W_I, q_slip, mu[0]);
  FrictionContactProblem* fc_c = siconos_contact(W_c, q_c, mu_c[0]);
  SolverOptions* fc_opts = solver_options_create(SICONOS_FRICTION_3D_NSGS);
  fc_opts->dparam[SICONOS_DPARAM_TOL] = 1e-10;
  for (auto [fc, hand] : {std::pair{fc_stick, r_stick}, std::pair{fc_slip, r_slip},
                          std::pair{fc_c, static_cast<const double*>(nullptr)}}) {
    std::fill(r, r + 3, 0.0);
    std::fill(u, u + 3, 0.0);
    const int status = fc3d_driver(fc, r, u, fc_opts);
    ok = ok && status == 0 && (hand == nullptr || near(r, hand, 3, 1e-9));
    if (hand == nullptr) std::copy(r, r + 3, r_c_siconos);
    std::printf("siconos fc3d_driver (NSGS): info %d, r = (%.15g, %.15g, %.15g)\n", status, r[0],
                r[1], r[2]);
  }
  auto siconos_fc = [&](FrictionContactProblem* fc) {
    return [&, fc] {
      r[0] = r[1] = r[2] = u[0] = u[1] = u[2] = 0;
      fc3d_driver(fc, r, u, fc_opts);
    };
  };
  Timed sic_lcp{[&] { lcp_lexicolemke(&sl.lcp, z, w, &lcp_status, lcp_opts); }};
  Timed sic_stick{siconos_fc(fc_stick)}, sic_slip{siconos_fc(fc_slip)}, sic_c{siconos_fc(fc_c)};
  Timed* peer_lcp = &sic_lcp;
  Timed* peer_stick = &sic_stick;
  Timed* peer_slip = &sic_slip;
  Timed* peer_c = &sic_c;
  all = {&sic_lcp, &sic_stick, &sic_slip, &sic_c};
#else
  std::printf("Siconos numerics not found: cpkit only (scripts/setup-deps.sh --bench)\n");
  Timed* peer_lcp = nullptr;
  Timed* peer_stick = nullptr;
  Timed* peer_slip = nullptr;
  Timed* peer_c = nullptr;
#endif

  // cpkit: first the answers, then the timings.
  for (const char* s : {"lemke", "auto"}) {
    const int code = cpkit_lcp_solve(2, M, q, s, nullptr, z, w, &info);
    ok = ok && code == 0 && near(z, z_hand, 2);
    std::printf("cpkit_lcp_solve(%s): status %d, z = (%.15g, %.15g)\n", s, code, z[0], z[1]);
  }
  for (auto [qc, hand] : {std::pair{q_stick, r_stick}, std::pair{q_slip, r_slip}}) {
    const int code =
        cpkit_fc3d_solve(1, 3, col_I, row_I, W_I_values, qc, mu, "auto", nullptr, r, u, &info);
    ok = ok && code == 0 && near(r, hand, 3);
    std::printf("cpkit_fc3d_solve(auto): status %d, r = (%.15g, %.15g, %.15g)\n", code, r[0],
                r[1], r[2]);
  }
  {
    const int code =
        cpkit_fc3d_solve(1, 9, col_full, row_full, W_c, q_c, mu_c, "auto", nullptr, r, u, &info);
    ok = ok && code == 0 && (std::isnan(r_c_siconos[0]) || near(r, r_c_siconos, 3, 1e-8));
    std::printf("cpkit_fc3d_solve(auto), coupled W: status %d, r = (%.15g, %.15g, %.15g)\n",
                code, r[0], r[1], r[2]);
  }
  const int batch = 1000;
  std::vector<double> Ms(4 * batch), qs(2 * batch), zs(2 * batch), ws(2 * batch);
  std::vector<double> Wb(9 * batch), qb(3 * batch), mub(batch), rb(3 * batch), ub(3 * batch);
  std::vector<int> st(batch);
  for (int k = 0; k < batch; ++k) {
    std::copy(M, M + 4, &Ms[4 * k]);
    std::copy(q, q + 2, &qs[2 * k]);
    std::copy(W_I, W_I + 9, &Wb[9 * k]);
    std::copy(q_stick, q_stick + 3, &qb[3 * k]);
    mub[k] = mu[0];
  }
  ok = ok && cpkit_lcp_solve_batch(batch, 2, Ms.data(), qs.data(), "lemke", nullptr, zs.data(),
                                   ws.data(), st.data(), &info) == 0 &&
       near(&zs[2 * (batch - 1)], z_hand, 2);
  ok = ok && cpkit_fc3d_solve_batch(batch, 1, Wb.data(), qb.data(), mub.data(), "auto", nullptr,
                                    rb.data(), ub.data(), st.data(), &info) == 0 &&
       near(&rb[3 * (batch - 1)], r_stick, 3);
  if (!ok) {
    std::printf("WRONG ANSWER: some solver missed the expected answer; no timings\n");
    return 1;
  }

  Timed lcp_lemke{[&] { cpkit_lcp_solve(2, M, q, "lemke", nullptr, z, w, &info); }};
  Timed lcp_auto{[&] { cpkit_lcp_solve(2, M, q, "auto", nullptr, z, w, &info); }};
  Timed lcp_null{[&] { cpkit_lcp_solve(2, M, q, "auto", nullptr, z, w, nullptr); }};
  Timed lcp_batch{[&] {
                    cpkit_lcp_solve_batch(batch, 2, Ms.data(), qs.data(), "lemke", nullptr,
                                          zs.data(), ws.data(), st.data(), &info);
                  },
                  batch};
  auto fc_call = [&](const int* col, const int* rowi, int nnz, const double* vals,
                     const double* qc, const double* m) {
    return [&, col, rowi, nnz, vals, qc, m] {
      cpkit_fc3d_solve(1, nnz, col, rowi, vals, qc, m, "auto", nullptr, r, u, &info);
    };
  };
  Timed cp_stick{fc_call(col_I, row_I, 3, W_I_values, q_stick, mu)};
  Timed cp_null{[&] {
    cpkit_fc3d_solve(1, 3, col_I, row_I, W_I_values, q_stick, mu, "auto", nullptr, r, u, nullptr);
  }};
  Timed cp_slip{fc_call(col_I, row_I, 3, W_I_values, q_slip, mu)};
  Timed cp_c{fc_call(col_full, row_full, 9, W_c, q_c, mu_c)};
  Timed fc_batch{[&] {
                   cpkit_fc3d_solve_batch(batch, 1, Wb.data(), qb.data(), mub.data(), "auto",
                                          nullptr, rb.data(), ub.data(), st.data(), &info);
                 },
                 batch};
  for (Timed* t : std::initializer_list<Timed*>{&lcp_lemke, &lcp_auto, &lcp_null, &lcp_batch,
                                                 &cp_stick, &cp_null, &cp_slip, &cp_c, &fc_batch})
    all.push_back(t);
  for (Timed* t : all) calibrate(*t);
  for (int k = 0; k < rounds; ++k)
    for (Timed* t : all) round_of(*t);

  std::printf("\n%d rounds; median us per call [minimum]; ratio of medians to Siconos' call\n\n",
              rounds);
  std::printf("| call (one problem unless per problem) | us/call [min] | vs Siconos |\n"
              "|---|---|---|\n");
  if (peer_lcp) row("siconos lcp_lexicolemke", *peer_lcp, peer_lcp);
  row("cpkit_lcp_solve(\"lemke\")", lcp_lemke, peer_lcp);
  row("cpkit_lcp_solve(\"auto\")", lcp_auto, peer_lcp);
  row("cpkit_lcp_solve(\"auto\"), info NULL (no clock read)", lcp_null, peer_lcp);
  row("cpkit_lcp_solve_batch(1000, \"lemke\") per problem", lcp_batch, peer_lcp);
  if (peer_stick) row("siconos fc3d_driver (NSGS), W = I, stick", *peer_stick, peer_stick);
  row("cpkit_fc3d_solve(\"auto\"), W = I, stick", cp_stick, peer_stick);
  row("cpkit_fc3d_solve(\"auto\"), W = I, stick, info NULL", cp_null, peer_stick);
  row("cpkit_fc3d_solve_batch(1000, \"auto\") per problem", fc_batch, peer_stick);
  if (peer_slip) row("siconos fc3d_driver (NSGS), W = I, slip", *peer_slip, peer_slip);
  row("cpkit_fc3d_solve(\"auto\"), W = I, slip", cp_slip, peer_slip);
  if (peer_c) row("siconos fc3d_driver (NSGS), coupled W", *peer_c, peer_c);
  row("cpkit_fc3d_solve(\"auto\"), coupled W", cp_c, peer_c);
  std::printf("\nload average after: %s\n", load_average().c_str());
#ifdef CPKIT_HAVE_SICONOS
  solver_options_delete(lcp_opts);
  solver_options_delete(fc_opts);
#endif
  return 0;
}
