// Routes 1 (analytic) and 2 (LCP + enumeration) of the rate problem agree on every input, and
// both agree with a brute force over the solution types written here; every reported solution
// satisfies the rate laws (checked by rate_test_util.hpp, independent of the library). Route 3
// (single LCP solvers) lands inside the set.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "rate_problem/rate_test_util.hpp"

using namespace cpkit::rate;
using cpkit::rate::test::brute_force_types;
using cpkit::rate::test::check_set_laws;
using cpkit::rate::test::compare_sets;

namespace {

struct Case {
  ContactParameters p;
  ContactState st;
  LoadRate f;
};

/// Random SPD A, mu, C_T, wear, state and load direction. `limit`: 0 general, 1 C_T = 0
/// (Lambda_A), 2 k_a = 0 (Lambda_C), 3 tiny C_T, 4 tiny k_a.
Case random_case(std::mt19937_64& rng, StateLabel label, int limit, bool softening = false) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Case c;
  c.p.a11 = 0.1 + 3 * U(rng);
  c.p.a22 = 0.1 + 3 * U(rng);
  c.p.a12 = (2 * U(rng) - 1) * 0.97 * std::sqrt(c.p.a11 * c.p.a22);
  c.p.mu = 0.05 + 2 * U(rng);
  c.p.C_T = U(rng) < 0.2 ? 0.0 : 2 * U(rng);
  c.p.k_a = U(rng) < 0.2 ? 0.0 : U(rng);
  c.p.P_s = 0.5 + 1.5 * U(rng);
  if (limit == 1) c.p.C_T = 0;
  if (limit == 2) c.p.k_a = 0;
  if (limit == 3) c.p.C_T = 1e-9 * U(rng);
  if (limit == 4) c.p.k_a = 1e-9 * U(rng);
  c.p.criterion = softening ? Criterion::kSoftening : Criterion::kCoulomb;
  c.st.label = label;
  c.st.sgn_PT = U(rng) < 0.5 ? 1 : -1;
  c.st.P_N = 0;
  if (label == StateLabel::kC || label == StateLabel::kD) {
    c.st.P_N = 0.1 + 5 * U(rng);
    if (softening && c.p.k_a > 0) {
      // stay below the bound (46): k P_N < mu
      const double bound = 3 * c.p.P_s * c.p.mu / c.p.k_a;
      c.st.P_N = std::min(c.st.P_N, 0.999 * bound * U(rng) + 1e-3 * bound);
    }
  }
  const double th = 2 * M_PI * U(rng);
  const double r = std::pow(10.0, 4 * U(rng) - 2);
  c.f = LoadRate{r * std::cos(th), r * std::sin(th)};
  return c;
}

std::vector<SolutionType> types_of(const RateSolutionSet& s) {
  std::vector<SolutionType> t;
  for (const auto& x : s.solutions) t.push_back(x.type);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

}  // namespace

TEST_CASE("routes 1 and 2 agree with each other and with brute force on random inputs",
          "[rate][routes][property]") {
  const auto label = GENERATE(StateLabel::kA, StateLabel::kB, StateLabel::kC, StateLabel::kD);
  const int limit = GENERATE(0, 1, 2, 3, 4);
  const bool softening = GENERATE(false, true);
  std::mt19937_64 rng(20261122u + 97u * static_cast<unsigned>(label) + 13u * limit + softening);
  int checked = 0, brute_checked = 0;
  for (int it = 0; it < 1500; ++it) {
    const Case c = random_case(rng, label, limit, softening);
    CAPTURE(it, c.p.a11, c.p.a12, c.p.a22, c.p.mu, c.p.C_T, c.p.k_a, c.p.P_s, c.st.P_N,
            c.st.sgn_PT, c.f.dF_T, c.f.dF_N);
    const RateSolutionSet r1 = solve_rate_problem(c.p, c.st, c.f, RateMethod::kAnalytic);
    const RateSolutionSet r2 = solve_rate_problem(c.p, c.st, c.f, RateMethod::kEnumerate);
    CAPTURE(r2.message);
    REQUIRE(r2.complete);
    const auto sc = cpkit::rate::test::scales(c.p, c.f);
    INFO(compare_sets(r1, r2, sc));
    REQUIRE(compare_sets(r1, r2, sc).empty());
    INFO(check_set_laws(c.p, c.st, c.f, r1));
    REQUIRE(check_set_laws(c.p, c.st, c.f, r1).empty());
    // summaries agree with the full sets
    const RateSummary s1 = summarize_rate_problem(c.p, c.st, c.f, RateMethod::kAnalytic);
    const RateSummary s2 = summarize_rate_problem(c.p, c.st, c.f, RateMethod::kEnumerate);
    REQUIRE(s1.count == r1.count());
    REQUIRE(s2.count == r2.count());
    REQUIRE(s1.types == r1.type_mask());
    REQUIRE(s2.types == r2.type_mask());
    REQUIRE(s2.reliable);
    // the precomputed (per parameter set) summary for maps gives the same answer
    const RatePrecomputed pre = precompute_rate_problem(c.p, c.st);
    const RateSummary s3 = summarize_rate_problem(pre, c.f);
    REQUIRE(s3.count == s2.count);
    REQUIRE(s3.types == s2.types);
    ++checked;
    if (label == StateLabel::kB || label == StateLabel::kD) {
      double margin = 0;
      const auto bt = brute_force_types(c.p, c.st, c.f, margin);
      if (margin > 1e-6 && !r1.infinite) {
        CHECK(bt == types_of(r1));
        REQUIRE(r1.count() == static_cast<int>(bt.size()));
        ++brute_checked;
      }
    }
  }
  CHECK(checked == 1500);
  if (label == StateLabel::kB || label == StateLabel::kD) CHECK(brute_checked > 1400);
}

TEST_CASE("state d LCP built from the rate equations equals [Lambda], [-L_s] (eqn (51))",
          "[rate][lcp]") {
  std::mt19937_64 rng(7);
  for (int it = 0; it < 500; ++it) {
    const Case c = random_case(rng, StateLabel::kD, it % 3, it % 2 == 1);
    const StateDLcp l = state_d_lcp(c.p, c.st, c.f);
    // eqn (51) and L_s typed in again here (mu -> mu - 2 kappa under (35))
    const double s = c.st.sgn_PT, k = c.p.k_a * c.st.P_N / (3 * c.p.P_s);
    const double m = c.p.criterion == Criterion::kSoftening ? c.p.mu - 2 * k : c.p.mu;
    const double det = c.p.a11 * c.p.a22 - c.p.a12 * c.p.a12;
    const double Lambda = c.p.a11 - m * c.p.a12 * s + k * (c.p.a12 * s - m * c.p.a22) -
                          m * c.p.C_T * k * det;
    const double Ls = (s + m * c.p.a12 * c.p.C_T) * c.f.dF_T - m * (1 + c.p.a11 * c.p.C_T) * c.f.dF_N;
    const double mag = c.p.a11 + c.p.a22 + 1;
    CHECK(l.M == Approx(Lambda).margin(1e-12 * mag * (1 + c.p.C_T) * (1 + k)));
    CHECK(l.q == Approx(-Ls).margin(1e-12 * (std::abs(c.f.dF_T) + std::abs(c.f.dF_N)) * mag * (1 + c.p.C_T) * (1 + m)));
    const RateIndicators ind = rate_indicators(c.p, c.st);
    CHECK(ind.Lambda == Approx(Lambda).margin(1e-12 * mag * (1 + c.p.C_T) * (1 + k)));
  }
}

TEST_CASE("limits C_T -> 0 and k_a -> 0 give the paper's Lambda_A and Lambda_C", "[rate][limits]") {
  // Lambda_C = a11 - mu a12 sgn P_T (k_a -> 0), Lambda_A = Lambda_C + kappa (a12 s - mu a22)
  // (C_T -> 0) [Stromberg et al. 1996, Sec. 4.3 d].
  ContactParameters p;
  p.a11 = 2;
  p.a12 = 0.7;
  p.a22 = 1.5;
  p.mu = 0.9;
  p.P_s = 2;
  ContactState st{StateLabel::kD, 3.0, -1};
  for (double eps : {1e-2, 1e-4, 1e-8, 0.0}) {
    p.C_T = 0.5;
    p.k_a = eps;
    const double lc = 2 - 0.9 * 0.7 * -1;  // 2.63
    CHECK(rate_indicators(p, st).Lambda == Approx(lc).margin(10 * eps + 1e-15));
    p.C_T = eps;
    p.k_a = 0.4;
    const double kappa = 0.4 * 3.0 / (3 * 2.0);  // 0.2
    const double la = lc + kappa * (0.7 * -1 - 0.9 * 1.5);  // 2.63 - 0.41 = 2.22
    CHECK(rate_indicators(p, st).Lambda == Approx(la).margin(10 * eps + 1e-15));
  }
  // the solution sets converge too: compare the C_T = 1e-10 set with the C_T = 0 set
  std::mt19937_64 rng(99);
  for (int it = 0; it < 300; ++it) {
    Case c = random_case(rng, it % 2 ? StateLabel::kB : StateLabel::kD, 1);
    const RateSolutionSet a = solve_rate_problem(c.p, c.st, c.f, RateMethod::kEnumerate);
    c.p.C_T = 1e-11;
    const RateSolutionSet b = solve_rate_problem(c.p, c.st, c.f, RateMethod::kEnumerate);
    CAPTURE(it);
    CHECK(compare_sets(a, b, cpkit::rate::test::scales(c.p, c.f), 1e-6).empty());
  }
}

TEST_CASE("route 3: every registered single solver lands inside the set", "[rate][route3]") {
  const auto& reg = cpkit::lcp::solvers();
  std::vector<std::string> names;
  for (const char* n : {"lemke", "fb-newton", "ipopt"})
    if (reg.find(n) != nullptr) names.push_back(n);
  REQUIRE(!names.empty());  // lemke at least
  std::mt19937_64 rng(31337);
  for (const auto& name : names) {
    CAPTURE(name);
    const int n = name == "ipopt" ? 6 : 300;
    int solved = 0;
    for (int it = 0; it < n; ++it) {
      const Case c = random_case(rng, it % 2 ? StateLabel::kB : StateLabel::kD, 0);
      CAPTURE(it);
      const RateSolutionSet all = solve_rate_problem(c.p, c.st, c.f, RateMethod::kAnalytic);
      const RateSolutionSet one = solve_rate_single(c.p, c.st, c.f, name);
      CHECK_FALSE(one.complete);
      REQUIRE(one.solutions.size() <= 1);
      if (one.solutions.empty()) {
        // Lemke may end on a ray when the set is empty or M is not copositive-plus; a solver
        // may fail: but never claim a solution where there is none.
        continue;
      }
      ++solved;
      const Rates& r = one.solutions.front().start;
      const double tol = std::max(1e-6, 1e3 * one.residual);  // solved_inaccurate: <= 1e-6
      const int k = find_piece(all, r, tol);
      INFO(check_set_laws(c.p, c.st, c.f, one));
      CHECK(check_set_laws(c.p, c.st, c.f, one, tol).empty());
      REQUIRE(k >= 0);
      CHECK(all.solutions[k].type == one.solutions.front().type);
    }
    CHECK(solved > n / 2);
  }
}

TEST_CASE("route 3: an unregistered solver is a clear InputError", "[rate][route3]") {
  ContactParameters p;
  ContactState st{StateLabel::kB, 0, 1};
  CHECK_THROWS_WITH(solve_rate_single(p, st, LoadRate{1, 1}, "no-such-solver"),
                    Catch::Contains("not registered"));
}

TEST_CASE("routes 1 and 2 agree on the degenerate lines (a11 = mu|a12|, Lambda = 0)",
          "[rate][routes][degenerate]") {
  std::mt19937_64 rng(1996);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int infinite = 0;
  for (int it = 0; it < 2000; ++it) {
    // A with a11 = mu |a12| exactly: dyadic data with few bits (multiples of 1/16), so that
    // D_s = a11 - s mu a12, N and L_s below are computed without rounding and are exact zeros
    // of the data (a rounded product mu |a12| would make D_s a nonzero number of the size of
    // its rounding, which the analytic route rightly leaves undecided)
    const auto q16 = [](double x) { return std::round(16 * x) / 16; };
    ContactParameters p;
    const int sg = U(rng) < 0.5 ? 1 : -1;
    p.mu = q16(0.25 + 2 * U(rng));
    p.a12 = sg * q16(0.25 + 2 * U(rng));
    p.a11 = p.mu * std::abs(p.a12);
    p.a22 = (p.a12 * p.a12 / p.a11) * (1.05 + 2 * U(rng));
    p.C_T = it % 3 == 0 ? 0.0 : q16(U(rng));
    ContactState st{StateLabel::kB, 0, 1};
    if (it % 2 == 1) {  // state d without wear: Lambda = a11 - s mu a12 = 0 for s = sgn a12
      st = ContactState{StateLabel::kD, 0.5 + U(rng), sg};
    }
    // loads: on the critical line (N = 0 in b, L_s = 0 in d), both senses, or random
    const double t = (U(rng) < 0.5 ? -1 : 1) * std::ldexp(1.0, static_cast<int>(4 * U(rng)) - 2);
    LoadRate f;
    const int pick = it % 4;
    const double c1 = 1 + p.a11 * p.C_T;
    if (st.label == StateLabel::kB) {
      f = pick < 3 ? LoadRate{t * p.a11, t * p.a12} : LoadRate{t, U(rng) - 0.5};  // N = 0
    } else {
      // L_s = (s + mu a12 C_T) dF_T - mu c1 dF_N = 0
      f = pick < 3 ? LoadRate{t * p.mu * c1, t * (sg + p.mu * p.a12 * p.C_T)}
                   : LoadRate{t, U(rng) - 0.5};
    }
    CAPTURE(it, p.a11, p.a12, p.a22, p.mu, p.C_T, st.P_N, st.sgn_PT, f.dF_T, f.dF_N);
    const RateSolutionSet r1 = solve_rate_problem(p, st, f, RateMethod::kAnalytic);
    const RateSolutionSet r2 = solve_rate_problem(p, st, f, RateMethod::kEnumerate);
    CAPTURE(r2.message);
    // b: always a solution; d with Lambda = 0 on L_s = 0: stick + ray
    if (st.label == StateLabel::kB || pick < 3) CHECK(r1.count() != 0);
    if (st.label == StateLabel::kD && pick < 3) CHECK(r1.count() == -1);
    const auto sc = cpkit::rate::test::scales(p, f);
    INFO(compare_sets(r1, r2, sc, 1e-6));
    REQUIRE(compare_sets(r1, r2, sc, 1e-6).empty());
    INFO(check_set_laws(p, st, f, r1));
    REQUIRE(check_set_laws(p, st, f, r1).empty());
    REQUIRE(summarize_rate_problem(p, st, f, RateMethod::kEnumerate).count == r2.count());
    const RateSummary s3 = summarize_rate_problem(precompute_rate_problem(p, st), f);
    CHECK(s3.count == r2.count());
    CHECK(s3.types == r2.type_mask());
    infinite += r1.infinite;
  }
  CHECK(infinite > 500);  // the segments and rays were actually exercised
}

TEST_CASE("rate problem in any units: A and the load scaled by 1e-12..1e12 (issue 24 item 17)",
          "[rate][routes][units]") {
  // Item 17: state b, A = 1e10 [[1, 0.3], [0.3, 1.2]], mu = 0.5, dF = (1, 0.5). Hand solution
  // (slip+, Dw_N = 0, dP_T = mu dP_N): 1 - P/2 = a11' l, 0.5 - P = a12' l, so dP_N = 4/17,
  // dP_T = 2/17, dw_T^i = 15/17 / 1e10; a11 > mu |a12|, so it is the only solution.
  ContactState st;
  st.label = StateLabel::kB;
  for (double cA : {1e-12, 1e-6, 1.0, 1e3, 1e10, 1e12}) {
    for (double cF : {1e-12, 1.0, 1e12}) {
      CAPTURE(cA, cF);
      ContactParameters p;
      p.a11 = 1 * cA;
      p.a12 = 0.3 * cA;
      p.a22 = 1.2 * cA;
      p.mu = 0.5;
      const LoadRate f{1 * cF, 0.5 * cF};
      for (RateMethod m : {RateMethod::kEnumerate, RateMethod::kAnalytic}) {
        const RateSolutionSet s = solve_rate_problem(p, st, f, m);
        CAPTURE(to_string(m), s.message);
        CHECK(s.complete);
        REQUIRE(s.count() == 1);
        CHECK(s.solutions[0].type == SolutionType::kSlipPlus);
        const Rates& r = s.solutions[0].start;
        CHECK(std::abs(r.dP_N - 4.0 / 17 * cF) <= 1e-13 * cF);
        CHECK(std::abs(r.dP_T - 2.0 / 17 * cF) <= 1e-13 * cF);
        CHECK(std::abs(r.dw_Ti - 15.0 / 17 * cF / cA) <= 1e-13 * cF / cA);
        CHECK(r.dw_N == 0);
      }
    }
  }
}

TEST_CASE("rate problem at the ends of double's range (issue 24 item 5)", "[rate][routes][units]") {
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 0.3;
  p.a22 = 1.2;
  p.mu = 0.5;
  ContactState st;
  st.label = StateLabel::kB;
  // dF = (1.7e308, 1): separation with dw_T = a22 dF_T / det A = 1.84e308: not representable.
  CHECK_THROWS_WITH(solve_rate_problem(p, st, LoadRate{1.7e308, 1}),
                    Catch::Contains("not representable"));
  // dF = (1e308, 1): separation, dw = A^-1 dF (det A = 1.11).
  const RateSolutionSet s = solve_rate_problem(p, st, LoadRate{1e308, 1});
  REQUIRE(s.count() == 1);
  CHECK(s.solutions[0].type == SolutionType::kSeparation);
  CHECK(std::abs(s.solutions[0].start.dw_T / (1.2e308 / 1.11) - 1) <= 1e-14);
  // subnormal dF = 2^-1063 (1, 0.5): the slip+ of the units test, scaled.
  const double t = std::ldexp(1.0, -1063);
  const RateSolutionSet u = solve_rate_problem(p, st, LoadRate{t, 0.5 * t});
  REQUIRE(u.count() == 1);
  CHECK(u.solutions[0].type == SolutionType::kSlipPlus);
  CHECK(std::abs(u.solutions[0].start.dP_N / (4.0 / 17 * t) - 1) <= 1e-3);
}

TEST_CASE("rate problem at cond(A) = 1e12: a slip of 1 beside a separation of 1e11 is a slip",
          "[rate][routes][conditioning]") {
  // Found by a random cond sweep: the enumeration typed the slip+ point "stick" because its type
  // test used a scale grown by the separation vertex (dw_T = 1.3e11), and `cpkit rate` exited 3.
  // Exact rational solution of the doubles (sympy, every active set): separation, stick, and
  // slip+ with dP_N = 0.17522969854464887, dP_T = 0.34385888164409234, dw_T^i = 1.0299381157285108.
  ContactParameters p;
  p.a11 = 0.38194048139952747;
  p.a12 = 0.48586206897353046;
  p.a22 = 0.618059518601419;
  p.mu = 1.962332210235906;
  ContactState st;
  st.label = StateLabel::kB;
  const LoadRate f{0.7372339413771619, 0.6756375623672025};
  for (RateMethod m : {RateMethod::kEnumerate, RateMethod::kAnalytic}) {
    const RateSolutionSet s = solve_rate_problem(p, st, f, m);
    CAPTURE(to_string(m), s.message);
    REQUIRE(s.complete);
    REQUIRE(s.count() == 3);
    CHECK(s.type_mask() == ((1u << static_cast<unsigned>(SolutionType::kSeparation)) |
                            (1u << static_cast<unsigned>(SolutionType::kStick)) |
                            (1u << static_cast<unsigned>(SolutionType::kSlipPlus))));
    for (const auto& x : s.solutions) {
      if (x.type != SolutionType::kSlipPlus) continue;
      CHECK(std::abs(x.start.dP_N - 0.17522969854464887) <= 1e-6);
      CHECK(std::abs(x.start.dw_Ti - 1.0299381157285108) <= 1e-4);
    }
  }
}

TEST_CASE("rate problem over cond(A) 1e2..1e12: the constructed solution, or incomplete",
          "[rate][routes][conditioning]") {
  // Construct-then-check, as for the step (test_step_conditioning.cpp): integer
  // A = [[d1 + k^2 d2, k d2], [k d2, d2]] (det = d1 d2, cond ~ k^4 d2 / d1), a state-b solution
  // chosen first (separation, stick inside the cone, or slip), dF = dP + A dw exactly. Since
  // a11 > mu |a12| the state-b solution is unique (Stromberg et al. 1996, Sec. 4.3), so the
  // enumeration route (the default, and what `cpkit rate` prints) must list exactly it, or say
  // complete = false. (The analytic route snaps sign tests within 1e-9 of their terms to 0
  // without saying so: at cond 1e12 it can call a separation with N = -2 against terms of 1e10
  // a zero-force slip; `cpkit rate` then reports a disagreement, exit 3, never a false answer.)
  std::mt19937_64 rng(20261127);
  std::uniform_int_distribution<int> small(1, 7), type(0, 3), sgn(0, 1);
  ContactState st;
  st.label = StateLabel::kB;
  int complete = 0, total = 0;
  for (int e = 2; e <= 12; ++e) {
    for (int rep = 0; rep < 12; ++rep) {
      const double d1 = small(rng), d2 = small(rng);
      double k = std::round(std::pow(std::pow(10.0, e) * d1 / d2, 0.25));
      if (sgn(rng)) k = -k;
      ContactParameters p;
      p.a11 = d1 + k * k * d2;
      p.a12 = k * d2;
      p.a22 = d2;
      p.mu = small(rng) / 8.0;
      const int t = type(rng);
      double dPT = 0, dPN = 0, dwT = 0, dwN = 0;
      SolutionType want = SolutionType::kStick;
      if (t == 0) {
        dwT = (2 * sgn(rng) - 1) * small(rng) / 8.0;
        dwN = -small(rng) / 8.0;
        want = SolutionType::kSeparation;
      } else if (t == 1) {
        dPN = 8 * small(rng);
        dPT = (2 * sgn(rng) - 1) * (small(rng) % 4) * p.mu * dPN / 8;
      } else {
        const double s = t == 2 ? 1 : -1;
        dPN = 8 * small(rng);
        dPT = s * p.mu * dPN;
        dwT = s * small(rng) / 8.0;
        want = t == 2 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
      }
      const LoadRate f{dPT + p.a11 * dwT + p.a12 * dwN, dPN + p.a12 * dwT + p.a22 * dwN};
      CAPTURE(e, rep, p.a11, p.a12, p.a22, p.mu, f.dF_T, f.dF_N, t);
      const double ftol = std::max(1e-10, 1e-14 * std::pow(10.0, e + 1));
      const double F = std::abs(f.dF_T) + std::abs(f.dF_N), D = std::abs(dwT) + std::abs(dwN);
      for (RateMethod m : {RateMethod::kEnumerate}) {
        const RateSolutionSet s = solve_rate_problem(p, st, f, m);
        CAPTURE(to_string(m), s.message);
        ++total;
        if (s.complete) {
          ++complete;
          REQUIRE(s.count() == 1);
        }
        for (const auto& x : s.solutions) {
          CHECK(x.type == want);
          CHECK(std::abs(x.start.dP_T - dPT) <= ftol * F);
          CHECK(std::abs(x.start.dP_N - dPN) <= ftol * F);
          CHECK(std::abs(x.start.dw_T - dwT) <= ftol * (D + F / p.a11));
          CHECK(std::abs(x.start.dw_N - dwN) <= ftol * (D + F / p.a11));
        }
      }
    }
  }
  INFO("complete answers: " << complete << " of " << total);
  CHECK(complete >= total * 3 / 4);
}
