// The implicit step of N coupled 3-D points (system_step_3d.hpp) against independent sources:
// (a) N = 1: every FB-SOC / multistart solution is in enumerate_step_3d's exact set;
// (b) block-diagonal A (uncoupled points): per point, every solution is in that point's exact
//     one-point set, and products of one-point exact solutions pass system_step_3d_residual;
// (c) isotropic points whose Y directions are decoupled and unloaded: every solution is a
//     solution of the 2-D N-point step rate::enumerate_system_step (the X-N DOFs);
// (d) units: forces scaled by 1e-12..1e12 and the stiffness by 1e-9..1e9 give the same verdicts;
// (e) bad input throws InputError.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

#include "rate3d_test_util.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/system_step.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/system_step_3d.hpp"

using namespace cpkit::rate;
namespace r2 = cpkit::rate;
using cpkit::test::coupled_spd;

namespace {
constexpr double kPi = 3.14159265358979323846;

/// A random admissible start state of one point: grazing, open, stick, on the ellipse.
Step3dState random_state(std::mt19937& rng, double mu, const Eigen::Vector2d& alpha, int kind,
                         bool y_zero) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  Step3dState s;
  switch (kind % 4) {
    case 0: break;
    case 1: s.g0 = -0.3 * pos(rng); break;
    default: {
      s.P_N0 = 2 * pos(rng);
      const double th = y_zero ? (u(rng) > 0 ? 0 : kPi) : kPi * u(rng);
      const double r = kind % 4 == 2 ? 0.9 * pos(rng) : 1.0;
      s.P_T0 = r * mu * s.P_N0 * alpha.cwiseProduct(Eigen::Vector2d(std::cos(th), std::sin(th)));
      if (y_zero) s.P_T0(1) = 0;
    }
  }
  return s;
}

SystemPoint3d random_point(std::mt19937& rng, bool isotropic, bool wear) {
  std::uniform_real_distribution<double> pos(0.05, 1);
  SystemPoint3d q;
  q.mu = 0.3 + 1.5 * pos(rng);
  q.C_T = pos(rng) < 0.5 ? 0.0 : 0.3 * pos(rng);
  q.k_a = wear ? 0.5 * pos(rng) : 0.0;
  q.P_s = 1;
  q.alpha = isotropic ? Eigen::Vector2d(1, 1) : Eigen::Vector2d(0.5 + pos(rng), 0.5 + pos(rng));
  return q;
}

/// A generic coupled SPD matrix of size n.
Eigen::MatrixXd random_spd(std::mt19937& rng, int n, double shift) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd B(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) B(i, j) = u(rng);
  Eigen::MatrixXd A = B * B.transpose() / n;
  A.diagonal().array() += shift;
  return A;
}

Eigen::VectorXd random_load(std::mt19937& rng, int n, bool y_zero) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd DF(n);
  for (int i = 0; i < n; ++i) DF(i) = u(rng);
  if (y_zero)
    for (int i = 1; i < n; i += 3) DF(i) = 0;
  return DF;
}

bool in_set(const Step3dValues& v, const Step3dSolutionSet& s, double F) {
  for (const auto& x : s.solutions)
    if (std::max((x.values.P_T1 - v.P_T1).cwiseAbs().maxCoeff(), std::abs(x.values.P_N1 - v.P_N1)) <=
        1e-6 * F)
      return true;
  return false;
}

double force_scale(const SystemStep3dProblem& p) {
  double f = p.DF.cwiseAbs().maxCoeff();
  for (const auto& s : p.states) f = std::max({f, s.P_N0, s.P_T0.cwiseAbs().maxCoeff()});
  return std::max(f, 1e-300);
}

}  // namespace

TEST_CASE("SystemStep3dN1InExactSet", "[system_step_3d]") {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> pos(0.05, 1);
  int problems = 0, found = 0, from_start = 0, agree_one_point = 0, iters = 0;
  for (int c = 0; c < 200; ++c) {
    SystemStep3dProblem p;
    const bool wear = c % 2 == 1;
    p.system.points.push_back(random_point(rng, false, wear));
    p.system.A = coupled_spd(rng, 1.0, c % 3 != 0);
    if (wear && c % 4 == 3) {
      p.wear.law = r2::WearLaw::kMrozStupkiewicz;
      p.system.points[0].k_a = 0;
      p.wear.k_M = 0.5 * pos(rng);
    }
    const auto& q = p.system.points[0];
    p.states.push_back(random_state(rng, q.mu, q.alpha, c, false));
    p.DF = random_load(rng, 3, false);
    REQUIRE(p.validate().empty());
    const Step3dSolutionSet exact = enumerate_step_3d(p.point_problem(0));
    if (!exact.complete) continue;
    ++problems;
    const double F = force_scale(p);
    const SystemStep3dSolveResult r = solve_system_step_3d_fb_soc(p);
    iters += r.iterations;
    const Step3dSolveResult one = solve_step_3d_fb_soc(p.point_problem(0));
    if ((r.status == cpkit::Status::kSolved) == (one.status == cpkit::Status::kSolved)) ++agree_one_point;
    if ((r.status == cpkit::Status::kSolved)) {
      ++from_start;
      CHECK(in_set(r.solution.points[0].values, exact, F));
      CHECK(r.solution.residual <= 1e-9);
    }
    const SystemStep3dSolutionSet ms = multistart_system_step_3d(p, 6, 7);
    CHECK_FALSE(ms.complete);
    for (const auto& s : ms.solutions) {
      CHECK(s.residual <= 1e-9);
      CHECK(in_set(s.points[0].values, exact, F));
    }
    found += ms.count();
    // The exact solutions pass the system residual (N = 1: the same terms).
    for (const auto& x : exact.solutions) {
      CHECK(system_step_3d_residual(p, {x.values}) <= 1e-9);
      CHECK(std::abs(system_step_3d_residual(p, {x.values}) - x.residual) <= 1e-13);
    }
  }
  std::cout << "[system_step_3d] N = 1: " << problems << " problems, FB-SOC from the start state "
            << from_start << " verified (" << double(iters) / std::max(problems, 1)
            << " Newton iterations on average), same verdict as the one-point solver in "
            << agree_one_point << "; multistart found " << found << " solutions\n";
  CHECK(problems >= 150);
  CHECK(from_start >= 0.9 * problems);
}

TEST_CASE("SystemStep3dBlockDiagonalIsPerPoint", "[system_step_3d]") {
  std::mt19937 rng(32);
  int problems = 0, sols = 0, products = 0;
  for (int c = 0; c < 60; ++c) {
    const int N = 2 + c % 2;
    SystemStep3dProblem p;
    p.system.A = Eigen::MatrixXd::Zero(3 * N, 3 * N);
    for (int i = 0; i < N; ++i) {
      p.system.points.push_back(random_point(rng, false, c % 3 == 1));
      p.system.A.block<3, 3>(3 * i, 3 * i) = coupled_spd(rng, 1.0, (c + i) % 2 == 0);
      const auto& q = p.system.points.back();
      p.states.push_back(random_state(rng, q.mu, q.alpha, c + i, false));
    }
    p.DF = random_load(rng, 3 * N, false);
    REQUIRE(p.validate().empty());
    std::vector<Step3dSolutionSet> exact;
    bool complete = true;
    for (int i = 0; i < N; ++i) {
      exact.push_back(enumerate_step_3d(p.point_problem(i)));
      complete = complete && exact.back().complete && exact.back().count() > 0;
    }
    if (!complete) continue;
    ++problems;
    const double F = force_scale(p);
    const SystemStep3dSolutionSet ms = multistart_system_step_3d(p, 12, 3);
    for (const auto& s : ms.solutions) {
      ++sols;
      for (int i = 0; i < N; ++i) CHECK(in_set(s.points[static_cast<std::size_t>(i)].values, exact[static_cast<std::size_t>(i)], F));
    }
    // Products of the one-point exact solutions are solutions of the system.
    for (int pick = 0; pick < 2; ++pick) {
      std::vector<Step3dValues> v;
      for (int i = 0; i < N; ++i) {
        const auto& e = exact[static_cast<std::size_t>(i)].solutions;
        v.push_back((pick == 0 ? e.front() : e.back()).values);
      }
      CHECK(system_step_3d_residual(p, v) <= 1e-9);
      ++products;
    }
  }
  std::cout << "[system_step_3d] block-diagonal: " << problems << " problems, " << sols
            << " multistart solutions, " << products << " products verified\n";
  CHECK(problems >= 40);
}

TEST_CASE("SystemStep3dDecoupledYEqualsTheTwoDimensionalStep", "[system_step_3d]") {
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> pos(0.05, 1);
  int problems = 0, sols = 0, found2d = 0, total2d = 0, several = 0;
  for (int c = 0; c < 80; ++c) {
    const int N = 2 + c % 2;
    const bool wear = c % 3 == 2;
    const Eigen::MatrixXd A2 = random_spd(rng, 2 * N, c % 2 == 0 ? 0.02 : 0.1);
    SystemStep3dProblem p;
    p.system.A = Eigen::MatrixXd::Zero(3 * N, 3 * N);
    r2::SystemStepProblem q2;
    q2.system.A = A2;
    q2.DF.resize(2 * N);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        p.system.A(3 * i, 3 * j) = A2(2 * i, 2 * j);
        p.system.A(3 * i, 3 * j + 2) = A2(2 * i, 2 * j + 1);
        p.system.A(3 * i + 2, 3 * j) = A2(2 * i + 1, 2 * j);
        p.system.A(3 * i + 2, 3 * j + 2) = A2(2 * i + 1, 2 * j + 1);
      }
    p.DF = random_load(rng, 3 * N, true);
    for (int i = 0; i < N; ++i) {
      p.system.A(3 * i + 1, 3 * i + 1) = 0.2 + pos(rng);  // Y decoupled
      p.system.points.push_back(random_point(rng, true, wear));
      if (c % 2 == 0) p.system.points.back().mu *= 2.5;  // large mu: several solutions
      const auto& q = p.system.points.back();
      p.states.push_back(random_state(rng, q.mu, q.alpha, c + i, true));
      r2::SystemPoint s2;
      s2.mu = q.mu;
      s2.C_T = q.C_T;
      s2.k_a = q.k_a;
      s2.P_s = q.P_s;
      s2.P_T = p.states.back().P_T0(0);
      s2.P_N = p.states.back().P_N0;
      s2.g = p.states.back().g0;
      s2.values_given = true;
      q2.system.points.push_back(s2);
      q2.DF(2 * i) = p.DF(3 * i);
      q2.DF(2 * i + 1) = p.DF(3 * i + 2);
    }
    REQUIRE(p.validate().empty());
    const r2::SystemStepSolutionSet s2 = r2::enumerate_system_step(q2);
    if (!s2.complete) continue;
    ++problems;
    const double F = force_scale(p);
    const SystemStep3dSolutionSet ms = multistart_system_step_3d(p, 12, 5);
    auto matches = [&](const SystemStep3dSolution& s, const r2::SystemStepSolution& t) {
      for (int i = 0; i < N; ++i) {
        const Step3dValues& v = s.points[static_cast<std::size_t>(i)].values;
        const r2::StepValues& w = t.values[static_cast<std::size_t>(i)];
        if (std::abs(v.P_T1(0) - w.P_T1) > 1e-6 * F || std::abs(v.P_N1 - w.P_N1) > 1e-6 * F ||
            std::abs(v.P_T1(1)) > 1e-6 * F)
          return false;
      }
      return true;
    };
    for (const auto& s : ms.solutions) {
      ++sols;
      bool any = false;
      for (const auto& t : s2.solutions) any = any || matches(s, t);
      CHECK(any);
    }
    total2d += static_cast<int>(s2.solutions.size());
    several += s2.solutions.size() > 1 ? 1 : 0;
    for (const auto& t : s2.solutions) {
      bool any = false;
      for (const auto& s : ms.solutions) any = any || matches(s, t);
      found2d += any ? 1 : 0;
    }
  }
  std::cout << "[system_step_3d] decoupled Y: " << problems << " problems, " << sols
            << " multistart solutions, " << found2d << "/" << total2d
            << " 2-D solutions found by the 3-D multistart (" << several
            << " problems with several)\n";
  CHECK(problems >= 50);
  CHECK(found2d >= 0.8 * total2d);
  CHECK(several >= 1);
}

TEST_CASE("SystemStep3dUnits", "[system_step_3d]") {
  std::mt19937 rng(34);
  int compared = 0, solved = 0;
  for (int c = 0; c < 30; ++c) {
    const int N = 2 + c % 3;
    SystemStep3dProblem p;
    p.system.A = random_spd(rng, 3 * N, 0.2);
    for (int i = 0; i < N; ++i) {
      p.system.points.push_back(random_point(rng, false, c % 2 == 1));
      const auto& q = p.system.points.back();
      p.states.push_back(random_state(rng, q.mu, q.alpha, c + i, false));
    }
    p.DF = random_load(rng, 3 * N, false);
    REQUIRE(p.validate().empty());
    const SystemStep3dSolveResult r = solve_system_step_3d_fb_soc(p);
    solved += (r.status == cpkit::Status::kSolved) ? 1 : 0;
    for (double sf : {1e-12, 1e-6, 1e6, 1e12})
      for (double sk : {1e-9, 1e9}) {
        SystemStep3dProblem q = p;
        q.system.A *= sk;
        q.DF *= sf;
        for (auto& pt : q.system.points) {
          pt.C_T /= sk;
          pt.k_a /= sf;
        }
        for (auto& s : q.states) {
          s.P_T0 *= sf;
          s.P_N0 *= sf;
          s.g0 *= sf / sk;
        }
        REQUIRE(q.validate().empty());
        const SystemStep3dSolveResult t = solve_system_step_3d_fb_soc(q);
        CHECK((t.status == cpkit::Status::kSolved) == (r.status == cpkit::Status::kSolved));
        if ((t.status == cpkit::Status::kSolved) && (r.status == cpkit::Status::kSolved))
          for (int i = 0; i < N; ++i) {
            const auto& a = r.solution.points[static_cast<std::size_t>(i)].values;
            const auto& b = t.solution.points[static_cast<std::size_t>(i)].values;
            CHECK(std::abs(b.P_N1 / sf - a.P_N1) <= 1e-7 * force_scale(p));
            CHECK((b.P_T1 / sf - a.P_T1).cwiseAbs().maxCoeff() <= 1e-7 * force_scale(p));
            CHECK(t.solution.points[static_cast<std::size_t>(i)].type ==
                  r.solution.points[static_cast<std::size_t>(i)].type);
          }
        // The residual of the scaled solution is the residual of the original one.
        std::vector<Step3dValues> v;
        for (const auto& x : r.solution.points) {
          Step3dValues y = x.values;
          y.P_T1 *= sf; y.DP_T *= sf; y.P_N1 *= sf; y.DP_N *= sf;
          const double d = sf / sk;
          y.Dw_T *= d; y.Dw_Ti *= d; y.Dw_N *= d; y.Dw_w *= d; y.g1 *= d; y.lambda *= d;
          v.push_back(y);
        }
        CHECK((system_step_3d_residual(q, v) <= 1e-9) == (r.solution.residual <= 1e-9));
        ++compared;
      }
  }
  std::cout << "[system_step_3d] units: " << compared << " scaled problems, " << solved
            << "/30 solved from the start state\n";
}

TEST_CASE("SystemStep3dBadInput", "[system_step_3d]") {
  SystemStep3dProblem p;
  p.system.A = Eigen::MatrixXd::Identity(6, 6);
  p.system.points.resize(2);
  p.states.resize(2);
  p.DF = Eigen::VectorXd::Constant(6, 0.5);
  REQUIRE(p.validate().empty());
  REQUIRE_NOTHROW(solve_system_step_3d_fb_soc(p));
  auto throws = [](const SystemStep3dProblem& q) {
    CHECK_FALSE(q.validate().empty());
    CHECK_THROWS_AS(solve_system_step_3d_fb_soc(q), cpkit::InputError);
    CHECK_THROWS_AS(multistart_system_step_3d(q, 2), cpkit::InputError);
  };
  SystemStep3dProblem q = p;
  q.DF.resize(5);
  throws(q);
  q = p;
  q.states.resize(1);
  throws(q);
  q = p;
  q.system.A(0, 3) = 0.5;  // not symmetric
  throws(q);
  q = p;
  q.system.A(0, 3) = q.system.A(3, 0) = 2;  // not positive definite
  throws(q);
  q = p;
  q.DF(4) = NAN;
  throws(q);
  q = p;
  q.states[1].g0 = 0.1;
  throws(q);
  q = p;
  q.states[1].P_N0 = 1;
  q.states[1].P_T0 = Eigen::Vector2d(1, 0);  // above mu P_N0
  throws(q);
  q = p;
  q.system.points[0].mu = -1;
  throws(q);
  q = p;
  q.system.points.clear();
  q.states.clear();
  q.system.A.resize(0, 0);
  q.DF.resize(0);
  throws(q);
  CHECK_THROWS_AS(multistart_system_step_3d(p, -1), cpkit::InputError);
  std::vector<Step3dStart> one(1);
  CHECK_THROWS_AS(solve_system_step_3d_fb_soc(p, {}, &one), cpkit::InputError);
  CHECK_THROWS_AS(system_step_3d_values(p, Eigen::VectorXd::Zero(5), Eigen::VectorXd::Zero(2)),
                  cpkit::InputError);
  CHECK(std::isinf(system_step_3d_residual(p, std::vector<Step3dValues>(1))));
}
