// Direction maps [Stromberg et al. 1996, Sec. 4.3, Fig. 5]: sector boundaries against the closed
// forms of docs/model.md (computed here by hand), counts against an independent classification
// written in this file and against the analytic route.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"

using namespace cpkit::rate;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr unsigned kSep = 1u << static_cast<unsigned>(SolutionType::kSeparation);
constexpr unsigned kStick = 1u << static_cast<unsigned>(SolutionType::kStick);
constexpr unsigned kSlipP = 1u << static_cast<unsigned>(SolutionType::kSlipPlus);
constexpr unsigned kSlipM = 1u << static_cast<unsigned>(SolutionType::kSlipMinus);

ContactParameters fig5(double mu) {
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 0.5;
  p.a22 = 1;
  p.C_T = 0.25;
  p.mu = mu;
  return p;
}
ContactState state_b() {
  ContactState s;
  s.label = StateLabel::kB;
  return s;
}

/// The paper's conditions b.i-b.iii (generic directions only: no form is zero), written out.
RateSummary hand_state_b(const ContactParameters& p, double theta) {
  const double fT = std::cos(theta), fN = std::sin(theta);
  const double g = 1 + p.a11 * p.C_T;
  const double N = p.a11 * fN - p.a12 * fT;
  RateSummary r;
  auto add = [&](unsigned m) { ++r.count; r.types |= m; };
  if (N < 0) add(kSep);  // b.i
  const double S = g * fN - p.a12 * p.C_T * fT;
  if (p.a12 * p.C_T * fT <= g * fN && std::abs(fT) + p.mu * p.a12 * p.C_T * fT <= p.mu * g * fN &&
      S >= 0)
    add(kStick);  // b.ii
  for (int s : {+1, -1}) {  // b.iii
    const double D = p.a11 - p.mu * p.a12 * s;
    const double lam = ((s + p.mu * p.a12 * p.C_T) * fT - p.mu * g * fN) / D;
    if (lam > 0 && N / D >= 0) add(s > 0 ? kSlipP : kSlipM);
  }
  return r;
}

double wrap(double t) { return t < 0 ? t + 2 * kPi : t; }
}  // namespace

TEST_CASE("Fig5SectorBoundariesMatchClosedForms", "[map][direction]") {
  struct Case {
    double mu;
    std::vector<double> critical;         // by hand from model.md
    std::vector<int> critical_count;
    std::vector<int> sector_count;        // sector starting at critical[k]
    std::vector<unsigned> sector_types;
  };
  // N = 0: tan theta = a12/a11; L+ = 0: tan theta = (1 + mu a12 C_T) / (mu (1 + a11 C_T));
  // L- = 0 on the stick side (dF_N > 0): theta = pi - atan((1 - mu a12 C_T) / (mu (1 + a11 C_T))).
  const double tN = std::atan(0.5);
  const Case fig5a{1.0,
                   {tN, std::atan(1.125 / 1.25), kPi - std::atan(0.875 / 1.25), tN + kPi},
                   {1, 1, 1, 1},
                   {1, 1, 1, 1},
                   {kSlipP, kStick, kSlipM, kSep}};
  const Case fig5b{3.0,
                   {std::atan(1.375 / 3.75), tN, kPi - std::atan(0.625 / 3.75), tN + kPi},
                   {2, 2, 1, 1},
                   {3, 1, 1, 1},
                   {kSep | kStick | kSlipP, kStick, kSlipM, kSep}};
  for (const Case& c : {fig5a, fig5b}) {
    CAPTURE(c.mu);
    const DirectionMap m = compute_direction_map(fig5(c.mu), state_b());
    REQUIRE(m.critical.size() == c.critical.size());
    REQUIRE(m.sectors.size() == c.critical.size());
    CHECK(m.inconsistent_sectors == 0);
    for (std::size_t k = 0; k < c.critical.size(); ++k) {
      CAPTURE(k);
      CHECK(m.critical[k].theta == Approx(c.critical[k]).margin(1e-13));
      CHECK(m.critical[k].summary.count == c.critical_count[k]);
      CHECK(m.sectors[k].theta_from == Approx(c.critical[k]).margin(1e-13));
      const double to = k + 1 < c.critical.size() ? c.critical[k + 1] : c.critical[0] + 2 * kPi;
      CHECK(m.sectors[k].theta_to == Approx(to).margin(1e-13));
      CHECK(m.sectors[k].summary.count == c.sector_count[k]);
      CHECK(m.sectors[k].summary.types == c.sector_types[k]);
    }
  }
}

TEST_CASE("CriticalDirectionsOfFig5bNameTheirConditions", "[map][direction]") {
  const DirectionMap m = compute_direction_map(fig5(3.0), state_b());
  REQUIRE(m.critical.size() == 4);
  CHECK(m.critical[0].conditions == std::vector<std::string>{"L+=0"});
  CHECK(m.critical[1].conditions == std::vector<std::string>{"N=0"});
  CHECK(m.critical[2].conditions == std::vector<std::string>{"L-=0"});
  CHECK(m.critical[3].conditions == std::vector<std::string>{"N=0"});
  // The exact load on a critical direction zeroes its form: N = a11 dF_N - a12 dF_T.
  CHECK(1.0 * m.critical[1].load.dF_N - 0.5 * m.critical[1].load.dF_T == 0.0);
}

TEST_CASE("SectorCountsAgreeWithHandClassificationAndAnalyticRoute", "[map][direction]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    ContactParameters p;
    p.a11 = 0.5 + 2 * u(rng);
    p.a22 = 0.5 + 2 * u(rng);
    p.a12 = (2 * u(rng) - 1) * 0.95 * std::sqrt(p.a11 * p.a22);
    p.mu = 0.1 + 4 * u(rng);
    p.C_T = trial % 4 == 0 ? 0.0 : 2 * u(rng);
    CAPTURE(trial, p.a11, p.a12, p.a22, p.mu, p.C_T);
    MapOptions opt;
    opt.method = RateMethod::kAnalytic;  // analytic cells, cross-checked by enumeration
    const DirectionMap m = compute_direction_map(p, state_b(), opt);
    CHECK(m.cross_checked);
    CHECK(m.disagreements == 0);
    CHECK(m.inconsistent_sectors == 0);
    const DirectionMap e = compute_direction_map(p, state_b());
    REQUIRE(e.sectors.size() == m.sectors.size());
    // Random directions: the hand classification equals the summary of the enclosing sector.
    for (int k = 0; k < 200; ++k) {
      const double th = 2 * kPi * u(rng);
      const DirectionSector* sec = nullptr;
      double dist = 1e9;
      for (const auto& s : e.sectors) {
        const double t = th < s.theta_from ? th + 2 * kPi : th;
        if (t > s.theta_from && t < s.theta_to) sec = &s;
        dist = std::min({dist, std::abs(t - s.theta_from), std::abs(t - s.theta_to)});
      }
      if (dist < 1e-9) continue;
      REQUIRE(sec != nullptr);
      const RateSummary h = hand_state_b(p, th);
      CAPTURE(th);
      CHECK(sec->summary.count == h.count);
      CHECK(sec->summary.types == h.types);
    }
    // Existence in state b for every direction [paper, Sec. 4.3].
    for (const auto& s : e.sectors) CHECK(s.summary.count != 0);
    for (const auto& c : e.critical) CHECK(c.summary.count != 0);
  }
}

TEST_CASE("StateDSectorsFollowTheSignOfLambda", "[map][direction]") {
  ContactParameters p = fig5(0.6);
  p.k_a = 1.5;
  p.P_s = 1;
  ContactState s;
  s.label = StateLabel::kD;
  s.P_N = 1;  // kappa = k_a P_N / (3 P_s) = 0.5
  for (int sgn : {+1, -1}) {
    s.sgn_PT = sgn;
    for (double mu : {0.6, 1.5}) {
      p.mu = mu;
      CAPTURE(sgn, mu);
      const double kappa = 0.5, g = 1 + p.a11 * p.C_T;
      const double Lambda = p.a11 - mu * sgn * p.a12 + kappa * (sgn * p.a12 - mu * p.a22) -
                            mu * kappa * p.C_T * p.detA();
      // L_s = 0: (s + mu a12 C_T) dF_T = mu g dF_N; L_s > 0 on the side theta_L - pi/2 .. + pi/2.
      const double cT = sgn + mu * p.a12 * p.C_T, cN = -mu * g;
      const double t1 = wrap(std::atan2(-cT, cN)), t2 = wrap(std::atan2(cT, -cN));
      const DirectionMap m = compute_direction_map(p, s);
      // Either sign: the types change across L_s = 0 (stick | slip), so both directions of
      // L_s = 0 are critical; on them only stick (lambda = 0).
      REQUIRE(m.critical.size() == 2);
      CHECK(m.critical[0].theta == Approx(std::min(t1, t2)).margin(1e-13));
      CHECK(m.critical[1].theta == Approx(std::max(t1, t2)).margin(1e-13));
      for (const auto& c : m.critical) CHECK(c.summary.count == 1);
      REQUIRE(m.sectors.size() == 2);
      for (const auto& sec : m.sectors) {
        const double mid = 0.5 * (sec.theta_from + sec.theta_to);
        const double L = cT * std::cos(mid) + cN * std::sin(mid);
        if (Lambda > 0) CHECK(sec.summary.count == 1);  // unique: stick (L < 0) or slip (L > 0)
        else CHECK(sec.summary.count == (L < 0 ? 2 : 0));
      }
    }
  }
}

// Softening criterion (35): the slip equations use mu_eff = mu - 2 kappa (docs/model.md), so the
// critical directions are where (s + m a12 C_T) dF_T - m (1 + a11 C_T) dF_N = 0 with m = mu_eff,
// and the sectors follow the sign of Lambda(m). Here kappa = 0.5: m = mu - 1.
TEST_CASE("StateDSofteningCriterionUsesMuEff", "[map][direction]") {
  ContactParameters p = fig5(0.6);
  p.k_a = 1.5;
  p.P_s = 1;
  p.criterion = Criterion::kSoftening;
  ContactState s;
  s.label = StateLabel::kD;
  s.P_N = 1;  // kappa = 0.5; (46) needs mu > kappa
  for (int sgn : {+1, -1}) {
    s.sgn_PT = sgn;
    for (double mu : {1.6, 3.0}) {  // m = 0.6 (Lambda > 0), m = 2 (Lambda < 0)
      p.mu = mu;
      CAPTURE(sgn, mu);
      const double kappa = 0.5, m = mu - 2 * kappa, g = 1 + p.a11 * p.C_T;
      const double Lambda = p.a11 - m * sgn * p.a12 + kappa * (sgn * p.a12 - m * p.a22) -
                            m * kappa * p.C_T * p.detA();
      const double cT = sgn + m * p.a12 * p.C_T, cN = -m * g;
      const double t1 = wrap(std::atan2(-cT, cN)), t2 = wrap(std::atan2(cT, -cN));
      MapOptions opt;
      opt.method = RateMethod::kAnalytic;  // cross-checked by the enumeration on every sample
      const DirectionMap map = compute_direction_map(p, s, opt);
      CHECK(map.disagreements == 0);
      CHECK(map.unreliable == 0);
      REQUIRE(map.critical.size() == 2);
      CHECK(map.critical[0].theta == Approx(std::min(t1, t2)).margin(1e-13));
      CHECK(map.critical[1].theta == Approx(std::max(t1, t2)).margin(1e-13));
      REQUIRE(map.sectors.size() == 2);
      for (const auto& sec : map.sectors) {
        const double mid = 0.5 * (sec.theta_from + sec.theta_to);
        const double L = cT * std::cos(mid) + cN * std::sin(mid);
        if (Lambda > 0) CHECK(sec.summary.count == 1);
        else CHECK(sec.summary.count == (L < 0 ? 2 : 0));
      }
    }
  }
}

TEST_CASE("StatesAAndCAreUniqueForEveryDirection", "[map][direction]") {
  for (StateLabel l : {StateLabel::kA, StateLabel::kC}) {
    ContactState s;
    s.label = l;
    s.P_N = l == StateLabel::kC ? 1.0 : 0.0;
    const DirectionMap m = compute_direction_map(fig5(3.0), s);
    REQUIRE(m.sectors.size() == 1);
    CHECK(m.sectors[0].theta_from == 0);
    CHECK(m.sectors[0].theta_to == Approx(2 * kPi));
    CHECK(m.sectors[0].summary.count == 1);
    CHECK(m.critical.empty());
  }
}

TEST_CASE("DegenerateA11EqualsMuA12GivesAContinuumOnN0", "[map][direction]") {
  // a11 = mu a12 (D+ = 0): on N = 0 with dF_N > 0 a segment of solutions (model.md Sec. 2),
  // on N = 0 with dF_N < 0 a unique slip- solution.
  const DirectionMap m = compute_direction_map(fig5(2.0), state_b());
  const double tN = std::atan(0.5);
  bool found_up = false, found_down = false;
  for (const auto& c : m.critical) {
    if (std::abs(c.theta - tN) < 1e-12) {
      found_up = true;
      CHECK(c.summary.count == -1);
    }
    if (std::abs(c.theta - tN - kPi) < 1e-12) {
      found_down = true;
      CHECK(c.summary.count == 1);
    }
  }
  CHECK(found_up);
  CHECK(found_down);
}

TEST_CASE("StateDWithLambdaZeroHasARayOnLs0", "[map][direction]") {
  // C_T = 0, a11 = 1, a12 = 0.5, a22 = 1, mu = 1, kappa = k_a P_N / (3 P_s) = 1:
  // Lambda = a11 - mu a12 + kappa (a12 - mu a22) = 0.5 - 0.5 = 0 exactly. model.md: one solution
  // (stick) for L_+ < 0, a ray on L_+ = 0, none for L_+ > 0; L_+ = dF_T - dF_N.
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 0.5;
  p.a22 = 1;
  p.mu = 1;
  p.C_T = 0;
  p.k_a = 3;
  p.P_s = 1;
  ContactState s;
  s.label = StateLabel::kD;
  s.P_N = 1;
  s.sgn_PT = +1;
  const DirectionMap m = compute_direction_map(p, s);
  REQUIRE(m.critical.size() == 2);
  CHECK(m.critical[0].theta == Approx(kPi / 4).margin(1e-14));
  CHECK(m.critical[1].theta == Approx(5 * kPi / 4).margin(1e-14));
  for (const auto& c : m.critical) CHECK(c.summary.count == -1);
  REQUIRE(m.sectors.size() == 2);
  CHECK(m.sectors[0].summary.count == 1);  // (pi/4, 5 pi/4): L_+ < 0, stick
  CHECK(m.sectors[0].summary.types == kStick);
  CHECK(m.sectors[1].summary.count == 0);  // L_+ > 0
}

TEST_CASE("DirectionMapRejectsBadInput", "[map][direction]") {
  ContactParameters p = fig5(1.0);
  p.mu = std::nan("");
  CHECK_THROWS_AS(compute_direction_map(p, state_b()), cpkit::InputError);
  p = fig5(1.0);
  p.a12 = 2.0;  // A not SPD
  CHECK_THROWS_AS(compute_direction_map(p, state_b()), cpkit::InputError);
  MapOptions opt;
  opt.method = RateMethod::kLemke;  // single-solution method: cannot count
  CHECK_THROWS_AS(compute_direction_map(fig5(1.0), state_b(), opt), cpkit::InputError);
}

// State d over random models (Lambda of both signs): on every sector and every exact critical
// direction L_s = 0 the enumeration route and the closed forms (d.i-d.ii) give the same count and
// types. (Until issue 6 fixed it, the enumeration missed the stick solution on L_s = 0 when
// Lambda < 0.)
TEST_CASE("StateDCriticalDirectionsAgreeAcrossRoutes", "[map][direction]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int disagreeing_maps = 0;
  for (int trial = 0; trial < 50; ++trial) {
    ContactParameters p;
    p.a11 = 0.5 + 2 * u(rng);
    p.a22 = 0.5 + 2 * u(rng);
    p.a12 = (2 * u(rng) - 1) * 0.95 * std::sqrt(p.a11 * p.a22);
    p.mu = 0.1 + 3 * u(rng);
    p.C_T = 2 * u(rng);
    p.k_a = 3 * u(rng);
    ContactState s;
    s.label = StateLabel::kD;
    s.P_N = 0.2 + 2 * u(rng);
    s.sgn_PT = u(rng) < 0.5 ? 1 : -1;
    MapOptions opt;
    opt.method = RateMethod::kAnalytic;
    disagreeing_maps += compute_direction_map(p, s, opt).disagreements > 0;
  }
  CHECK(disagreeing_maps == 0);
}
