// `--measure` (issue 35): the measure that decides "solved" (core/friction_measure.hpp,
// lcp/friction/measure_solve.hpp). Independent source: the natural map written here from its
// definition (FCLIB's F_nat, Siconos' fc3d_compute_error),
//   F_i = r_i - P_K(r_i - u_hat_i), u = W r + q, u_hat = u + mu |u_T| e_N,
//   P_K(n, t) = (n, t) inside K_mu; 0 inside the polar cone (mu |t| <= -n); otherwise
//   s (1, mu t / |t|) with s = (n + mu |t|) / (1 + mu^2),
// and a one-contact problem solved by hand: W = I, q = (-1, 0.3, 0.4), mu = 0.5 sticks at the
// cone's edge, r* = -q = (1, -0.3, -0.4) (|r_T| = 0.5 = mu r_N), u = 0. At r = (1, 0, 0):
// u = (0, 0.3, 0.4), u_hat = (0.25, 0.3, 0.4), r - u_hat = (0.75, -0.3, -0.4) (|t| = 0.5 >
// mu n = 0.375), s = (0.75 + 0.25) / 1.25 = 0.8, P_K = (0.8, -0.24, -0.32), F = (0.2, 0.24,
// 0.32), |F| = sqrt(0.2), |q| = sqrt(1.25): relative_q = 0.4, relative_max = |F| / max(|q|,
// |r| = 1, |u| = 0.5) = 0.4.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/friction/fc_bench.hpp"
#include "cpkit/lcp/friction/fc_request.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/solvers.hpp"

using namespace cpkit;
using namespace cpkit::lcp::friction;

namespace {

namespace fs = std::filesystem;

std::string data(const std::string& rel) {
  return (fs::path(CPKIT_TEST_DATA_DIR) / "fclib" / rel).string();
}

FrictionContactProblem hand_problem() {
  FrictionContactProblem p;
  p.W = Eigen::MatrixXd::Identity(3, 3).sparseView();
  p.q = Eigen::Vector3d(-1, 0.3, 0.4);
  p.mu = Eigen::VectorXd::Constant(1, 0.5);
  return p;
}

/// |F_nat(r)|_2 over all contacts, from the definition in the header comment.
double natural_map_norm(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = p.W * r + p.q;
  double sum = 0;
  for (Eigen::Index i = 0; i < p.contacts(); ++i) {
    const double mu = p.mu[i];
    const Eigen::Vector3d ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
    Eigen::Vector3d uh = ui;
    uh[0] += mu * ui.tail<2>().norm();
    const Eigen::Vector3d x = ri - uh;
    const double n = x[0], t = x.tail<2>().norm();
    Eigen::Vector3d proj;
    if (t <= mu * n) {
      proj = x;
    } else if (mu * t <= -n) {
      proj.setZero();
    } else {
      const double s = (n + mu * t) / (1 + mu * mu);
      proj << s, mu * s * x[1] / t, mu * s * x[2] / t;
    }
    sum += (ri - proj).squaredNorm();
  }
  return std::sqrt(sum);
}

double relative_q(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  return natural_map_norm(p, r) / p.q.norm();
}

}  // namespace

TEST_CASE("relative_q and relative_max of a one-contact r are the hand values", "[friction][measure]") {
  const FrictionContactProblem p = hand_problem();
  const FrictionErrors e = friction_errors(p, Eigen::Vector3d(1, 0, 0));
  CHECK(e.relative_q == Approx(0.4).epsilon(1e-14));
  CHECK(e.relative_max == Approx(0.4).epsilon(1e-14));
  CHECK(measured(e, FrictionMeasure::kRelativeQ) == e.relative_q);
  CHECK(measured(e, FrictionMeasure::kRelativeMax) == e.relative_max);
  CHECK(measured(e, FrictionMeasure::kUnitFree) == e.unit_free);
  // r = (2, 0, 0) at q = (-1, 0, 0): u = (1, 0, 0), r - u_hat = (1, 0, 0) is in K: F = (1, 0, 0):
  // relative_q = 1 / 1, relative_max = 1 / max(1, |r| = 2, |u| = 1) = 0.5.
  FrictionContactProblem normal = p;
  normal.q = Eigen::Vector3d(-1, 0, 0);
  const FrictionErrors n = friction_errors(normal, Eigen::Vector3d(2, 0, 0));
  CHECK(n.relative_q == 1.0);
  CHECK(n.relative_max == 0.5);
  // The same hand values with the units computed once by the caller (the solvers' path), and
  // finalize() with them calls (2, 0, 0) what it is: not a solution.
  const FrictionUnits units = friction_units(normal);
  const FrictionErrors nu = friction_errors(normal, units, Eigen::Vector3d(2, 0, 0));
  CHECK(nu.relative_q == 1.0);
  CHECK(nu.relative_max == 0.5);
  SolveResult claim;
  claim.z = Eigen::Vector3d(2, 0, 0);
  claim.status = Status::kSolved;
  const SolveResult judged = finalize(normal, units, claim, CommonOptions{});
  CHECK(judged.status == Status::kNumericalFailure);
  CHECK(judged.w.isApprox(Eigen::Vector3d(1, 0, 0)));
  // finalize() stores the errors it computed with its verdict: the hand values, whatever errors
  // the claim came with; a point it cannot judge keeps none.
  claim.friction_errors = FrictionErrors{0, 0, 0};
  const SolveResult stored = finalize(normal, units, claim, CommonOptions{});
  REQUIRE(stored.friction_errors);
  CHECK(stored.friction_errors->relative_q == 1.0);
  CHECK(stored.friction_errors->relative_max == 0.5);
  CHECK(stored.friction_errors->unit_free == stored.residuals.natural);
  claim.z = Eigen::Vector3d(NAN, 0, 0);
  CHECK_FALSE(finalize(normal, units, claim, CommonOptions{}).friction_errors);
  CHECK_THROWS_AS(friction_errors(normal, units, Eigen::VectorXd::Zero(6)), InputError);
}

TEST_CASE("q = 0 divides by nothing: relative_q is the absolute |F_nat|", "[friction][measure]") {
  // r = (1, 0, 0), q = 0: u = r, r - u_hat = 0, F = r: |F| = 1 (no division by |q| = 0);
  // relative_max = 1 / max(0, 1, 1) = 1; r = 0 solves it: every error 0, none NaN.
  FrictionContactProblem p = hand_problem();
  p.q.setZero();
  const FrictionErrors e = friction_errors(p, Eigen::Vector3d(1, 0, 0));
  CHECK(e.relative_q == 1.0);
  CHECK(e.relative_max == 1.0);
  const FrictionErrors zero = friction_errors(p, Eigen::Vector3d::Zero());
  CHECK(zero.relative_q == 0.0);
  CHECK(zero.relative_max == 0.0);
  SolveResult r = solve_in_measure(p, *lcp::solvers().find("auto"), CommonOptions{},
                                   FrictionMeasure::kRelativeQ);
  CHECK(r.status == Status::kSolved);
  CHECK(r.z.norm() <= 1e-12);
}

TEST_CASE("a solve in each measure reaches the hand solution within tol in it", "[friction][measure]") {
  const FrictionContactProblem p = hand_problem();
  for (FrictionMeasure m : {FrictionMeasure::kUnitFree, FrictionMeasure::kRelativeQ,
                            FrictionMeasure::kRelativeMax}) {
    INFO(to_string(m));
    CommonOptions o;
    o.tol = 1e-10;
    const SolveResult r = solve_in_measure(p, *lcp::solvers().find("auto"), o, m);
    REQUIRE(r.status == Status::kSolved);
    CHECK((r.z - Eigen::Vector3d(1, -0.3, -0.4)).norm() <= 1e-9);
    CHECK(relative_q(p, r.z) <= 1e-9);
  }
}

TEST_CASE("decide_in_measure: solved only within tol in the measure, never against the verdict",
          "[friction][measure]") {
  const FrictionContactProblem p = hand_problem();
  // r* moved by 1e-7 along e_N: a small natural map (its size computed by the definition).
  SolveResult near;
  near.z = Eigen::Vector3d(1 + 1e-7, -0.3, -0.4);
  const double rq = relative_q(p, near.z);
  REQUIRE(rq > 1e-9);
  REQUIRE(rq < 1e-6);
  CommonOptions o;
  for (double tol : {rq / 2, rq * 2}) {
    o.tol = tol;
    SolveResult r = finalize(p, near, o);  // the unit-free decision
    REQUIRE(is_solution(r.status));
    decide_in_measure(p, r, o, FrictionMeasure::kRelativeQ);
    CHECK((r.status == Status::kSolved) == (rq <= tol));
    if (r.status != Status::kSolved) CHECK(r.status == Status::kSolvedInaccurate);
  }
  // What the verdict refused stays refused, however small the relative error.
  SolveResult refused = near;
  refused.status = Status::kNumericalFailure;
  o.tol = 1e-3;
  decide_in_measure(p, refused, o, FrictionMeasure::kRelativeMax);
  CHECK(refused.status == Status::kNumericalFailure);
  // Above tol_acceptable in the measure: not a solution, with the reason. F4-04 (mu = 1e13): its
  // stick solution is r* = -W^-1 q = (8/3, -10/3, -1) (README). Moved by 1e-15 in r_T (a
  // rounding's worth), u_T ~ 1e-15, which mu |u_T| turns into a natural map of ~1e-2: the
  // unit-free verdict accepts it, the field's measure cannot tell it from a wrong answer.
  const FrictionContactProblem huge_mu =
      read_friction_problem(data("hostile/F4-04_one_contact_mu1e13.dat"));
  SolveResult stick;
  stick.z = Eigen::Vector3d(8.0 / 3, -10.0 / 3 + 1e-15, -1);
  stick = finalize(huge_mu, stick, CommonOptions{});
  REQUIRE(stick.status == Status::kSolved);
  REQUIRE(relative_q(huge_mu, stick.z) > CommonOptions{}.tol_acceptable);
  decide_in_measure(huge_mu, stick, CommonOptions{}, FrictionMeasure::kRelativeQ);
  CHECK(!is_solution(stick.status));
  CHECK(stick.message.find("not a solution in relative_q") != std::string::npos);
}

TEST_CASE("LMGC_100_PR_PerioBox at tol 1e-8 in relative_q: within 1e-8 when called solved",
          "[friction][measure][real]") {
  // Issue 35: at the unit-free 1e-8 this file's |F_nat| / |q| is 1.2e-4.
  FcRequest a;
  a.file = data("measure/LMGC_100_PR_PerioBox-i00361-60-03000.hdf5");
  a.solver = "prox";
  a.tol = 1e-8;
  a.measure = "relative_q";
  const FcSolveOutcome out = run_fc_solve_request(a);
  REQUIRE(out.problem.contacts() == 60);
  REQUIRE(out.result.z.size() == 180);
  const double rq = relative_q(out.problem, out.result.z);
  INFO(out.result.message << "; relative_q recomputed " << rq);
  CHECK(out.measure == FrictionMeasure::kRelativeQ);
  CHECK(out.result.status == Status::kSolved);  // prox gets there (8e-9, measured)
  if (out.result.status == Status::kSolved) {
    CHECK(rq <= 1e-8 * (1 + 1e-6));
    CHECK(out.exit_code == kExitOk);
  }
}

TEST_CASE("hostile files are never solved in a relative measure where the verdict refuses",
          "[friction][measure][hostile]") {
  // F4-01: no solution (the README's proof); F4-02: the global verdict refuses the condensed
  // answer; F4-04: a huge mu, where the only solution is the stick r (README): whatever is
  // called solved must be inside K_mu.
  int decided = 0;
  for (const char* name : {"F4-01_exact_rank1_a.dat", "F4-02_M_rank_deficient_a.dat",
                           "F4-04_one_contact_mu1e13.dat"}) {
    for (const char* m : {"relative_q", "relative_max"}) {
      FcRequest a;
      a.file = data(std::string("hostile/") + name);
      a.solver = "nsgs";
      a.tol = 1e-6;
      a.measure = m;
      a.time_limit_s = 2;
      const FcSolveOutcome out = run_fc_solve_request(a);
      INFO(name << " " << m << ": " << to_string(out.result.status) << " " << out.result.message);
      if (std::string(name).rfind("F4-04", 0) == 0) {
        if (is_solution(out.result.status))
          for (Eigen::Index i = 0; i < out.problem.contacts(); ++i)
            CHECK(out.result.z.segment<2>(3 * i + 1).norm() <=
                  out.problem.mu[i] * out.result.z[3 * i] * (1 + 1e-12));
      } else {
        CHECK(!is_solution(out.result.status));
        CHECK(out.exit_code == kExitInconclusive);
      }
      ++decided;
    }
  }
  CHECK(decided == 6);
}

TEST_CASE("an unknown measure is an input error listing the measures", "[friction][measure][bad]") {
  FcRequest a;
  a.file = data("local/FrictionContact3D_1c.dat");
  a.measure = "relative";
  const std::string names = "(valid: unit_free, relative_q, relative_max)";
  auto message = [](auto call) -> std::string {
    try {
      call();
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  CHECK(message([&] { run_fc_solve_request(a); }).find("unknown measure 'relative' for --measure " + names) !=
        std::string::npos);
  CHECK(message([&] { run_fc_solutions_request(a); }).find(names) != std::string::npos);
  FcBenchRequest b;
  b.files = {a.file};
  b.measure = "RELATIVE_Q";
  CHECK(message([&] { prepare_fc_bench(b); }).find("unknown measure 'RELATIVE_Q'") != std::string::npos);
  CHECK(FcBenchRequest{}.measure == "relative_q");  // the published profiles' measure
  CHECK(FcRequest{}.measure == "unit_free");
  CHECK(friction_measure_from_string("relative_max") == FrictionMeasure::kRelativeMax);
  CHECK(!friction_measure_from_string(""));
}

TEST_CASE("fc solutions in relative_q: every solution called solved is within tol in it",
          "[friction][measure]") {
  FcRequest a;
  a.file = data("local/FrictionContact3D_1c.dat");
  a.tol = 1e-12;
  a.measure = "relative_q";
  const FcSolutionsOutcome out = run_fc_solutions_request(a);
  int solved = 0;
  for (const auto& s : out.set.solutions) {
    if (s.status != Status::kSolved) continue;
    CHECK(relative_q(out.problem, s.z) <= 1e-12 * (1 + 1e-6));
    ++solved;
  }
  CHECK(solved >= 1);
  CHECK(out.exit_code == kExitOk);
}

TEST_CASE("auto's answers on real files: finalize() decides them again the same way, and the "
          "stored errors are the natural map's", "[friction][measure][auto]") {
  // auto no longer judges its chosen answer a second time (every stage returned through
  // finalize() at the caller's tol): a fresh verdict (finalize(), then the measure's decision)
  // must agree, and relative_q must be the natural map's norm written in this test.
  int decided = 0;
  for (const char* name : {"FrictionContact3D_1c.dat", "FC3D_Example1.dat", "Rover1039.dat",
                           "NESpheres_10_1.dat", "Confeti-ex03-Fc3D-SBM.dat"}) {
    INFO(name);
    const FrictionContactProblem p = read_friction_problem(data(std::string("local/") + name));
    for (FrictionMeasure m : {FrictionMeasure::kUnitFree, FrictionMeasure::kRelativeQ}) {
      CommonOptions o;
      o.tol = 1e-8;
      const SolveResult r = solve_in_measure(p, *lcp::solvers().find("auto"), o, m);
      REQUIRE(r.status == Status::kSolved);
      REQUIRE(r.friction_errors);
      SolveResult again = finalize(p, r, o);  // the unit-free verdict, then the measure's
      decide_in_measure(p, again, o, m);
      CHECK(again.status == Status::kSolved);
      CHECK(again.residuals.natural == r.residuals.natural);
      CHECK(r.friction_errors->unit_free == r.residuals.natural);
      const double F = relative_q(p, r.z);
      // Two roundings of one number: equal to 1e-9 of it, or to 1e-14 of |q| near 0.
      CHECK(std::abs(r.friction_errors->relative_q - F) <= 1e-9 * F + 1e-14);
      if (m == FrictionMeasure::kRelativeQ) CHECK(F <= 1e-8);
      ++decided;
    }
  }
  CHECK(decided == 10);
}

