// Solvers of one 3-D implicit step (step_solvers_3d.hpp) against independent sources:
// (a) the 2-D step's complete active-set enumeration (rate::enumerate_step) for isotropic points
//     whose Y direction is decoupled and unloaded (every FB-SOC / Ipopt solution must be a 2-D
//     solution; the faceted LCP with even k, vertices at +-X, must give exactly the 2-D set);
// (b) the exact enumeration enumerate_step_3d (trigonometric polynomial, a different algorithm):
//     FB-SOC and Ipopt solutions belong to its set, faceted counts approach its counts;
// (c) rotation of the tangential plane of isotropic problems rotates the FB-SOC solution;
// (d) units: the same verdicts for data scaled by 1e-12..1e12;
// (e) bad input throws InputError.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

#include "rate3d_test_util.hpp"
#include "test_budget.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"

using namespace cpkit::rate;
namespace r2 = cpkit::rate;

using cpkit::test::coupled_spd;
using cpkit::test::family_size;

namespace {
constexpr double kPi = 3.14159265358979323846;

/// A random admissible start state: grazing, open, stick inside the ellipse, or on it.
Step3dState random_state(std::mt19937& rng, const ContactParameters3d& p, int kind, bool y_zero) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  Step3dState s;
  switch (kind % 4) {
    case 0: break;  // grazing
    case 1: s.g0 = -0.3 * pos(rng); break;
    case 2: {
      s.P_N0 = 2 * pos(rng);
      const double th = y_zero ? (u(rng) > 0 ? 0 : kPi) : kPi * u(rng);
      s.P_T0 = 0.9 * pos(rng) * p.mu * s.P_N0 * (p.alpha.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th)));
      if (y_zero) s.P_T0(1) = 0;
      break;
    }
    default: {
      s.P_N0 = 2 * pos(rng);
      const double th = y_zero ? (u(rng) > 0 ? 0 : kPi) : kPi * u(rng);
      s.P_T0 = p.mu * s.P_N0 * (p.alpha.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th)));
      if (y_zero) s.P_T0(1) = 0;
    }
  }
  return s;
}

/// Deterministic starts around the problem's scale.
std::vector<Step3dStart> starts(std::mt19937& rng, const Step3dProblem& p, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  const double F = std::max({p.DF.cwiseAbs().maxCoeff(), p.state.P_N0, 1e-300});
  const double L = F / p.params.A.cwiseAbs().maxCoeff();
  std::vector<Step3dStart> out;
  for (int i = 0; i < n; ++i) {
    Step3dStart s;
    s.P_N1 = i % 3 == 0 ? 0 : F * std::exp(-3 + 4 * u(rng));
    const double th = 2 * kPi * u(rng);
    s.P_T1 = p.params.mu * s.P_N1 * u(rng) * Eigen::Vector2d(std::cos(th), std::sin(th));
    s.lambda = i % 2 == 0 ? 0 : L * std::exp(-3 + 4 * u(rng));
    out.push_back(s);
  }
  return out;
}

bool matches_2d(const Step3dSolution& s, const r2::StepSolutionSet& ref, double F) {
  if (std::abs(s.values.P_T1(1)) > 1e-7 * F) return false;
  for (const auto& r : ref.solutions)
    if (r.kind == r2::RateSolution::Kind::kPoint &&
        std::abs(r.start.P_T1 - s.values.P_T1(0)) <= 1e-6 * F &&
        std::abs(r.start.P_N1 - s.values.P_N1) <= 1e-6 * F)
      return true;
  return false;
}

struct Decoupled {
  Step3dProblem p3;
  r2::StepProblem p2;
};

/// Isotropic point, A_XY = A_YN = 0, DF_Y = 0, P_TY0 = 0, and the same X-N problem in 2-D.
Decoupled decoupled(std::mt19937& rng, int c, bool wear) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  Decoupled d;
  r2::ContactParameters& q = d.p2.params;
  q.a11 = 0.2 + 2 * pos(rng);
  q.a22 = 0.2 + 2 * pos(rng);
  q.a12 = 0.95 * u(rng) * std::sqrt(q.a11 * q.a22);
  q.mu = 0.1 + 3 * pos(rng);
  q.C_T = c % 3 == 0 ? 0 : pos(rng);
  ContactParameters3d& p = d.p3.params;
  p.A << q.a11, 0, q.a12, 0, 0.3 + pos(rng), 0, q.a12, 0, q.a22;
  p.mu = q.mu;
  p.C_T = q.C_T;
  if (wear) {
    if (c % 2 == 0) {
      q.k_a = p.k_a = 0.3 * pos(rng);
    } else {
      d.p2.wear.law = d.p3.wear.law = r2::WearLaw::kMrozStupkiewicz;
      d.p2.wear.k_M = d.p3.wear.k_M = 0.3 * pos(rng);
    }
  }
  d.p3.state = random_state(rng, p, c, true);
  d.p2.state = {d.p3.state.P_T0(0), d.p3.state.P_N0, d.p3.state.g0};
  const double th = kPi * u(rng);
  d.p3.DF = Eigen::Vector3d(std::cos(th), 0, std::sin(th));
  d.p2.load = {d.p3.DF(0), d.p3.DF(2)};
  return d;
}

double force_scale(const Step3dProblem& p) {
  return std::max({p.DF.cwiseAbs().maxCoeff(), p.state.P_T0.cwiseAbs().maxCoeff(), p.state.P_N0,
                   p.params.A.cwiseAbs().maxCoeff() * std::abs(p.state.g0)});
}

}  // namespace

TEST_CASE("FB-SOC and Ipopt solutions of a decoupled isotropic point are 2-D step solutions",
          "[step3d][solvers]") {
  std::mt19937 rng(11);
  int problems = 0, fb_first = 0, fb_runs = 0, fb_ok = 0, ip_runs = 0, ip_ok = 0, iters = 0;
  int complete_2d_found = 0, multi = 0;
  double fb_seconds = 0, ip_seconds = 0;
  for (int c = 0; c < family_size(400, 48); ++c) {
    const Decoupled d = decoupled(rng, c, c % 2 == 1);
    REQUIRE(d.p3.validate().empty());
    const r2::StepSolutionSet ref = r2::enumerate_step(d.p2, {1e-9, false});
    if (ref.infinite) continue;
    ++problems;
    if (ref.count() > 1) ++multi;
    const double F = force_scale(d.p3);
    std::vector<Step3dSolution> found;
    auto st = starts(rng, d.p3, 6);
    for (int i = 0; i <= 6; ++i) {
      const Step3dSolveResult r = solve_step_3d_fb_soc(d.p3, step_3d_solver_options(), i == 0 ? nullptr : &st[i - 1]);
      ++fb_runs;
      fb_seconds += r.seconds;
      iters += r.iterations;
      if (!(r.status == cpkit::Status::kSolved)) continue;
      ++fb_ok;
      if (i == 0) ++fb_first;
      CAPTURE(c, i, r.solution.values.P_T1(0), r.solution.values.P_T1(1), r.solution.values.P_N1,
              ref.count());
      CHECK(r.solution.residual <= 1e-9);
      CHECK(matches_2d(r.solution, ref, F));
      found.push_back(r.solution);
    }
    if (c % 8 == 0) {
      const Step3dSolveResult r = solve_step_3d_ipopt(d.p3);
      ++ip_runs;
      ip_seconds += r.seconds;
      if ((r.status == cpkit::Status::kSolved)) {
        ++ip_ok;
        CAPTURE(c, r.solution.values.P_T1(0), r.solution.values.P_N1);
        CHECK(matches_2d(r.solution, ref, F));
      }
    }
    sort_and_dedup_step_3d(d.p3, found);
    if (static_cast<int>(found.size()) == ref.count()) ++complete_2d_found;
  }
  std::cout << "[step3d decoupled] " << problems << " problems (" << multi
            << " with several 2-D solutions): FB-SOC from the start state " << fb_first << "/"
            << problems << ", all starts " << fb_ok << "/" << fb_runs << " verified, "
            << static_cast<double>(iters) / fb_runs << " iterations and "
            << 1e6 * fb_seconds / fb_runs << " us per solve; every 2-D solution found from 7 starts in "
            << complete_2d_found << "/" << problems << "; Ipopt " << ip_ok << "/" << ip_runs
            << " verified, " << 1e3 * ip_seconds / std::max(ip_runs, 1) << " ms per solve\n";
  CHECK(fb_first >= 0.9 * problems);
  CHECK(ip_ok >= 0.8 * ip_runs);
}

TEST_CASE("faceted step with even k and a decoupled isotropic point: exactly the 2-D solutions",
          "[step3d][faceted]") {
  std::mt19937 rng(12);
  int n = 0, several = 0;
  for (int c = 0; c < 600; ++c) {
    const Decoupled d = decoupled(rng, c, false);
    const r2::StepSolutionSet ref = r2::enumerate_step(d.p2, {1e-9, false});
    if (ref.infinite) continue;
    ++n;
    if (ref.count() > 1) ++several;
    const int k = 4 + 2 * (c % 8);
    const FacetedStep3dResult got = solve_step_3d_faceted(d.p3, k);
    const double F = force_scale(d.p3);
    CAPTURE(c, k, ref.count(), got.set.count(), got.set.message);
    CHECK(got.lcp);
    CHECK(got.set.complete);
    REQUIRE(got.set.count() == ref.count());
    for (const auto& s : got.set.solutions) {
      CHECK(matches_2d(s, ref, F));
      CHECK(s.residual <= 1e-9);  // at the vertices +-X the polygon holds the elliptic law
    }
  }
  CHECK(several >= 5);
  std::cout << "[step3d faceted even k] " << n << " problems, " << several
            << " with several solutions: all equal to the 2-D sets\n";
}

TEST_CASE("FB-SOC rotates with the tangential plane of an isotropic problem", "[step3d][solvers]") {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  int solved = 0, n = 0;
  for (int c = 0; c < family_size(300, 48); ++c) {
    Step3dProblem p;
    p.params.A = coupled_spd(rng, 1.5, false);
    p.params.mu = 0.2 + 2 * pos(rng);
    p.params.C_T = c % 2 ? 0 : pos(rng);
    p.params.k_a = c % 3 == 0 ? 0.3 * pos(rng) : 0;
    p.state = random_state(rng, p.params, c, false);
    p.DF = Eigen::Vector3d(u(rng), u(rng), u(rng));
    const double phi = kPi * u(rng);
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    R.topLeftCorner<2, 2>() << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
    Step3dProblem q = p;
    q.params.A = R * p.params.A * R.transpose();
    q.params.A = 0.5 * (q.params.A + q.params.A.transpose()).eval();
    q.DF = R * p.DF;
    q.state.P_T0 = R.topLeftCorner<2, 2>() * p.state.P_T0;
    const Step3dSolveResult a = solve_step_3d_fb_soc(p), b = solve_step_3d_fb_soc(q);
    ++n;
    CAPTURE(c, (a.status == cpkit::Status::kSolved), (b.status == cpkit::Status::kSolved), a.solution.residual, b.solution.residual);
    CHECK((a.status == cpkit::Status::kSolved) == (b.status == cpkit::Status::kSolved));
    if (!(a.status == cpkit::Status::kSolved) || !(b.status == cpkit::Status::kSolved)) continue;
    ++solved;
    const double F = force_scale(p);
    const Eigen::Vector2d rot = R.topLeftCorner<2, 2>() * a.solution.values.P_T1;
    CHECK((rot - b.solution.values.P_T1).cwiseAbs().maxCoeff() <= 1e-7 * F);
    CHECK(std::abs(a.solution.values.P_N1 - b.solution.values.P_N1) <= 1e-7 * F);
    CHECK(a.solution.type == b.solution.type);
  }
  CHECK(solved >= 0.9 * n);
}

TEST_CASE("FB-SOC verdicts do not depend on units", "[step3d][solvers]") {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  // 24 problems x 8 rescalings (60 took a minute): each rescaling also runs the faceted chain,
  // with Ipopt where its FB Newton stalls (under the sanitizers: 4 problems, 13 minutes otherwise).
  for (int c = 0; c < family_size(24, 4); ++c) {
    Step3dProblem p;
    p.params.A = coupled_spd(rng, 1.5, false);
    p.params.mu = 0.2 + 2 * pos(rng);
    p.params.C_T = c % 2 ? 0 : pos(rng);
    p.params.alpha = Eigen::Vector2d(0.4 + pos(rng), 0.4 + pos(rng));
    p.params.k_a = c % 3 == 0 ? 0.3 * pos(rng) : 0;
    p.state = random_state(rng, p.params, c, false);
    p.DF = Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Step3dSolveResult ref = solve_step_3d_fb_soc(p);
    const FacetedStep3dResult fref = solve_step_3d_faceted(p, 8);
    for (double s : {1e-12, 1e-6, 1e6, 1e12}) {
      for (int mode = 0; mode < 2; ++mode) {
        Step3dProblem q = p;
        if (mode == 0) {  // forces scaled by s, lengths by s (A fixed): g0 s, k_a / s
          q.DF *= s;
          q.state.P_T0 *= s;
          q.state.P_N0 *= s;
          q.state.g0 *= s;
          q.params.k_a /= s;
        } else {  // stiffness scaled by s: lengths by 1/s (forces fixed), C_T / s
          q.params.A *= s;
          q.params.C_T /= s;
          q.state.g0 /= s;
        }
        const double fs = mode == 0 ? s : 1.0, ls = mode == 0 ? s : 1 / s;
        const Step3dSolveResult r = solve_step_3d_fb_soc(q);
        CAPTURE(c, s, mode, ref.solution.residual, r.solution.residual);
        REQUIRE((r.status == cpkit::Status::kSolved) == (ref.status == cpkit::Status::kSolved));
        if (!(r.status == cpkit::Status::kSolved)) continue;
        CHECK(r.solution.type == ref.solution.type);
        const double F = force_scale(p);
        CHECK((r.solution.values.P_T1 / fs - ref.solution.values.P_T1).cwiseAbs().maxCoeff() <=
              1e-9 * F);
        CHECK(std::abs(r.solution.values.P_N1 / fs - ref.solution.values.P_N1) <= 1e-9 * F);
        CHECK(std::abs(r.solution.values.lambda / ls - ref.solution.values.lambda) <=
              1e-9 * (F / p.params.A.cwiseAbs().maxCoeff()));
        const FacetedStep3dResult f = solve_step_3d_faceted(q, 8);
        CHECK(f.set.count() == fref.set.count());
        CHECK(f.set.complete == fref.set.complete);
      }
    }
  }
}

TEST_CASE("FB-SOC, Ipopt and the chain agree with the exact enumeration; faceted counts settle",
          "[step3d][solvers][exact]") {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  const int ks[4] = {8, 16, 32, 64};
  int agree[4] = {0, 0, 0, 0}, n_complete = 0, n_multi = 0, fb_in = 0, fb_ok = 0, ip_ok = 0,
      ip_runs = 0;
  double t_exact = 0, t_fb = 0, t_fac[4] = {0, 0, 0, 0};
  int n_fb = 0;
  const int n_problems = family_size(300, 40);
  for (int c = 0; c < n_problems; ++c) {
    Step3dProblem p;
    p.params.A = coupled_spd(rng, 3.0, false);
    p.params.mu = 0.5 + 4 * pos(rng);
    p.params.C_T = c % 2 ? 0 : pos(rng);
    p.params.alpha = Eigen::Vector2d(0.4 + pos(rng), 0.4 + pos(rng));
    p.state = random_state(rng, p.params, c, false);
    p.DF = Eigen::Vector3d(u(rng), u(rng), u(rng));
    auto t0 = std::chrono::steady_clock::now();
    const Step3dSolutionSet ex = enumerate_step_3d(p);
    t_exact += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!ex.complete) continue;
    ++n_complete;
    if (ex.count() > 1) ++n_multi;
    const double F = force_scale(p);
    auto in_exact = [&](const Step3dSolution& s) {
      for (const auto& e : ex.solutions)
        if ((e.values.P_T1 - s.values.P_T1).cwiseAbs().maxCoeff() <= 1e-6 * F &&
            std::abs(e.values.P_N1 - s.values.P_N1) <= 1e-6 * F)
          return true;
      return false;
    };
    auto st = starts(rng, p, 4);
    for (int i = 0; i <= 4; ++i) {
      const Step3dSolveResult r = solve_step_3d_fb_soc(p, step_3d_solver_options(), i == 0 ? nullptr : &st[i - 1]);
      t_fb += r.seconds;
      ++n_fb;
      if (!(r.status == cpkit::Status::kSolved)) continue;
      ++fb_ok;
      CAPTURE(c, i, ex.count());
      CHECK(in_exact(r.solution));
      fb_in += in_exact(r.solution);
    }
    if (c % 10 == 0) {
      ++ip_runs;
      const Step3dSolveResult r = solve_step_3d_ipopt(p);
      if ((r.status == cpkit::Status::kSolved)) {
        ++ip_ok;
        CHECK(in_exact(r.solution));
      }
      const Step3dChainResult ch = solve_step_3d(p);
      CHECK((ch.status == cpkit::Status::kSolved) == (ex.count() > 0));
      if ((ch.status == cpkit::Status::kSolved)) CHECK(ch.solver == "exact");
    }
    for (int j = 0; j < 4; ++j) {
      t0 = std::chrono::steady_clock::now();
      const FacetedStep3dResult f = solve_step_3d_faceted(p, ks[j]);
      t_fac[j] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (f.set.count() == ex.count()) ++agree[j];
    }
  }
  std::cout << "[step3d exact] " << n_complete << " complete problems (" << n_multi
            << " with several solutions): exact " << 1e6 * t_exact / n_problems << " us, FB-SOC "
            << 1e6 * t_fb / std::max(n_fb, 1) << " us per solve (" << fb_ok << "/" << n_fb
            << " verified), Ipopt " << ip_ok << "/" << ip_runs << "; faceted count = exact count:";
  for (int j = 0; j < 4; ++j)
    std::cout << " k=" << ks[j] << " " << agree[j] << " (" << 1e6 * t_fac[j] / n_complete
              << " us)";
  std::cout << "\n";
  CHECK(n_complete >= 2 * n_problems / 3);
  CHECK(n_multi >= n_problems / 30);
  CHECK(fb_in == fb_ok);
  CHECK(agree[3] >= agree[0]);
  CHECK(agree[3] >= 0.95 * n_complete);
}

TEST_CASE("multistart lists verified solutions and never claims completeness", "[step3d][solvers]") {
  std::mt19937 rng(16);
  for (int c = 0; c < family_size(10, 3); ++c) {
    const Decoupled d = decoupled(rng, c, c % 2 == 1);
    const r2::StepSolutionSet ref = r2::enumerate_step(d.p2, {1e-9, false});
    if (ref.infinite) continue;
    const Step3dSolutionSet m = multistart_step_3d(d.p3, 12, 7);
    CHECK_FALSE(m.complete);
    CHECK(!m.message.empty());
    CHECK(m.count() <= ref.count());
    for (const auto& s : m.solutions) CHECK(matches_2d(s, ref, force_scale(d.p3)));
    // deterministic for a seed
    CHECK(multistart_step_3d(d.p3, 12, 7).count() == m.count());
  }
}

TEST_CASE("step solvers 3-D: bad input throws InputError", "[step3d][solvers]") {
  Step3dProblem p;
  p.DF = {1, 0, -1};
  CHECK_NOTHROW(solve_step_3d_fb_soc(p));
  Step3dProblem bad = p;
  bad.params.mu = -1;
  CHECK_THROWS_AS(solve_step_3d_fb_soc(bad), cpkit::InputError);
  CHECK_THROWS_AS(solve_step_3d_ipopt(bad), cpkit::InputError);
  CHECK_THROWS_AS(solve_step_3d_faceted(bad, 8), cpkit::InputError);
  CHECK_THROWS_AS(solve_step_3d(bad), cpkit::InputError);
  CHECK_THROWS_AS(multistart_step_3d(bad, 3), cpkit::InputError);
  bad = p;
  bad.DF(1) = std::nan("");
  CHECK_THROWS_AS(solve_step_3d_fb_soc(bad), cpkit::InputError);
  bad = p;
  bad.state.P_N0 = -1;
  CHECK_THROWS_AS(solve_step_3d_fb_soc(bad), cpkit::InputError);
  CHECK_THROWS_AS(solve_step_3d_faceted(p, 2), cpkit::InputError);
  CHECK_THROWS_AS(solve_step_3d_faceted(p, 65), cpkit::InputError);
  Step3dChainOptions o;
  o.chain = {"exact", "lemke"};
  CHECK_THROWS_AS(solve_step_3d(p, o), cpkit::InputError);
  o.chain.clear();
  CHECK_THROWS_AS(solve_step_3d(p, o), cpkit::InputError);
  cpkit::CommonOptions so = step_3d_solver_options();
  so.tol = 0;
  CHECK_THROWS_AS(solve_step_3d_fb_soc(p, so), cpkit::InputError);
  CHECK_THROWS_AS(multistart_step_3d(p, -1), cpkit::InputError);
  Step3dStart s;
  s.P_N1 = std::nan("");
  CHECK_THROWS_AS(solve_step_3d_fb_soc(p, step_3d_solver_options(), &s), cpkit::InputError);
}

TEST_CASE("finalize_step_3d grants solved only from the data", "[step3d]") {
  // docs/contact_3d.md's step: the exact enumeration (an independent route) lists 3 solutions.
  Step3dProblem step;
  step.params.A << 1.0, 0.0, 0.8, 0.0, 1.0, 0.3, 0.8, 0.3, 1.5;
  step.params.mu = 2.0;
  step.params.C_T = 0.25;
  step.params.k_a = 0.3;
  step.params.alpha = {0.6, 1.0};
  step.DF = {1.0, 0.5, 0.9};
  const Step3dSolutionSet all = enumerate_step_3d(step);
  REQUIRE(all.complete);
  REQUIRE(all.count() == 3);
  const cpkit::CommonOptions o = step_3d_solver_options();
  for (const auto& s : all.solutions) {
    Step3dSolveResult claim;  // no claim at all: the verdict alone grants kSolved
    claim.solution.values = s.values;
    finalize_step_3d(step, claim, o);
    CHECK(claim.status == cpkit::Status::kSolved);
    CHECK(claim.z[2] == s.values.P_N1);
    Step3dSolveResult wrong;  // a claimed solution 1% off in P_N1 is refuted
    wrong.status = cpkit::Status::kSolved;
    wrong.solution.values = s.values;
    wrong.solution.values.P_N1 = s.values.P_N1 * 1.01 + 0.01;
    finalize_step_3d(step, wrong, o);
    CHECK(wrong.status == cpkit::Status::kNumericalFailure);
  }
}
