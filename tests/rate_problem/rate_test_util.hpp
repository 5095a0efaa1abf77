#pragma once
// Test helpers for the rate problem, written independently of the library's routes: a checker
// of the rate laws of [Stromberg et al. 1996, Sec. 4.2] + eqn (50), a brute-force solver over
// the solution types, and a comparison of two solution sets.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cpkit/rate_problem/rate/point_rate.hpp"

namespace cpkit::rate::test {

/// Magnitudes for relative comparisons: forces and displacement rates.
struct Scales {
  double F, W;
};
inline Scales scales(const ContactParameters& p, const LoadRate& f) {
  const double F = std::abs(f.dF_T) + std::abs(f.dF_N) + 1e-300;
  return {F, F * (p.C_T + 1.0 / p.a11 + 1.0 / p.a22)};
}

/// Empty when `r` satisfies the rate laws of the state as a solution of type `type`; else the
/// first violated law. tol is relative to the magnitudes of the rates and the load.
inline std::string check_rate_laws(const ContactParameters& p, const ContactState& st,
                                   const LoadRate& f, const Rates& r, SolutionType type,
                                   double tol = 1e-7) {
  const double F = std::abs(f.dF_T) + std::abs(f.dF_N) + std::abs(r.dP_T) + std::abs(r.dP_N) + 1e-300;
  const double W = std::abs(r.dw_T) + std::abs(r.dw_N) + std::abs(r.dw_Ti) + std::abs(r.dw_w) +
                   F * (p.C_T + 1.0 / p.a11 + 1.0 / p.a22);
  const double aW = (std::abs(p.a11) + std::abs(p.a12) + std::abs(p.a22)) * W;
  // (50): dF - dP = A dw
  if (std::abs(f.dF_T - r.dP_T - p.a11 * r.dw_T - p.a12 * r.dw_N) > tol * (F + aW))
    return "tangential equilibrium (50)";
  if (std::abs(f.dF_N - r.dP_N - p.a12 * r.dw_T - p.a22 * r.dw_N) > tol * (F + aW))
    return "normal equilibrium (50)";
  // (27): dw_T = C_T dP_T + dw_T^i
  if (std::abs(r.dw_T - p.C_T * r.dP_T - r.dw_Ti) > tol * W) return "dw_T = C_T dP_T + dw_T^i";
  const bool sep = r.dw_N < -tol * W;
  const int sx = r.dw_Ti > tol * W ? 1 : (r.dw_Ti < -tol * W ? -1 : 0);
  switch (st.label) {
    case StateLabel::kA:
      if (type != SolutionType::kOpen) return "state a: type must be open";
      if (std::abs(r.dP_T) > tol * F || std::abs(r.dP_N) > tol * F) return "state a: dP != 0";
      if (std::abs(r.dw_w) > tol * W) return "state a: wear";
      if (std::abs(r.dw_Ti - r.dw_T) > tol * W) return "state a: dw_T^i != dw_T";
      return {};
    case StateLabel::kB: {
      if (r.dP_N < -tol * F) return "b: dP_N < 0";
      if (r.dw_N > tol * W) return "b: dw_N > 0 (penetration)";
      if (std::abs(r.dw_w) > tol * W) return "b: wear";
      if (std::abs(r.dP_T) > p.mu * r.dP_N + tol * F) return "b: |dP_T| > mu dP_N";
      if (sep && r.dP_N > tol * F) return "b: dP_N dw_N != 0";
      if (sx != 0 && std::abs(r.dP_T - sx * p.mu * r.dP_N) > tol * F) return "b: slip off the cone";
      const SolutionType t = sep ? SolutionType::kSeparation
                                 : (sx > 0 ? SolutionType::kSlipPlus
                                           : (sx < 0 ? SolutionType::kSlipMinus : SolutionType::kStick));
      if (t != type) return "b: type mismatch";
      return {};
    }
    case StateLabel::kC:
      if (type != SolutionType::kStick) return "c: type must be stick";
      if (std::abs(r.dw_N) > tol * W || std::abs(r.dw_Ti) > tol * W || std::abs(r.dw_w) > tol * W)
        return "c: dw_N, dw_T^i, dw^w must vanish";
      return {};
    case StateLabel::kD: {
      const int s = st.sgn_PT;
      const double kappa = p.k_a * st.P_N / (3.0 * p.P_s);
      const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * kappa : p.mu;
      const double lambda = s * r.dw_Ti;
      if (lambda < -tol * W) return "d: slip against sgn P_T";
      if (std::abs(r.dw_N - kappa * lambda) > tol * W) return "d: dw_N != kappa lambda";
      if (std::abs(r.dw_w - kappa * lambda) > tol * W) return "d: dw^w != kappa lambda";
      if (s * r.dP_T > m * r.dP_N + tol * F) return "d: s dP_T > mu dP_N (cone rate)";
      if (sx != 0 && std::abs(s * r.dP_T - m * r.dP_N) > tol * F) return "d: slip off the cone";
      const SolutionType t = sx > 0 ? SolutionType::kSlipPlus
                                    : (sx < 0 ? SolutionType::kSlipMinus : SolutionType::kStick);
      if (t != type) return "d: type mismatch";
      return {};
    }
  }
  return "unknown state";
}

/// Checks every point of the set: points, closed ends, and interior points of segments/rays.
inline std::string check_set_laws(const ContactParameters& p, const ContactState& st,
                                  const LoadRate& f, const RateSolutionSet& set, double tol = 1e-7) {
  auto lerp = [](const Rates& a, const Rates& d, double t) {
    return Rates{a.dP_T + t * d.dP_T, a.dP_N + t * d.dP_N, a.dw_T + t * d.dw_T,
                 a.dw_N + t * d.dw_N, a.dw_Ti + t * d.dw_Ti, a.dw_w + t * d.dw_w};
  };
  for (const auto& s : set.solutions) {
    std::string e;
    if (s.kind == RateSolution::Kind::kPoint) {
      e = check_rate_laws(p, st, f, s.start, s.type, tol);
    } else {
      Rates d = s.direction;
      if (s.kind == RateSolution::Kind::kSegment)
        d = Rates{s.end.dP_T - s.start.dP_T, s.end.dP_N - s.start.dP_N, s.end.dw_T - s.start.dw_T,
                  s.end.dw_N - s.start.dw_N, s.end.dw_Ti - s.start.dw_Ti, s.end.dw_w - s.start.dw_w};
      for (double t : {0.25, 0.5, 0.75, s.kind == RateSolution::Kind::kRay ? 7.0 : 0.9})
        if (e.empty()) e = check_rate_laws(p, st, f, lerp(s.start, d, t), s.type, tol);
      if (e.empty() && s.start_closed) e = check_rate_laws(p, st, f, s.start, s.type, tol);
      if (e.empty() && s.kind == RateSolution::Kind::kSegment && s.end_closed)
        e = check_rate_laws(p, st, f, s.end, s.type, tol);
    }
    if (!e.empty()) return std::string(to_string(s.type)) + " " + std::string(to_string(s.kind)) + ": " + e;
  }
  return {};
}

/// Brute force over the solution types (generic cases): for each type hypothesis, the linear
/// rate equations are solved with Eigen and the inequalities checked. Returns the sorted list of
/// types found; `margin` receives the smallest relative slack of any inequality decision, so that
/// callers can skip cases too close to a boundary.
inline std::vector<SolutionType> brute_force_types(const ContactParameters& p,
                                                   const ContactState& st, const LoadRate& f,
                                                   double& margin) {
  margin = 1e300;
  std::vector<SolutionType> out;
  const double F = std::abs(f.dF_T) + std::abs(f.dF_N);
  auto decide = [&](double v, double scale) {  // v > 0 ?
    margin = std::min(margin, std::abs(v) / scale);
    return v > 0;
  };
  // unknowns x = (dP_T, dP_N, dw_T, dw_N, dw_Ti); equations: (50) x2, (27), + 2 type equations
  auto solve = [&](const Eigen::Matrix<double, 2, 5>& extra, const Eigen::Vector2d& rhs) {
    Eigen::Matrix<double, 5, 5> K;
    K << 1, 0, p.a11, p.a12, 0,  //
        0, 1, p.a12, p.a22, 0,   //
        -p.C_T, 0, 1, 0, -1,     //
        extra;
    Eigen::Matrix<double, 5, 1> b;
    b << f.dF_T, f.dF_N, 0, rhs(0), rhs(1);
    return Eigen::Matrix<double, 5, 1>(K.fullPivLu().solve(b));
  };
  const double W = F * (p.C_T + 1.0 / p.a11 + 1.0 / p.a22);
  if (st.label == StateLabel::kB) {
    Eigen::Matrix<double, 2, 5> E;
    // separation: dP = 0
    E << 1, 0, 0, 0, 0, 0, 1, 0, 0, 0;
    auto x = solve(E, Eigen::Vector2d(0, 0));
    if (decide(-x(3), W)) out.push_back(SolutionType::kSeparation);
    // stick: dw_N = 0, dw_Ti = 0
    E << 0, 0, 0, 1, 0, 0, 0, 0, 0, 1;
    x = solve(E, Eigen::Vector2d(0, 0));
    if (decide(x(1), F) && decide(p.mu * x(1) - std::abs(x(0)), F)) out.push_back(SolutionType::kStick);
    for (int s : {1, -1}) {
      // slip s: dw_N = 0, dP_T - s mu dP_N = 0
      E << 0, 0, 0, 1, 0, 1, -s * p.mu, 0, 0, 0;
      x = solve(E, Eigen::Vector2d(0, 0));
      if (decide(x(1), F) && decide(s * x(4), W))
        out.push_back(s > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus);
    }
  } else if (st.label == StateLabel::kD) {
    const int s = st.sgn_PT;
    const double kappa = p.k_a * st.P_N / (3.0 * p.P_s);
    const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * kappa : p.mu;
    Eigen::Matrix<double, 2, 5> E;
    E << 0, 0, 0, 1, 0, 0, 0, 0, 0, 1;
    auto x = solve(E, Eigen::Vector2d(0, 0));
    if (decide(m * x(1) - s * x(0) + 1e-300, F)) out.push_back(SolutionType::kStick);
    // slip: dw_N - s kappa dw_Ti = 0 (dw_N = kappa lambda), s dP_T - m dP_N = 0
    E << 0, 0, 0, 1, -s * kappa, s, -m, 0, 0, 0;
    x = solve(E, Eigen::Vector2d(0, 0));
    if (decide(s * x(4), W)) out.push_back(s > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Same pieces (type, kind, ends, closedness), rates within tol relative to the magnitudes.
inline bool close(const Rates& a, const Rates& b, const Scales& s, double tol) {
  const double x[] = {a.dP_T, a.dP_N, a.dw_T, a.dw_N, a.dw_Ti, a.dw_w};
  const double y[] = {b.dP_T, b.dP_N, b.dw_T, b.dw_N, b.dw_Ti, b.dw_w};
  for (int c = 0; c < 6; ++c) {
    const double sc = std::max({c < 2 ? s.F : s.W, std::abs(x[c]), std::abs(y[c])});
    if (std::abs(x[c] - y[c]) > tol * sc) return false;
  }
  return true;
}

inline bool same_piece(const RateSolution& a, const RateSolution& b, const Scales& s, double tol) {
  if (a.type != b.type || a.kind != b.kind) return false;
  if (a.kind == RateSolution::Kind::kPoint) return close(a.start, b.start, s, tol);
  if (a.kind == RateSolution::Kind::kSegment)
    return (close(a.start, b.start, s, tol) && close(a.end, b.end, s, tol) &&
            a.start_closed == b.start_closed && a.end_closed == b.end_closed) ||
           (close(a.start, b.end, s, tol) && close(a.end, b.start, s, tol) &&
            a.start_closed == b.end_closed && a.end_closed == b.start_closed);
  // ray: same start and closedness, parallel directions (compare normalised by dw_T^i)
  if (!close(a.start, b.start, s, tol) || a.start_closed != b.start_closed) return false;
  if (a.direction.dw_Ti == 0 || b.direction.dw_Ti == 0) return false;
  const double ka = 1.0 / std::abs(a.direction.dw_Ti), kb = 1.0 / std::abs(b.direction.dw_Ti);
  const Rates da{a.direction.dP_T * ka, a.direction.dP_N * ka, a.direction.dw_T * ka,
                 a.direction.dw_N * ka, a.direction.dw_Ti * ka, a.direction.dw_w * ka};
  const Rates db{b.direction.dP_T * kb, b.direction.dP_N * kb, b.direction.dw_T * kb,
                 b.direction.dw_N * kb, b.direction.dw_Ti * kb, b.direction.dw_w * kb};
  return close(da, db, Scales{s.F / s.W, 1.0}, tol);
}

inline std::string compare_sets(const RateSolutionSet& a, const RateSolutionSet& b, const Scales& s,
                                double tol = 1e-7) {
  if (a.count() != b.count())
    return "count " + std::to_string(a.count()) + " vs " + std::to_string(b.count());
  if (a.solutions.size() != b.solutions.size()) return "number of pieces";
  std::vector<bool> used(b.solutions.size(), false);
  for (const auto& x : a.solutions) {
    bool ok = false;
    for (std::size_t k = 0; k < b.solutions.size() && !ok; ++k)
      if (!used[k] && same_piece(x, b.solutions[k], s, tol)) ok = used[k] = true;
    if (!ok) return "unmatched " + std::string(to_string(x.type)) + " " + std::string(to_string(x.kind));
  }
  return {};
}

}  // namespace cpkit::rate::test
