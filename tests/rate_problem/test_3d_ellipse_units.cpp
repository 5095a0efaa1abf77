// The units of the friction ellipse (issue 24, item 2): multiplying alpha by c and dividing mu
// by c leaves the friction set ||D^-1 P_T|| <= mu P_N and the flow direction D^-2 P_T unchanged;
// with Archard's wear k P_N |D dw_T^i| also divided by c (k_a / c) the model is the same, and
// only the multiplier lambda = |D dw_T^i| scales (by c). Independent source: that identity of
// the model (docs/contact_3d.md, (38)-(40)); every 3-D route must give the same solutions
// (forces, displacements; lambda times c) for c in 1e-12..1e12, also with A and the loads
// scaled at the same time (the force and stiffness units).
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "rate3d_test_util.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"

using namespace cpkit::rate;

namespace {
constexpr double kPi = 3.14159265358979323846;
const double kUnits[] = {1e-12, 1e-8, 1e-4, 1e4, 1e8, 1e12};

/// The same model with the ellipse in the unit c (and the force unit s: A s, C_T / s, loads s,
/// k_a / s).
ContactParameters3d in_units(ContactParameters3d p, double c, double s) {
  p.alpha *= c;
  p.mu /= c;
  p.k_a /= c * s;
  p.A *= s;
  p.C_T /= s;
  return p;
}

bool close(double a, double b, double scale) { return std::abs(a - b) <= 1e-7 * scale; }

bool same_rates(const Rates3d& a, const Rates3d& b, double s) {
  const double f = std::max({a.dP_T.cwiseAbs().maxCoeff(), std::abs(a.dP_N), 1e-300});
  const double d = std::max({a.dw_T.cwiseAbs().maxCoeff(), std::abs(a.dw_N), 1e-300});
  return close(a.dP_T(0), b.dP_T(0) / s, f) && close(a.dP_T(1), b.dP_T(1) / s, f) &&
         close(a.dP_N, b.dP_N / s, f) && close(a.dw_T(0), b.dw_T(0), d) &&
         close(a.dw_T(1), b.dw_T(1), d) && close(a.dw_N, b.dw_N, d) &&
         close(a.dw_Ti(0), b.dw_Ti(0), d) && close(a.dw_Ti(1), b.dw_Ti(1), d);
}

/// Step values of the unit (c, s) against the reference: forces / s, lambda / c.
bool same_step(const Step3dValues& a, const Step3dValues& b, double c, double s) {
  const double f = std::max({a.P_T1.cwiseAbs().maxCoeff(), std::abs(a.P_N1), 1e-300});
  const double d = std::max({a.Dw_T.cwiseAbs().maxCoeff(), std::abs(a.Dw_N), 1e-300});
  return close(a.P_T1(0), b.P_T1(0) / s, f) && close(a.P_T1(1), b.P_T1(1) / s, f) &&
         close(a.P_N1, b.P_N1 / s, f) && close(a.Dw_T(0), b.Dw_T(0), d) &&
         close(a.Dw_T(1), b.Dw_T(1), d) && close(a.Dw_N, b.Dw_N, d) &&
         close(a.Dw_w, b.Dw_w, d) && close(a.lambda, b.lambda / c, std::max(a.lambda, d));
}

/// Forces and displacements only, to 1e-6 (an iterative solver's answer; lambda is not unique
/// at P1 = 0).
bool same_point(const Step3dValues& a, const Step3dValues& b, double s) {
  const double f = std::max({a.P_T1.cwiseAbs().maxCoeff(), std::abs(a.P_N1), 1e-300});
  // displacements relative to their own size or to forces / |A| (|A| ~ 1 in the reference)
  const double d = std::max({a.Dw_T.cwiseAbs().maxCoeff(), std::abs(a.Dw_N), 1e-3 * f});
  auto near = [](double x, double y, double sc) { return std::abs(x - y) <= 1e-6 * sc; };
  return near(a.P_T1(0), b.P_T1(0) / s, f) && near(a.P_T1(1), b.P_T1(1) / s, f) &&
         near(a.P_N1, b.P_N1 / s, f) && near(a.Dw_T(0), b.Dw_T(0), d) &&
         near(a.Dw_T(1), b.Dw_T(1), d) && near(a.Dw_N, b.Dw_N, d);
}

ContactParameters3d random_params(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(0.05, 1);
  ContactParameters3d p;
  p.A = cpkit::test::coupled_spd(rng, 1.5, rng() % 2 == 0);
  p.mu = 0.2 + 2 * pos(rng);
  p.C_T = rng() % 2 ? 0.0 : pos(rng);
  p.alpha = {0.3 + pos(rng), 0.3 + pos(rng)};
  p.k_a = rng() % 2 ? 0.0 : pos(rng);
  return p;
}

}  // namespace

TEST_CASE("3-D rate: the issue's ellipse reproducers", "[rate3d][units]") {
  // A slip that must stay a slip, and a stick that must stay a stick, for every unit c.
  ContactParameters3d p;
  p.A << 2, 0, 1, 0, 1.5, 0.3, 1, 0.3, 2;
  p.mu = 0.8;
  p.alpha = {1, 0.5};
  for (const Eigen::Vector3d& dF : {Eigen::Vector3d(1, 0.4, 0.3), Eigen::Vector3d(0.1, 0.05, 1)}) {
    const RateSolutionSet3d ref = solve_rate_3d(p, {}, dF);
    REQUIRE(ref.complete);
    REQUIRE(ref.count() >= 1);
    for (double c : kUnits) {
      CAPTURE(c, dF.transpose());
      const RateSolutionSet3d x = solve_rate_3d(in_units(p, c, 1), {}, dF);
      INFO(x.message);
      CHECK(x.complete);
      REQUIRE(x.count() == ref.count());
      for (int k = 0; k < ref.count(); ++k) {
        CHECK(x.solutions[k].type == ref.solutions[k].type);
        CHECK(same_rates(ref.solutions[k].at, x.solutions[k].at, 1));
        if (x.solutions[k].type == SolutionType::kStick)
          CHECK(x.solutions[k].at.dw_Ti.cwiseAbs().maxCoeff() == 0);
      }
    }
  }
}

TEST_CASE("3-D rate (exact and faceted), every state: the same solutions in every ellipse unit",
          "[rate3d][units]") {
  std::mt19937 rng(2402);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.2, 1);
  for (int trial = 0; trial < 60; ++trial) {
    const ContactParameters3d p = random_params(rng);
    ContactState3d st;
    st.state = "bcd"[trial % 3];
    if (st.state != 'b') {
      st.P_N = pos(rng);
      const double th = kPi * u(rng);
      st.P_T = (st.state == 'c' ? 0.5 : 1.0) * p.mu * st.P_N *
               p.alpha.cwiseProduct(Eigen::Vector2d(std::cos(th), std::sin(th)));
    }
    const Eigen::Vector3d dF(u(rng), u(rng), u(rng));
    const RateSolutionSet3d ref = solve_rate_3d(p, st, dF);
    const RateSolutionSet3d fref = solve_rate_3d_faceted(p, dF, 8);
    for (double c : kUnits)
      for (double s : {1.0, 1e-9, 1e9}) {
        CAPTURE(trial, st.state, c, s);
        ContactState3d sts = st;
        sts.P_T *= s;
        sts.P_N *= s;
        const ContactParameters3d q = in_units(p, c, s);
        const RateSolutionSet3d x = solve_rate_3d(q, sts, s * dF);
        INFO(ref.message << " / " << x.message);
        CHECK(x.complete == ref.complete);
        REQUIRE(x.count() == ref.count());
        for (int k = 0; k < ref.count(); ++k) {
          CHECK(x.solutions[k].type == ref.solutions[k].type);
          CHECK(same_rates(ref.solutions[k].at, x.solutions[k].at, s));
        }
        if (st.state != 'b') continue;
        const RateSolutionSet3d f = solve_rate_3d_faceted(q, s * dF, 8);
        CHECK(f.complete == fref.complete);
        REQUIRE(f.count() == fref.count());
        for (int k = 0; k < fref.count(); ++k) CHECK(same_rates(fref.solutions[k].at, f.solutions[k].at, s));
      }
  }
}

TEST_CASE("3-D step (exact, FB-SOC, faceted): the same solutions in every ellipse unit",
          "[step3d][units]") {
  std::mt19937 rng(2403);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.2, 1);
  for (int trial = 0; trial < 60; ++trial) {
    Step3dProblem p;
    p.params = random_params(rng);
    if (trial % 4 == 3) {
      p.wear.law = cpkit::rate::WearLaw::kMrozStupkiewicz;
      p.wear.k_M = 0.3 * pos(rng);
    }
    if (trial % 2) {
      p.state.P_N0 = pos(rng);
      const double th = kPi * u(rng);
      p.state.P_T0 = 0.7 * p.params.mu * p.state.P_N0 *
                     p.params.alpha.cwiseProduct(Eigen::Vector2d(std::cos(th), std::sin(th)));
    }
    p.DF << u(rng), u(rng), u(rng);
    const Step3dSolutionSet ref = enumerate_step_3d(p);
    const Step3dSolveResult fb_ref = solve_step_3d_fb_soc(p);
    for (double c : kUnits)
      for (double s : {1.0, 1e-9, 1e9}) {
        CAPTURE(trial, c, s);
        Step3dProblem q = p;
        q.params = in_units(p.params, c, s);
        q.wear.k_M = p.wear.k_M / s;  // c_w = k_M mu: mu / c, lambda c
        q.state.P_T0 *= s;
        q.state.P_N0 *= s;
        q.DF *= s;
        const Step3dSolutionSet x = enumerate_step_3d(q);
        INFO(ref.message << " / " << x.message);
        CHECK(x.complete == ref.complete);
        REQUIRE(x.count() == ref.count());
        for (int k = 0; k < ref.count(); ++k) {
          CHECK(x.solutions[k].type == ref.solutions[k].type);
          CHECK(same_step(ref.solutions[k].values, x.solutions[k].values, c, s));
          CHECK(x.solutions[k].residual <= 1e-9);
        }
        // FB-SOC is a local method: with several solutions it may reach another one, but
        // always one of the exact set, whatever the units.
        const Step3dSolveResult fb = solve_step_3d_fb_soc(q);
        CHECK((fb.status == cpkit::Status::kSolved) == (fb_ref.status == cpkit::Status::kSolved));
        if ((fb.status == cpkit::Status::kSolved) && ref.complete) {
          bool in_set = false;
          for (const auto& r : ref.solutions)
            in_set = in_set || same_point(r.values, fb.solution.values, s);
          CHECK(in_set);
        }
        if (q.wear_coefficient() == 0) {
          const FacetedStep3dResult f = solve_step_3d_faceted(q, 8);
          const FacetedStep3dResult fr = solve_step_3d_faceted(p, 8);
          REQUIRE(f.set.count() == fr.set.count());
          for (int k = 0; k < f.set.count(); ++k)
            CHECK(same_step(fr.set.solutions[k].values, f.set.solutions[k].values, c, s));
        }
      }
  }
}

TEST_CASE("N-point 3-D rate and step: the same solutions in every ellipse unit",
          "[rate3d][step3d][system][units]") {
  std::mt19937 rng(2404);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.2, 1);
  for (int trial = 0; trial < 12; ++trial) {
    ContactSystem3d sys;
    const int N = 2;
    Eigen::MatrixXd L(3 * N, 3 * N);
    for (int i = 0; i < L.size(); ++i) L(i) = u(rng);
    sys.A = L * L.transpose() + 0.2 * Eigen::MatrixXd::Identity(3 * N, 3 * N);
    for (int i = 0; i < N; ++i) {
      SystemPoint3d pt;
      pt.mu = 0.3 + pos(rng);
      pt.C_T = trial % 2 ? 0.0 : pos(rng);
      pt.alpha = {0.3 + pos(rng), 0.3 + pos(rng)};
      pt.state.state = 'b';
      sys.points.push_back(pt);
    }
    Eigen::VectorXd dF(3 * N);
    for (int i = 0; i < 3 * N; ++i) dF(i) = u(rng);
    const SystemRateSet3d ref = solve_system_rate_3d_faceted(sys, dF, 4);
    SystemStep3dProblem sp;
    sp.system = sys;
    sp.states.assign(N, Step3dState{});
    sp.DF = dF;
    const SystemStep3dSolveResult sref = solve_system_step_3d_fb_soc(sp);
    for (double c : kUnits) {
      CAPTURE(trial, c);
      ContactSystem3d q = sys;
      for (auto& pt : q.points) pt.alpha *= c, pt.mu /= c;
      const SystemRateSet3d x = solve_system_rate_3d_faceted(q, dF, 4);
      CHECK(x.complete == ref.complete);
      REQUIRE(x.count() == ref.count());
      for (int k = 0; k < ref.count(); ++k)
        for (int i = 0; i < N; ++i) {
          CHECK(x.solutions[k].types[i] == ref.solutions[k].types[i]);
          CHECK(same_rates(ref.solutions[k].rates[i], x.solutions[k].rates[i], 1));
        }
      SystemStep3dProblem sq = sp;
      sq.system = q;
      const SystemStep3dSolveResult s = solve_system_step_3d_fb_soc(sq);
      CHECK((s.status == cpkit::Status::kSolved) == (sref.status == cpkit::Status::kSolved));
      if ((s.status == cpkit::Status::kSolved) && (sref.status == cpkit::Status::kSolved))
        for (int i = 0; i < N; ++i)
          CHECK(same_step(sref.solution.points[i].values, s.solution.points[i].values, c, 1));
    }
  }
}
