#include "cpkit/rate_problem/step/step_enumeration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {
namespace {

constexpr double kDegTol = 1e-12;  // relative size under which a coefficient is zero

double sgn1(double v) noexcept { return v < 0 ? -1.0 : 1.0; }

/// Everything the pieces need, computed once per problem.
struct Setup {
  double a11, a12, a22, mu, C_T, detA, D0, e, S, T, cw, kc;
  double P0, PT0, g0;
  double fscale, dscale;
};

Setup make_setup(const StepProblem& p) noexcept {
  const ContactParameters& a = p.params;
  Setup s;
  s.a11 = a.a11;
  s.a12 = a.a12;
  s.a22 = a.a22;
  s.mu = a.mu;
  s.C_T = a.C_T;
  s.detA = a.detA();
  s.D0 = a.D0();
  s.e = 1 + a.a11 * a.C_T;
  s.S = s.e * p.load.dF_N - a.a12 * a.C_T * p.load.dF_T;
  s.T = a.a22 * p.load.dF_T - a.a12 * p.load.dF_N;
  s.cw = p.wear_coefficient();
  s.kc = p.softening();
  s.P0 = std::max(p.state.P_N0, 0.0);
  s.PT0 = p.state.P_T0;
  s.g0 = p.state.g0;
  s.fscale = std::max({std::abs(s.PT0), s.P0, std::abs(p.load.dF_T), std::abs(p.load.dF_N),
                       std::numeric_limits<double>::min()});
  s.dscale = std::abs(s.g0) + s.fscale * ((s.a11 + s.a22) / s.detA + s.C_T);
  return s;
}

/// Horner evaluation of c[3] x^3 + ... + c[0] and of the bound on its rounding.
double poly(const double c[4], double x) noexcept {
  return ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
}
double poly_scale(const double s[4], double x) noexcept {
  const double ax = std::abs(x);
  return ((s[3] * ax + s[2]) * ax + s[1]) * ax + s[0];
}

/// Real roots of the cubic (c[3] != 0) in [lo, hi], by bracketing between critical points.
int cubic_roots_in(const double c[4], const double sc[4], double lo, double hi,
                   double roots[4]) noexcept {
  double crit[2];
  const double dc2 = 3 * c[3], dc1 = 2 * c[2], dc0 = c[1];
  int nc = stable_quadratic_roots(dc2, dc1, dc0, 3 * sc[3], 2 * sc[2], sc[1], 0.0, crit);
  if (nc < 0) nc = 0;
  double brk[4];
  int nb = 0;
  brk[nb++] = lo;
  if (nc == 2 && crit[0] > crit[1]) std::swap(crit[0], crit[1]);
  for (int i = 0; i < nc; ++i)
    if (crit[i] > lo && crit[i] < hi) brk[nb++] = crit[i];
  brk[nb++] = hi;
  int n = 0;
  auto add = [&](double x) {
    for (int i = 0; i < n; ++i)
      if (std::abs(roots[i] - x) <= 1e-12 * (1 + std::abs(x))) return;
    if (n < 4) roots[n++] = x;
  };
  for (int i = 0; i < nb; ++i) {
    const double fx = poly(c, brk[i]);
    if (std::abs(fx) <= 1e-13 * poly_scale(sc, brk[i])) add(brk[i]);
  }
  for (int i = 0; i + 1 < nb; ++i) {
    double u = brk[i], v = brk[i + 1];
    double fu = poly(c, u), fv = poly(c, v);
    if (fu == 0 || fv == 0 || (fu < 0) == (fv < 0)) continue;
    // Safeguarded Newton (rtsafe): keep the bracket, fall back to bisection.
    double x = 0.5 * (u + v);
    for (int it = 0; it < 200; ++it) {
      const double fx = poly(c, x);
      if (fx == 0) break;
      if ((fx < 0) == (fu < 0)) {
        u = x;
        fu = fx;
      } else {
        v = x;
      }
      const double dfx = (3 * c[3] * x + 2 * c[2]) * x + c[1];
      double xn = (dfx != 0) ? x - fx / dfx : 0.5 * (u + v);
      if (!(xn > u && xn < v)) xn = 0.5 * (u + v);
      if (std::abs(xn - x) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(x) ||
          v - u <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(u), std::abs(v))) {
        x = xn;
        break;
      }
      x = xn;
    }
    add(x);
  }
  return n;
}

struct Continuum {
  SolutionType type;
  int s;
  double x_lo, x_hi;  // x_hi may be +inf (ray)
  double b0, b1;      // xi(x) = s (b0 + b1 x) / detA
};

struct Work {
  StepPoints pts;
  Continuum cont[2];
  int ncont = 0;
};

/// Adds a point (after the residual check and de-duplication).
void try_point(const StepProblem& p, const StepNcp& ncp, const Setup& st, double x, double xi,
               double tol, StepPoints& out) noexcept {
  if (!std::isfinite(x) || !std::isfinite(xi)) return;
  // P_N1 slightly below 0 is rounding: snap to 0.
  if (st.P0 + x < 0) {
    if (st.P0 + x < -1e-9 * st.fscale) return;
    x = -st.P0;
  }
  const StepValues v = step_values(p, x, xi);
  if (ncp.residual(step_unknowns(v)) > tol) return;
  for (int i = 0; i < out.n; ++i) {
    const StepPoint& q = out.points[i];
    if (std::abs(q.DP_N - x) <= 1e-9 * st.fscale && std::abs(q.xi - xi) <= 1e-9 * st.dscale)
      return;
  }
  if (out.n >= kMaxStepPoints) return;
  StepPoint pt;
  pt.type = classify_step(p, v);
  pt.DP_N = x;
  pt.xi = xi;
  out.points[out.n++] = pt;
}

void enumerate_core(const StepProblem& p, const StepNcp& ncp, double tol, Work& w) noexcept {
  const Setup st = make_setup(p);
  w.pts.n = 0;
  w.pts.infinite = false;
  w.ncont = 0;
  // 1. P_N1 = 0: P_T1 = 0 fixes xi.
  {
    const double x = -st.P0;
    const double xi = (st.D0 * st.PT0 + st.T - st.a12 * st.P0) / st.detA;
    try_point(p, ncp, st, x, xi, tol, w.pts);
  }
  // 2. stick: g1 = 0 with xi = 0.
  {
    const double x = (st.D0 * st.g0 + st.S) / st.e;
    try_point(p, ncp, st, x, 0.0, tol, w.pts);
  }
  // 3. slip s = +1, -1.
  for (int s = 1; s >= -1; s -= 2) {
    const double Y0 = st.mu * st.P0 - st.kc * st.P0 * st.P0;
    const double margin = Y0 - s * st.PT0;
    const double b0 = -st.D0 * margin + s * st.T;
    const double b1 = s * st.a12 - st.D0 * st.mu + 2 * st.D0 * st.kc * st.P0;
    const double b2 = st.D0 * st.kc;
    const double sb0 = st.D0 * (st.mu * st.P0 + st.kc * st.P0 * st.P0 + std::abs(st.PT0)) +
                       std::abs(st.a22 * p.load.dF_T) + std::abs(st.a12 * p.load.dF_N);
    const double sb1 = std::abs(st.a12) + st.D0 * st.mu + 2 * st.D0 * st.kc * st.P0;
    const double sb2 = b2;
    const double a0 = st.D0 * st.g0 + st.S;
    const double a1 = -st.e;
    const double a2 = -s * st.a12 - st.D0 * st.cw * st.P0;
    const double a3 = -st.D0 * st.cw;
    const double sa0 = st.D0 * std::abs(st.g0) + st.e * std::abs(p.load.dF_N) +
                       std::abs(st.a12 * st.C_T * p.load.dF_T);
    const double sa1 = st.e;
    const double sa2 = std::abs(st.a12) + st.D0 * st.cw * st.P0;
    const double sa3 = -a3;
    const double c[4] = {st.detA * a0 + a2 * b0, st.detA * a1 + a2 * b1 + a3 * b0,
                         a3 * b1 + a2 * b2, a3 * b2};
    const double sc[4] = {st.detA * sa0 + sa2 * sb0, st.detA * sa1 + sa2 * sb1 + sa3 * sb0,
                          sa3 * sb1 + sa2 * sb2, sa3 * sb2};
    const SolutionType type = s > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
    double roots[4];
    int nr;
    const double x_lo = -st.P0;
    if (c[3] != 0) {
      const double x_hi = st.mu / st.kc - st.P0;  // Y(P_N1) >= 0, condition (46)
      nr = cubic_roots_in(c, sc, x_lo, x_hi, roots);
    } else {
      nr = stable_quadratic_roots(c[2], c[1], c[0], sc[2], sc[1], sc[0], kDegTol, roots);
    }
    if (nr < 0) {
      // The gap row holds identically along the friction row: a continuum in x >= -P0 with
      // l(x) = (b0 + b1 x)/detA >= 0 (b2 = 0 here: the cubic case never degenerates).
      const bool b1_zero = std::abs(b1) <= kDegTol * sb1;
      double lo = x_lo, hi = std::numeric_limits<double>::infinity();
      bool empty = false;
      if (b1_zero) {
        if (b0 < -kDegTol * sb0) empty = true;
      } else if (b1 > 0) {
        lo = std::max(lo, -b0 / b1);
      } else {
        hi = -b0 / b1;
        if (hi < lo - 1e-12 * st.fscale) empty = true;
      }
      if (!empty) {
        if (std::isfinite(hi) && hi - lo <= 1e-12 * st.fscale) {
          const double xm = std::max(lo, hi);
          try_point(p, ncp, st, xm, s * (b0 + b1 * xm) / st.detA, tol, w.pts);
        } else if (w.ncont < 2) {
          w.cont[w.ncont++] = Continuum{type, s, lo, hi, b0, b1_zero ? 0.0 : b1};
          w.pts.infinite = true;
        }
      }
      continue;
    }
    for (int i = 0; i < nr; ++i) {
      const double x = roots[i];
      if (st.P0 + x < -1e-9 * st.fscale) continue;
      double l = ((b2 * x + b1) * x + b0) / st.detA;
      if (l < -1e-9 * st.dscale) continue;
      l = std::max(l, 0.0);
      try_point(p, ncp, st, x, s * l, tol, w.pts);
    }
  }
}

double distance(const StepValues& v) noexcept { return std::abs(v.DP_N) + std::abs(v.DP_T); }

}  // namespace

int stable_quadratic_roots(double c2, double c1, double c0, double scale2, double scale1,
                           double scale0, double deg_tol, double roots[2]) noexcept {
  const bool z2 = std::abs(c2) <= deg_tol * scale2;
  if (z2) {
    const bool z1 = std::abs(c1) <= deg_tol * scale1;
    if (z1) return (std::abs(c0) <= deg_tol * scale0) ? -1 : 0;
    roots[0] = -c0 / c1;
    return 1;
  }
  double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) {
    if (disc >= -1e-12 * (c1 * c1 + 4 * std::abs(c2 * c0))) {
      disc = 0;
    } else {
      return 0;
    }
  }
  const double q = -0.5 * (c1 + sgn1(c1) * std::sqrt(disc));
  if (q == 0) {  // c1 = 0 and c0 = 0: double root at 0
    roots[0] = 0;
    return 1;
  }
  roots[0] = q / c2;
  if (disc == 0) return 1;
  roots[1] = c0 / q;
  return 2;
}

void enumerate_step_points(const StepProblem& problem, const StepNcp& ncp, StepPoints& out,
                           double tol) noexcept {
  Work w;
  enumerate_core(problem, ncp, tol, w);
  out = w.pts;
}

int StepSolutionSet::count() const noexcept {
  return infinite ? -1 : static_cast<int>(solutions.size());
}

unsigned StepSolutionSet::type_mask() const noexcept {
  unsigned m = 0;
  for (const auto& s : solutions) m |= 1u << static_cast<int>(s.type);
  return m;
}

StepSolutionSet enumerate_step(const StepProblem& problem, const StepEnumerationOptions& opt) {
  throw_if_invalid(problem.validate(), "step");
  if (!(opt.tol > 0) || !std::isfinite(opt.tol))
    throw InputError("step enumeration: tol must be finite and > 0");
  const StepNcp ncp = build_step_ncp_unchecked(problem);
  Work w;
  enumerate_core(problem, ncp, opt.tol, w);
  StepSolutionSet set;
  set.infinite = w.pts.infinite;
  // Continua first. A continuum's interior has its slip type; an end of another type
  // (classify_step: stick where xi = 0, open where P_N1 = 0 after an open start) is open and
  // listed as a point of its own type (the partition of piece_geometry.hpp).
  std::vector<StepSolution> conts;
  std::vector<StepValues> open_ends;
  const Setup st = make_setup(problem);
  for (int i = 0; i < w.ncont; ++i) {
    const Continuum& c = w.cont[i];
    auto at = [&](double x) { return step_values(problem, x, c.s * (c.b0 + c.b1 * x) / st.detA); };
    StepSolution sol;
    sol.type = c.type;
    sol.start = at(c.x_lo);
    sol.residual = ncp.residual(step_unknowns(sol.start));
    sol.start_closed = classify_step(problem, sol.start) == c.type;
    if (!sol.start_closed) open_ends.push_back(sol.start);
    if (std::isfinite(c.x_hi)) {
      sol.kind = RateSolution::Kind::kSegment;
      sol.end = at(c.x_hi);
      sol.residual = std::max(sol.residual, ncp.residual(step_unknowns(sol.end)));
      sol.end_closed = classify_step(problem, sol.end) == c.type;
      if (!sol.end_closed) open_ends.push_back(sol.end);
    } else {
      sol.kind = RateSolution::Kind::kRay;
      const StepValues v1 = at(c.x_lo + 1.0);
      sol.direction.DP_T = v1.DP_T - sol.start.DP_T;
      sol.direction.DP_N = v1.DP_N - sol.start.DP_N;
      sol.direction.Dw_T = v1.Dw_T - sol.start.Dw_T;
      sol.direction.Dw_N = v1.Dw_N - sol.start.Dw_N;
      sol.direction.Dw_Ti = v1.Dw_Ti - sol.start.Dw_Ti;
      sol.direction.Dw_w = v1.Dw_w - sol.start.Dw_w;
      sol.direction.P_T1 = sol.direction.DP_T;
      sol.direction.P_N1 = sol.direction.DP_N;
      sol.direction.g1 = v1.g1 - sol.start.g1;
    }
    conts.push_back(sol);
  }
  auto same_point = [&](double DP_N, double xi, const StepValues& v) {
    return std::abs(v.DP_N - DP_N) <= 1e-9 * st.fscale && std::abs(v.Dw_Ti - xi) <= 1e-9 * st.dscale;
  };
  auto at_open_end = [&](double DP_N, double xi) {
    for (const auto& v : open_ends)
      if (same_point(DP_N, xi, v)) return true;
    return false;
  };
  auto on_continuum = [&](const StepPoint& pt) {
    for (int i = 0; i < w.ncont; ++i) {
      const Continuum& c = w.cont[i];
      if (pt.DP_N < c.x_lo - 1e-9 * st.fscale || pt.DP_N > c.x_hi + 1e-9 * st.fscale) continue;
      const double xi = c.s * (c.b0 + c.b1 * pt.DP_N) / st.detA;
      if (std::abs(xi - pt.xi) <= 1e-9 * st.dscale) return true;
    }
    return false;
  };
  auto add_point = [&](const StepValues& v) {
    StepSolution sol;
    sol.start = v;
    sol.type = classify_step(problem, v);
    sol.residual = ncp.residual(step_unknowns(v));
    set.solutions.push_back(sol);
  };
  for (int i = 0; i < w.pts.n; ++i) {
    const StepPoint& pt = w.pts.points[i];
    // Points on the closed part of a continuum belong to it; an open end is a point of its own.
    if (on_continuum(pt) && !at_open_end(pt.DP_N, pt.xi)) continue;
    add_point(step_values(problem, pt.DP_N, pt.xi));
  }
  for (const auto& v : open_ends) {
    bool listed = false;
    for (const auto& sol : set.solutions)
      listed = listed || same_point(v.DP_N, v.Dw_Ti, sol.start);
    if (!listed) add_point(v);
  }
  for (auto& c : conts) set.solutions.push_back(c);
  std::stable_sort(set.solutions.begin(), set.solutions.end(),
                   [](const StepSolution& a, const StepSolution& b) {
                     return static_cast<int>(a.type) < static_cast<int>(b.type);
                   });
  set.continuous_count = -1;
  if (opt.detect_jumps && !set.infinite) {
    // Homotopy in t: follow the solutions of the step with increment t (DF_T, DF_N) from t = 0
    // (where the start state itself is a solution) to t = 1, linking each solution to its
    // nearest neighbour at the previous t. A solution is continuous (rate-consistent) when its
    // chain leads back to the start state; jumps stay O(1) away from every such chain.
    constexpr int kSteps = 128;
    const double link = 0.1 * st.fscale;
    auto dist = [&](const StepValues& a, const StepValues& b) {
      return std::abs(a.DP_N - b.DP_N) + std::abs(a.DP_T - b.DP_T) +
             st.detA / st.D0 * std::abs(a.Dw_Ti - b.Dw_Ti);
    };
    std::vector<StepValues> prev_v, cur_v;
    std::vector<char> prev_r, cur_r;
    bool ok = true;
    for (int k = 0; k <= kSteps && ok; ++k) {
      const double t = static_cast<double>(k) / kSteps;
      StepProblem pt = problem;
      pt.load.dF_T *= t;
      pt.load.dF_N *= t;
      const StepNcp n_t = build_step_ncp_unchecked(pt);
      Work wt;
      enumerate_core(pt, n_t, opt.tol, wt);
      if (wt.pts.infinite) {
        ok = false;
        break;
      }
      cur_v.clear();
      cur_r.clear();
      for (int i = 0; i < wt.pts.n; ++i) {
        const StepValues v = step_values(pt, wt.pts.points[i].DP_N, wt.pts.points[i].xi);
        bool r = false;
        if (k == 0) {
          r = distance(v) + st.detA / st.D0 * std::abs(v.Dw_Ti) <= 1e-9 * st.fscale;
        } else {
          double best = INFINITY;
          int bi = -1;
          for (std::size_t j = 0; j < prev_v.size(); ++j) {
            const double d = dist(v, prev_v[j]);
            if (d < best) {
              best = d;
              bi = static_cast<int>(j);
            }
          }
          r = bi >= 0 && prev_r[bi] && best <= link;
        }
        cur_v.push_back(v);
        cur_r.push_back(r ? 1 : 0);
      }
      std::swap(prev_v, cur_v);
      std::swap(prev_r, cur_r);
    }
    if (ok) {
      // prev_v now holds the t = 1 solutions: match them to the reported points.
      set.continuous_count = 0;
      for (auto& sol : set.solutions) {
        double best = INFINITY;
        int bi = -1;
        for (std::size_t j = 0; j < prev_v.size(); ++j) {
          const double d = dist(sol.start, prev_v[j]);
          if (d < best) {
            best = d;
            bi = static_cast<int>(j);
          }
        }
        sol.jump = !(bi >= 0 && prev_r[bi]);
        if (!sol.jump) ++set.continuous_count;
      }
    }
  }
  return set;
}

}  // namespace cpkit::rate
