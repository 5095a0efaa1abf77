// The incremental step: NCP construction and all solutions (step_enumeration.hpp).
// Independent sources: the physical equations solved here with Eigen, the rate problem's closed
// forms of docs/model.md written out here, brute-force basis enumeration of the 3x3 LCP, and a
// dense scan of the reduced equations for the wear NCP.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "test_budget.hpp"

using namespace cpkit::rate;
using cpkit::test::family_size;

namespace {

struct Phys {
  double DP_T, DP_N, Dw_T, Dw_N, xi, Dw_w, P_T1, P_N1, g1;
};

/// The step's physical quantities for given (P_N1, l+, l-), from equilibrium solved directly:
/// DP_T + a11 Dw_T + a12 Dw_N = dF_T, a12 Dw_T + a22 Dw_N = dF_N - DP_N, Dw_T - C_T DP_T = xi.
Phys physical(const StepProblem& p, double P_N1, double lp, double lm) {
  const auto& a = p.params;
  Eigen::Matrix3d K;
  K << 1, a.a11, a.a12, 0, a.a12, a.a22, -a.C_T, 1, 0;
  const double DP_N = P_N1 - p.state.P_N0;
  const double xi = lp - lm;
  const Eigen::Vector3d r(p.load.dF_T, p.load.dF_N - DP_N, xi);
  const Eigen::Vector3d s = K.fullPivLu().solve(r);
  Phys ph;
  ph.DP_T = s[0];
  ph.Dw_T = s[1];
  ph.Dw_N = s[2];
  ph.DP_N = DP_N;
  ph.xi = xi;
  const double kw = p.wear.law == WearLaw::kArchard ? a.k_a / (3 * a.P_s) : p.wear.k_M * a.mu;
  ph.Dw_w = kw * P_N1 * (lp + lm);
  ph.P_T1 = p.state.P_T0 + ph.DP_T;
  ph.P_N1 = P_N1;
  ph.g1 = p.state.g0 + ph.Dw_N - ph.Dw_w;
  return ph;
}

double yield_of(const StepProblem& p, double P) {
  const double kc = p.params.criterion == Criterion::kSoftening ? p.params.k_a / (3 * p.params.P_s) : 0;
  return p.params.mu * P - kc * P * P;
}

/// Natural residual of the physical complementarity conditions, relative to the data scale.
double physical_residual(const StepProblem& p, const StepValues& v) {
  const double lp = std::max(v.Dw_Ti, 0.0), lm = std::max(-v.Dw_Ti, 0.0);
  const Phys ph = physical(p, v.P_N1, lp, lm);
  const double Y = yield_of(p, v.P_N1);
  const double scale = 1 + std::max({std::abs(p.state.P_N0), std::abs(p.state.P_T0),
                                     std::abs(p.load.dF_T), std::abs(p.load.dF_N),
                                     std::abs(v.P_N1), std::abs(v.P_T1)});
  double r = 0;
  r = std::max(r, std::abs(std::min(v.P_N1, -ph.g1)));
  r = std::max(r, std::abs(std::min(lp, Y - ph.P_T1)));
  r = std::max(r, std::abs(std::min(lm, Y + ph.P_T1)));
  // The reported values must be the physical ones.
  r = std::max({r, std::abs(ph.DP_T - v.DP_T), std::abs(ph.Dw_T - v.Dw_T),
                std::abs(ph.Dw_N - v.Dw_N), std::abs(ph.Dw_w - v.Dw_w), std::abs(ph.g1 - v.g1)});
  return r / scale;
}

StepProblem base(double a11, double a12, double a22, double mu, double C_T = 0) {
  StepProblem p;
  p.params.a11 = a11;
  p.params.a12 = a12;
  p.params.a22 = a22;
  p.params.mu = mu;
  p.params.C_T = C_T;
  return p;
}

/// Rate solution from state b (model.md Sec. 2, closed forms), unique case a11 > mu|a12|.
/// Returns (dP_T, dP_N, dw_T, dw_N, dw_Ti).
std::array<double, 5> rate_state_b(const ContactParameters& a, double dFT, double dFN) {
  const double detA = a.a11 * a.a22 - a.a12 * a.a12;
  const double e = 1 + a.a11 * a.C_T;
  const double N = a.a11 * dFN - a.a12 * dFT;
  const double S = e * dFN - a.a12 * a.C_T * dFT;
  auto L = [&](int s) { return (s + a.mu * a.a12 * a.C_T) * dFT - a.mu * e * dFN; };
  if (N < 0) {  // separation: dP = 0, dw = A^-1 dF
    const double wT = (a.a22 * dFT - a.a12 * dFN) / detA, wN = (a.a11 * dFN - a.a12 * dFT) / detA;
    return {0, 0, wT, wN, wT};
  }
  if (S >= 0 && L(1) <= 0 && L(-1) <= 0) {
    const double dPT = dFT / e, dPN = S / e;
    return {dPT, dPN, a.C_T * dPT, 0, 0};
  }
  for (int s : {1, -1}) {
    const double Ds = a.a11 - s * a.mu * a.a12;
    const double dPN = N / Ds, lam = L(s) / Ds;
    if (dPN >= 0 && lam > 0) {
      const double dPT = s * a.mu * dPN;
      return {dPT, dPN, a.C_T * dPT + s * lam, 0, s * lam};
    }
  }
  FAIL("no rate solution found in the test's closed forms");
  return {};
}

}  // namespace

TEST_CASE("StepNcpMatchesThePhysicalEquations", "[step]") {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int it = 0; it < 200; ++it) {
    StepProblem p = base(1.5 + u(gen), 0.5 * u(gen), 1.5 + u(gen), 0.6 + 0.4 * u(gen),
                         it % 2 ? 0.0 : 0.5 + 0.4 * u(gen));
    p.params.k_a = it % 3 ? 0.2 + 0.1 * u(gen) : 0.0;
    p.params.criterion = it % 4 == 0 ? Criterion::kSoftening : Criterion::kCoulomb;
    p.state.P_N0 = 0.5 + 0.4 * u(gen);
    p.state.P_T0 = 0.9 * u(gen) * yield_of(p, p.state.P_N0);
    p.load = {u(gen), u(gen)};
    REQUIRE(p.validate().empty());
    const StepNcp ncp = build_step_ncp(p);
    const Eigen::Vector3d z(std::abs(u(gen)) + 0.1, std::abs(u(gen)), std::abs(u(gen)));
    const Eigen::Vector3d F = ncp.F(z);
    const Phys ph = physical(p, z[0], z[1], z[2]);
    const double D0 = p.params.a22 + p.params.C_T * p.params.detA();
    const double Y = yield_of(p, z[0]);
    CAPTURE(it);
    CHECK(F[0] == Approx(-D0 * ph.g1).margin(1e-12));
    CHECK(F[1] == Approx(D0 * (Y - ph.P_T1)).margin(1e-12));
    CHECK(F[2] == Approx(D0 * (Y + ph.P_T1)).margin(1e-12));
    // Jacobian against central differences.
    const Eigen::Matrix3d J = ncp.jacobian(z);
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[j] = 1e-6;
      const Eigen::Vector3d fd = (ncp.F(z + e) - ncp.F(z - e)) / 2e-6;
      for (int i = 0; i < 3; ++i) CHECK(J(i, j) == Approx(fd[i]).margin(1e-7));
    }
  }
}

TEST_CASE("StableQuadraticHasNoCancellation", "[step]") {
  double r[2];
  // x^2 - 1e8 x + 1: roots 1e8 and 1e-8 (the textbook formula loses the small one).
  REQUIRE(stable_quadratic_roots(1, -1e8, 1, 1, 1e8, 1, 1e-12, r) == 2);
  const double lo = std::min(r[0], r[1]), hi = std::max(r[0], r[1]);
  CHECK(lo == Approx(1.0000000000000000e-8).epsilon(1e-14));
  CHECK(hi == Approx(1e8).epsilon(1e-14));
  CHECK(stable_quadratic_roots(0, 2, -4, 1, 2, 4, 1e-12, r) == 1);
  CHECK(r[0] == 2);
  CHECK(stable_quadratic_roots(0, 0, 0, 1, 1, 1, 1e-12, r) == -1);
  CHECK(stable_quadratic_roots(0, 0, 1, 1, 1, 1, 1e-12, r) == 0);
  CHECK(stable_quadratic_roots(1, 0, 1, 1, 1, 1, 1e-12, r) == 0);
}

TEST_CASE("NoWearFromStateBTheStepIsTheRateTimesTheIncrement", "[step]") {
  // k_a = 0 from state b (P = 0, g0 = 0): the step LCP is positively homogeneous in the
  // increment, so its unique solution (a11 > mu|a12|) is the rate solution times the increment.
  for (double C_T : {0.0, 0.7}) {
    const StepProblem p0 = base(2.0, 0.6, 1.3, 0.5, C_T);
    for (int k = 0; k < 72; ++k) {
      const double th = 2 * M_PI * (k + 0.37) / 72;
      const double h = 0.7;
      StepProblem p = p0;
      p.load = {h * std::cos(th), h * std::sin(th)};
      const auto rate = rate_state_b(p.params, std::cos(th), std::sin(th));
      const StepSolutionSet set = enumerate_step(p);
      CAPTURE(C_T, th);
      REQUIRE(set.count() == 1);
      const StepValues& v = set.solutions[0].start;
      CHECK(v.DP_T == Approx(h * rate[0]).margin(1e-12));
      CHECK(v.DP_N == Approx(h * rate[1]).margin(1e-12));
      CHECK(v.Dw_T == Approx(h * rate[2]).margin(1e-12));
      CHECK(v.Dw_N == Approx(h * rate[3]).margin(1e-12));
      CHECK(v.Dw_Ti == Approx(h * rate[4]).margin(1e-12));
      CHECK(v.Dw_w == 0);
      CHECK_FALSE(set.solutions[0].jump);
    }
  }
}

TEST_CASE("SmallIncrementsConvergeToTheRateSolutionInStateD", "[step]") {
  // State d (P_T0 = s mu P_N0) with wear: the rate solution is eqn (51) (model.md), Lambda > 0.
  StepProblem p = base(2.0, 0.4, 1.5, 0.4, 0.3);
  p.params.k_a = 0.6;
  p.params.P_s = 1;
  const int s = 1;
  p.state.P_N0 = 1.2;
  p.state.P_T0 = s * p.params.mu * p.state.P_N0;
  const auto& a = p.params;
  const double detA = a.detA(), kappa = a.k_a * p.state.P_N0 / (3 * a.P_s);
  const double Lambda = a.a11 - a.mu * s * a.a12 + kappa * (s * a.a12 - a.mu * a.a22) -
                        a.mu * kappa * a.C_T * detA;
  REQUIRE(Lambda > 0);
  const double dFT = 1.0, dFN = 0.3;
  const double Ls = (s + a.mu * a.a12 * a.C_T) * dFT - a.mu * (1 + a.a11 * a.C_T) * dFN;
  REQUIRE(Ls > 0);  // slip continues
  const double lam = Ls / Lambda;
  const double dPN = ((a.a11 + s * a.a12 * kappa) * dFN - (a.a12 + s * a.a22 * kappa) * dFT) / Lambda;
  const double dPT = s * a.mu * dPN;
  double prev_err = INFINITY;
  for (double h : {1e-1, 1e-2, 1e-3, 1e-4}) {
    p.load = {h * dFT, h * dFN};
    const StepSolutionSet set = enumerate_step(p);
    const StepSolution* cont = nullptr;
    for (const auto& sol : set.solutions)
      if (!sol.jump) {
        REQUIRE(cont == nullptr);  // exactly one rate-consistent solution
        cont = &sol;
      }
    REQUIRE(cont != nullptr);
    CHECK(cont->type == SolutionType::kSlipPlus);
    const StepValues& v = cont->start;
    const double err = std::max({std::abs(v.DP_N / h - dPN), std::abs(v.DP_T / h - dPT),
                                 std::abs(v.Dw_Ti / h - s * lam),
                                 std::abs(v.Dw_w / h - kappa * lam),
                                 std::abs(v.Dw_N / h - kappa * lam)});
    CAPTURE(h, err);
    CHECK(err < 5 * h);  // first order in the increment
    CHECK(err < prev_err);
    prev_err = err;
  }
}

TEST_CASE("StateDWithNegativeLambdaHasAJumpWhereTheRateHasNone", "[step]") {
  // a11 - mu a12 < 0: Lambda = -0.8 (k_a = 0). L_+ = dF_T - mu dF_N.
  StepProblem p = base(1.0, 0.9, 1.0, 2.0);
  p.state = {2.0, 1.0, 0.0};  // P_T0 = mu P_N0: state d, s = +1
  SECTION("L_+ > 0: the rate problem has no solution; the step jumps to separation") {
    p.load = {0.01, 0.0};
    const StepSolutionSet set = enumerate_step(p);
    REQUIRE(set.count() == 1);
    CHECK(set.solutions[0].type == SolutionType::kSeparation);
    CHECK(set.solutions[0].jump);
    CHECK(set.continuous_count == 0);
    CHECK(set.solutions[0].start.P_N1 == 0);
    CHECK(set.solutions[0].start.DP_N == Approx(-1.0));
  }
  SECTION("L_+ < 0: two rate solutions (stick, slip) plus the jump: three") {
    p.load = {-0.01, 0.0};
    const StepSolutionSet set = enumerate_step(p);
    REQUIRE(set.count() == 3);
    CHECK(set.continuous_count == 2);
    int jumps = 0;
    for (const auto& s : set.solutions) {
      CHECK(physical_residual(p, s.start) < 1e-12);
      if (s.jump) {
        ++jumps;
        CHECK(s.type == SolutionType::kSeparation);
      }
    }
    CHECK(jumps == 1);
    // The slip solution: dP_N = -(a12) dF_T / Lambda (dF_N = 0), lambda = L/Lambda.
    const double Lambda = 1.0 - 2.0 * 0.9;
    bool slip_found = false;
    for (const auto& s : set.solutions)
      if (s.type == SolutionType::kSlipPlus) {
        slip_found = true;
        CHECK(s.start.DP_N == Approx(-(0.9 * -0.01) / Lambda));
        CHECK(s.start.Dw_Ti == Approx(-0.01 / Lambda));
      }
    CHECK(slip_found);
  }
}

TEST_CASE("NoWearStepAgreesWithBruteForceBasisEnumeration", "[step]") {
  // k_a = 0: the step is the LCP (M, q) of model.md Sec. 3. Enumerate its 8 complementary
  // bases here (Eigen LU), map to physical (DP_N, xi) and compare with enumerate_step.
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0, multi = 0;
  for (int it = 0; it < 400; ++it) {
    StepProblem p = base(1.2 + u(gen), 0.0, 1.2 + u(gen), 1.5 + u(gen),
                         it % 2 ? 0.0 : 0.5 + 0.4 * u(gen));
    p.params.a12 = 0.9 * u(gen) * std::sqrt(p.params.a11 * p.params.a22);
    if (p.params.detA() < 0.05) continue;
    const int st = it % 3;  // 0: b, 1: c, 2: d
    if (st > 0) {
      p.state.P_N0 = 0.6 + 0.4 * u(gen);
      const double sgn = u(gen) > 0 ? 1 : -1;
      p.state.P_T0 = sgn * p.params.mu * p.state.P_N0 * (st == 2 ? 1.0 : 0.5);
    }
    p.load = {u(gen), u(gen)};
    const StepSolutionSet set = enumerate_step(p);
    if (set.infinite) continue;
    const StepNcp ncp = build_step_ncp(p);
    // Brute force.
    std::vector<std::pair<double, double>> truth;  // (P_N1, xi)
    for (int mask = 0; mask < 8; ++mask) {
      std::vector<int> B;
      for (int i = 0; i < 3; ++i)
        if (mask & (1 << i)) B.push_back(i);
      Eigen::Vector3d z = Eigen::Vector3d::Zero();
      if (!B.empty()) {
        const int nb = static_cast<int>(B.size());
        Eigen::MatrixXd MB(nb, nb);
        Eigen::VectorXd qB(nb);
        for (int i = 0; i < nb; ++i) {
          qB[i] = -ncp.q[B[i]];
          for (int j = 0; j < nb; ++j) MB(i, j) = ncp.M(B[i], B[j]);
        }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(MB);
        if (lu.rank() < nb) continue;  // singular: its solutions appear in a smaller basis
        const Eigen::VectorXd zB = lu.solve(qB);
        for (int i = 0; i < nb; ++i) z[B[i]] = zB[i];
      }
      const Eigen::Vector3d w = ncp.M * z + ncp.q;
      bool ok = true;
      for (int i = 0; i < 3; ++i) ok = ok && z[i] >= -1e-10 && w[i] >= -1e-10;
      if (!ok) continue;
      const double P = std::max(z[0], 0.0), xi = z[1] - z[2];
      bool dup = false;
      for (auto& t : truth) dup = dup || (std::abs(t.first - P) < 1e-8 && std::abs(t.second - xi) < 1e-8);
      if (!dup) truth.emplace_back(P, xi);
    }
    CAPTURE(it, p.params.a11, p.params.a12, p.params.a22, p.params.mu, p.params.C_T,
            p.state.P_T0, p.state.P_N0, p.load.dF_T, p.load.dF_N);
    REQUIRE(static_cast<int>(truth.size()) == set.count());
    for (const auto& t : truth) {
      bool found = false;
      for (const auto& s : set.solutions)
        found = found || (std::abs(s.start.P_N1 - t.first) < 1e-8 && std::abs(s.start.Dw_Ti - t.second) < 1e-8);
      CHECK(found);
    }
    ++compared;
    if (truth.size() > 1) ++multi;
  }
  CHECK(compared > 300);
  CHECK(multi > 0);
}

TEST_CASE("WearStepSolutionsAgreeWithADenseScanOfTheReducedEquations", "[step]") {
  // k_a > 0 (criteria (38) and (35)): every enumerated solution satisfies the physical
  // complementarity conditions, and per slip sign the number of solutions equals the number of
  // sign changes of the gap function along the friction curve, found by a dense scan here.
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int with3 = 0;
  for (int it = 0; it < family_size(150, 80); ++it) {
    StepProblem p = base(1.2 + u(gen), 0.0, 1.2 + u(gen), 1.5 + u(gen),
                         it % 2 ? 0.0 : 0.5 + 0.4 * u(gen));
    p.params.a12 = 0.9 * u(gen) * std::sqrt(p.params.a11 * p.params.a22);
    if (p.params.detA() < 0.05) continue;
    p.params.k_a = 1.5 + 1.2 * u(gen);
    if (it % 5 == 0) p.params.k_a *= 0.1;
    p.params.criterion = it % 3 == 0 ? Criterion::kSoftening : Criterion::kCoulomb;
    const double kk = p.params.k();
    p.state.P_N0 = 0.6 + 0.4 * u(gen);
    if (p.params.criterion == Criterion::kSoftening)
      p.state.P_N0 = std::min(p.state.P_N0, 0.8 * p.params.mu / kk);
    p.state.P_T0 = (u(gen) > 0 ? 1 : -1) * yield_of(p, p.state.P_N0) * (it % 2 ? 1.0 : 0.3);
    p.load = {1.5 * u(gen), 1.5 * u(gen)};
    const StepSolutionSet set = enumerate_step(p);
    REQUIRE_FALSE(set.infinite);
    CAPTURE(it);
    for (const auto& s : set.solutions) CHECK(physical_residual(p, s.start) < 1e-10);
    for (int sgn : {1, -1}) {
      // Along P in (0, Pmax]: l(P) from s P_T1 = Y(P) (P_T1 affine in l), then g1(P, l(P)).
      const double Pmax = p.params.criterion == Criterion::kSoftening ? p.params.mu / kk : 200.0;
      auto gap_on_curve = [&](double P, double& l) {
        const Phys a0 = physical(p, P, 0, 0);
        const Phys a1 = sgn > 0 ? physical(p, P, 1, 0) : physical(p, P, 0, 1);
        const double slope = sgn * (a1.P_T1 - a0.P_T1);  // d(s P_T1)/dl < 0
        l = (yield_of(p, P) - sgn * a0.P_T1) / slope;
        return sgn > 0 ? physical(p, P, l, 0).g1 : physical(p, P, 0, l).g1;
      };
      int changes = 0;
      const int N = 20000;
      double lprev = 0, gprev = 0;
      for (int i = 0; i <= N; ++i) {
        const double P = Pmax * (1e-9 + (1 - 1e-9) * std::pow(static_cast<double>(i) / N, 3));
        double l;
        const double g = gap_on_curve(P, l);
        if (i > 0 && (g < 0) != (gprev < 0) && l > 1e-9 && lprev > 1e-9) ++changes;
        gprev = g;
        lprev = l;
      }
      int found = 0;
      for (const auto& s : set.solutions)
        if ((sgn > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus) == s.type &&
            s.start.P_N1 > 1e-9 && std::abs(s.start.Dw_Ti) > 1e-9)
          ++found;
      CAPTURE(sgn, changes, found);
      CHECK(found == changes);
    }
    if (set.count() == 3) ++with3;
  }
  CHECK(with3 > 0);
}

TEST_CASE("SofteningCriterionEnforcesCondition46", "[step]") {
  // Criterion (35): |P_T| <= mu P_N - k P_N^2 needs P_N <= mu/k (46). Pressing a stuck point
  // (a12 = 0, no tangential load) beyond mu/k has no solution; just below it, stick.
  StepProblem p = base(1.0, 0.0, 1.0, 0.5);
  p.params.k_a = 0.3;  // k = 0.1, mu/k = 5
  p.params.criterion = Criterion::kSoftening;
  p.state = {0.0, 4.9, 0.0};
  p.load = {0.0, 0.05};
  StepSolutionSet set = enumerate_step(p);
  REQUIRE(set.count() == 1);
  CHECK(set.solutions[0].type == SolutionType::kStick);
  CHECK(set.solutions[0].start.P_N1 == Approx(4.95));
  p.load = {0.0, 0.2};
  set = enumerate_step(p);
  CHECK(set.count() == 0);
  // The same step with the Coulomb criterion (38) is a plain stick.
  p.params.criterion = Criterion::kCoulomb;
  set = enumerate_step(p);
  REQUIRE(set.count() == 1);
  CHECK(set.solutions[0].start.P_N1 == Approx(5.1));
}

TEST_CASE("DegenerateDataGiveASegmentNotSampledPoints", "[step]") {
  // a11 = mu a12 (D_+ = 0) and N = a11 dF_N - a12 dF_T = 0 with dF_N > 0 from state b, no wear:
  // the rate solutions form a segment from stick to zero-force slip (model.md); so do the steps.
  // As in the rate problem the stick end is not slip: the segment is open there and the stick
  // point is listed on its own.
  StepProblem p = base(1.0, 2.0, 5.0, 0.5);
  p.load = {1.0, 2.0};
  const StepSolutionSet set = enumerate_step(p);
  CHECK(set.infinite);
  CHECK(set.count() == -1);
  REQUIRE(set.solutions.size() == 2);
  CHECK(set.solutions[0].type == SolutionType::kStick);
  CHECK(set.solutions[0].kind == RateSolution::Kind::kPoint);
  const StepSolution& s = set.solutions[1];
  CHECK(s.kind == RateSolution::Kind::kSegment);
  CHECK(s.type == SolutionType::kSlipPlus);
  // Ends: zero-force slip (P = 0) and stick (xi = 0, dP = dF / (1 + a11 C_T)).
  const bool lo_first = s.start.P_N1 < s.end.P_N1;
  const StepValues lo = lo_first ? s.start : s.end;
  const StepValues hi = lo_first ? s.end : s.start;
  CHECK(lo.P_N1 == Approx(0).margin(1e-12));
  CHECK(hi.P_N1 == Approx(2.0));
  CHECK(hi.Dw_Ti == Approx(0).margin(1e-12));
  CHECK((lo_first ? s.start_closed : s.end_closed));
  CHECK_FALSE((lo_first ? s.end_closed : s.start_closed));
  CHECK(set.solutions[0].start.P_N1 == Approx(2.0));
  CHECK(set.solutions[0].start.DP_T == Approx(1.0));
  CHECK(physical_residual(p, lo) < 1e-12);
  CHECK(physical_residual(p, hi) < 1e-12);
}

TEST_CASE("StickEndOfAStickSlipSegmentIsStick", "[step]") {
  // Issue 11, sec. 4: from state b (P = 0, g0 = 0) with k_a = 0, a11 = mu |a12| and
  // DF = (0.5, 0.5). Hand calculation with a11 = a12 = mu = 1, a22 = 2, C_T = 0 (det A = 1,
  // D0 = a22 = 2, N = a11 DF_N - a12 DF_T = 0): the gap row and the friction row P_T1 = P_N1
  // coincide, DP_T = (a22 DF_T - a12 DF_N + a12 DP_N - det A xi) / D0 = (0.5 + x - xi) / 2 = x
  // along xi = 0.5 - x, x = DP_N in [0, 0.5]:
  //   x = 0:   P = 0, Dw_Ti = 0.5, g1 = 0   (zero-force slip: slip+, closed end)
  //   x = 0.5: P = (0.5, 0.5), Dw_Ti = 0   (stick: open end of the slip+ segment, a point)
  StepProblem p = base(1.0, 1.0, 2.0, 1.0);
  p.load = {0.5, 0.5};
  const StepSolutionSet set = enumerate_step(p);
  CHECK(set.infinite);
  REQUIRE(set.solutions.size() == 2);
  const StepSolution& stick = set.solutions[0];
  CHECK(stick.type == SolutionType::kStick);
  CHECK(stick.kind == RateSolution::Kind::kPoint);
  CHECK(stick.start.DP_N == Approx(0.5));
  CHECK(stick.start.DP_T == Approx(0.5));
  CHECK(stick.start.Dw_Ti == Approx(0).margin(1e-12));
  CHECK(physical_residual(p, stick.start) < 1e-12);
  const StepSolution& seg = set.solutions[1];
  CHECK(seg.type == SolutionType::kSlipPlus);
  REQUIRE(seg.kind == RateSolution::Kind::kSegment);
  const bool slip_first = seg.start.Dw_Ti > seg.end.Dw_Ti;
  const StepValues& slip_end = slip_first ? seg.start : seg.end;
  const StepValues& stick_end = slip_first ? seg.end : seg.start;
  CHECK((slip_first ? seg.start_closed : seg.end_closed));
  CHECK_FALSE((slip_first ? seg.end_closed : seg.start_closed));
  CHECK(slip_end.DP_N == Approx(0).margin(1e-12));
  CHECK(slip_end.DP_T == Approx(0).margin(1e-12));
  CHECK(slip_end.Dw_Ti == Approx(0.5));
  CHECK(slip_end.g1 == Approx(0).margin(1e-12));
  CHECK(stick_end.DP_N == Approx(0.5));
  CHECK(stick_end.Dw_Ti == Approx(0).margin(1e-12));
  // The midpoint is slip+: P_T1 = mu P_N1 = 0.25 with Dw_Ti = 0.25 > 0.
  CHECK(classify_step(p, step_values(p, 0.25, 0.25)) == SolutionType::kSlipPlus);
}

TEST_CASE("MrozStupkiewiczWithCoulombIsArchardWithKmMu", "[step]") {
  // Eqn (41) with |p_T| = mu p_N in slip: Dw^w = k_M mu P_N1 |Dw_T^i| (the paper's remark).
  StepProblem a = base(1.5, 0.2, 1.0, 0.4);
  a.state = {0.4, 1.0, 0.0};
  a.load = {0.8, 0.1};
  StepProblem m = a;
  m.wear.law = WearLaw::kMrozStupkiewicz;
  m.wear.k_M = 0.25;
  a.params.k_a = 3 * a.params.P_s * 0.25 * 0.4;
  const auto sa = enumerate_step(a), sm = enumerate_step(m);
  REQUIRE(sa.count() == sm.count());
  REQUIRE(sa.count() >= 1);
  for (std::size_t i = 0; i < sa.solutions.size(); ++i) {
    CHECK(sa.solutions[i].start.Dw_w == Approx(sm.solutions[i].start.Dw_w).epsilon(1e-12));
    CHECK(sm.solutions[i].start.Dw_w ==
          Approx(0.25 * sm.solutions[i].start.P_T1 * sm.solutions[i].start.Dw_Ti).epsilon(1e-9));
  }
}

TEST_CASE("StepBadInputThrows", "[step][input]") {
  const StepProblem ok = base(1.0, 0.2, 1.0, 0.5);
  auto throws = [](StepProblem p) { CHECK_THROWS_AS(enumerate_step(p), cpkit::InputError); };
  StepProblem p = ok;
  p.load.dF_T = std::numeric_limits<double>::quiet_NaN();
  throws(p);
  p = ok;
  p.state.g0 = 0.1;  // penetration
  throws(p);
  p = ok;
  p.state.P_N0 = -1;
  throws(p);
  p = ok;
  p.state = {0.6, 1.0, 0.0};  // |P_T0| > mu P_N0
  throws(p);
  p = ok;
  p.state = {0.0, 1.0, -0.5};  // P_N0 > 0 with an open gap
  throws(p);
  p = ok;
  p.params.a12 = 2;  // A not SPD
  throws(p);
  p = ok;
  p.params.mu = 0;
  throws(p);
  p = ok;
  p.wear.law = WearLaw::kMrozStupkiewicz;
  p.params.criterion = Criterion::kSoftening;
  throws(p);
  p = ok;
  p.params.k_a = 1;
  CHECK_THROWS_AS(step_as_lcp(p), cpkit::InputError);
  CHECK_NOTHROW(step_as_lcp(ok));
}
