// The N-point rate problem against independent answers: N = 1 against the one-point routes,
// block-diagonal A against the product of one-point sets, and a brute force over type tuples
// (one square linear system per tuple, written here) on random 2- and 3-point systems.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/system/system_rate.hpp"

#include "system_test_util.hpp"

using namespace cpkit::rate;
using Kind = RateSolution::Kind;

namespace {

using Vec = Eigen::VectorXd;

Vec stack(const SystemRates& r) {
  Vec x(6 * r.dP_T.size());
  x << r.dP_T, r.dP_N, r.dw_T, r.dw_N, r.dw_Ti, r.dw_w;
  return x;
}
Vec stack1(const Rates& r) {
  Vec x(6);
  x << r.dP_T, r.dP_N, r.dw_T, r.dw_N, r.dw_Ti, r.dw_w;
  return x;
}
double rel(const Vec& a, const Vec& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / (1.0 + std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>()));
}

using cpkit::test::random_label;
using cpkit::test::random_point;
using cpkit::test::random_spd;

/// Is the one-point piece p among the N-point set's pieces (N = 1)?
bool has_piece(const SystemRateSolutionSet& s, const RateSolution& p, double tol) {
  for (const auto& q : s.solutions) {
    if (q.kind != p.kind || q.types.size() != 1 || q.types[0] != p.type) continue;
    if (p.kind == Kind::kPoint && rel(stack(q.start), stack1(p.start)) <= tol) return true;
    if (p.kind == Kind::kRay && rel(stack(q.start), stack1(p.start)) <= tol &&
        q.start_closed == p.start_closed) {
      // directions: same up to a positive factor
      const Vec a = stack(q.direction), b = stack1(p.direction);
      if (rel(a / a.lpNorm<Eigen::Infinity>(), b / b.lpNorm<Eigen::Infinity>()) <= tol) return true;
    }
    if (p.kind == Kind::kSegment) {
      const bool same = rel(stack(q.start), stack1(p.start)) <= tol && rel(stack(q.end), stack1(p.end)) <= tol &&
                        q.start_closed == p.start_closed && q.end_closed == p.end_closed;
      const bool swapped = rel(stack(q.start), stack1(p.end)) <= tol && rel(stack(q.end), stack1(p.start)) <= tol &&
                           q.start_closed == p.end_closed && q.end_closed == p.start_closed;
      if (same || swapped) return true;
    }
  }
  return false;
}

/// Brute force: every type tuple's square linear system (6N unknowns: dP_T, dP_N, dw_T, dw_N,
/// dw_Ti, dw_w per point), solved and checked against the tuple's sign conditions. Returns
/// false when some tuple's system is singular or some sign test is too close to call.
bool brute_force(const ContactSystem& S, const Vec& dF, std::vector<std::pair<TypeTuple, Vec>>& out) {
  const int N = S.n_points();
  const int n = 6 * N;
  auto iP_T = [&](int i) { return i; };
  auto iP_N = [&](int i) { return N + i; };
  auto iw_T = [&](int i) { return 2 * N + i; };
  auto iw_N = [&](int i) { return 3 * N + i; };
  auto iw_Ti = [&](int i) { return 4 * N + i; };
  auto iw_w = [&](int i) { return 5 * N + i; };
  // candidate types per point
  std::vector<std::vector<SolutionType>> cands(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    const auto& st = S.points[static_cast<std::size_t>(i)].state;
    auto& c = cands[static_cast<std::size_t>(i)];
    switch (st.label) {
      case StateLabel::kA: c = {SolutionType::kOpen}; break;
      case StateLabel::kB: c = {SolutionType::kSeparation, SolutionType::kStick, SolutionType::kSlipPlus, SolutionType::kSlipMinus}; break;
      case StateLabel::kC: c = {SolutionType::kStick}; break;
      case StateLabel::kD: c = {SolutionType::kStick, st.sgn_PT > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus}; break;
    }
  }
  std::vector<SolutionType> t(static_cast<std::size_t>(N));
  bool ok = true;
  const double F = dF.lpNorm<1>() + 1e-300;
  std::function<void(int)> rec = [&](int i) {
    if (i == N) {
      Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
      Vec b = Vec::Zero(n);
      int r = 0;
      for (int p = 0; p < N; ++p) {  // equilibrium dP + A dw = dF
        for (int d = 0; d < 2; ++d) {
          K(r, d == 0 ? iP_T(p) : iP_N(p)) = 1;
          for (int j = 0; j < N; ++j) {
            K(r, iw_T(j)) += S.A(2 * p + d, 2 * j);
            K(r, iw_N(j)) += S.A(2 * p + d, 2 * j + 1);
          }
          b(r++) = dF(2 * p + d);
        }
      }
      for (int p = 0; p < N; ++p) {
        const SystemPoint& P = S.points[static_cast<std::size_t>(p)];
        const double kappa = P.k_a / (3 * P.P_s) * P.state.P_N;
        K(r, iw_T(p)) = 1; K(r, iP_T(p)) = -P.C_T; K(r, iw_Ti(p)) = -1; ++r;  // (27)
        switch (t[static_cast<std::size_t>(p)]) {
          case SolutionType::kOpen:
          case SolutionType::kSeparation:
            K(r++, iP_T(p)) = 1; K(r++, iP_N(p)) = 1; K(r++, iw_w(p)) = 1;  // dP = 0, no wear
            break;
          case SolutionType::kStick:
            K(r++, iw_N(p)) = 1; K(r++, iw_Ti(p)) = 1; K(r++, iw_w(p)) = 1;
            break;
          default: {
            const int s = t[static_cast<std::size_t>(p)] == SolutionType::kSlipPlus ? 1 : -1;
            if (P.state.label == StateLabel::kB) {
              K(r++, iw_N(p)) = 1;
              K(r, iP_T(p)) = 1; K(r, iP_N(p)) = -s * P.mu; ++r;
              K(r++, iw_w(p)) = 1;
            } else {  // d: on the cone's rate, dw_N = dw^w = kappa lambda, lambda = s dw_Ti
              K(r, iP_T(p)) = s; K(r, iP_N(p)) = -P.mu; ++r;
              K(r, iw_N(p)) = 1; K(r, iw_Ti(p)) = -s * kappa; ++r;
              K(r, iw_w(p)) = 1; K(r, iw_Ti(p)) = -s * kappa; ++r;
            }
          }
        }
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
      lu.setThreshold(1e-11);
      if (!lu.isInvertible()) { ok = false; return; }
      const Vec x = lu.solve(b);
      // sign conditions, relative to the load and the solution's size
      const double sf = F + x.head(2 * N).lpNorm<Eigen::Infinity>();
      const double sw = x.tail(4 * N).lpNorm<Eigen::Infinity>() + 1e-300;
      const double gap = 1e-7;
      bool fine = true;
      auto pos = [&](double v, double s, bool) {  // v >= 0 (or > 0): borderline = not generic
        if (std::abs(v) <= gap * s) ok = false;
        if (v < 0) fine = false;
      };
      for (int p = 0; p < N && fine; ++p) {
        const SystemPoint& P = S.points[static_cast<std::size_t>(p)];
        const int s = P.state.sgn_PT;
        switch (t[static_cast<std::size_t>(p)]) {
          case SolutionType::kSeparation: pos(-x(iw_N(p)), sw, true); break;
          case SolutionType::kStick:
            if (P.state.label == StateLabel::kB) {
              pos(x(iP_N(p)), sf, false);
              pos(P.mu * x(iP_N(p)) - x(iP_T(p)), sf, false);
              pos(P.mu * x(iP_N(p)) + x(iP_T(p)), sf, false);
            }
            if (P.state.label == StateLabel::kD) pos(P.mu * x(iP_N(p)) - s * x(iP_T(p)), sf, false);
            break;
          case SolutionType::kSlipPlus:
          case SolutionType::kSlipMinus: {
            const int sl = t[static_cast<std::size_t>(p)] == SolutionType::kSlipPlus ? 1 : -1;
            if (P.state.label == StateLabel::kB) pos(x(iP_N(p)), sf, false);
            pos(sl * x(iw_Ti(p)), sw, true);
            break;
          }
          default: break;
        }
      }
      if (fine) out.emplace_back(encode_types(t), x);
      return;
    }
    for (SolutionType c : cands[static_cast<std::size_t>(i)]) {
      t[static_cast<std::size_t>(i)] = c;
      rec(i + 1);
    }
  };
  rec(0);
  return ok;
}

}  // namespace

TEST_CASE("N = 1 gives the one-point answers", "[rate][system]") {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> U(-1, 1);
  int compared = 0, infinite = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, random_label(rng))};
    S.A = random_spd(rng, 2);
    if (trial % 3 == 0) {  // the softening criterion (35): mu_eff = mu - 2 kappa in state d
      S.criterion = Criterion::kSoftening;
      SystemPoint& q = S.points[0];
      const double k = q.k_a / (3 * q.P_s);
      if (q.state.label == StateLabel::kD) q.P_T = q.state.sgn_PT * (q.mu * q.P_N - k * q.P_N * q.P_N);
    }
    ContactParameters par = S.point_parameters(0);
    Vec dF(2);
    dF << U(rng), U(rng);
    if (trial % 10 == 0 && S.points[0].state.label == StateLabel::kB) {
      // degenerate a11 = mu |a12| with a load on N = a11 dF_N - a12 dF_T = 0
      S.points[0].mu = S.A(0, 0) / std::abs(S.A(0, 1));
      par = S.point_parameters(0);
      dF(1) = std::abs(dF(1));
      dF(0) = S.A(0, 0) * dF(1) / S.A(0, 1);
    }
    if (!S.validate().empty()) continue;  // e.g. beyond the bound (46)
    const RateSolutionSet one = solve_rate_problem(par, S.points[0].state, LoadRate{dF(0), dF(1)});
    const SystemRateSolutionSet sys = solve_rate_problem(S, dF);
    CAPTURE(trial, S.A, dF, to_string(S.points[0].state.label), S.points[0].mu, one.count(), sys.count(), sys.message);
    REQUIRE(sys.complete == one.complete);
    REQUIRE(sys.count() == one.count());
    REQUIRE(sys.solutions.size() == one.solutions.size());
    for (const auto& p : one.solutions) CHECK(has_piece(sys, p, 1e-7));
    ++compared;
    infinite += one.infinite ? 1 : 0;
  }
  CHECK(compared > 2500);
  CHECK(infinite > 10);
}

TEST_CASE("block-diagonal A gives the product of one-point sets", "[rate][system]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  int multi = 0;
  for (int trial = 0; trial < 400; ++trial) {
    ContactSystem S;
    S.points = {random_point(rng, random_label(rng)), random_point(rng, random_label(rng))};
    S.A = Eigen::MatrixXd::Zero(4, 4);
    S.A.block(0, 0, 2, 2) = random_spd(rng, 2);
    S.A.block(2, 2, 2, 2) = random_spd(rng, 2);
    Vec dF(4);
    for (int k = 0; k < 4; ++k) dF(k) = U(rng);
    if (!S.validate().empty()) continue;
    const RateSolutionSet a = solve_rate_problem(S.point_parameters(0), S.points[0].state, LoadRate{dF(0), dF(1)});
    const RateSolutionSet b = solve_rate_problem(S.point_parameters(1), S.points[1].state, LoadRate{dF(2), dF(3)});
    const SystemRateSolutionSet s = solve_rate_problem(S, dF);
    if (a.infinite || b.infinite) continue;
    CAPTURE(trial, s.message);
    REQUIRE(s.count() == a.count() * b.count());
    multi += s.count() > 1 ? 1 : 0;
    for (const auto& x : a.solutions)
      for (const auto& y : b.solutions) {
        bool found = false;
        for (const auto& z : s.solutions) {
          if (z.types != std::vector<SolutionType>{x.type, y.type}) continue;
          Vec want(12);
          want << x.start.dP_T, y.start.dP_T, x.start.dP_N, y.start.dP_N, x.start.dw_T, y.start.dw_T,
              x.start.dw_N, y.start.dw_N, x.start.dw_Ti, y.start.dw_Ti, x.start.dw_w, y.start.dw_w;
          found = found || rel(stack(z.start), want) <= 1e-7;
        }
        CHECK(found);
      }
  }
  CHECK(multi > 5);
}

TEST_CASE("brute force over type tuples on random 2- and 3-point systems", "[rate][system]") {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(-1, 1);
  std::map<int, int> counts;
  int compared = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int N = 2 + trial % 2;
    ContactSystem S;
    for (int i = 0; i < N; ++i) {
      // states b and d make the interesting cases
      const double r = (U(rng) + 1) / 2;
      const StateLabel l = r < 0.4 ? StateLabel::kB : (r < 0.8 ? StateLabel::kD : random_label(rng));
      S.points.push_back(random_point(rng, l));
      SystemPoint& q = S.points.back();
      q.mu *= 1.5;  // more non-uniqueness
      q.P_T = q.state.label == StateLabel::kD ? q.state.sgn_PT * q.mu * q.P_N : 0.0;
    }
    S.A = random_spd(rng, 2 * N);
    if (!S.validate().empty()) continue;
    Vec dF(2 * N);
    for (int k = 0; k < 2 * N; ++k) dF(k) = U(rng);
    std::vector<std::pair<TypeTuple, Vec>> bf;
    if (!brute_force(S, dF, bf)) continue;  // a degenerate tuple: not a generic case
    const SystemRateSolutionSet s = solve_rate_problem(S, dF);
    CAPTURE(trial, N, s.message, bf.size(), s.count());
    REQUIRE(s.complete);
    REQUIRE(!s.infinite);
    REQUIRE(s.count() == static_cast<int>(bf.size()));
    for (const auto& [tt, x] : bf) {
      bool found = false;
      for (const auto& z : s.solutions) found = found || (encode_types(z.types) == tt && rel(stack(z.start), x) <= 1e-7);
      CHECK(found);
    }
    ++counts[s.count()];
    ++compared;
  }
  CAPTURE(compared, counts[0], counts[1], counts[2], counts[3], counts[4]);
  CHECK(compared > 1000);
  CHECK(counts[0] > 0);
  CHECK(counts[2] > 0);
  CHECK(counts[4] > 0);
}

TEST_CASE("continua: a degenerate point times a regular one; two degenerate points", "[rate][system]") {
  // point 1 alone: a11 = mu |a12| and N = 0 with dF_N > 0 gives a segment from stick to
  // zero-force slip (docs/contact_model.md); point 2 in state c (one solution)
  ContactSystem S;
  SystemPoint p1;
  p1.mu = 2;
  p1.state.label = StateLabel::kB;
  SystemPoint p2 = p1;
  S.points = {p1, p2};
  S.A = Eigen::MatrixXd::Zero(4, 4);
  S.A.block(0, 0, 2, 2) << 1, 0.5, 0.5, 1;  // a11 = mu a12
  S.A.block(2, 2, 2, 2) << 1, 0.5, 0.5, 1;
  Vec dF(4);
  dF << 1, 0.5, 0, 1;  // point 1: N = a11 dF_N - a12 dF_T = 0; point 2: unique (dF_T = 0)
  const RateSolutionSet one = solve_rate_problem(S.point_parameters(0), p1.state, LoadRate{1, 0.5});
  const RateSolutionSet two = solve_rate_problem(S.point_parameters(1), p2.state, LoadRate{0, 1});
  REQUIRE(one.infinite);
  REQUIRE(two.count() == 1);
  const SystemRateSolutionSet s = solve_rate_problem(S, dF);
  CAPTURE(s.message);
  CHECK(s.complete);
  CHECK(s.count() == -1);
  CHECK(s.solutions.size() == one.solutions.size());
  int segments = 0;
  for (const auto& z : s.solutions) segments += z.kind == Kind::kSegment ? 1 : 0;
  CHECK(segments >= 1);
  // both points degenerate: the product of two segments is a square -> reported, not listed
  dF << 1, 0.5, 1, 0.5;
  const SystemRateSolutionSet sq = solve_rate_problem(S, dF);
  CHECK_FALSE(sq.complete);
  CHECK(sq.count() == -1);
  CHECK(sq.message.find("dimension 2") != std::string::npos);
}

namespace {
/// Point 1's part of an N-point rate vector (N = 2) as one-point Rates.
Rates first_point(const SystemRates& r) {
  return Rates{r.dP_T(0), r.dP_N(0), r.dw_T(0), r.dw_N(0), r.dw_Ti(0), r.dw_w(0)};
}
}  // namespace

TEST_CASE("continua of a degenerate point coupled to nothing: segments and rays carry over",
          "[rate][system]") {
  // Point 1 degenerate on purpose (b: a11 = mu|a12| with N = 0; d: Lambda = 0 with L_s = 0),
  // point 2 in state c on its own block: the N-point set is point 1's set times one stick point.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> U(0, 1);
  int segments = 0, rays = 0;
  for (int trial = 0; trial < 400; ++trial) {
    ContactSystem S;
    const bool use_d = trial % 2 == 1;
    SystemPoint p1 = random_point(rng, use_d ? StateLabel::kD : StateLabel::kB);
    SystemPoint p2 = random_point(rng, StateLabel::kC);
    S.A = Eigen::MatrixXd::Zero(4, 4);
    S.A.block(0, 0, 2, 2) = random_spd(rng, 2);
    S.A.block(2, 2, 2, 2) = random_spd(rng, 2);
    const double a11 = S.A(0, 0), a12 = S.A(0, 1), a22 = S.A(1, 1), det = a11 * a22 - a12 * a12;
    Vec dF(4);
    dF << 0, 0.2 + U(rng), U(rng) - 0.5, U(rng);
    if (!use_d) {
      p1.mu = a11 / std::abs(a12);
      dF(0) = a11 * dF(1) / a12;  // N = a11 dF_N - a12 dF_T = 0, dF_N > 0
    } else {
      const int s = p1.state.sgn_PT;
      const double kappa = p1.k_a / (3 * p1.P_s) * p1.state.P_N;
      const double denom = s * a12 + kappa * a22 + kappa * p1.C_T * det;
      const double mu = (a11 + kappa * s * a12) / denom;  // Lambda = 0, eqn (51)
      if (!(mu > 0.05 && mu < 50)) continue;
      p1.mu = mu;
      p1.P_T = s * mu * p1.P_N;
      dF(0) = mu * (1 + a11 * p1.C_T) * dF(1) / (s + mu * a12 * p1.C_T);  // L_s = 0
    }
    S.points = {p1, p2};
    if (!S.validate().empty()) continue;
    const RateSolutionSet one = solve_rate_problem(S.point_parameters(0), p1.state, LoadRate{dF(0), dF(1)});
    const SystemRateSolutionSet sys = solve_rate_problem(S, dF);
    CAPTURE(trial, use_d, sys.message, one.count(), sys.count());
    REQUIRE(sys.complete == one.complete);
    REQUIRE(sys.count() == one.count());
    REQUIRE(sys.solutions.size() == one.solutions.size());
    // project onto point 1 and compare piece by piece
    SystemRateSolutionSet proj;
    const RateSolutionSet two = solve_rate_problem(S.point_parameters(1), p2.state, LoadRate{dF(2), dF(3)});
    REQUIRE(two.count() == 1);
    for (const auto& z : sys.solutions) {
      CHECK(z.types[1] == SolutionType::kStick);
      const Rates& r2 = two.solutions[0].start;
      Vec got(6);
      got << z.start.dP_T(1), z.start.dP_N(1), z.start.dw_T(1), z.start.dw_N(1), z.start.dw_Ti(1), z.start.dw_w(1);
      CHECK(rel(got, stack1(r2)) <= 1e-9);
      SystemRateSolution w;
      w.types = {z.types[0]};
      w.kind = z.kind;
      auto cut = [](const SystemRates& r) {
        SystemRates x;
        const Rates p = first_point(r);
        x.dP_T = Vec::Constant(1, p.dP_T); x.dP_N = Vec::Constant(1, p.dP_N);
        x.dw_T = Vec::Constant(1, p.dw_T); x.dw_N = Vec::Constant(1, p.dw_N);
        x.dw_Ti = Vec::Constant(1, p.dw_Ti); x.dw_w = Vec::Constant(1, p.dw_w);
        return x;
      };
      w.start = cut(z.start);
      w.start_closed = z.start_closed;
      w.end = z.kind == Kind::kSegment ? cut(z.end) : w.start;
      w.end_closed = z.end_closed;
      w.direction = z.kind == Kind::kRay ? cut(z.direction) : w.start;
      proj.solutions.push_back(w);
    }
    for (const auto& p : one.solutions) {
      CHECK(has_piece(proj, p, 1e-7));
      segments += p.kind == Kind::kSegment ? 1 : 0;
      rays += p.kind == Kind::kRay ? 1 : 0;
    }
  }
  CHECK(segments > 20);
  CHECK(rays > 20);
}

TEST_CASE("single solvers answer inside the enumerated set", "[rate][system]") {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> U(-1, 1);
  int found = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int N = 2 + trial % 2;
    ContactSystem S;
    for (int i = 0; i < N; ++i) S.points.push_back(random_point(rng, random_label(rng)));
    S.A = random_spd(rng, 2 * N);
    Vec dF(2 * N);
    for (int k = 0; k < 2 * N; ++k) dF(k) = U(rng);
    const SystemRateSolutionSet all = solve_rate_problem(S, dF);
    for (RateMethod m : {RateMethod::kLemke, RateMethod::kFbNewton}) {
      const SystemRateSolutionSet one = solve_rate_problem(S, dF, m);
      CHECK_FALSE(one.complete);
      if (one.solutions.empty()) continue;
      CAPTURE(trial, one.message);
      CHECK_FALSE(one.disagreement);
      CHECK(contains(all, one.solutions[0].start, std::max(1e-7, 1e3 * one.residual)));
      ++found;
    }
  }
  CHECK(found > 40);
}

TEST_CASE("N-point rate problem: bad input", "[rate][system]") {
  ContactSystem S;
  S.points.resize(2);
  S.A = Eigen::MatrixXd::Identity(4, 4);
  CHECK_THROWS_AS(solve_rate_problem(S, Vec::Zero(3)), cpkit::InputError);
  Vec nan = Vec::Zero(4);
  nan(2) = std::nan("");
  CHECK_THROWS_AS(solve_rate_problem(S, nan), cpkit::InputError);
  CHECK_THROWS_AS(solve_rate_problem(S, Vec::Zero(4), RateMethod::kAnalytic), cpkit::InputError);
  S.A(0, 1) = 3;
  CHECK_THROWS_AS(solve_rate_problem(S, Vec::Zero(4)), cpkit::InputError);
}

TEST_CASE("beyond the enumeration's size limit: complete = false, nothing listed", "[rate][system]") {
  ContactSystem S;
  S.points.resize(9);  // 9 points in state b: LCP size 27 > 24
  S.A = Eigen::MatrixXd::Identity(18, 18);
  const SystemRateSolutionSet s = solve_rate_problem(S, Vec::Ones(18));
  CHECK_FALSE(s.complete);
  CHECK(s.solutions.empty());
  CHECK(s.message.find("limit") != std::string::npos);
}

TEST_CASE("summary agrees with the full solve", "[rate][system]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 100; ++trial) {
    const int N = 1 + trial % 3;
    ContactSystem S;
    for (int i = 0; i < N; ++i) S.points.push_back(random_point(rng, random_label(rng)));
    S.A = random_spd(rng, 2 * N);
    const SystemRatePrecomputed pre = precompute_system_rate(S);
    Vec dF(2 * N);
    for (int k = 0; k < 2 * N; ++k) dF(k) = U(rng);
    const SystemRateSolutionSet s = solve_rate_problem(S, dF);
    const SystemRateSummary sum = summarize_rate_problem(pre, dF);
    CHECK(sum.count == s.count());
    std::set<TypeTuple> want;
    for (const auto& z : s.solutions) want.insert(encode_types(z.types));
    CHECK(sum.n_tuples == static_cast<int>(want.size()));
    CHECK(std::set<TypeTuple>(sum.tuples.begin(), sum.tuples.begin() + sum.n_tuples) == want);
    if (!s.solutions.empty()) CHECK(decode_types(encode_types(s.solutions[0].types), N) == s.solutions[0].types);
  }
  const SystemRatePrecomputed pre = precompute_system_rate([] {
    ContactSystem S;
    S.points.resize(1);
    S.A = Eigen::Matrix2d::Identity();
    return S;
  }());
  CHECK_FALSE(summarize_rate_problem(pre, Vec::Zero(3)).reliable);
}

TEST_CASE("summaries from two threads on one precomputed system agree with one thread",
          "[rate][system]") {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> U(-1, 1);
  ContactSystem S;
  for (int i = 0; i < 3; ++i) S.points.push_back(random_point(rng, i == 1 ? StateLabel::kD : StateLabel::kB));
  S.A = random_spd(rng, 6);
  const SystemRatePrecomputed pre = precompute_system_rate(S);
  std::vector<Vec> loads;
  for (int k = 0; k < 200; ++k) {
    Vec f(6);
    for (int j = 0; j < 6; ++j) f(j) = U(rng);
    loads.push_back(f);
  }
  std::vector<int> serial(loads.size()), par(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) serial[k] = summarize_rate_problem(pre, loads[k]).count;
  auto work = [&](std::size_t from) {
    for (std::size_t k = from; k < loads.size(); k += 2) par[k] = summarize_rate_problem(pre, loads[k]).count;
  };
  std::thread t0(work, 0), t1(work, 1);
  t0.join();
  t1.join();
  CHECK(par == serial);
}
