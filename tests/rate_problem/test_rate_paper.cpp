// The statements of [Stromberg et al. 1996, Sec. 4.3] as tests, hand-computed cases (the hand
// calculation is in each comment), and the degenerate lines of docs/model.md. Every case runs
// through both complete routes (analytic and enumerate).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "rate_problem/rate_test_util.hpp"

using namespace cpkit::rate;

namespace {

ContactParameters params(double a11, double a12, double a22, double mu, double C_T = 0,
                         double k_a = 0, double P_s = 1) {
  ContactParameters p;
  p.a11 = a11;
  p.a12 = a12;
  p.a22 = a22;
  p.mu = mu;
  p.C_T = C_T;
  p.k_a = k_a;
  p.P_s = P_s;
  return p;
}

void check_rates(const Rates& r, double dP_T, double dP_N, double dw_T, double dw_N, double dw_Ti,
                 double dw_w) {
  CHECK(r.dP_T == Approx(dP_T).margin(1e-12));
  CHECK(r.dP_N == Approx(dP_N).margin(1e-12));
  CHECK(r.dw_T == Approx(dw_T).margin(1e-12));
  CHECK(r.dw_N == Approx(dw_N).margin(1e-12));
  CHECK(r.dw_Ti == Approx(dw_Ti).margin(1e-12));
  CHECK(r.dw_w == Approx(dw_w).margin(1e-12));
}

const RateSolution* find(const RateSolutionSet& s, SolutionType t) {
  for (const auto& x : s.solutions)
    if (x.type == t) return &x;
  return nullptr;
}

const auto kRoutes = {RateMethod::kAnalytic, RateMethod::kEnumerate};

}  // namespace

TEST_CASE("state a: open, dw = A^-1 dF (hand)", "[rate][paper]") {
  // A = [[2,1],[1,3]], det 5, dF = (1,2): dw_T = (3*1 - 1*2)/5 = 0.2, dw_N = (2*2 - 1*1)/5 = 0.6.
  const auto m = GENERATE(values(kRoutes));
  const auto s = solve_rate_problem(params(2, 1, 3, 0.5), {StateLabel::kA, 0, 1}, {1, 2}, m);
  REQUIRE(s.count() == 1);
  REQUIRE(s.solutions[0].type == SolutionType::kOpen);
  check_rates(s.solutions[0].start, 0, 0, 0.2, 0.6, 0.2, 0);
  CHECK(s.unique_for_all_directions);
}

TEST_CASE("state b, a11 > mu|a12|: hand-computed separation, stick, slip", "[rate][paper]") {
  const auto m = GENERATE(values(kRoutes));
  CAPTURE(to_string(m));
  const ContactParameters p = params(2, 1, 3, 0.5);  // D_+ = 1.5, D_- = 2.5, det A = 5
  const ContactState b{StateLabel::kB, 0, 1};
  {  // dF = (1,-1): N = 2(-1) - 1 = -3 < 0; dw = A^-1 dF = ((3+1)/5, (-2-1)/5) = (0.8, -0.6)
    const auto s = solve_rate_problem(p, b, {1, -1}, m);
    REQUIRE(s.count() == 1);
    REQUIRE(s.solutions[0].type == SolutionType::kSeparation);
    check_rates(s.solutions[0].start, 0, 0, 0.8, -0.6, 0.8, 0);
    CHECK(s.D_plus == Approx(1.5));
    CHECK(s.D_minus == Approx(2.5));
    CHECK(s.unique_for_all_directions);
  }
  {  // dF = (0.2, 1): |0.2| <= 0.5 * 1, stick with dP = dF, dw = 0
    const auto s = solve_rate_problem(p, b, {0.2, 1}, m);
    REQUIRE(s.count() == 1);
    REQUIRE(s.solutions[0].type == SolutionType::kStick);
    check_rates(s.solutions[0].start, 0.2, 1, 0, 0, 0, 0);
  }
  {  // C_T = 0.5, dF = (1.5, 1): c1 = 2, N = 0.5, L_+ = 1.25*1.5 - 0.5*2*1 = 0.875,
     // dP_N = N/D_+ = 1/3, lambda = 0.875/1.5 = 7/12, dP_T = 1/6, dw_T = 0.5/6 + 7/12 = 2/3.
     // Check (50): 1.5 - 1/6 = 4/3 = 2 * 2/3; 1 - 1/3 = 2/3 = 1 * 2/3.
    ContactParameters q = p;
    q.C_T = 0.5;
    const auto s = solve_rate_problem(q, b, {1.5, 1}, m);
    REQUIRE(s.count() == 1);
    REQUIRE(s.solutions[0].type == SolutionType::kSlipPlus);
    check_rates(s.solutions[0].start, 1.0 / 6, 1.0 / 3, 2.0 / 3, 0, 7.0 / 12, 0);
  }
}

TEST_CASE("state b, a11 < mu|a12|: three solutions (Fig. 5b, hand)", "[rate][paper]") {
  // A = [[1,2],[2,5]] (det 1), mu = 1: D_+ = -1, D_- = 3. dF = (1, 1.2):
  // N = 1.2 - 2 = -0.8 < 0: separation, dw = (5*1 - 2*1.2, 1.2 - 2) = (2.6, -0.8);
  // stick: |1| <= 1 * 1.2: dP = (1, 1.2); slip+: dP_N = N/D_+ = 0.8, lambda = L_+/D_+ =
  // (1 - 1.2)/(-1) = 0.2, dP_T = 0.8, dw_T = 0.2 (check: 1 - 0.8 = 0.2 = 1*0.2; 1.2 - 0.8 = 2*0.2).
  const auto m = GENERATE(values(kRoutes));
  const auto s = solve_rate_problem(params(1, 2, 5, 1), {StateLabel::kB, 0, 1}, {1, 1.2}, m);
  REQUIRE(s.count() == 3);
  CHECK_FALSE(s.unique_for_all_directions);
  REQUIRE(find(s, SolutionType::kSeparation));
  check_rates(find(s, SolutionType::kSeparation)->start, 0, 0, 2.6, -0.8, 2.6, 0);
  REQUIRE(find(s, SolutionType::kStick));
  check_rates(find(s, SolutionType::kStick)->start, 1, 1.2, 0, 0, 0, 0);
  REQUIRE(find(s, SolutionType::kSlipPlus));
  check_rates(find(s, SolutionType::kSlipPlus)->start, 0.8, 0.8, 0.2, 0, 0.2, 0);
}

TEST_CASE("state b: a solution for every direction; unique for all iff a11 > mu|a12|",
          "[rate][paper]") {
  std::mt19937_64 rng(5150);
  std::uniform_real_distribution<double> U(0, 1);
  for (int it = 0; it < 60; ++it) {
    const double a11 = 0.2 + 2 * U(rng), a22 = 0.2 + 2 * U(rng);
    const double a12 = (2 * U(rng) - 1) * 0.95 * std::sqrt(a11 * a22);
    const double mu = 0.1 + 3 * U(rng);
    const ContactParameters p = params(a11, a12, a22, mu, it % 3 == 0 ? 0.0 : U(rng));
    const bool unique_expected = a11 > mu * std::abs(a12);
    CAPTURE(it, a11, a12, a22, mu);
    bool some_nonunique = false;
    // 720 uniform directions plus directions near the line N = 0 (dF along +-(a11, a12)), where
    // the non-uniqueness cone of a slightly negative D_s opens (its width is O(|D_s|)).
    std::vector<double> angles;
    for (int k = 0; k < 720; ++k) angles.push_back(2 * M_PI * (k + 0.5) / 720);
    for (double sgn : {1.0, -1.0})
      for (double off : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1})
        for (double side : {1.0, -1.0})
          angles.push_back(std::atan2(sgn * a12, sgn * a11) + side * off);
    for (double th : angles) {
      for (auto m : kRoutes) {
        const RateSummary s =
            summarize_rate_problem(p, {StateLabel::kB, 0, 1}, {std::cos(th), std::sin(th)}, m);
        REQUIRE(s.count != 0);  // existence for every direction
        if (s.count != 1) some_nonunique = true;
      }
    }
    CHECK(some_nonunique == !unique_expected);
    CHECK(rate_indicators(p, {StateLabel::kB, 0, 1}).unique_for_all_directions == unique_expected);
  }
}

TEST_CASE("state b degenerate a11 = mu|a12|: segment on N = 0, dF_N > 0 (hand)", "[rate][paper]") {
  // A = [[1,2],[2,5]], mu = 0.5: D_+ = 1 - 0.5*2 = 0. On N = 0 (dF_T = mu dF_N) with dF = (1, 2)
  // and C_T = 0.5 (c1 = 1.5): (1 + a11 C_T) dP_N + |a12| lambda = dF_N, i.e. the segment from
  // stick (dP_N = 2/1.5 = 4/3, dP_T = mu dP_N = 2/3, lambda = 0, open end: that point is stick)
  // to zero-force slip (dP = 0, lambda = 2/2 = 1, dw_T = 1; closed). The stick point itself:
  // dP_T = 1/1.5 = 2/3, dP_N = (1.5*2 - 2*0.5*1)/1.5 = 4/3, dw_T = C_T dP_T = 1/3.
  const auto m = GENERATE(values(kRoutes));
  const auto s = solve_rate_problem(params(1, 2, 5, 0.5, 0.5), {StateLabel::kB, 0, 1}, {1, 2}, m);
  CHECK(s.count() == -1);
  CHECK(s.infinite);
  REQUIRE(s.solutions.size() == 2);
  const RateSolution* st = find(s, SolutionType::kStick);
  const RateSolution* sl = find(s, SolutionType::kSlipPlus);
  REQUIRE(st);
  REQUIRE(sl);
  CHECK(st->kind == RateSolution::Kind::kPoint);
  check_rates(st->start, 2.0 / 3, 4.0 / 3, 1.0 / 3, 0, 0, 0);
  REQUIRE(sl->kind == RateSolution::Kind::kSegment);
  check_rates(sl->start, 2.0 / 3, 4.0 / 3, 1.0 / 3, 0, 0, 0);
  CHECK_FALSE(sl->start_closed);
  check_rates(sl->end, 0, 0, 1, 0, 1, 0);
  CHECK(sl->end_closed);
  CHECK_FALSE(s.unique_for_all_directions);
}

TEST_CASE("state b degenerate a11 = mu|a12|: unique slip with dP = 0 on N = 0, dF_N < 0",
          "[rate][paper]") {
  // a12 = +2 (D_+ = 0): dF = (-1, -2) is on N = 0 with dF_N < 0. Slip- (sign -sgn a12):
  // D_- = 2, L_- = -dF_T - mu (dF_N) = 1 + 1 = 2, lambda = 1, dP_N = N/D_- = 0: dw_T = -1.
  // a12 = -2 (D_- = 0): dF = (1, -2) (dF_T = -mu dF_N): unique slip+ with lambda = 1.
  const auto m = GENERATE(values(kRoutes));
  auto s = solve_rate_problem(params(1, 2, 5, 0.5), {StateLabel::kB, 0, 1}, {-1, -2}, m);
  REQUIRE(s.count() == 1);
  REQUIRE(s.solutions[0].type == SolutionType::kSlipMinus);
  check_rates(s.solutions[0].start, 0, 0, -1, 0, -1, 0);
  s = solve_rate_problem(params(1, -2, 5, 0.5), {StateLabel::kB, 0, 1}, {1, -2}, m);
  REQUIRE(s.count() == 1);
  REQUIRE(s.solutions[0].type == SolutionType::kSlipPlus);
  check_rates(s.solutions[0].start, 0, 0, 1, 0, 1, 0);
  // and the mirrored segment: a12 = -2, dF = (-1, 2) on N = 0: slip- segment to dw_T = -1
  s = solve_rate_problem(params(1, -2, 5, 0.5), {StateLabel::kB, 0, 1}, {-1, 2}, m);
  CHECK(s.count() == -1);
  const RateSolution* sl = find(s, SolutionType::kSlipMinus);
  REQUIRE(sl);
  REQUIRE(sl->kind == RateSolution::Kind::kSegment);
  check_rates(sl->end, 0, 0, -1, 0, -1, 0);
}

TEST_CASE("state c: unique stick for every direction (hand)", "[rate][paper]") {
  // a11 = 2, a12 = 1, C_T = 0.5, dF = (1, 1): c1 = 2, dP_T = 0.5, dP_N = (2 - 0.5)/2 = 0.75,
  // dw_T = C_T dP_T = 0.25 (check: 1 - 0.5 = 2*0.25; 1 - 0.75 = 1*0.25).
  const auto m = GENERATE(values(kRoutes));
  const ContactParameters p = params(2, 1, 3, 0.5, 0.5, 0.3);
  const ContactState c{StateLabel::kC, 1.0, 1};
  const auto s = solve_rate_problem(p, c, {1, 1}, m);
  REQUIRE(s.count() == 1);
  check_rates(s.solutions[0].start, 0.5, 0.75, 0.25, 0, 0, 0);
  CHECK(s.unique_for_all_directions);
  for (int k = 0; k < 360; ++k) {
    const double th = 2 * M_PI * k / 360;
    const RateSummary r = summarize_rate_problem(p, c, {std::cos(th), std::sin(th)}, m);
    CHECK(r.count == 1);
    CHECK(r.types == 1u << static_cast<unsigned>(SolutionType::kStick));
  }
}

TEST_CASE("state d, Lambda > 0: slip with wear (hand)", "[rate][paper]") {
  // A = [[1,0.5],[0.5,1]] (det 0.75), mu = 0.8, C_T = 0.5, k_a = 0.6, P_s = 1, P_N = 2, s = +1:
  // kappa = 0.6*2/3 = 0.4; Lambda = 1 - 0.4 + 0.4(0.5 - 0.8) - 0.8*0.4*0.5*0.75 = 0.36.
  // dF = (2, 1): L_+ = (1 + 0.8*0.5*0.5)*2 - 0.8*1.5*1 = 1.2; lambda = 1.2/0.36 = 10/3;
  // dP_N = [(1 + 0.5*0.4)*1 - (0.5 + 0.4)*2]/0.36 = -5/3; dP_T = -4/3; dw_N = dw^w = 4/3;
  // dw_T = 0.5*(-4/3) + 10/3 = 8/3. (50): 2 + 4/3 = 8/3 + 0.5*4/3; 1 + 5/3 = 0.5*8/3 + 4/3.
  const auto m = GENERATE(values(kRoutes));
  const ContactParameters p = params(1, 0.5, 1, 0.8, 0.5, 0.6, 1);
  const ContactState d{StateLabel::kD, 2.0, 1};
  const auto s = solve_rate_problem(p, d, {2, 1}, m);
  CHECK(s.Lambda == Approx(0.36));
  CHECK(s.unique_for_all_directions);
  REQUIRE(s.count() == 1);
  REQUIRE(s.solutions[0].type == SolutionType::kSlipPlus);
  check_rates(s.solutions[0].start, -4.0 / 3, -5.0 / 3, 8.0 / 3, 4.0 / 3, 10.0 / 3, 4.0 / 3);
  for (int k = 0; k < 360; ++k) {
    const double th = 2 * M_PI * (k + 0.25) / 360;
    CHECK(summarize_rate_problem(p, d, {std::cos(th), std::sin(th)}, m).count == 1);
  }
}

TEST_CASE("state d, Lambda < 0: two, one, none as L_s < 0, = 0, > 0 (hand)", "[rate][paper]") {
  // A = [[1,0.5],[0.5,1]], mu = 3, no wear, C_T = 0, s = +1: Lambda = 1 - 1.5 = -0.5,
  // L_+ = dF_T - 3 dF_N. dF = (1,1): L = -2: stick dP = (1,1) and slip with lambda = 4,
  // dP_N = (1 - 0.5)/(-0.5) = -1, dP_T = -3, dw_T = 4 (check: 1+3 = 4 = 1*4; 1+1 = 2 = 0.5*4).
  // dF = (3,1): L = 0: stick only. dF = (4,1): L = 1: none.
  const auto m = GENERATE(values(kRoutes));
  const ContactParameters p = params(1, 0.5, 1, 3);
  const ContactState d{StateLabel::kD, 1.0, 1};
  auto s = solve_rate_problem(p, d, {1, 1}, m);
  CHECK(s.Lambda == Approx(-0.5));
  CHECK_FALSE(s.unique_for_all_directions);
  REQUIRE(s.count() == 2);
  check_rates(find(s, SolutionType::kStick)->start, 1, 1, 0, 0, 0, 0);
  REQUIRE(find(s, SolutionType::kSlipPlus));
  check_rates(find(s, SolutionType::kSlipPlus)->start, -3, -1, 4, 0, 4, 0);
  s = solve_rate_problem(p, d, {3, 1}, m);
  REQUIRE(s.count() == 1);
  CHECK(s.solutions[0].type == SolutionType::kStick);
  s = solve_rate_problem(p, d, {4, 1}, m);
  CHECK(s.count() == 0);
}

TEST_CASE("state d, Lambda = 0: one, a ray, none as L_s < 0, = 0, > 0 (hand)", "[rate][paper]") {
  // mu = 2: Lambda = 1 - 2*0.5 = 0, L_+ = dF_T - 2 dF_N. dF = (2,1): L = 0: stick dP = (2,1)
  // plus the ray lambda > 0 from it (open start): per unit lambda, row 1 of the slip system
  // gives 2 dP_N' + 1 = 0, dP_N' = -1/2, dP_T' = mu dP_N' = -1, dw_T' = 1
  // (check (50) linear part: 1 = 1*1 + 0; 1/2 = 0.5*1). dF = (1,1): L = -1: stick only.
  // dF = (3,1): L = 1: none.
  const auto m = GENERATE(values(kRoutes));
  const ContactParameters p = params(1, 0.5, 1, 2);
  const ContactState d{StateLabel::kD, 1.0, 1};
  auto s = solve_rate_problem(p, d, {2, 1}, m);
  CHECK(s.Lambda == Approx(0).margin(1e-15));
  CHECK(s.count() == -1);
  REQUIRE(s.solutions.size() == 2);
  check_rates(find(s, SolutionType::kStick)->start, 2, 1, 0, 0, 0, 0);
  const RateSolution* ray = find(s, SolutionType::kSlipPlus);
  REQUIRE(ray);
  REQUIRE(ray->kind == RateSolution::Kind::kRay);
  CHECK_FALSE(ray->start_closed);
  check_rates(ray->start, 2, 1, 0, 0, 0, 0);
  const double k = 1.0 / ray->direction.dw_Ti;  // normalise to unit lambda
  REQUIRE(k > 0);
  CHECK(ray->direction.dP_N * k == Approx(-0.5));
  CHECK(ray->direction.dP_T * k == Approx(-1));
  CHECK(ray->direction.dw_T * k == Approx(1));
  CHECK(ray->direction.dw_N * k == Approx(0).margin(1e-12));
  s = solve_rate_problem(p, d, {1, 1}, m);
  REQUIRE(s.count() == 1);
  CHECK(s.solutions[0].type == SolutionType::kStick);
  CHECK(solve_rate_problem(p, d, {3, 1}, m).count() == 0);
}

TEST_CASE("state d: unique for every direction iff Lambda > 0, else 2/1/0 (sweep)",
          "[rate][paper]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> U(0, 1);
  for (int it = 0; it < 60; ++it) {
    const double a11 = 0.2 + 2 * U(rng), a22 = 0.2 + 2 * U(rng);
    const double a12 = (2 * U(rng) - 1) * 0.95 * std::sqrt(a11 * a22);
    const ContactParameters p = params(a11, a12, a22, 0.1 + 3 * U(rng), U(rng), U(rng), 1);
    const ContactState d{StateLabel::kD, 0.1 + 4 * U(rng), U(rng) < 0.5 ? 1 : -1};
    const double Lambda = rate_indicators(p, d).Lambda;
    CAPTURE(it, Lambda);
    int n2 = 0, n0 = 0;
    for (int k = 0; k < 720; ++k) {
      const double th = 2 * M_PI * (k + 0.5) / 720;
      for (auto m : kRoutes) {
        const int c = summarize_rate_problem(p, d, {std::cos(th), std::sin(th)}, m).count;
        if (Lambda > 0) REQUIRE(c == 1);
        n2 += c == 2;
        n0 += c == 0;
      }
    }
    if (Lambda < 0) {
      CHECK(n2 > 0);  // L_s < 0 directions: two solutions
      CHECK(n0 > 0);  // L_s > 0 directions: none
    }
  }
}

TEST_CASE("criterion (35) in state d: mu -> mu - 2 kappa in the cone rate (hand)", "[rate][paper]") {
  // |P_T| = mu P_N - k P_N^2 has rate s dP_T = (mu - 2 k P_N) dP_N = mu_eff dP_N; flow rule as (38).
  // a11=1, a12=0.5, a22=1, mu=0.8, C_T=0, k_a=0.6, P_s=1, P_N=2: kappa = 0.4, mu_eff = 0;
  // Lambda = 1 + 0.4*0.5 = 1.2; L_+ = dF_T. dF = (1.2, 0): lambda = 1,
  // dP_N = [(1 + 0.2)*0 - (0.5 + 0.4)*1.2]/1.2 = -0.9, dP_T = 0, dw_N = dw^w = 0.4, dw_T = 1.
  // (50): 1.2 - 0 = 1*1 + 0.5*0.4; 0 + 0.9 = 0.5*1 + 1*0.4.
  const auto m = GENERATE(values(kRoutes));
  ContactParameters p = params(1, 0.5, 1, 0.8, 0, 0.6, 1);
  p.criterion = Criterion::kSoftening;
  const auto s = solve_rate_problem(p, {StateLabel::kD, 2.0, 1}, {1.2, 0}, m);
  CHECK(s.Lambda == Approx(1.2));
  REQUIRE(s.count() == 1);
  REQUIRE(s.solutions[0].type == SolutionType::kSlipPlus);
  check_rates(s.solutions[0].start, 0, -0.9, 1, 0.4, 1, 0.4);
}

TEST_CASE("every solution of the swept cases satisfies the rate laws", "[rate][paper]") {
  std::mt19937_64 rng(8080);
  std::uniform_real_distribution<double> U(0, 1);
  for (int it = 0; it < 200; ++it) {
    const double a11 = 0.2 + 2 * U(rng), a22 = 0.2 + 2 * U(rng);
    const double a12 = (2 * U(rng) - 1) * 0.95 * std::sqrt(a11 * a22);
    const ContactParameters p = params(a11, a12, a22, 0.1 + 3 * U(rng), U(rng), U(rng), 1);
    const ContactState st{it % 2 ? StateLabel::kB : StateLabel::kD, it % 2 ? 0.0 : 1.5, 1};
    const double th = 2 * M_PI * U(rng);
    const LoadRate f{std::cos(th), std::sin(th)};
    for (auto m : kRoutes) {
      const auto s = solve_rate_problem(p, st, f, m);
      INFO(cpkit::rate::test::check_set_laws(p, st, f, s));
      CHECK(cpkit::rate::test::check_set_laws(p, st, f, s).empty());
    }
  }
}
