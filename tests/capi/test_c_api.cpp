// The C API (capi/include/cpkit/cpkit.h) called as a C program calls it. Oracles: hand answers
// (the 2x2 LCP, one contact sticking, slipping and separated), problems CONSTRUCTED from a chosen
// solution (z* >= 0 and w* >= 0 complementary, q = w* - M z*; M a P-matrix, so z* is the only
// solution; a contact with W = diag(a, b, b) and a chosen r*, whose solution is unique), the
// numbers of a committed problem file read by eye, and, for the JSON routes, the library's own
// request run on the same file (the C API only carries it). Every entry point: bad input gives
// 2 with a message, nothing crashes, and many threads may solve at once.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/cpkit.h"
#include "cpkit/lcp/friction/one_contact.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/requests/rate_request.hpp"
#include "cpkit/rate_problem/report/json.hpp"

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// W = I of one contact in compressed sparse columns.
const int kColI[4] = {0, 1, 2, 3}, kRowI[3] = {0, 1, 2};
const double kValI[3] = {1, 1, 1};

std::string message(const cpkit_info& info) { return info.message; }

/// A random n x n P-matrix (strictly diagonally dominant with a positive diagonal), column-major,
/// and q built from a chosen complementary pair: z*_i > 0 or w*_i > 0 (never both).
struct Constructed {
  std::vector<double> M, q, z;
};
Constructed constructed_lcp(int n, std::mt19937& g) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.5, 3);
  Constructed c;
  c.M.assign(static_cast<std::size_t>(n) * n, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) c.M[j * n + i] = i == j ? 0 : u(g);
  for (int i = 0; i < n; ++i) {
    double off = 0;
    for (int j = 0; j < n; ++j) off += std::abs(c.M[j * n + i]);
    c.M[i * n + i] = off + pos(g);
  }
  c.z.assign(n, 0);
  std::vector<double> w(n, 0);
  for (int i = 0; i < n; ++i) (g() % 2 ? c.z[i] : w[i]) = pos(g);
  c.q = w;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) c.q[i] -= c.M[j * n + i] * c.z[j];
  return c;
}

/// One contact W = diag(a, b, b) with a chosen answer: stick (r* inside the cone, q = -W r*) or
/// separation (r* = 0, q_N > 0). With this W the problem is a projection: r* is its only solution.
struct ConstructedContact {
  double W[9] = {0};
  double q[3], mu, r[3];
};
ConstructedContact constructed_contact(std::mt19937& g) {
  std::uniform_real_distribution<double> pos(0.5, 3), unit(-1, 1), frac(0, 0.9);
  ConstructedContact c;
  const double a = pos(g), b = pos(g);
  c.W[0] = a;
  c.W[4] = c.W[8] = b;
  c.mu = pos(g) / 3;
  if (g() % 4 == 0) {
    c.r[0] = c.r[1] = c.r[2] = 0;
    c.q[0] = pos(g), c.q[1] = unit(g), c.q[2] = unit(g);
    return c;
  }
  const double rN = pos(g), phi = 6.283185307179586 * frac(g), t = frac(g) * c.mu * rN;
  c.r[0] = rN, c.r[1] = t * std::cos(phi), c.r[2] = t * std::sin(phi);
  c.q[0] = -a * c.r[0], c.q[1] = -b * c.r[1], c.q[2] = -b * c.r[2];
  return c;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("C API: info.seconds is the call's wall time, before and after the clock's calibration",
          "[capi]") {
  // Oracle: steady_clock read around each call by the test. The call's own clock
  // (capi/src/call_clock.hpp) is steady_clock for the first 10 ms of the process and then,
  // where the CPU has an invariant counter, the counter at a rate measured against it: both
  // phases are crossed here (calls for > 20 ms), and every reading lies within the outer one.
  using Clock = std::chrono::steady_clock;
  const double M[4] = {2, 1, 1, 2}, q[2] = {-5, -6};
  double z[2], w[2];
  cpkit_info info;
  const auto begin = Clock::now();
  int calls = 0;
  while (std::chrono::duration<double>(Clock::now() - begin).count() < 0.02 || calls < 1000) {
    const auto t0 = Clock::now();
    REQUIRE(cpkit_lcp_solve(2, M, q, "auto", nullptr, z, w, &info) == 0);
    const double outer = std::chrono::duration<double>(Clock::now() - t0).count();
    INFO("call " << calls << ": info.seconds " << info.seconds << ", outer " << outer);
    REQUIRE(info.seconds >= 0);
    REQUIRE(info.seconds <= outer * 1.01 + 1e-7);  // the counter's rate: ~1e-5 relative
    ++calls;
  }
  // A slower call (n = 60, the general route): most of its outer time is inside it.
  const int n = 60;
  std::vector<double> Mb(n * n, 0.0), qb(n, -1.0), zb(n), wb(n);
  for (int i = 0; i < n; ++i) Mb[i * (n + 1)] = 2 + i % 3;
  const auto t0 = Clock::now();
  REQUIRE(cpkit_lcp_solve(n, Mb.data(), qb.data(), "lemke", nullptr, zb.data(), wb.data(),
                          &info) == 0);
  const double outer = std::chrono::duration<double>(Clock::now() - t0).count();
  CHECK(info.seconds <= outer * 1.01 + 1e-7);
  CHECK(info.seconds >= 0.5 * outer);
}

TEST_CASE("C API: the tiny LCP by hand, every route", "[capi]") {
  const double M[4] = {2, 1, 1, 2}, q[2] = {-5, -6};
  // auto and lemke take the closed enumeration of n <= 4; fb-newton the registered solver.
  for (const char* solver : {"auto", "lemke", "fb-newton"}) {
    double z[2], w[2];
    cpkit_info info;
    info.status = 99;
    CAPTURE(solver);
    REQUIRE(cpkit_lcp_solve(2, M, q, solver, nullptr, z, w, &info) == 0);
    CHECK(info.status == 0);
    CHECK(message(info).empty());
    // Lemke and the enumeration solve M z = -q directly; fb-newton iterates to tol = 1e-10.
    const double err = std::strcmp(solver, "fb-newton") == 0 ? 1e-9 : 1e-14;
    CHECK(z[0] == Approx(4.0 / 3).epsilon(err));
    CHECK(z[1] == Approx(7.0 / 3).epsilon(err));
    CHECK(std::abs(w[0]) < err);
    CHECK(std::abs(w[1]) < err);
    CHECK(info.residual <= 1e-10);
    CHECK(info.seconds >= 0);
  }
  double z[2], w[2];
  CHECK(cpkit_lcp_solve(2, M, q, nullptr, nullptr, z, w, nullptr) == 0);  // NULL: auto, no info
  CHECK(z[0] == Approx(4.0 / 3).epsilon(1e-14));
}

TEST_CASE("C API: an LCP with no solution is 1 with the solver's account", "[capi]") {
  // w = z - 1 >= 0 needs z >= 1; w = -z - 1 can never be >= 0 for z >= 0: infeasible.
  const double M[1] = {-1}, q[1] = {-1};
  double z[1], w[1];
  cpkit_info info;
  CHECK(cpkit_lcp_solve(1, M, q, "lemke", nullptr, z, w, &info) == 1);
  CHECK(info.status == 1);
  CHECK(message(info).rfind("cpkit: ", 0) == 0);
}

TEST_CASE("C API: constructed LCPs, n = 1..6, equal the chosen solution", "[capi]") {
  std::mt19937 g(37);
  int decided = 0;
  for (int n = 1; n <= 6; ++n)
    for (int k = 0; k < 40; ++k) {
      const Constructed c = constructed_lcp(n, g);
      for (const char* solver : {"auto", "lemke"}) {
        std::vector<double> z(n), w(n);
        cpkit_info info;
        REQUIRE(cpkit_lcp_solve(n, c.M.data(), c.q.data(), solver, nullptr, z.data(), w.data(),
                                &info) == 0);
        for (int i = 0; i < n; ++i) REQUIRE(z[i] == Approx(c.z[i]).margin(1e-10));
        ++decided;
      }
    }
  CHECK(decided == 480);
}

TEST_CASE("C API: one contact by hand (stick, slip, separation) and two contacts", "[capi]") {
  struct Case {
    double q[3], r[3], u[3];
  };
  // W = I, mu = 0.5. stick: u = 0, r = -q. slip: r_N = 1, u_T = (1, 0) - 0.5 (1, 0) = (0.5, 0).
  // separation: r = 0, u = q.
  const Case cases[] = {{{-1, 0.2, 0}, {1, -0.2, 0}, {0, 0, 0}},
                        {{-1, 1, 0}, {1, -0.5, 0}, {0, 0.5, 0}},
                        {{1, 0.3, -0.2}, {0, 0, 0}, {1, 0.3, -0.2}}};
  const double mu[1] = {0.5};
  for (const Case& c : cases)
    for (const char* solver : {"auto", "nsgs", "fb-soc"}) {
      CAPTURE(solver, c.q[0], c.q[1]);
      double r[3], u[3];
      cpkit_info info;
      REQUIRE(cpkit_fc3d_solve(1, 3, kColI, kRowI, kValI, c.q, mu, solver, nullptr, r, u, &info) ==
              0);
      CHECK(info.status == 0);
      for (int i = 0; i < 3; ++i) {
        CHECK(r[i] == Approx(c.r[i]).margin(1e-9));
        CHECK(u[i] == Approx(c.u[i]).margin(1e-9));
      }
    }
  // Two uncoupled contacts (W = I of 6 rows): the general route; stick and slip as above.
  const int col[7] = {0, 1, 2, 3, 4, 5, 6}, row[6] = {0, 1, 2, 3, 4, 5};
  const double val[6] = {1, 1, 1, 1, 1, 1}, q[6] = {-1, 0.2, 0, -1, 1, 0}, mu2[2] = {0.5, 0.5};
  const double expect[6] = {1, -0.2, 0, 1, -0.5, 0};
  double r[6], u[6];
  cpkit_options o;
  cpkit_default_options(&o);
  REQUIRE(cpkit_fc3d_solve(2, 6, col, row, val, q, mu2, "auto", &o, r, u, nullptr) == 0);
  for (int i = 0; i < 6; ++i) CHECK(r[i] == Approx(expect[i]).margin(1e-9));
}

TEST_CASE("C API: the friction verdict on candidates by hand", "[capi]") {
  const double q[3] = {-1, 0.2, 0}, mu[1] = {0.5};
  const double good[3] = {1, -0.2, 0}, zero[3] = {0, 0, 0};
  cpkit_fc3d_error_values e;
  int state = -1;
  cpkit_info info;
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, q, mu, good, nullptr, &e, &state, &info) == 0);
  CHECK(e.unit_free <= 1e-15);
  CHECK(e.relative_q <= 1e-15);
  CHECK(state == 1);  // stick
  // r = 0 with q_N < 0 is never accepted: the normal condition is violated by 1 (unit-free).
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, q, mu, zero, nullptr, &e, &state, &info) == 5);
  CHECK(e.unit_free == Approx(1));
  CHECK(info.status == 5);
  CHECK(message(info).find("not a solution") != std::string::npos);
  const double qs[3] = {-1, 1, 0}, slip[3] = {1, -0.5, 0};
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, qs, mu, slip, nullptr, nullptr, &state,
                          nullptr) == 0);
  CHECK(state == 2);
  const double qo[3] = {1, 0, 0};
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, qo, mu, zero, nullptr, nullptr, &state,
                          nullptr) == 0);
  CHECK(state == 0);
  const double bad[3] = {kNaN, 0, 0};  // a non-finite candidate is rejected, not bad input
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, q, mu, bad, nullptr, &e, nullptr, nullptr) == 5);
}

TEST_CASE("C API: bad input is 2 with a message naming it, for every entry point", "[capi]") {
  const double M[4] = {2, 1, 1, 2}, q[2] = {-5, -6};
  double z[2] = {7, 7}, w[2] = {7, 7};
  cpkit_info info;
  auto lcp = [&](int n, const double* Mp, const double* qp, const char* s, const cpkit_options* o,
                 double* zp, double* wp) {
    const int code = cpkit_lcp_solve(n, Mp, qp, s, o, zp, wp, &info);
    CHECK(info.status == code);
    return code;
  };
  CHECK(lcp(-1, M, q, "lemke", nullptr, z, w) == 2);
  CHECK(message(info) == "cpkit: bad input: n must be >= 1, got -1");
  CHECK(lcp(0, M, q, "lemke", nullptr, z, w) == 2);
  CHECK(lcp(2, nullptr, q, "lemke", nullptr, z, w) == 2);
  CHECK(message(info) == "cpkit: bad input: M is NULL");
  CHECK(lcp(2, M, nullptr, "lemke", nullptr, z, w) == 2);
  CHECK(lcp(2, M, q, "lemke", nullptr, nullptr, w) == 2);
  CHECK(message(info) == "cpkit: bad input: z is NULL");
  CHECK(lcp(2, M, q, "lemke", nullptr, z, nullptr) == 2);
  const double q_nan[2] = {-5, kNaN}, M_inf[4] = {2, 1, INFINITY, 2};
  CHECK(lcp(2, M, q_nan, "lemke", nullptr, z, w) == 2);
  CHECK(message(info) == "cpkit: bad input: q has a non-finite entry (NaN or Inf) at index 1");
  CHECK(lcp(2, M_inf, q, "auto", nullptr, z, w) == 2);
  CHECK(message(info).find("M has a non-finite entry") != std::string::npos);
  CHECK(lcp(2, M, q, "no-such-solver", nullptr, z, w) == 2);
  CHECK(message(info).find("unknown LCP solver 'no-such-solver' (valid: lemke") != std::string::npos);
  CHECK(lcp(2, M, q, "nsgs", nullptr, z, w) == 2);  // a friction-only solver
  CHECK(message(info).find("unknown LCP solver 'nsgs'") != std::string::npos);
  cpkit_options o;
  cpkit_default_options(&o);
  o.tol = 0.5;
  CHECK(lcp(2, M, q, "lemke", &o, z, w) == 2);
  CHECK(message(info).find("options->tol must be in (0, 1e-3]") != std::string::npos);
  cpkit_default_options(&o);
  o.max_iter = -3;
  CHECK(lcp(2, M, q, "lemke", &o, z, w) == 2);
  cpkit_default_options(&o);
  o.time_limit = kNaN;
  CHECK(lcp(2, M, q, "lemke", &o, z, w) == 2);
  CHECK(z[0] == 7);  // nothing written on bad input
  CHECK(cpkit_lcp_solve(-1, M, q, "lemke", nullptr, z, w, nullptr) == 2);  // no info: no crash

  // Friction: sizes, pointers, the CSC structure, mu.
  const double qc[3] = {-1, 0.2, 0}, mu[1] = {0.5}, mu_neg[1] = {-0.1};
  double r[3], u[3];
  auto fc = [&](int contacts, int nnz, const int* col, const int* row, const double* val,
                const double* qq, const double* m, const char* s) {
    return cpkit_fc3d_solve(contacts, nnz, col, row, val, qq, m, s, nullptr, r, u, &info);
  };
  CHECK(fc(0, 3, kColI, kRowI, kValI, qc, mu, "auto") == 2);
  CHECK(message(info) == "cpkit: bad input: contacts must be >= 1, got 0");
  CHECK(fc(1, 3, nullptr, kRowI, kValI, qc, mu, "auto") == 2);
  CHECK(message(info) == "cpkit: bad input: col_ptr is NULL");
  const int col_bad[4] = {1, 1, 2, 3}, row_out[3] = {0, 3, 2}, row_dup[3] = {0, 0, 2};
  const int col_dup[4] = {0, 2, 2, 3};
  CHECK(fc(1, 3, col_bad, kRowI, kValI, qc, mu, "auto") == 2);
  CHECK(message(info).find("col_ptr[0] must be 0") != std::string::npos);
  CHECK(fc(1, 3, kColI, row_out, kValI, qc, mu, "auto") == 2);
  CHECK(message(info).find("row_index[1] = 3 is outside 0..2") != std::string::npos);
  CHECK(fc(1, 3, col_dup, row_dup, kValI, qc, mu, "auto") == 2);
  CHECK(message(info).find("row_index must increase within each column") != std::string::npos);
  CHECK(fc(1, 2, kColI, kRowI, kValI, qc, mu, "auto") == 2);  // col_ptr runs past nnz
  CHECK(fc(1, 3, kColI, kRowI, kValI, qc, mu_neg, "auto") == 2);
  CHECK(message(info).find("mu[0] must be a finite number >= 0") != std::string::npos);
  const double qc_nan[3] = {-1, kNaN, 0};
  CHECK(fc(1, 3, kColI, kRowI, kValI, qc_nan, mu, "auto") == 2);
  CHECK(message(info) == "cpkit: bad input: q has a non-finite entry (NaN or Inf) at index 1");
  CHECK(fc(1, 3, kColI, kRowI, kValI, qc, mu, "fb-newton") == 2);  // an LCP-only solver
  CHECK(message(info).find("unknown friction solver 'fb-newton' (valid: ") != std::string::npos);
  CHECK(cpkit_fc3d_errors(1, 3, kColI, kRowI, kValI, qc, mu, nullptr, nullptr, nullptr, nullptr,
                          &info) == 2);
  CHECK(message(info) == "cpkit: bad input: r is NULL");

  // Batches: count < 0, a bad problem named by its index, nothing written.
  CHECK(cpkit_lcp_solve_batch(-1, 2, M, q, "auto", nullptr, z, w, nullptr, &info) == 2);
  CHECK(cpkit_lcp_solve_batch(0, 2, nullptr, nullptr, "auto", nullptr, nullptr, nullptr, nullptr,
                              &info) == 0);  // nothing to do
  CHECK(cpkit_fc3d_solve_batch(1, 0, kValI, qc, mu, "auto", nullptr, r, u, nullptr, &info) == 2);

  // Files and JSON.
  cpkit_fc3d_problem p;
  CHECK(cpkit_fc3d_read("/nonexistent/problem.hdf5", &p, &info) == 2);
  CHECK(message(info).find("/nonexistent/problem.hdf5") != std::string::npos);
  CHECK(p.col_ptr == nullptr);
  CHECK(cpkit_fc3d_read(nullptr, &p, &info) == 2);
  CHECK(message(info) == "cpkit: bad input: path is NULL");
  char* json = reinterpret_cast<char*>(1);
  CHECK(cpkit_system_rate("{", 0, nullptr, nullptr, 0, &json, &info) == 2);
  CHECK(json == nullptr);
  CHECK(message(info).find("system_json") != std::string::npos);
  CHECK(cpkit_system_step(nullptr, 0, nullptr, &json, &info) == 2);
  CHECK(message(info) == "cpkit: bad input: system_json is NULL");
  cpkit_free(nullptr);
  cpkit_fc3d_problem_free(nullptr);
}

TEST_CASE("C API: batched LCPs equal one-by-one calls and the chosen solutions", "[capi]") {
  std::mt19937 g(7);
  for (int n : {2, 4, 6}) {  // the closed enumeration (n <= 4) and the registered solver (6)
    const int count = 200;
    std::vector<double> M, q, zs;
    for (int k = 0; k < count; ++k) {
      const Constructed c = constructed_lcp(n, g);
      M.insert(M.end(), c.M.begin(), c.M.end());
      q.insert(q.end(), c.q.begin(), c.q.end());
      zs.insert(zs.end(), c.z.begin(), c.z.end());
    }
    std::vector<double> z(count * n), w(count * n);
    std::vector<int> status(count, -1);
    cpkit_info info;
    REQUIRE(cpkit_lcp_solve_batch(count, n, M.data(), q.data(), "lemke", nullptr, z.data(),
                                  w.data(), status.data(), &info) == 0);
    CHECK(info.residual <= 1e-10);
    for (int k = 0; k < count; ++k) {
      REQUIRE(status[k] == 0);
      double z1[6], w1[6];
      REQUIRE(cpkit_lcp_solve(n, &M[k * n * n], &q[k * n], "lemke", nullptr, z1, w1, nullptr) == 0);
      for (int i = 0; i < n; ++i) {
        REQUIRE(z[k * n + i] == z1[i]);  // the same route, bit for bit
        REQUIRE(w[k * n + i] == w1[i]);
        REQUIRE(z[k * n + i] == Approx(zs[k * n + i]).margin(1e-10));
      }
    }
    // One NaN in problem 7: status 2 naming it, no answer written.
    q[7 * n + 1] = kNaN;
    std::fill(z.begin(), z.end(), 5.0);
    CHECK(cpkit_lcp_solve_batch(count, n, M.data(), q.data(), "lemke", nullptr, z.data(), w.data(),
                                status.data(), &info) == 2);
    CHECK(message(info) ==
          "cpkit: bad input: q of problem 7 has a non-finite entry (NaN or Inf) at index 1");
    CHECK(z[0] == 5.0);
  }
  // A problem without a solution in a batch: its code, the first one's message.
  const double M2[2] = {1, -1}, q2[2] = {-1, -1};  // z = 1 solves the first; the second: none
  double z2[2], w2[2];
  int st[2];
  cpkit_info info;
  CHECK(cpkit_lcp_solve_batch(2, 1, M2, q2, "lemke", nullptr, z2, w2, st, &info) == 1);
  CHECK(st[0] == 0);
  CHECK(st[1] == 1);
  CHECK(z2[0] == Approx(1));
  CHECK(message(info).rfind("problem 1: cpkit: ", 0) == 0);
}

TEST_CASE("C API: batched contacts equal one-by-one calls and the chosen answers", "[capi]") {
  std::mt19937 g(11);
  const int count = 300;
  std::vector<double> W, q, mu, rs;
  for (int k = 0; k < count; ++k) {
    const ConstructedContact c = constructed_contact(g);
    W.insert(W.end(), c.W, c.W + 9);
    q.insert(q.end(), c.q, c.q + 3);
    mu.push_back(c.mu);
    rs.insert(rs.end(), c.r, c.r + 3);
  }
  for (const char* solver : {"auto", "nsgs", "fb-soc"}) {
    CAPTURE(solver);
    std::vector<double> r(count * 3), u(count * 3);
    std::vector<int> status(count, -1);
    REQUIRE(cpkit_fc3d_solve_batch(count, 1, W.data(), q.data(), mu.data(), solver, nullptr,
                                   r.data(), u.data(), status.data(), nullptr) == 0);
    for (int k = 0; k < count; ++k) {
      REQUIRE(status[k] == 0);
      // The same problem one by one, W in CSC (the diagonal).
      const double val[3] = {W[k * 9], W[k * 9 + 4], W[k * 9 + 8]};
      double r1[3], u1[3];
      REQUIRE(cpkit_fc3d_solve(1, 3, kColI, kRowI, val, &q[k * 3], &mu[k], solver, nullptr, r1, u1,
                               nullptr) == 0);
      for (int i = 0; i < 3; ++i) {
        REQUIRE(r[k * 3 + i] == Approx(r1[i]).margin(1e-13));
        REQUIRE(r[k * 3 + i] == Approx(rs[k * 3 + i]).margin(1e-9));
      }
    }
  }
  // Two contacts per problem (the registered solver's route): both hand cases of W = I.
  double W2[36] = {0};
  for (int i = 0; i < 6; ++i) W2[i * 6 + i] = 1;
  const double q2[6] = {-1, 0.2, 0, -1, 1, 0}, mu2[2] = {0.5, 0.5};
  const double expect[6] = {1, -0.2, 0, 1, -0.5, 0};
  double r2[6], u2[6];
  REQUIRE(cpkit_fc3d_solve_batch(1, 2, W2, q2, mu2, "auto", nullptr, r2, u2, nullptr, nullptr) == 0);
  for (int i = 0; i < 6; ++i) CHECK(r2[i] == Approx(expect[i]).margin(1e-9));
}

TEST_CASE("C API: many threads solving at once get their own answers", "[capi]") {
  const int threads = 6, per_thread = 300;
  std::vector<int> wrong(threads, 0), done(threads, 0);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([t, &wrong, &done] {
      std::mt19937 g(1000 + t);
      for (int k = 0; k < per_thread; ++k) {
        const int n = 1 + (k + t) % 6;
        const Constructed c = constructed_lcp(n, g);
        double z[6], w[6];
        cpkit_info info;
        const char* solver = k % 3 == 0 ? "fb-newton" : k % 3 == 1 ? "lemke" : "auto";
        bool ok = cpkit_lcp_solve(n, c.M.data(), c.q.data(), solver, nullptr, z, w, &info) == 0;
        for (int i = 0; ok && i < n; ++i) ok = std::abs(z[i] - c.z[i]) <= 1e-9;
        const ConstructedContact cc = constructed_contact(g);
        const double val[3] = {cc.W[0], cc.W[4], cc.W[8]};
        double r[3], u[3];
        ok = ok && cpkit_fc3d_solve(1, 3, kColI, kRowI, val, cc.q, &cc.mu,
                                    k % 2 ? "nsgs" : "fb-soc", nullptr, r, u, &info) == 0;
        for (int i = 0; ok && i < 3; ++i) ok = std::abs(r[i] - cc.r[i]) <= 1e-9;
        // a bad call in the middle leaves the thread's next answers intact
        if (k % 50 == 0) ok = ok && cpkit_lcp_solve(n, c.M.data(), c.q.data(), "xyz", nullptr, z,
                                                    w, &info) == 2;
        wrong[t] += ok ? 0 : 1;
        ++done[t];
      }
    });
  for (auto& th : pool) th.join();
  for (int t = 0; t < threads; ++t) {
    CHECK(done[t] == per_thread);
    CHECK(wrong[t] == 0);
  }
}

TEST_CASE("C API: reading a Siconos file (library-allocated and caller-owned)", "[capi]") {
  // FrictionContact3D_1c.dat, read by eye: one contact, W = [[15, -1, -2], [-1, 14, 1],
  // [-2, 1, 16]] (symmetric: columns = rows), q = (-1, 2, 3), mu = 0.1.
  const std::string path = std::string(CPKIT_TEST_DATA_DIR) + "/fclib/local/FrictionContact3D_1c.dat";
  const double W[9] = {15, -1, -2, -1, 14, 1, -2, 1, 16}, q[3] = {-1, 2, 3};
  cpkit_fc3d_problem p;
  cpkit_info info;
  REQUIRE(cpkit_fc3d_read(path.c_str(), &p, &info) == 0);
  REQUIRE(p.contacts == 1);
  REQUIRE(p.nnz == 9);
  for (int j = 0; j < 3; ++j) {
    CHECK(p.col_ptr[j] == 3 * j);
    for (int k = 0; k < 3; ++k) {
      CHECK(p.row_index[3 * j + k] == k);
      CHECK(p.values[3 * j + k] == W[3 * j + k]);
    }
    CHECK(p.q[j] == q[j]);
  }
  CHECK(p.col_ptr[3] == 9);
  CHECK(p.mu[0] == 0.1);
  // Solved through the C API, then judged by the verdict.
  double r[3], u[3];
  REQUIRE(cpkit_fc3d_solve(p.contacts, p.nnz, p.col_ptr, p.row_index, p.values, p.q, p.mu, "auto",
                           nullptr, r, u, &info) == 0);
  CHECK(cpkit_fc3d_errors(p.contacts, p.nnz, p.col_ptr, p.row_index, p.values, p.q, p.mu, r,
                          nullptr, nullptr, nullptr, nullptr) == 0);
  cpkit_fc3d_problem_free(&p);
  CHECK(p.values == nullptr);

  int contacts = 0, nnz = 0;
  REQUIRE(cpkit_fc3d_read_sizes(path.c_str(), &contacts, &nnz, &info) == 0);
  CHECK(contacts == 1);
  CHECK(nnz == 9);
  std::vector<int> col(3 * contacts + 1), row(nnz);
  std::vector<double> val(nnz), qq(3 * contacts), mu(contacts);
  REQUIRE(cpkit_fc3d_read_into(path.c_str(), contacts, nnz, col.data(), row.data(), val.data(),
                               qq.data(), mu.data(), &info) == 0);
  for (int k = 0; k < 9; ++k) CHECK(val[k] == W[k]);
  CHECK(cpkit_fc3d_read_into(path.c_str(), contacts, 8, col.data(), row.data(), val.data(),
                             qq.data(), mu.data(), &info) == 2);
  CHECK(message(info).find("has 1 contact and 9 stored entries") != std::string::npos);
}

TEST_CASE("C API: a system's rate problem and step as JSON", "[capi]") {
  const std::string path = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/two_point_system.json";
  const std::string text = read_text(path);
  REQUIRE(!text.empty());
  char* json = nullptr;
  cpkit_info info;
  // The rate problem with the file's dF: the C API carries the library's request unchanged, so
  // its answer is what run_rate_request gives for the file itself (`cpkit rate --system FILE`).
  const int code = cpkit_system_rate(text.c_str(), 0, nullptr, nullptr, 0, &json, &info);
  cpkit::rate::RateRequest request;
  request.system = path;
  const cpkit::rate::RateOutcome direct = cpkit::rate::run_rate_request(request);
  REQUIRE(json != nullptr);
  CHECK(code == static_cast<int>(direct.exit_code));
  nlohmann::json from_c = nlohmann::json::parse(json);
  nlohmann::json from_cpp = cpkit::rate::rate_outcome_json(direct, "0");
  for (auto* j : {&from_c, &from_cpp}) {  // names and timings differ
    (*j)["input"].erase("system");
    j->erase("seconds");
  }
  CHECK(from_c["solutions"] == from_cpp["solutions"]);
  CHECK(from_c["count"] == from_cpp["count"]);
  CHECK(from_c["count"].get<int>() >= 1);
  cpkit_free(json);
  // The step with the file's dF given explicitly: 2N numbers; 2N - 1 is bad input.
  const double dF[4] = {1.0, -1.0, 0.5, 1.0};
  json = nullptr;
  CHECK(cpkit_system_step(text.c_str(), 4, dF, &json, &info) == 0);
  REQUIRE(json != nullptr);
  const nlohmann::json step = nlohmann::json::parse(json);
  CHECK(step.contains("solutions"));
  CHECK(step["count"] != 0);
  cpkit_free(json);
  CHECK(cpkit_system_step(text.c_str(), 3, dF, &json, &info) == 2);
  CHECK(message(info).find("--dF") != std::string::npos);
  // Coupled 3-D points: the rate problem needs the faceted route (facets = K), as on the
  // command line; without it, bad input saying so.
  const std::string text_3d =
      read_text(std::string(CPKIT_SOURCE_DIR) + "/docs/examples/two_point_system_3d.json");
  CHECK(cpkit_system_rate(text_3d.c_str(), 0, nullptr, nullptr, 0, &json, &info) == 2);
  CHECK(message(info).find("--facets K") != std::string::npos);
  const int code_3d = cpkit_system_rate(text_3d.c_str(), 0, nullptr, nullptr, 16, &json, &info);
  CHECK(code_3d != 2);
  REQUIRE(json != nullptr);
  CHECK(nlohmann::json::parse(json)["input"]["facets"] == 16);
  cpkit_free(json);
}

namespace {

/// Every solution of a small LCP by brute force over the 2^n complementary bases
/// (z_S = -M_SS^{-1} q_S, z = 0 off S, checked z >= 0 and w >= 0 within 1e-9 of the data's
/// size); `unique` is false when two bases give different points or a basis is singular.
struct BruteForce {
  int count = 0;
  bool singular = false;
  Eigen::VectorXd z;
};
BruteForce brute_force(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
  const int n = static_cast<int>(q.size());
  BruteForce b;
  const double scale = q.lpNorm<Eigen::Infinity>() + M.lpNorm<Eigen::Infinity>();
  for (unsigned S = 0; S < (1u << n); ++S) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i)
      if (S >> i & 1u) idx.push_back(i);
    const int k = static_cast<int>(idx.size());
    Eigen::MatrixXd A(k, k);
    Eigen::VectorXd rhs(k);
    for (int a = 0; a < k; ++a) {
      rhs[a] = -q[idx[a]];
      for (int c = 0; c < k; ++c) A(a, c) = M(idx[a], idx[c]);
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    if (k > 0) {
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
      if (!lu.isInvertible() || std::abs(lu.determinant()) < 1e-10 * std::pow(scale, k)) {
        b.singular = true;
        continue;
      }
      const Eigen::VectorXd x = lu.solve(rhs);
      for (int a = 0; a < k; ++a) z[idx[a]] = x[a];
    }
    const Eigen::VectorXd w = M * z + q;
    const double size = 1e-9 * (1 + scale * (1 + z.lpNorm<Eigen::Infinity>()));
    if (z.minCoeff() < -size || w.minCoeff() < -size) continue;
    if (b.count > 0 && (z - b.z).lpNorm<Eigen::Infinity>() <= size) continue;  // the same point
    ++b.count;
    b.z = z;
  }
  return b;
}

}  // namespace

TEST_CASE("C API: tiny LCPs on the per-call path equal the registered solver and brute force",
          "[capi]") {
  // n = 1..4 with "lemke" and "auto" take the allocation-free path when the enumeration proves
  // one solution. Problems: positive definite M (one solution) and general M with q made from a
  // chosen complementary pair (z*, w*) (a solution exists; there may be several), at mixed
  // scales. Oracles: the brute force above (the answer, when it finds exactly one point and no
  // singular basis) and the registered "auto" chain through finalize() (the general route: its
  // status, and its point where the solution is unique); the reported residual and w are
  // finalize()'s numbers on the returned z.
  std::mt19937 g(4837);
  std::normal_distribution<double> gauss;
  std::uniform_int_distribution<int> scale(-8, 8);
  const cpkit::SolverEntry& automatic = *cpkit::lcp::solvers().find("auto");
  int unique = 0, compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 1 + trial % 4;
    Eigen::MatrixXd M(n, n);
    Eigen::VectorXd q(n), zs = Eigen::VectorXd::Zero(n), ws = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) {
      (g() % 2 ? zs[i] : ws[i]) = std::abs(gauss(g));
      for (int j = 0; j < n; ++j) M(i, j) = gauss(g);
    }
    if (trial % 3 != 0) M = M * M.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);  // PD
    q = ws - M * zs;
    const double s = std::ldexp(1.0, scale(g));  // units: (M, q) -> s (M, q) changes nothing
    M *= s;
    q *= s * std::ldexp(1.0, scale(g));
    CAPTURE(trial, n);
    const cpkit::LcpProblem p(M, q);
    const cpkit::SolveResult general = automatic.solve_lcp(p, cpkit::CommonOptions{});
    REQUIRE(cpkit::is_solution(general.status));  // a solution exists by construction
    const BruteForce b = brute_force(M, q);
    for (const char* solver : {"lemke", "auto"}) {
      CAPTURE(solver);
      std::vector<double> z(n), w(n);
      cpkit_info info;
      const int code = cpkit_lcp_solve(n, M.data(), q.data(), solver, nullptr, z.data(), w.data(),
                                       &info);
      if (b.count == 1 && !b.singular) {  // the unique solution: every route must find it
        REQUIRE(code == 0);
        for (int i = 0; i < n; ++i) {
          const double tol = 1e-8 * b.z.lpNorm<Eigen::Infinity>();
          REQUIRE(std::abs(z[i] - b.z[i]) <= tol);
          REQUIRE(std::abs(general.z[i] - b.z[i]) <= tol);
        }
        ++unique;
      }
      if (code == 0) {  // the verdict on the returned point is finalize()'s, number included
        const Eigen::VectorXd zv = Eigen::Map<Eigen::VectorXd>(z.data(), n);
        Eigen::VectorXd wv;
        const cpkit::Residuals res = cpkit::lcp_residuals(p, zv, wv);
        REQUIRE(res.natural <= cpkit::CommonOptions{}.tol_acceptable);
        REQUIRE(info.residual == res.natural);
        for (int i = 0; i < n; ++i) REQUIRE(w[i] == wv[i]);
      } else {
        REQUIRE(std::strcmp(solver, "lemke") == 0);  // Lemke may miss a non-monotone problem
      }
      ++compared;
    }
  }
  CHECK(compared == 800);
  CHECK(unique >= 500);
}

TEST_CASE("C API: one contact on the per-call path equals the registered NSGS and the closed form",
          "[capi]") {
  // Decoupled isotropic contacts W = diag(a, c, c) (the projection by hand: r_N =
  // max(0, -q_N / a), r_T = -q_T / c projected onto |r_T| <= mu r_N) and coupled ones
  // (W = J J^T, the solution checked against the registered NSGS where both are unique by the
  // closed form of lcp::friction::one_contact_solutions). The reported residual is the
  // friction verdict's number on the returned r.
  std::mt19937 g(2037);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> pos(0.2, 3);
  std::uniform_int_distribution<int> scale(-6, 6);
  const double mus[] = {0.0, 0.1, 0.5, 2.0};
  const cpkit::SolverEntry& nsgs = *cpkit::lcp::solvers().find("nsgs");
  int by_hand = 0, by_nsgs = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool decoupled = trial % 2 == 0;
    cpkit::Mat3 W;
    if (decoupled) {
      W = cpkit::Vec3(pos(g), 0, 0).asDiagonal();
      W(1, 1) = W(2, 2) = pos(g);
    } else {
      cpkit::Mat3 J;
      for (int i = 0; i < 9; ++i) J.data()[i] = gauss(g);
      W = J * J.transpose() + 0.05 * cpkit::Mat3::Identity();
    }
    const double s = std::ldexp(1.0, scale(g));
    W *= s;
    const cpkit::Vec3 q = s * std::ldexp(1.0, scale(g)) * cpkit::Vec3(gauss(g), gauss(g), gauss(g));
    const double mu = mus[trial % 4];
    const int col[4] = {0, 3, 6, 9}, row[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
    double r[3], u[3];
    cpkit_info info;
    CAPTURE(trial, decoupled, mu);
    const int code =
        cpkit_fc3d_solve(1, 9, col, row, W.data(), q.data(), &mu, "auto", nullptr, r, u, &info);
    cpkit::FrictionContactProblem p;
    Eigen::MatrixXd Wd = W;
    p.W = Wd.sparseView(1.0, -1.0);  // all 9 entries stored, as given to the C API
    p.q = q;
    p.mu = Eigen::VectorXd::Constant(1, mu);
    const Eigen::Map<const cpkit::Vec3> rv(r);
    if (code == 0) {
      const cpkit::FrictionErrors e = cpkit::friction_errors(p, rv);
      REQUIRE(e.unit_free <= cpkit::CommonOptions{}.tol_acceptable);
      REQUIRE(info.residual == e.unit_free);
    }
    const double size = 1e-9 * std::max(rv.norm(), q.norm() / W.cwiseAbs().maxCoeff());
    if (decoupled) {  // unique: the projection by hand
      REQUIRE(code == 0);
      cpkit::Vec3 hand(q[0] < 0 ? -q[0] / W(0, 0) : 0, -q[1] / W(1, 1), -q[2] / W(1, 1));
      if (hand[0] == 0) hand.setZero();
      const double t = hand.tail<2>().norm();
      if (t > mu * hand[0]) hand.tail<2>() *= mu * hand[0] / t;
      REQUIRE((rv - hand).norm() <= size);
      ++by_hand;
      continue;
    }
    const auto all = cpkit::lcp::friction::one_contact_solutions(W, q, mu);
    if (all.count != 1) continue;
    const cpkit::SolveResult general = nsgs.solve_fc(p, cpkit::CommonOptions{});
    if (!cpkit::is_solution(general.status)) continue;
    REQUIRE(code == 0);
    REQUIRE((rv - all.r[0]).norm() <= size);
    REQUIRE((general.z - rv).norm() <= 1e-6 * std::max(rv.norm(), size));
    ++by_nsgs;
  }
  CHECK(by_hand == 200);
  CHECK(by_nsgs >= 120);
}

TEST_CASE("C API: one contact with several solutions: one of them, and nsgs' from r = 0",
          "[capi]") {
  // Non-symmetric W (J J^T + 0.05 I + 0.3 J), where a contact may have several solutions: the
  // per-call path's answer must be one of the closed form's solutions (one_contact_solutions,
  // checked against a brute-force search in tests/lcp/test_friction_one_contact.cpp), accepted
  // by the verdict, and the answer of the registered nsgs from r = 0 (whose first local step is
  // the same local solve).
  std::mt19937 g(5837);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> mus(0.05, 2);
  const cpkit::SolverEntry& nsgs = *cpkit::lcp::solvers().find("nsgs");
  int several = 0;
  for (int trial = 0; trial < 4000 && several < 20; ++trial) {
    cpkit::Mat3 J;
    for (int i = 0; i < 9; ++i) J.data()[i] = gauss(g);
    const cpkit::Mat3 W = J * J.transpose() + 0.05 * cpkit::Mat3::Identity() + 0.3 * J;
    const cpkit::Vec3 q(gauss(g), gauss(g), gauss(g));
    const double mu = mus(g);
    const auto all = cpkit::lcp::friction::one_contact_solutions(W, q, mu);
    if (all.count < 2) continue;
    ++several;
    CAPTURE(trial, W, q, mu);
    const int col[4] = {0, 3, 6, 9}, row[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
    double r[3], u[3];
    REQUIRE(cpkit_fc3d_solve(1, 9, col, row, W.data(), q.data(), &mu, "auto", nullptr, r, u,
                             nullptr) == 0);
    const Eigen::Map<const cpkit::Vec3> rv(r);
    bool among = false;
    for (int k = 0; k < all.count; ++k)
      among = among || (all.r[k] - rv).norm() <= 1e-7 * (1 + rv.norm());
    REQUIRE(among);
    cpkit::FrictionContactProblem p;
    p.W = Eigen::MatrixXd(W).sparseView(1.0, -1.0);
    p.q = q;
    p.mu = Eigen::VectorXd::Constant(1, mu);
    REQUIRE(cpkit::friction_errors(p, rv).unit_free <= cpkit::CommonOptions{}.tol);
    const cpkit::SolveResult general = nsgs.solve_fc(p, cpkit::CommonOptions{});
    REQUIRE(cpkit::is_solution(general.status));
    REQUIRE((general.z - rv).norm() <= 1e-9 * (1 + rv.norm()));
  }
  CHECK(several == 20);
}

TEST_CASE("C API: tiny LCPs by hand through the P-matrix route and past it", "[capi]") {
  double z[2], w[2];
  cpkit_info info;
  // M = [[1, -3], [0, 1]]: principal minors 1, 1 and 1 (a P-matrix, though not positive
  // definite: its symmetric part has eigenvalues 1 +- 1.5). q = (-1, -1): w = 0 gives z_1 = 1,
  // z_0 = 1 + 3 z_1 = 4, the only solution.
  const double M[4] = {1, 0, -3, 1}, q[2] = {-1, -1};
  REQUIRE(cpkit_lcp_solve(2, M, q, "auto", nullptr, z, w, &info) == 0);
  CHECK(z[0] == 4.0);
  CHECK(z[1] == 1.0);
  CHECK(w[0] == 0.0);
  CHECK(w[1] == 0.0);
  // q = (5, -1): the guess basis {1} gives z = (0, 1), w_0 = 5 - 3 = 2 >= 0: z = (0, 1).
  const double q2[2] = {5, -1};
  REQUIRE(cpkit_lcp_solve(2, M, q2, "lemke", nullptr, z, w, &info) == 0);
  CHECK(z[0] == 0.0);
  CHECK(z[1] == 1.0);
  CHECK(w[0] == 2.0);
  // q = (2, -1): the guess {1} gives w_0 = 2 - 3 = -1 < 0; the basis {0, 1}: z_1 = 1,
  // z_0 = -2 + 3 = 1.
  const double q3[2] = {2, -1};
  REQUIRE(cpkit_lcp_solve(2, M, q3, "auto", nullptr, z, w, &info) == 0);
  CHECK(z[0] == 1.0);
  CHECK(z[1] == 1.0);
  // M = [[1, 1], [1, 1]] (singular: not a P-matrix), q = (-1, -1): every z >= 0 with
  // z_0 + z_1 = 1 solves it; the enumeration finds a continuum and the general route answers.
  const double S[4] = {1, 1, 1, 1};
  REQUIRE(cpkit_lcp_solve(2, S, q, "auto", nullptr, z, w, &info) == 0);
  CHECK(z[0] + z[1] == Approx(1.0).epsilon(1e-12));
  CHECK(std::min(z[0], z[1]) >= 0.0);
  CHECK(std::abs(w[0]) <= 1e-12);
}
