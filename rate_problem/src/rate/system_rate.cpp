// The N-point rate problem (docs/contact_model.md, "N points"): the LCP of size 3 n_b + n_d
// after eliminating the free unknowns, enumerated completely and mapped back to physical rates.
#include "cpkit/rate_problem/rate/system_rate.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "physical_pieces.hpp"
#include "rate_detail.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

/// Snap of rounding noise: an LCP entry within this fraction of the size of the terms it is
/// made of is an exact zero (as the one-point state d LCP does, rate_lcp.cpp).
constexpr double kSnap = 1e-10;

/// Point i of the system as the elimination sees it: its rows T = 2i (tangential) and
/// Nn = 2i + 1 (normal) of A, its first LCP variable k (-1 in states a and c), the force scale
/// kc = A_TT of its z and its state label.
struct PointRows {
  const SystemPoint& P;
  ContactParameters par;
  int T, Nn, k;
  double kc;
  StateLabel l;
};

PointRows point_rows(const ContactSystem& S, const std::vector<int>& off, int i) {
  const SystemPoint& P = S.points[static_cast<std::size_t>(i)];
  return {P, S.point_parameters(i), 2 * i, 2 * i + 1, off[static_cast<std::size_t>(i)],
          S.A(2 * i, 2 * i), P.state.label};
}

}  // namespace

TypeTuple encode_types(const std::vector<SolutionType>& types) noexcept {
  TypeTuple code = 0, w = 1;
  for (std::size_t i = 0; i < types.size() && i < static_cast<std::size_t>(kMaxTupleNPoints); ++i) {
    code += w * static_cast<TypeTuple>(types[i]);
    w *= 5;
  }
  return code;
}

std::vector<SolutionType> decode_types(TypeTuple code, int n_points) {
  std::vector<SolutionType> t(static_cast<std::size_t>(std::max(n_points, 0)));
  for (auto& x : t) {
    x = static_cast<SolutionType>(code % 5);
    code /= 5;
  }
  return t;
}

std::string types_string(const std::vector<SolutionType>& types) {
  std::string s;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (i) s += "/";
    s += std::string(to_string(types[i]));
  }
  return s;
}

SystemRatePrecomputed precompute_system_rate(const ContactSystem& system) {
  throw_if_invalid(system.validate(), "contact system");
  SystemRatePrecomputed pre;
  pre.system = system;
  const ContactSystem& S = pre.system;
  const int N = S.n_points(), n2 = 2 * N;
  const Eigen::MatrixXd& A = S.A;
  // LCP variables: b -> (dP_N, k l+, k l-), d -> k lambda, k = A_TT of the point (so that every
  // z is a force and the enumeration's relative tests compare like with like).
  std::vector<int> off(static_cast<std::size_t>(N), -1);
  int m = 0;
  for (int i = 0; i < N; ++i) {
    const StateLabel l = S.points[static_cast<std::size_t>(i)].state.label;
    if (l == StateLabel::kB) { off[static_cast<std::size_t>(i)] = m; m += 3; }
    if (l == StateLabel::kD) { off[static_cast<std::size_t>(i)] = m; m += 1; }
  }
  pre.m = m;
  // Equations for dw: E dw = Bf dF + R z, two rows per point (docs/contact_model.md):
  //   a: A_i dw = dF_i (dP_i = 0)
  //   b: dw_T + C_T A_T dw = C_T dF_T + (l+ - l-);   A_N dw = dF_N - dP_N
  //   c: dw_T + C_T A_T dw = C_T dF_T;               dw_N = 0
  //   d: dw_T + C_T A_T dw = C_T dF_T + s lambda;    dw_N = kappa lambda
  // (dw_T - C_T dP_T = dw_T^i with dP = dF - A dw.) Nonsingular: the free block of the model's
  // elimination is negative definite.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n2, n2), Bf = Eigen::MatrixXd::Zero(n2, n2),
                  R = Eigen::MatrixXd::Zero(n2, std::max(m, 0));
  for (int i = 0; i < N; ++i) {
    const auto [P, par, T, Nn, k, kc, l] = point_rows(S, off, i);
    if (l == StateLabel::kA) {
      E.row(T) = A.row(T);
      Bf(T, T) = 1;
      E.row(Nn) = A.row(Nn);
      Bf(Nn, Nn) = 1;
      continue;
    }
    E.row(T) = P.C_T * A.row(T);
    E(T, T) += 1;
    Bf(T, T) = P.C_T;
    if (l == StateLabel::kB) {
      R(T, k + 1) = 1 / kc;
      R(T, k + 2) = -1 / kc;
      E.row(Nn) = A.row(Nn);
      Bf(Nn, Nn) = 1;
      R(Nn, k) = -1;
    } else {
      E(Nn, Nn) = 1;
      if (l == StateLabel::kD) {
        R(T, k) = P.state.sgn_PT / kc;
        R(Nn, k) = par.kappa(P.state.P_N) / kc;
      }
    }
  }
  // row equilibration (rows have the units of A or are dimensionless)
  for (int r = 0; r < n2; ++r) {
    const double s = E.row(r).cwiseAbs().maxCoeff();
    E.row(r) /= s;
    Bf.row(r) /= s;
    if (m > 0) R.row(r) /= s;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(E);
  const Eigen::MatrixXd Xf = lu.solve(Bf);
  const Eigen::MatrixXd Xz = m > 0 ? Eigen::MatrixXd(lu.solve(R)) : Eigen::MatrixXd(n2, 0);
  // physical rates: rows [q N, (q+1) N) hold quantity q of (dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w)
  pre.Pf = Eigen::MatrixXd::Zero(6 * N, n2);
  pre.Pz = Eigen::MatrixXd::Zero(6 * N, m);
  const Eigen::MatrixXd dPf = Eigen::MatrixXd::Identity(n2, n2) - A * Xf;
  const Eigen::MatrixXd dPz = -A * Xz;
  for (int i = 0; i < N; ++i) {
    const auto [P, par, T, Nn, k, kc, l] = point_rows(S, off, i);
    if (l != StateLabel::kA) {  // a: dP = 0 exactly
      pre.Pf.row(i) = dPf.row(T);
      pre.Pz.row(i) = dPz.row(T);
      pre.Pf.row(N + i) = dPf.row(Nn);
      pre.Pz.row(N + i) = dPz.row(Nn);
    }
    pre.Pf.row(2 * N + i) = Xf.row(T);
    pre.Pz.row(2 * N + i) = Xz.row(T);
    if (l == StateLabel::kA || l == StateLabel::kB) {
      pre.Pf.row(3 * N + i) = Xf.row(Nn);
      pre.Pz.row(3 * N + i) = Xz.row(Nn);
    }
    switch (l) {
      case StateLabel::kA:  // dw_T^i = dw_T (P = 0)
        pre.Pf.row(4 * N + i) = Xf.row(T);
        pre.Pz.row(4 * N + i) = Xz.row(T);
        break;
      case StateLabel::kB:
        pre.Pf.row(N + i).setZero();  // dP_N is z_k exactly
        pre.Pz.row(N + i).setZero();
        pre.Pz(N + i, k) = 1;
        pre.Pz(4 * N + i, k + 1) = 1 / kc;
        pre.Pz(4 * N + i, k + 2) = -1 / kc;
        break;
      case StateLabel::kC:
        break;  // dw_N = dw_T^i = dw^w = 0
      case StateLabel::kD: {
        const double kappa = par.kappa(P.state.P_N);
        pre.Pz(3 * N + i, k) = kappa / kc;
        pre.Pz(4 * N + i, k) = P.state.sgn_PT / kc;
        pre.Pz(5 * N + i, k) = kappa / kc;
        break;
      }
    }
  }
  // w = G (physical rates) + H z: b -> (-A_NN dw_N, mu dP_N - dP_T, mu dP_N + dP_T),
  // d -> mu_eff dP_N - s dP_T (mu_eff = mu - 2 kappa under the softening criterion (35)).
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(m, 6 * N);
  for (int i = 0; i < N; ++i) {
    const SystemPoint& P = S.points[static_cast<std::size_t>(i)];
    const ContactParameters par = S.point_parameters(i);
    const int k = off[static_cast<std::size_t>(i)];
    if (P.state.label == StateLabel::kB) {
      G(k, 3 * N + i) = -A(2 * i + 1, 2 * i + 1);
      G(k + 1, N + i) = P.mu;
      G(k + 1, i) = -1;
      G(k + 2, N + i) = P.mu;
      G(k + 2, i) = 1;
    } else if (P.state.label == StateLabel::kD) {
      const double mu_eff = S.criterion == Criterion::kSoftening
                                ? P.mu - 2.0 * par.kappa(P.state.P_N)
                                : P.mu;
      G(k, N + i) = mu_eff;
      G(k, i) = -P.state.sgn_PT;
    }
  }
  pre.M = G * pre.Pz;
  pre.Q = G * pre.Pf;
  const Eigen::MatrixXd terms = G.cwiseAbs() * pre.Pz.cwiseAbs();
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < m; ++c)
      if (std::abs(pre.M(r, c)) <= kSnap * terms(r, c)) pre.M(r, c) = 0;
  pre.G = G;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
  pre.inv_min_eig = 1.0 / eig.eigenvalues()(0);
  pre.inv_max_eig = 1.0 / eig.eigenvalues()(eig.eigenvalues().size() - 1);
  for (const auto& P : S.points) pre.max_C_T = std::max(pre.max_C_T, P.C_T);
  return pre;
}

namespace {

void check_load(const ContactSystem& s, const Eigen::VectorXd& dF) {
  if (dF.size() != 2 * s.n_points()) {
    std::ostringstream m;
    m << "dF has " << dF.size() << " entries, need 2N = " << 2 * s.n_points()
      << " (T_1, N_1, T_2, N_2, ...)";
    throw InputError(m.str());
  }
  if (!dF.allFinite()) throw InputError("dF has a NaN or infinite entry");
}

}  // namespace

namespace detail {

Eigen::VectorXd system_q(const SystemRatePrecomputed& pre, const Eigen::VectorXd& dF) {
  Eigen::VectorXd q = pre.Q * dF;
  // the size of the terms of w at z = 0
  const Eigen::VectorXd t = pre.G.cwiseAbs() * (pre.Pf.cwiseAbs() * dF.cwiseAbs());
  // only rounding is snapped (256 ulps x cond(A) of the terms, as physical_pieces bounds the
  // rates): a q_r of the data one ulp past a critical load keeps its sign (issue 24)
  const double snap = std::min(kSnap, 256 * 0x1p-52 * std::max(1.0, pre.inv_min_eig / pre.inv_max_eig));
  for (int r = 0; r < pre.m; ++r)
    if (std::abs(q(r)) <= snap * t(r)) q(r) = 0;
  return q;
}

}  // namespace detail

namespace {

/// The rate problem is solved in its own units (detail::Units): force unit f = max |dF_i|,
/// stiffness unit max |A_ij| (the length unit f / max |A_ij| is applied by disp_back). It is
/// invariant under a change of units (dF / f, A / max|A_ij|, C_T max|A_ij|; kappa and the
/// states are dimensionless or only their signs matter), so every tolerance is unit-free and
/// loads near the ends of double's range stay representable (issue 24, item 5).
using detail::Units;

/// A force rate of the scaled problem in the caller's units.
double force_back(const Units& u, double x) { return x * u.force; }

/// A displacement rate of the scaled problem in the caller's units: x f / amax without an
/// intermediate overflow or underflow.
double disp_back(const Units& u, double x) {
  const double a = (x * u.force) / u.stiffness;
  if (std::isfinite(a) && (a == 0 || std::abs(a) >= std::numeric_limits<double>::min()))
    return x == 0 || a != 0 ? a : (x / u.stiffness) * u.force;
  return (x / u.stiffness) * u.force;
}

[[noreturn]] void not_representable(const std::string& what) {
  throw InputError("the rate problem's solution is not representable in double precision: " +
                   what + " (rates beyond about 1e308 in the units of the data; rescale dF)");
}

void rates_from_units(SystemRates& r, const Units& u) {
  for (Eigen::VectorXd* v : {&r.dP_T, &r.dP_N})
    for (Eigen::Index k = 0; k < v->size(); ++k) (*v)(k) = force_back(u, (*v)(k));
  for (Eigen::VectorXd* v : {&r.dw_T, &r.dw_N, &r.dw_Ti, &r.dw_w})
    for (Eigen::Index k = 0; k < v->size(); ++k) (*v)(k) = disp_back(u, (*v)(k));
  for (const Eigen::VectorXd* v : {&r.dP_T, &r.dP_N, &r.dw_T, &r.dw_N, &r.dw_Ti, &r.dw_w})
    if (!v->allFinite()) not_representable("a force or displacement rate overflows");
}

void set_from_units(SystemRateSolutionSet& s, const Units& u) {
  for (auto& p : s.solutions) {
    rates_from_units(p.start, u);
    if (p.kind == RateSolution::Kind::kSegment) rates_from_units(p.end, u);
    if (p.kind == RateSolution::Kind::kRay) {
      // a direction: renormalised to unit max-norm in the force components (as listed)
      SystemRates& d = p.direction;
      const double fmax = std::max(d.dP_T.lpNorm<Eigen::Infinity>(), d.dP_N.lpNorm<Eigen::Infinity>());
      if (fmax > 0) {  // else a unit max-norm displacement direction: unchanged
        Units dir = u;
        dir.force = 1;  // forces keep their unit max-norm; displacements get the length unit 1 / amax
        rates_from_units(d, dir);
      }
    }
  }
  // the scales are sums of sizes: capped at the largest double when only they overflow
  s.force_scale = std::min(force_back(u, s.force_scale), std::numeric_limits<double>::max());
  s.disp_scale = std::min(disp_back(u, s.disp_scale), std::numeric_limits<double>::max());
}

}  // namespace

SystemRateSolutionSet solve_rate_problem(const ContactSystem& system_in,
                                         const Eigen::VectorXd& dF_in, RateMethod method) {
  if (method == RateMethod::kAnalytic)
    throw InputError("method analytic exists for one point only (use enumerate, lemke, "
                     "fb-newton or ipopt)");
  throw_if_invalid(system_in.validate(), "contact system");
  check_load(system_in, dF_in);
  Units units;
  units.stiffness = system_in.A.cwiseAbs().maxCoeff();
  const double fmax = dF_in.lpNorm<Eigen::Infinity>();
  units.force = fmax > 0 ? fmax : 1.0;
  ContactSystem system = system_in;
  system.A /= units.stiffness;
  for (auto& q : system.points) q.C_T *= units.stiffness;
  for (const auto& q : system.points)
    if (!std::isfinite(q.C_T))
      not_representable("C_T times the stiffness overflows");
  const Eigen::VectorXd dF = dF_in / units.force;
  const SystemRatePrecomputed pre = precompute_system_rate(system);
  SystemRateSolutionSet all = detail::enumerate_system(pre, dF);
  if (method == RateMethod::kEnumerate) {
    set_from_units(all, units);
    return all;
  }
  const std::string name(to_string(method));
  const SolverEntry* entry = detail::find_lcp_solver(name);
  if (entry == nullptr || !entry->solve_lcp)
    throw InputError("LCP solver '" + name + "' is not registered in this build");
  SystemRateSolutionSet one;
  one.complete = false;
  one.force_scale = all.force_scale;
  one.disp_scale = all.disp_scale;
  Eigen::VectorXd z(pre.m);
  if (pre.m == 0) {
    one.message = "no point is in state b or d: the linear rate system was solved directly";
  } else {
    const LcpProblem lcp(pre.M, detail::system_q(pre, dF), "N-point rate problem");
    SolveResult r = entry->solve_lcp(lcp, CommonOptions{});
    one.message = detail::solver_message(*entry, r);
    one.residual = r.residuals.natural;
    if (!is_solution(r.status)) return one;
    z = r.z;
  }
  SystemRateSolution s;
  s.start = detail::to_rates(pre, pre.Pf * dF + pre.Pz * z);
  s.types = detail::classify_system_rates(pre, s.start, all.force_scale, all.disp_scale);
  one.disagreement = !contains(all, s.start, std::max(1e-7, 1e3 * one.residual));
  if (one.disagreement) one.message += "; this solution is NOT in the enumerated set";
  one.solutions.push_back(std::move(s));
  set_from_units(one, units);
  return one;
}

SystemRateSummary summarize_rate_problem(const SystemRatePrecomputed& pre,
                                         const Eigen::VectorXd& dF, bool on_critical) noexcept {
  SystemRateSummary out;
  if (dF.size() != pre.Pf.cols() || !dF.allFinite()) {  // invalid input: say so, do not guess
    out.reliable = false;
    return out;
  }
  try {
    // counts and types are positively homogeneous in dF: judge the load at unit size
    const double f = dF.lpNorm<Eigen::Infinity>();
    const SystemRateSolutionSet set =
        detail::enumerate_system(pre, f > 0 ? Eigen::VectorXd(dF / f) : dF, on_critical);
    out.count = set.count();
    out.reliable = set.complete;
    for (const auto& s : set.solutions) {
      const TypeTuple t = encode_types(s.types);
      bool seen = false;
      for (int k = 0; k < out.n_tuples && k < SystemRateSummary::kCap; ++k) seen = seen || out.tuples[static_cast<std::size_t>(k)] == t;
      if (seen) continue;
      if (out.n_tuples < SystemRateSummary::kCap) out.tuples[static_cast<std::size_t>(out.n_tuples)] = t;
      else out.reliable = false;
      ++out.n_tuples;
    }
    std::sort(out.tuples.begin(), out.tuples.begin() + std::min(out.n_tuples, SystemRateSummary::kCap));
  } catch (...) {  // allocation failure or an invalid input: say so, never throw from noexcept
    out.count = 0;
    out.n_tuples = 0;
    out.reliable = false;
  }
  return out;
}

}  // namespace cpkit::rate
