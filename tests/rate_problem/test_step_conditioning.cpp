// The one-point 2-D step in any units and at any conditioning of A (issue 24, items 3 and 5):
// every listed solution is verified unit-free, a candidate that can be neither verified nor
// rejected makes the set incomplete, and scaling A (or A and the loads) changes nothing but the
// units of the answer. Independent sources: exact rational solutions of the examples
// (sympy over the doubles taken exactly, values quoted below), closed forms derived here by hand,
// and construct-then-check (a solution chosen first in integers, the load derived from the
// equations exactly in double, uniqueness from the paper's condition a11 > mu |a12| for state b).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"

using namespace cpkit::rate;

namespace {

StepProblem grazing(double a11, double a12, double a22, double mu, double C_T, double DFT,
                    double DFN) {
  StepProblem p;
  p.params.a11 = a11;
  p.params.a12 = a12;
  p.params.a22 = a22;
  p.params.mu = mu;
  p.params.C_T = C_T;
  p.load = {DFT, DFN};
  return p;
}

bool close(double x, double ref, double rel, double abs_floor) {
  return std::abs(x - ref) <= rel * std::abs(ref) + abs_floor;
}

/// The problem with A (and C_T, g0) in units scaled by cA and forces (loads, state, P_s, k_M)
/// by cF: forces of the answer scale by cF, displacements by cF / cA.
StepProblem scaled(const StepProblem& p, double cA, double cF) {
  StepProblem q = p;
  q.params.a11 *= cA;
  q.params.a12 *= cA;
  q.params.a22 *= cA;
  q.params.C_T /= cA;
  q.params.P_s *= cF;
  q.wear.k_M /= cF;
  q.state.P_T0 *= cF;
  q.state.P_N0 *= cF;
  q.state.g0 *= cF / cA;
  q.load.dF_T *= cF;
  q.load.dF_N *= cF;
  return q;
}

}  // namespace

TEST_CASE("Step in units of 1e10: one slip+, no penetrating 'separation' (issue 24 item 3)",
          "[step][units]") {
  // Hand solution, slip+ from grazing (C_T = 0): P_T1 = mu P_N1, Dw_N = 0, so
  // 1 - P/2 = a11' l and 0.5 - P = a12' l (A = 1e10 A'): P_N1 = 4/17, P_T1 = 2/17,
  // Dw_T^i = 15/17 1e-10. Separation would need Dw_N = (a11 DF_N - a12 DF_T)/det A < 0: it is
  // > 0 (the old code listed it with g1 = +1.8e-11, a penetration).
  for (double unit : {1.0, 1e10}) {
    CAPTURE(unit);
    const StepProblem p = grazing(1 * unit, 0.3 * unit, 1.2 * unit, 0.5, 0, 1, 0.5);
    const StepSolutionSet s = enumerate_step(p);
    CHECK(s.complete);
    REQUIRE(s.count() == 1);
    const StepValues& v = s.solutions[0].start;
    CHECK(s.solutions[0].type == SolutionType::kSlipPlus);
    CHECK(close(v.P_N1, 4.0 / 17, 1e-13, 0));
    CHECK(close(v.P_T1, 2.0 / 17, 1e-13, 0));
    CHECK(close(v.Dw_Ti, 15.0 / 17 / unit, 1e-13, 0));
    CHECK(std::abs(v.g1) <= 1e-15 / unit);
  }
}

TEST_CASE("Step at cond(A) = 1e7: the slip- point is slip-, not 'stick' (issue 24 item 3)",
          "[step][units]") {
  // Exact rational solution of the doubles (sympy, all four active sets): one slip- with the
  // values below; stick and separation fail their sign conditions. Dw_T^i is 43 % of Dw_T.
  const StepProblem p = grazing(127600897.60974222, 34985746.76265956, 9592443.16983857,
                                1.468801105377418, 7.96941781947783e-11, -0.2694949768340834,
                                0.17897876001458093);
  const StepSolutionSet s = enumerate_step(p);
  for (const auto& sol : s.solutions) CHECK(sol.type == SolutionType::kSlipMinus);
  if (s.complete) {
    REQUIRE(s.count() == 1);
    const StepValues& v = s.solutions[0].start;
    CHECK(close(v.DP_N, 0.1802709301241728, 1e-8, 0));
    CHECK(close(v.DP_T, -0.2647821414338003, 1e-8, 0));
    CHECK(close(v.Dw_T, -3.693418689496191e-11, 1e-6, 0));
    CHECK(close(v.Dw_Ti, -1.583259173274164e-11, 1e-6, 0));
  }
  CHECK(s.complete);  // measured: verified and complete
}

TEST_CASE("Step loads at the ends of double's range (issue 24 item 5)", "[step][units]") {
  // DF = (1.7e308, 1): the only solution is a separation with Dw_T = a22 DF_T / det A =
  // 1.84e308 > DBL_MAX: not representable, refused (as `rate` does).
  StepProblem p = grazing(1, 0.3, 1.2, 0.5, 0, 1.7e308, 1);
  try {
    (void)enumerate_step(p);
    FAIL("a non-representable solution was not refused");
  } catch (const cpkit::InputError& e) {
    CHECK(std::string(e.what()).find("not representable") != std::string::npos);
  }
  // DF = (1e308, 1): separation, DP = 0, Dw = A^-1 DF (hand: det A = 1.11).
  p.load = {1e308, 1};
  const StepSolutionSet s = enumerate_step(p);
  CHECK(s.complete);
  REQUIRE(s.count() == 1);
  CHECK(s.solutions[0].type == SolutionType::kSeparation);
  CHECK(close(s.solutions[0].start.Dw_T, 1.2e308 / 1.11, 1e-14, 0));
  CHECK(close(s.solutions[0].start.Dw_N, -0.3e308 / 1.11, 1e-14, 0));
  CHECK(s.solutions[0].start.P_N1 == 0);
  // Subnormal loads 2^-1064 (2, 1): the answer of DF = (1, 0.5) times 2^-1063 (hand, as in the
  // units test: slip+, P_N1 = 4/17, Dw_T^i = 15/17), to the precision subnormals carry.
  const double t = std::ldexp(1.0, -1063);
  p.load = {t, 0.5 * t};
  const StepSolutionSet u = enumerate_step(p);
  CHECK(u.complete);
  REQUIRE(u.count() == 1);
  CHECK(u.solutions[0].type == SolutionType::kSlipPlus);
  CHECK(close(u.solutions[0].start.P_N1, 4.0 / 17 * t, 1e-3, 0));
  CHECK(close(u.solutions[0].start.Dw_Ti, 15.0 / 17 * t, 1e-3, 0));
  p.load = {1e-320, 0};  // tangential only: separation (Dw_N = -a12 DF_T / det A < 0)
  const StepSolutionSet w = enumerate_step(p);
  REQUIRE(w.count() == 1);
  CHECK(w.solutions[0].type == SolutionType::kSeparation);
}

TEST_CASE("Step solution set is invariant under scaling A, and A with the loads, by 1e-12..1e12",
          "[step][units]") {
  std::vector<StepProblem> probs;
  probs.push_back(grazing(1, 0.3, 1.2, 0.5, 0, 1, 0.5));  // one slip+
  probs.push_back(grazing(127600897.60974222, 34985746.76265956, 9592443.16983857,
                          1.468801105377418, 7.96941781947783e-11, -0.2694949768340834,
                          0.17897876001458093));  // cond 1e7, slip-
  {
    StepProblem p = grazing(1, 0.9, 1, 1.5, 0.2, 1, 0.3);  // a11 < mu a12: several solutions
    probs.push_back(p);
  }
  {
    StepProblem p = grazing(2, -0.5, 1.5, 0.4, 0.1, -0.3, -0.2);  // separation
    probs.push_back(p);
  }
  {
    StepProblem p = grazing(2, 0.5, 1.5, 0.4, 0.1, 0.8, 0.4);  // wear, from a loaded state
    p.params.k_a = 0.3;
    p.params.P_s = 0.7;
    p.state = {0.1, 1.0, 0};
    probs.push_back(p);
  }
  {
    StepProblem p = grazing(2, 0.5, 1.5, 0.6, 0.1, 0.5, -0.1);  // softening (35)
    p.params.k_a = 0.3;
    p.params.P_s = 0.7;
    p.params.criterion = Criterion::kSoftening;
    p.state = {0.2, 0.5, 0};
    probs.push_back(p);
  }
  {
    StepProblem p = grazing(2, 0.5, 1.5, 0.6, 0.1, 0.5, 0.7);  // from an open gap
    p.state = {0, 0, -0.05};
    probs.push_back(p);
  }
  const double cs[] = {1e-12, 1e-9, 3e-7, 1e-3, 7.5, 1e3, 1e6, 1e9, 1e12};
  for (std::size_t k = 0; k < probs.size(); ++k) {
    const StepSolutionSet ref = enumerate_step(probs[k]);
    REQUIRE(ref.complete);
    REQUIRE(ref.count() >= 1);
    for (double c : cs) {
      for (int with_loads = 0; with_loads < 2; ++with_loads) {
        const double cF = with_loads ? c : 1.0;
        CAPTURE(k, c, with_loads);
        const StepSolutionSet s = enumerate_step(scaled(probs[k], c, cF));
        CHECK(s.complete);
        REQUIRE(s.count() == ref.count());
        CHECK(s.type_mask() == ref.type_mask());
        CHECK(s.continuous_count == ref.continuous_count);
        for (std::size_t i = 0; i < s.solutions.size(); ++i) {
          const StepValues& a = s.solutions[i].start;
          const StepValues& b = ref.solutions[i].start;
          CHECK(s.solutions[i].type == ref.solutions[i].type);
          const double F = std::abs(b.P_N1) + std::abs(b.P_T1) + 1;
          const double D = std::abs(b.Dw_T) + std::abs(b.Dw_N) + 1e-300;
          CHECK(close(a.DP_T / cF, b.DP_T, 1e-12, 1e-12 * F));
          CHECK(close(a.DP_N / cF, b.DP_N, 1e-12, 1e-12 * F));
          CHECK(close(a.Dw_T * c / cF, b.Dw_T, 1e-9, 1e-12 * D));
          CHECK(close(a.Dw_Ti * c / cF, b.Dw_Ti, 1e-9, 1e-12 * D));
          CHECK(close(a.Dw_N * c / cF, b.Dw_N, 1e-9, 1e-12 * D));
        }
      }
    }
  }
}

TEST_CASE("Step over cond(A) 1e2..1e12: the constructed solution, or complete = false",
          "[step][conditioning]") {
  // Construct-then-check. A = P^T diag(d1, d2) P with P = [[1, 0], [k, 1]] and small integers:
  // A = [[d1 + k^2 d2, k d2], [k d2, d2]], integer (exact in double), det A = d1 d2,
  // cond(A) ~ k^4 d2 / d1. A solution is chosen in integers (forces) and multiples of 1/8
  // (slip magnitudes), the load derived exactly: DF = DP + A Dw. From the grazing state without
  // wear the step is the state-b rate problem, which has exactly one solution for every load
  // when a11 > mu |a12| (Stromberg et al. 1996, Sec. 4.3; docs/model.md): here
  // a11 = d1 + k^2 d2 > mu |k| d2 holds for mu < |k|. So the set must be {that solution}, or
  // the enumeration must say complete = false (listing only points that match it).
  std::mt19937_64 rng(20261126);
  std::uniform_int_distribution<int> small(1, 7), type(0, 3), sgn(0, 1);
  int complete = 0, total = 0;
  for (int e = 2; e <= 12; ++e) {
    for (int rep = 0; rep < 12; ++rep) {
      const double d1 = small(rng), d2 = small(rng);
      // cond ~ k^4 d2/d1: k ~ (10^e d1/d2)^(1/4), an integer.
      double k = std::round(std::pow(std::pow(10.0, e) * d1 / d2, 0.25));
      if (sgn(rng)) k = -k;
      const double a11 = d1 + k * k * d2, a12 = k * d2, a22 = d2;
      const double mu = small(rng) / 8.0;  // < 1 <= |k|
      const int t = type(rng);
      double DPT = 0, DPN = 0, DwT = 0, DwN = 0;
      SolutionType want = SolutionType::kStick;
      if (t == 0) {  // separation: DP = 0, Dw_N < 0
        DwT = (2 * sgn(rng) - 1) * small(rng) / 8.0;
        DwN = -small(rng) / 8.0;
        want = SolutionType::kSeparation;
      } else if (t == 1) {  // stick strictly inside the cone: Dw = 0
        DPN = 8 * small(rng);
        DPT = (2 * sgn(rng) - 1) * (small(rng) % 4) * mu * DPN / 8;
      } else {  // slip s: P_T1 = s mu P_N1, Dw_N = 0, Dw_T = s l
        const double s = t == 2 ? 1 : -1;
        DPN = 8 * small(rng);
        DPT = s * mu * DPN;
        DwT = s * small(rng) / 8.0;
        want = t == 2 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
      }
      const double DFT = DPT + a11 * DwT + a12 * DwN, DFN = DPN + a12 * DwT + a22 * DwN;
      const StepProblem p = grazing(a11, a12, a22, mu, 0, DFT, DFN);
      CAPTURE(e, rep, a11, a12, a22, mu, DFT, DFN, t);
      StepEnumerationOptions o;
      o.detect_jumps = false;
      const StepSolutionSet s = enumerate_step(p, o);
      ++total;
      if (s.complete) {
        ++complete;
        REQUIRE(s.count() == 1);
      }
      REQUIRE(s.count() >= 0);
      // cond(A) eps bounds the forward error of the listed values.
      const double cond = std::pow(10.0, e + 1), ftol = std::max(1e-10, 1e-14 * cond);
      const double F = std::abs(DFT) + std::abs(DFN), D = std::abs(DwT) + std::abs(DwN);
      for (const auto& sol : s.solutions) {
        CHECK(sol.type == want);
        CHECK(close(sol.start.DP_T, DPT, 0, ftol * F));
        CHECK(close(sol.start.DP_N, DPN, 0, ftol * F));
        CHECK(close(sol.start.Dw_T, DwT, 0, ftol * (D + F / a11)));
        CHECK(close(sol.start.Dw_N, DwN, 0, ftol * (D + F / a11)));
      }
      if (e <= 6) CHECK(s.complete);  // well enough conditioned: always decided
    }
  }
  INFO("complete answers: " << complete << " of " << total);
  CHECK(complete >= total * 3 / 4);
}
