// The contact-model types: validation (bad input throws InputError naming the problem),
// enum names, the classification of a configuration into the states a-d.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/wear.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"

using namespace cpkit::rate;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_CASE("ContactParameters::validate names the bad field", "[rate][model]") {
  ContactParameters p;
  CHECK(p.validate().empty());
  auto bad = [](auto change, const char* needle) {
    ContactParameters q;
    change(q);
    const std::string m = q.validate();
    CAPTURE(m, needle);
    CHECK(m.find(needle) != std::string::npos);
  };
  bad([](ContactParameters& q) { q.a12 = 2; }, "positive definite");      // det < 0
  bad([](ContactParameters& q) { q.a12 = 1; }, "positive definite");      // det = 0
  bad([](ContactParameters& q) { q.a11 = -1; q.a22 = -1; }, "positive definite");
  bad([](ContactParameters& q) { q.mu = 0; }, "mu");
  bad([](ContactParameters& q) { q.mu = -0.1; }, "mu");
  bad([](ContactParameters& q) { q.C_T = -1e-3; }, "C_T");
  bad([](ContactParameters& q) { q.k_a = -1; }, "k_a");
  bad([](ContactParameters& q) { q.P_s = 0; }, "P_s");
  bad([](ContactParameters& q) { q.a11 = kNaN; }, "a11");
  bad([](ContactParameters& q) { q.mu = kInf; }, "mu");
  bad([](ContactParameters& q) { q.C_T = kNaN; }, "C_T");
  CHECK(p.D0() == Approx(1.0));
  p.a11 = 2; p.a12 = 1; p.a22 = 3; p.C_T = 0.5;
  CHECK(p.detA() == Approx(5));
  CHECK(p.D0() == Approx(3 + 0.5 * 5));
  p.k_a = 0.6; p.P_s = 2;
  CHECK(p.kappa(3) == Approx(0.6 * 3 / 6));
}

TEST_CASE("enum names round-trip", "[rate][model]") {
  for (auto c : {Criterion::kCoulomb, Criterion::kSoftening})
    CHECK(criterion_from_string(to_string(c)) == c);
  CHECK(criterion_from_string("38") == Criterion::kCoulomb);
  CHECK(criterion_from_string("35") == Criterion::kSoftening);
  CHECK_FALSE(criterion_from_string("36"));
  for (auto s : {StateLabel::kA, StateLabel::kB, StateLabel::kC, StateLabel::kD})
    CHECK(state_from_string(to_string(s)) == s);
  CHECK_FALSE(state_from_string("e"));
  // The words of docs/model.md's states are aliases of the letters.
  CHECK(state_from_string("open") == StateLabel::kA);
  CHECK(state_from_string("grazing") == StateLabel::kB);
  CHECK(state_from_string("stick") == StateLabel::kC);
  CHECK(state_from_string("sliding") == StateLabel::kD);
  CHECK(to_string(StateLabel::kC) == "c");
  CHECK(to_string(Criterion::kCoulomb) == "coulomb");
  for (auto t : {SolutionType::kOpen, SolutionType::kSeparation, SolutionType::kStick,
                 SolutionType::kSlipPlus, SolutionType::kSlipMinus, SolutionType::kSlip})
    CHECK(solution_type_from_string(to_string(t)) == t);
  CHECK(to_string(SolutionType::kSlip) == "slip");  // the 3-D type's string (JSON "type")
  CHECK(to_string(SolutionType::kSlipPlus) == "slip+");
  for (auto m : {RateMethod::kEnumerate, RateMethod::kAnalytic, RateMethod::kLemke,
                 RateMethod::kFbNewton, RateMethod::kIpopt})
    CHECK(rate_method_from_string(to_string(m)) == m);
  CHECK(to_string(RateSolution::Kind::kRay) == "ray");
}

TEST_CASE("wear law and branch rule names (the CLI's --wear-law and --branch-rule values)",
          "[rate][model]") {
  // docs/model.md: the laws (37) Archard and (41) Mroz-Stupkiewicz, `--wear-law mroz`.
  CHECK(to_string(WearLaw::kArchard) == "archard");
  CHECK(to_string(WearLaw::kMrozStupkiewicz) == "mroz-stupkiewicz");
  for (const char* name : {"archard", "37"}) CHECK(wear_law_from_string(name) == WearLaw::kArchard);
  for (const char* name : {"mroz-stupkiewicz", "mroz", "41"})
    CHECK(wear_law_from_string(name) == WearLaw::kMrozStupkiewicz);
  for (const char* name : {"Archard", "38", "", "unknown"}) CHECK_FALSE(wear_law_from_string(name));
  CHECK(to_string(BranchRule::kClosest) == "closest");
  CHECK(to_string(BranchRule::kStop) == "stop");
  CHECK(branch_rule_from_string("closest") == BranchRule::kClosest);
  CHECK(branch_rule_from_string("stop") == BranchRule::kStop);
  CHECK_FALSE(branch_rule_from_string("Stop"));
}

TEST_CASE("ContactState::validate", "[rate][model]") {
  ContactParameters p;
  CHECK(ContactState{StateLabel::kB, 0, 1}.validate(p).empty());
  CHECK(ContactState{StateLabel::kD, 1, -1}.validate(p).empty());
  CHECK_FALSE(ContactState{StateLabel::kC, 0, 1}.validate(p).empty());   // P_N <= 0 in c
  CHECK_FALSE(ContactState{StateLabel::kD, -1, 1}.validate(p).empty());  // P_N <= 0 in d
  CHECK_FALSE(ContactState{StateLabel::kD, 1, 0}.validate(p).empty());   // no sliding sign
  CHECK_FALSE(ContactState{StateLabel::kD, kNaN, 1}.validate(p).empty());
  CHECK_FALSE(ContactState{StateLabel::kB, 1, 1}.validate(p).empty());   // P = 0 in b
  // (46) under (35): k P_N < mu, k = k_a/(3 P_s) = 0.1 with k_a = 0.3, P_s = 1, mu = 0.5: P_N < 5
  p.criterion = Criterion::kSoftening;
  p.k_a = 0.3;
  CHECK(ContactState{StateLabel::kD, 4.9, 1}.validate(p).empty());
  CHECK(ContactState{StateLabel::kD, 5.01, 1}.validate(p).find("(46)") != std::string::npos);
  CHECK(ContactState{StateLabel::kD, 5.0, 1}.validate(p).find("(46)") != std::string::npos);
  CHECK(ContactState{StateLabel::kC, 7.0, 1}.validate(p).find("(46)") != std::string::npos);
  p.criterion = Criterion::kCoulomb;
  CHECK(ContactState{StateLabel::kD, 7.0, 1}.validate(p).empty());  // no bound for (38)
}

TEST_CASE("classify: states a-d with the documented tolerance", "[rate][model]") {
  ContactParameters p;  // mu = 0.5
  auto cl = [&](double wN, double ww, double PN, double PT) {
    return classify(ContactConfiguration{wN, ww, 0, PN, PT}, p);
  };
  CHECK(cl(-0.1, 0, 0, 0).label == StateLabel::kA);
  CHECK(cl(0.3, 0.3, 0, 0).label == StateLabel::kB);
  CHECK(cl(0.3, 0.3 + 1e-14, 0, 0).label == StateLabel::kB);  // within tol: grazing
  CHECK(cl(0, 0, 2, 0.5).label == StateLabel::kC);
  const ContactState d = cl(0, 0, 2, -1);
  CHECK(d.label == StateLabel::kD);
  CHECK(d.sgn_PT == -1);
  CHECK(d.P_N == 2);
  CHECK(cl(0, 0, 2, 1 - 1e-14).label == StateLabel::kD);  // on the cone within tol
  CHECK(cl(0, 0, 2, 1 - 1e-6).label == StateLabel::kC);
  // inadmissible
  CHECK_THROWS_AS(cl(0, 0, -1, 0), cpkit::InputError);          // tension
  CHECK_THROWS_AS(cl(0.1, 0, 0, 0), cpkit::InputError);         // penetration
  CHECK_THROWS_AS(cl(0, 0, 2, 1.1), cpkit::InputError);         // outside the cone
  CHECK_THROWS_AS(cl(0, 0, 0, 0.1), cpkit::InputError);         // P_T without P_N
  CHECK_THROWS_AS(cl(-0.1, 0, 1, 0), cpkit::InputError);        // force with an open gap
  CHECK_THROWS_AS(cl(kNaN, 0, 0, 0), cpkit::InputError);
  // criterion (35): |P_T| <= mu P_N - k P_N^2; k = 0.1 (k_a = 0.3, P_s = 1): at P_N = 2 the
  // limit is 1 - 0.4 = 0.6
  p.criterion = Criterion::kSoftening;
  p.k_a = 0.3;
  CHECK(cl(0, 0, 2, 0.6).label == StateLabel::kD);
  CHECK(cl(0, 0, 2, 0.5).label == StateLabel::kC);
  CHECK_THROWS_AS(cl(0, 0, 2, 0.7), cpkit::InputError);
  CHECK_THROWS_AS(cl(0, 0, 6, 0), cpkit::InputError);  // beyond the bound (46)
}

TEST_CASE("solve_rate_problem: bad input throws InputError naming the problem", "[rate][model]") {
  ContactParameters p;
  const ContactState b{StateLabel::kB, 0, 1};
  for (auto m : {RateMethod::kEnumerate, RateMethod::kAnalytic, RateMethod::kLemke}) {
    CAPTURE(to_string(m));
    CHECK_THROWS_WITH(solve_rate_problem(p, b, {kNaN, 1}, m), Catch::Contains("load rate"));
    CHECK_THROWS_WITH(solve_rate_problem(p, b, {1, kInf}, m), Catch::Contains("load rate"));
    ContactParameters q = p;
    q.a12 = 3;
    CHECK_THROWS_WITH(solve_rate_problem(q, b, {1, 1}, m), Catch::Contains("positive definite"));
    q = p;
    q.mu = 0;
    CHECK_THROWS_WITH(solve_rate_problem(q, b, {1, 1}, m), Catch::Contains("mu"));
    CHECK_THROWS_WITH(solve_rate_problem(p, {StateLabel::kC, 0, 1}, {1, 1}, m),
                      Catch::Contains("P_N > 0"));
    CHECK_THROWS_WITH(solve_rate_problem(p, {StateLabel::kD, -2, 1}, {1, 1}, m),
                      Catch::Contains("P_N > 0"));
    CHECK_THROWS_AS(solve_rate_problem(p, {StateLabel::kD, 1, 0}, {1, 1}, m), cpkit::InputError);
  }
}

TEST_CASE("zero load: the unique zero solution", "[rate][model]") {
  ContactParameters p;
  p.a12 = 0.9;
  p.mu = 3;  // a11 < mu |a12|: non-unique for some directions, still unique at dF = 0
  for (auto label : {StateLabel::kA, StateLabel::kB, StateLabel::kC, StateLabel::kD}) {
    const ContactState st{label, label == StateLabel::kC || label == StateLabel::kD ? 1.0 : 0.0, 1};
    for (auto m : {RateMethod::kEnumerate, RateMethod::kAnalytic}) {
      const auto s = solve_rate_problem(p, st, {0, 0}, m);
      CAPTURE(to_string(label), to_string(m));
      if (label == StateLabel::kD) {
        // Lambda = 1 - 3*0.9 < 0 and L_s = 0: stick only (the slip branch needs L_s/Lambda > 0)
        CHECK(s.Lambda < 0);
      }
      REQUIRE(s.count() == 1);
      CHECK(s.solutions[0].start.dP_N == 0);
      CHECK(s.solutions[0].start.dw_T == 0);
    }
  }
}
