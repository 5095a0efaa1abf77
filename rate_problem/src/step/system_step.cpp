#include "cpkit/rate_problem/step/system_step.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/spd.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/rate_problem/step/step_enumeration.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

constexpr double kDegTol = 1e-12;  // relative size under which a coefficient or pivot is zero
constexpr double kStepLawTol = 1e-8;  // acceptance bound of the step's laws (step_laws_violation)
/// A candidate that misses the acceptance bounds by less than kGray eps cond(A) (what rounding
/// in the elimination can do to a true root) is undecided; empty for a well-conditioned A.
constexpr double kGray = 1e3;
/// Largest cond(A) (2-norm) for which the enumeration is called complete: a seeded sweep of
/// coupled 2-point steps against a long-double brute force is right up to cond 1e10 and misses
/// full separations from 1e11 on (the displacements of the soft mode lose their digits).
constexpr double kMaxProvedCond = 1e9;

/// The units the enumeration works in: force unit f (the largest force of the data) and length
/// unit l = f / max|A_ij| (so that A is O(1)). The step is invariant under a change of units
/// (forces / f, lengths / l, A l / f, C_T f / l, k_a f), so enumerating in these units makes
/// every tolerance unit-free and keeps loads near the ends of double's range representable
/// (issue 24, items 4 and 5).
detail::Units step_units(const SystemStepProblem& p) {
  const ContactSystem& s = p.system;
  const double amax = s.A.cwiseAbs().maxCoeff();
  double f = p.DF.cwiseAbs().maxCoeff(), gmax = 0;
  for (const auto& q : s.points) {
    f = std::max({f, std::abs(q.P_N), std::abs(q.P_T)});
    gmax = std::max(gmax, std::abs(q.g));
  }
  if (!(f > 0)) f = amax * gmax;  // no force at all: the force that closes the largest gap
  if (!(f > 0) || !std::isfinite(f)) f = amax;  // nothing but A: every unknown is zero
  detail::Units u;
  u.force = f;
  u.stiffness = amax;
  // f / amax beyond double's range: the nearest representable length unit (the solution may
  // still fit; from_units says when it does not)
  u.length = std::min(std::max(f / amax, std::numeric_limits<double>::min()),
                 std::numeric_limits<double>::max());
  return u;
}

[[noreturn]] void not_representable(const std::string& what) {
  throw InputError("the step is not representable in double precision: " + what +
                   " (rescale the data: forces and displacements beyond about 1e308 or below "
                   "1e-308 in the units of the problem)");
}

SystemStepProblem to_units(const SystemStepProblem& p, const detail::Units& u) {
  SystemStepProblem q = p;
  q.system.A = p.system.A * (u.length / u.force);
  q.DF = p.DF / u.force;
  for (auto& x : q.system.points) {
    x.P_N /= u.force;
    x.P_T /= u.force;
    x.g /= u.length;
    x.C_T *= u.force / u.length;
    x.k_a *= u.force;
  }
  if (!q.system.A.allFinite() || !q.DF.allFinite()) not_representable("A or DF in units of the load");
  for (const auto& x : q.system.points)
    if (!std::isfinite(x.P_N) || !std::isfinite(x.P_T) || !std::isfinite(x.g) ||
        !std::isfinite(x.C_T) || !std::isfinite(x.k_a))
      not_representable("a point's data in units of the load");
  return q;
}

void from_units(StepValues& v, const detail::Units& u) {
  for (double* x : {&v.DP_T, &v.DP_N, &v.P_T1, &v.P_N1}) *x *= u.force;
  for (double* x : {&v.Dw_T, &v.Dw_N, &v.Dw_Ti, &v.Dw_w, &v.g1}) *x *= u.length;
  for (double x : {v.DP_T, v.DP_N, v.P_T1, v.P_N1, v.Dw_T, v.Dw_N, v.Dw_Ti, v.Dw_w, v.g1})
    if (!std::isfinite(x)) not_representable("a solution's forces or displacements overflow");
}

/// The affine maps of u = (P_N1 (N), xi (N)) computed once per problem:
/// P_T1 = pt0 + PT u, Dw_N = wn0 + WN u, Dw_T = wt0 + WT u (wt0/WT: total tangential Dw).
struct Maps {
  int N = 0;
  Eigen::VectorXd pt0, wn0, wt0, P0, PT0, g0, mu, k, C_T;
  Eigen::MatrixXd PT, WN, WT;
  double fscale = 0, dscale = 0;
};

Maps make_maps(const SystemStepProblem& p) {
  const ContactSystem& s = p.system;
  const int N = s.n_points();
  Maps m;
  m.N = N;
  m.P0.resize(N);
  m.PT0.resize(N);
  m.g0.resize(N);
  m.mu.resize(N);
  m.k.resize(N);
  m.C_T.resize(N);
  for (int i = 0; i < N; ++i) {
    const SystemPoint& q = s.points[static_cast<std::size_t>(i)];
    m.P0[i] = std::max(q.P_N, 0.0);
    m.PT0[i] = q.P_T;
    m.g0[i] = q.g;
    m.mu[i] = q.mu;
    m.k[i] = q.k_a / (3.0 * q.P_s);
    m.C_T[i] = q.C_T;
  }
  // G y = rhs, y = (Dw (2N), DP_T (N)): A Dw + E_T DP_T = DF - E_N DP_N; Dw_T - C_T DP_T = xi.
  const int n = 3 * N;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, n);
  G.topLeftCorner(2 * N, 2 * N) = s.A;
  for (int i = 0; i < N; ++i) {
    G(2 * i, 2 * N + i) = 1;
    G(2 * N + i, 2 * i) = 1;
    G(2 * N + i, 2 * N + i) = -m.C_T[i];
  }
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(n, 2 * N + 1);
  for (int i = 0; i < 2 * N; ++i) R(i, 0) = p.DF[i];
  for (int i = 0; i < N; ++i) {
    R(2 * i + 1, 0) += m.P0[i];   // DP_N = P_N1 - P_N0
    R(2 * i + 1, 1 + i) = -1;     // d/dP_N1
    R(2 * N + i, 1 + N + i) = 1;  // d/dxi
  }
  const Eigen::MatrixXd Y = G.partialPivLu().solve(R);
  m.pt0.resize(N);
  m.wn0.resize(N);
  m.wt0.resize(N);
  m.PT.resize(N, 2 * N);
  m.WN.resize(N, 2 * N);
  m.WT.resize(N, 2 * N);
  for (int i = 0; i < N; ++i) {
    m.pt0[i] = m.PT0[i] + Y(2 * N + i, 0);
    m.PT.row(i) = Y.block(2 * N + i, 1, 1, 2 * N);
    m.wn0[i] = Y(2 * i + 1, 0);
    m.WN.row(i) = Y.block(2 * i + 1, 1, 1, 2 * N);
    m.wt0[i] = Y(2 * i, 0);
    m.WT.row(i) = Y.block(2 * i, 1, 1, 2 * N);
  }
  double f = std::max({m.P0.cwiseAbs().maxCoeff(), m.PT0.cwiseAbs().maxCoeff(),
                       p.DF.cwiseAbs().maxCoeff()});
  m.fscale = std::max(f, std::numeric_limits<double>::min());
  // Displacement scale: the largest point compliance (as classify_step uses for one point).
  double comp = 0;
  for (int i = 0; i < N; ++i) {
    const ContactParameters a = s.point_parameters(i);
    comp = std::max(comp, (a.a11 + a.a22) / a.detA() + a.C_T);
  }
  m.dscale = m.g0.cwiseAbs().maxCoeff() + m.fscale * comp;
  return m;
}

/// The step NCP F(z), z = (P_N1, l+, l-) per point.
void ncp_F(const Maps& m, const Eigen::VectorXd& z, Eigen::VectorXd& F) {
  const int N = m.N;
  Eigen::VectorXd u(2 * N);
  for (int i = 0; i < N; ++i) {
    u[i] = z[3 * i];
    u[N + i] = z[3 * i + 1] - z[3 * i + 2];
  }
  F.resize(3 * N);
  for (int i = 0; i < N; ++i) {
    const double PT1 = m.pt0[i] + m.PT.row(i).dot(u);
    const double g_lin = m.g0[i] + m.wn0[i] + m.WN.row(i).dot(u);
    F[3 * i] = -g_lin + m.k[i] * z[3 * i] * (z[3 * i + 1] + z[3 * i + 2]);
    F[3 * i + 1] = m.mu[i] * z[3 * i] - PT1;
    F[3 * i + 2] = m.mu[i] * z[3 * i] + PT1;
  }
}

void ncp_J(const Maps& m, const Eigen::VectorXd& z, Eigen::MatrixXd& J) {
  const int N = m.N;
  J.setZero(3 * N, 3 * N);
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      // du_j/dz: P_N1_j = z[3j], xi_j = z[3j+1] - z[3j+2].
      const double dPT_P = m.PT(i, j), dPT_x = m.PT(i, N + j);
      const double dWN_P = m.WN(i, j), dWN_x = m.WN(i, N + j);
      J(3 * i, 3 * j) = -dWN_P;
      J(3 * i, 3 * j + 1) = -dWN_x;
      J(3 * i, 3 * j + 2) = dWN_x;
      J(3 * i + 1, 3 * j) = -dPT_P;
      J(3 * i + 1, 3 * j + 1) = -dPT_x;
      J(3 * i + 1, 3 * j + 2) = dPT_x;
      J(3 * i + 2, 3 * j) = dPT_P;
      J(3 * i + 2, 3 * j + 1) = dPT_x;
      J(3 * i + 2, 3 * j + 2) = -dPT_x;
    }
    J(3 * i, 3 * i) += m.k[i] * (z[3 * i + 1] + z[3 * i + 2]);
    J(3 * i, 3 * i + 1) += m.k[i] * z[3 * i];
    J(3 * i, 3 * i + 2) += m.k[i] * z[3 * i];
    J(3 * i + 1, 3 * i) += m.mu[i];
    J(3 * i + 2, 3 * i) += m.mu[i];
  }
}

McpProblem make_mcp(const Maps& maps) {
  auto F = [maps](const Vec& x, Vec& f) {
    if (x.size() != 3 * maps.N) return false;
    ncp_F(maps, x, f);
    return f.allFinite();
  };
  auto J = [maps](const Vec& x, Mat& j) {
    if (x.size() != 3 * maps.N) return false;
    ncp_J(maps, x, j);
    return j.allFinite();
  };
  McpProblem mcp = make_ncp(3 * maps.N, F, J, "N-point incremental step");
  mcp.x0 = Vec::Zero(3 * maps.N);
  for (int i = 0; i < maps.N; ++i) mcp.x0[3 * i] = maps.P0[i];
  return mcp;
}

/// One equation of an active set in the scaled unknowns v = (P_N1, sigma xi): the linear part
/// a . v + a0, plus (bilinear rows) -c P_N1,i xi_i.
struct Row {
  Eigen::RowVectorXd a;
  double a0 = 0;
  int bil = -1;   // point index of the bilinear term, -1: linear
  double c = 0;   // coefficient of P_N1,i * xi_i (xi = v_{N+i} / sigma)
};

const char* kTypeNames[4] = {"separation", "stick", "slip+", "slip-"};

struct Enumerator {
  const SystemStepProblem& p;
  const Maps& m;
  const McpProblem& mcp;
  double tol;
  double sigma;  // xi scale: v_{N+i} = sigma xi_i (force units)
  double cond;   // cond(A), 2-norm
  double gray;   // kGray eps cond(A): the undecided band above the acceptance bounds
  SystemStepSolutionSet& out;
  std::vector<Eigen::VectorXd> found;  // u of accepted solutions
  std::vector<int> code;

  std::string set_name() const {
    std::string s = "(";
    for (std::size_t i = 0; i < code.size(); ++i) {
      if (i) s += "/";
      s += kTypeNames[code[i]];
    }
    return s + ")";
  }

  void note(const std::string& why) {
    out.complete = false;
    if (out.notes.size() < 20) out.notes.push_back("active set " + set_name() + ": " + why);
    else if (out.notes.size() == 20) out.notes.push_back("(further unresolved active sets not listed)");
  }

  /// The equations of the active set `code`.
  std::vector<Row> rows() const {
    const int N = m.N;
    std::vector<Row> r;
    r.reserve(2 * N);
    auto lin = [&](const Eigen::RowVectorXd& du, double c0) {
      // du is d/du with u = (P_N1, xi); convert to v = (P_N1, sigma xi).
      Row row;
      row.a = du;
      row.a.tail(N) /= sigma;
      row.a0 = c0;
      return row;
    };
    for (int i = 0; i < N; ++i) {
      Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(2 * N);
      switch (code[i]) {
        case 0: {  // separation: P_N1 = 0, P_T1 = 0
          e[i] = 1;
          r.push_back(lin(e, 0));
          r.push_back(lin(m.PT.row(i), m.pt0[i]));
          break;
        }
        case 1: {  // stick: xi = 0, g1 = g0 + Dw_N = 0
          e[N + i] = 1;
          r.push_back(lin(e, 0));
          r.push_back(lin(m.WN.row(i), m.g0[i] + m.wn0[i]));
          break;
        }
        default: {  // slip s: s P_T1 - mu P_N1 = 0; g0 + Dw_N - k s P_N1 xi = 0
          const double s = code[i] == 2 ? 1.0 : -1.0;
          Eigen::RowVectorXd f = s * m.PT.row(i);
          f[i] -= m.mu[i];
          r.push_back(lin(f, s * m.pt0[i]));
          Row g = lin(m.WN.row(i), m.g0[i] + m.wn0[i]);
          if (m.k[i] > 0) {
            g.bil = i;
            g.c = -m.k[i] * s / sigma;  // in v: -k s P_N1 (v_{N+i} / sigma)
          }
          r.push_back(g);
        }
      }
    }
    return r;
  }

  /// Largest violation of the step's laws by the per-point values, from the data (A, DF, the
  /// start values), unit-free: equilibrium DF - DP = A Dw row by row against its terms,
  /// Dw_T = C_T DP_T + Dw_Ti, Dw^w = k P_N1 |Dw_Ti|, g1 = g0 + Dw_N - Dw^w, and per point
  /// P_N1 >= 0, g1 <= 0, P_N1 g1 = 0, |P_T1| <= mu P_N1, Dw_Ti != 0 only with
  /// P_T1 = sgn(Dw_Ti) mu P_N1; forces against the force scale, lengths against the
  /// displacement scale (the enumeration's units make both O(1)).
  double step_laws_violation(const std::vector<StepValues>& v) const {
    const int N = m.N;
    const double fs = m.fscale, ds = m.dscale;
    auto r0 = [](double x, double sc) {
      if (!std::isfinite(x)) return std::numeric_limits<double>::infinity();
      return x == 0 ? 0.0 : std::abs(x) / std::max(sc, std::numeric_limits<double>::min());
    };
    Eigen::VectorXd DP(2 * N), Dw(2 * N);
    for (int i = 0; i < N; ++i) {
      const StepValues& x = v[static_cast<std::size_t>(i)];
      DP(2 * i) = x.DP_T;
      DP(2 * i + 1) = x.DP_N;
      Dw(2 * i) = x.Dw_T;
      Dw(2 * i + 1) = x.Dw_N;
    }
    const Eigen::MatrixXd& A = p.system.A;
    const Eigen::VectorXd res = p.DF - DP - A * Dw;
    const Eigen::VectorXd terms =
        p.DF.cwiseAbs() + DP.cwiseAbs() + A.cwiseAbs() * Dw.cwiseAbs();
    double w = 0;
    for (int r = 0; r < 2 * N; ++r) w = std::max(w, r0(res(r), terms(r) + 1e-6 * fs));
    for (int i = 0; i < N; ++i) {
      const StepValues& x = v[static_cast<std::size_t>(i)];
      const double mu = m.mu[i];
      const double fmu = fs * (1 + mu);
      w = std::max(w, r0(x.Dw_T - m.C_T[i] * x.DP_T - x.Dw_Ti,
                         std::abs(x.Dw_T) + m.C_T[i] * std::abs(x.DP_T) + std::abs(x.Dw_Ti) + 1e-6 * ds));
      w = std::max(w, r0(x.Dw_w - m.k[i] * std::max(x.P_N1, 0.0) * std::abs(x.Dw_Ti), ds));
      w = std::max(w, r0(x.P_N1 - (m.P0[i] + x.DP_N), fs));
      w = std::max(w, r0(x.g1 - (m.g0[i] + x.Dw_N - x.Dw_w), ds));
      w = std::max(w, x.P_N1 < 0 ? r0(x.P_N1, fs) : 0.0);
      w = std::max(w, x.g1 > 0 ? r0(x.g1, ds) : 0.0);
      w = std::max(w, std::min(r0(x.P_N1, fs), r0(x.g1, ds)));  // P_N1 g1 = 0
      w = std::max(w, std::max(0.0, std::abs(x.P_T1) - mu * x.P_N1) / fmu);
      // slip: the friction force on the limit, in the direction of the slip
      const double onlimit = x.Dw_Ti > 0 ? std::abs(x.P_T1 - mu * x.P_N1)
                                         : std::abs(x.P_T1 + mu * x.P_N1);
      if (x.Dw_Ti != 0) w = std::max(w, std::min(r0(x.Dw_Ti, ds), onlimit / fmu));
    }
    return w;
  }

  /// The type of point i, judged against the system's force and displacement scales (as
  /// classify_step does for one point with that point's own scales: a point that carries no
  /// load of its own must not have its rounding noise, e.g. P_N1 = 1e-17 of the system's
  /// forces, judged against itself).
  SolutionType classify(int i, const StepValues& v) const {
    constexpr double t = 1e-9;
    const double fs = std::max({m.fscale, std::abs(v.P_N1), std::abs(v.P_T1)});
    if (v.P_N1 <= t * fs) {
      if (m.g0[i] < -t * m.dscale) return SolutionType::kOpen;
      if (v.g1 < -t * m.dscale) return SolutionType::kSeparation;
    }
    if (std::abs(v.Dw_Ti) <= t * m.dscale) return SolutionType::kStick;
    return v.Dw_Ti > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
  }

  /// Accepts a candidate v when the step NCP holds (unit-free residual) and it is new.
  void accept(const Eigen::VectorXd& v) {
    const int N = m.N;
    if (!v.allFinite()) return;
    Eigen::VectorXd u = v;
    u.tail(N) /= sigma;
    for (int i = 0; i < N; ++i) {
      if (u[i] < 0) {
        if (u[i] < -1e-9 * m.fscale) return;
        u[i] = 0;  // rounding below 0
      }
    }
    Vec z(3 * N);
    for (int i = 0; i < N; ++i) {
      z[3 * i] = u[i];
      z[3 * i + 1] = std::max(u[N + i], 0.0);
      z[3 * i + 2] = std::max(-u[N + i], 0.0);
    }
    Vec F;
    ncp_F(m, z, F);
    const Residuals res = mcp_residuals(mcp, z, F);
    if (!res.finite) return;
    // Second, independent test: the step's laws from the data, point by point in their own
    // units (step_laws_violation). A candidate must pass both; one that misses either by less
    // than the gray factor is a root that could not be decided: not listed, not complete.
    const std::vector<StepValues> vals = system_step_values(p, u.head(N), u.tail(N));
    const double phys = step_laws_violation(vals);
    const bool pass = res.natural <= tol && phys <= kStepLawTol;
    if (!pass) {
      if (res.natural <= std::max(tol, gray) && phys <= std::max(kStepLawTol, gray)) {
        std::ostringstream o;
        o << "a candidate within the rounding of the elimination (" << gray
          << " at cond(A) = " << cond << ") of the acceptance bounds (NCP residual "
          << res.natural << ", violation of the step laws " << phys
          << ") could not be decided: not listed";
        note(o.str());
      }
      return;
    }
    for (const auto& f : found) {
      if ((f.head(N) - u.head(N)).cwiseAbs().maxCoeff() <= 1e-9 * m.fscale &&
          (f.tail(N) - u.tail(N)).cwiseAbs().maxCoeff() <= 1e-9 * m.dscale)
        return;
    }
    found.push_back(u);
    SystemStepSolution sol;
    sol.residual = res.natural;
    sol.values = vals;
    for (int i = 0; i < N; ++i) sol.types.push_back(classify(i, sol.values[static_cast<std::size_t>(i)]));
    out.solutions.push_back(std::move(sol));
  }

  /// Newton on the square system (linear rows + bilinear rows) from v.
  bool newton(const std::vector<Row>& R, Eigen::VectorXd& v) const {
    const int n = static_cast<int>(v.size());
    Eigen::VectorXd f(n);
    Eigen::MatrixXd J(n, n);
    for (int it = 0; it < 60; ++it) {
      double fs = 0;
      for (int r = 0; r < n; ++r) {
        const Row& row = R[static_cast<std::size_t>(r)];
        f[r] = row.a.dot(v) + row.a0;
        J.row(r) = row.a;
        double sc = row.a.cwiseAbs().dot(v.cwiseAbs()) + std::abs(row.a0);
        if (row.bil >= 0) {
          const int i = row.bil;
          f[r] += row.c * v[i] * v[m.N + i];
          J(r, i) += row.c * v[m.N + i];
          J(r, m.N + i) += row.c * v[i];
          sc += std::abs(row.c * v[i] * v[m.N + i]);
        }
        fs = std::max(fs, std::abs(f[r]) / std::max(sc, std::numeric_limits<double>::min()));
      }
      if (fs <= 1e-15) return true;
      const Eigen::VectorXd dv = J.fullPivLu().solve(f);
      if (!dv.allFinite()) return false;
      v -= dv;
      if (dv.cwiseAbs().maxCoeff() <= 1e-15 * (1 + v.cwiseAbs().maxCoeff())) return true;
    }
    return false;
  }

  void run_set() {
    const int N = m.N, n = 2 * N;
    std::vector<Row> R = rows();
    std::vector<const Row*> lin_rows, bil_rows;
    for (const auto& r : R) (r.bil >= 0 ? bil_rows : lin_rows).push_back(&r);
    const int mm = static_cast<int>(bil_rows.size());
    const int nl = n - mm;
    // Linear part, rows equilibrated by their largest coefficient.
    Eigen::MatrixXd L(nl, n);
    Eigen::VectorXd b(nl);
    for (int r = 0; r < nl; ++r) {
      const double sc = std::max(lin_rows[static_cast<std::size_t>(r)]->a.cwiseAbs().maxCoeff(),
                                 std::numeric_limits<double>::min());
      L.row(r) = lin_rows[static_cast<std::size_t>(r)]->a / sc;
      b[r] = -lin_rows[static_cast<std::size_t>(r)]->a0 / sc;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(L);
    lu.setThreshold(kDegTol);
    if (lu.rank() < nl) {
      const Eigen::VectorXd v0 = lu.solve(b);
      if ((L * v0 - b).cwiseAbs().maxCoeff() <= 1e-9 * (1 + b.cwiseAbs().maxCoeff()))
        note("its linear equations are singular and consistent (a continuum or a degenerate "
             "case); not resolved");
      return;  // inconsistent: no solution in this active set
    }
    const Eigen::VectorXd v0 = lu.solve(b);
    if (mm == 0) {
      accept(v0);
      return;
    }
    Eigen::MatrixXd K = lu.kernel();  // n x mm
    for (int j = 0; j < mm; ++j) K.col(j).normalize();
    // Bilinear row j on v = v0 + K t: alpha(t) + c beta(t) gamma(t), each affine.
    struct Aff {
      double c0;
      Eigen::VectorXd c;
    };
    auto affine = [&](const Eigen::RowVectorXd& a, double a0) {
      return Aff{a.dot(v0) + a0, (a * K).transpose()};
    };
    if (mm == 1) {
      const Row& r = *bil_rows[0];
      const int i = r.bil;
      const Aff al = affine(r.a, r.a0);
      const double b0 = v0[i], b1 = K(i, 0), g0 = v0[N + i], g1 = K(N + i, 0);
      const double c2 = r.c * b1 * g1, c1 = al.c[0] + r.c * (b0 * g1 + b1 * g0),
                   c0 = al.c0 + r.c * b0 * g0;
      const double s2 = std::abs(c2),
                   s1 = r.a.cwiseAbs().dot(K.col(0).cwiseAbs()) +
                        std::abs(r.c) * (std::abs(b0 * g1) + std::abs(b1 * g0)),
                   s0 = r.a.cwiseAbs().dot(v0.cwiseAbs()) + std::abs(r.a0) + std::abs(r.c * b0 * g0);
      double roots[2];
      const int nr = stable_quadratic_roots(c2, c1, c0, s2, s1, s0, kDegTol, roots);
      if (nr < 0) {
        note("the bilinear equation vanishes on the line of the linear ones (a continuum); not "
             "resolved");
        return;
      }
      for (int k = 0; k < nr; ++k) {
        Eigen::VectorXd v = v0 + K.col(0) * roots[k];
        newton(R, v);
        accept(v);
      }
      return;
    }
    if (mm == 2) {
      solve_two(R, bil_rows, v0, K);
      return;
    }
    // m >= 3: Newton from the wear-free solution of this active set (the small-wear root).
    std::vector<Row> R0 = R;
    for (auto& r : R0) r.bil = -1;
    Eigen::MatrixXd L0(n, n);
    Eigen::VectorXd b0(n);
    for (int r = 0; r < n; ++r) {
      L0.row(r) = R0[static_cast<std::size_t>(r)].a;
      b0[r] = -R0[static_cast<std::size_t>(r)].a0;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu0(L0);
    Eigen::VectorXd v = lu0.isInvertible() ? Eigen::VectorXd(lu0.solve(b0)) : v0;
    // The root continued from the wear-free solution, searched only when that solution is
    // near this active set's sign conditions (P_N1 >= 0, s xi >= 0 of its slipping points,
    // within 10% of the force and displacement scales): Newton directly, else continuation
    // in the wear coefficients (scaled by 1/8 ... 1).
    bool near = true;
    for (const Row* r : bil_rows) {
      const int i = r->bil;
      const double s = code[static_cast<std::size_t>(i)] == 2 ? 1.0 : -1.0;
      near = near && v[i] >= -0.1 * m.fscale && s * v[N + i] / sigma >= -0.1 * m.dscale;
    }
    if (near) {
      Eigen::VectorXd w = v;
      bool ok = newton(R, w);
      if (!ok) {
        ok = true;
        w = v;
        std::vector<Row> Rh = R;
        for (int k = 1; k <= 8 && ok; ++k) {
          for (std::size_t r = 0; r < R.size(); ++r) Rh[r].c = R[r].c * k / 8.0;
          ok = newton(Rh, w);
        }
      }
      if (ok) accept(w);
    }
    std::ostringstream o;
    o << mm << " points slip with wear: up to " << (1 << mm)
      << " roots; only the one continued from the wear-free solution was searched (Newton)";
    note(o.str());
  }

  /// m = 2: the two conics in the plane v = v0 + K t, by the Sylvester resultant.
  void solve_two(const std::vector<Row>& R, const std::vector<const Row*>& br,
                 const Eigen::VectorXd& v0, const Eigen::MatrixXd& K0) {
    const int N = m.N;
    // Conic j: [xx, xy, yy, x, y, 1] in t = (x, y).
    auto conic = [&](const Row& r, const Eigen::MatrixXd& K, double co[6], double& scale) {
      const int i = r.bil;
      const double a0 = r.a.dot(v0) + r.a0;
      const Eigen::RowVectorXd aK = r.a * K;
      const double b0 = v0[i], b1 = K(i, 0), b2 = K(i, 1);
      const double g0 = v0[N + i], g1 = K(N + i, 0), g2 = K(N + i, 1);
      const double c = r.c;
      co[0] = c * b1 * g1;
      co[1] = c * (b1 * g2 + b2 * g1);
      co[2] = c * b2 * g2;
      co[3] = aK[0] + c * (b0 * g1 + b1 * g0);
      co[4] = aK[1] + c * (b0 * g2 + b2 * g0);
      co[5] = a0 + c * b0 * g0;
      scale = r.a.cwiseAbs().dot(v0.cwiseAbs()) + std::abs(r.a0) +
              (r.a.cwiseAbs() * K.cwiseAbs()).sum() +
              std::abs(c) * (std::abs(b0) + std::abs(b1) + std::abs(b2)) *
                  (std::abs(g0) + std::abs(g1) + std::abs(g2));
    };
    // A rotation of t that gives both conics a y^2 term (a generic projection direction).
    const double angles[] = {0.0, 0.5, 1.1, 1.7, 2.3, 2.9};
    double best = -1;
    Eigen::MatrixXd K = K0;
    double q[2][6], sc[2];
    for (double th : angles) {
      Eigen::Matrix2d Rt;
      Rt << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
      const Eigen::MatrixXd Kt = K0 * Rt;
      double qt[2][6], st[2];
      conic(*br[0], Kt, qt[0], st[0]);
      conic(*br[1], Kt, qt[1], st[1]);
      const double score = std::min(std::abs(qt[0][2]) / st[0], std::abs(qt[1][2]) / st[1]) +
                           1e-3 * std::max(std::abs(qt[0][2]) / st[0], std::abs(qt[1][2]) / st[1]);
      if (score > best) {
        best = score;
        K = Kt;
        std::copy(qt[0], qt[0] + 6, q[0]);
        std::copy(qt[1], qt[1] + 6, q[1]);
        sc[0] = st[0];
        sc[1] = st[1];
      }
    }
    const bool quad0 = std::max({std::abs(q[0][0]), std::abs(q[0][1]), std::abs(q[0][2])}) > kDegTol * sc[0];
    const bool quad1 = std::max({std::abs(q[1][0]), std::abs(q[1][1]), std::abs(q[1][2])}) > kDegTol * sc[1];
    std::vector<Eigen::Vector2d> cands;
    if (!quad0 && !quad1) {
      // Both equations are linear in the plane.
      Eigen::Matrix2d B;
      B << q[0][3], q[0][4], q[1][3], q[1][4];
      Eigen::FullPivLU<Eigen::Matrix2d> l2(B);
      l2.setThreshold(kDegTol);
      if (l2.rank() < 2) {
        note("the two wear equations are dependent in their plane; not resolved");
        return;
      }
      cands.push_back(l2.solve(Eigen::Vector2d(-q[0][5], -q[1][5])));
    } else {
      // Polynomials in x: A_j (const), B_j = q3' ... as coefficient arrays (low to high).
      using P = std::vector<double>;
      auto mul = [](const P& a, const P& b) {
        P r(a.size() + b.size() - 1, 0.0);
        for (std::size_t i = 0; i < a.size(); ++i)
          for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
        return r;
      };
      auto sub = [](P a, const P& b) {
        if (a.size() < b.size()) a.resize(b.size(), 0.0);
        for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
        return a;
      };
      auto abs_p = [](P a) {
        for (auto& x : a) x = std::abs(x);
        return a;
      };
      auto add = [](P a, const P& b) {
        if (a.size() < b.size()) a.resize(b.size(), 0.0);
        for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
        return a;
      };
      const P A1{q[0][2]}, A2{q[1][2]};
      const P B1{q[0][4], q[0][1]}, B2{q[1][4], q[1][1]};
      const P C1{q[0][5], q[0][3], q[0][0]}, C2{q[1][5], q[1][3], q[1][0]};
      const P u1 = sub(mul(A1, C2), mul(A2, C1));
      const P u2 = sub(mul(A1, B2), mul(A2, B1));
      const P u3 = sub(mul(B1, C2), mul(B2, C1));
      P res = sub(mul(u1, u1), mul(u2, u3));
      // Its rounding scale: the same products of absolute values.
      const P v1 = add(mul(abs_p(A1), abs_p(C2)), mul(abs_p(A2), abs_p(C1)));
      const P v2 = add(mul(abs_p(A1), abs_p(B2)), mul(abs_p(A2), abs_p(B1)));
      const P v3 = add(mul(abs_p(B1), abs_p(C2)), mul(abs_p(B2), abs_p(C1)));
      const P rs = add(mul(v1, v1), mul(v2, v3));
      double rmax = 0, smax = 0;
      for (std::size_t i = 0; i < res.size(); ++i) {
        rmax = std::max(rmax, std::abs(res[i]));
        smax = std::max(smax, rs[i]);
      }
      if (rmax <= 1e-11 * smax) {
        note("the resultant of the two wear equations vanishes identically (a common "
             "component: a continuum or a degenerate case); not resolved");
        return;
      }
      while (res.size() > 1 && std::abs(res.back()) <= 1e-14 * smax) res.pop_back();
      const int deg = static_cast<int>(res.size()) - 1;
      std::vector<double> xs;
      if (deg == 1) {
        xs.push_back(-res[0] / res[1]);
      } else if (deg >= 2) {
        Eigen::MatrixXd Cm = Eigen::MatrixXd::Zero(deg, deg);
        for (int i = 1; i < deg; ++i) Cm(i, i - 1) = 1;
        for (int i = 0; i < deg; ++i) Cm(i, deg - 1) = -res[static_cast<std::size_t>(i)] / res.back();
        Eigen::EigenSolver<Eigen::MatrixXd> es(Cm, false);
        for (int i = 0; i < deg; ++i) {
          const std::complex<double> z = es.eigenvalues()[i];
          // Near-real eigenvalues are candidates (a double root splits by O(sqrt(eps))); each
          // is polished and verified, so a generous bound only costs time.
          if (std::abs(z.imag()) <= 1e-6 * (1 + std::abs(z))) xs.push_back(z.real());
        }
      }
      for (double x : xs) {
        for (int j = 0; j < 2; ++j) {
          const double a = q[j][2], bb = q[j][1] * x + q[j][4],
                       c = (q[j][0] * x + q[j][3]) * x + q[j][5];
          double ys[2];
          const double s = sc[j];
          const int ny = stable_quadratic_roots(a, bb, c, s, s, s, kDegTol, ys);
          for (int k = 0; k < ny; ++k) cands.emplace_back(x, ys[k]);
        }
      }
    }
    for (const auto& t : cands) {
      Eigen::VectorXd v = v0 + K * t;
      newton(R, v);
      accept(v);
    }
  }
};

}  // namespace

StepProblem point_step_problem(const SystemStepProblem& p, int i) {
  StepProblem sp;
  sp.params = p.system.point_parameters(i);
  const SystemPoint& q = p.system.points[static_cast<std::size_t>(i)];
  sp.state.P_T0 = q.P_T;
  sp.state.P_N0 = q.P_N;
  sp.state.g0 = q.g;
  sp.load.dF_T = p.DF[2 * i];
  sp.load.dF_N = p.DF[2 * i + 1];
  return sp;
}

std::string SystemStepProblem::validate() const {
  const ContactSystem& s = system;
  const int N = s.n_points();
  std::ostringstream o;
  if (N < 1) return "the system has no points";
  if (s.A.rows() != 2 * N || s.A.cols() != 2 * N) {
    o << "A is " << s.A.rows() << " x " << s.A.cols() << "; " << N << " points need " << 2 * N
      << " x " << 2 * N;
    return o.str();
  }
  if (DF.size() != 2 * N) {
    o << "DF has " << DF.size() << " numbers; " << N << " points need " << 2 * N;
    return o.str();
  }
  if (!s.A.allFinite()) return "A has a value that is not finite";
  if (!DF.allFinite()) return "DF has a value that is not finite";
  // symmetric to 1e-12 relative, positive definite judged scale-free (core/spd.hpp)
  if (const SpdVerdict spd = check_spd(s.A, 1e-12, 0.0); !spd.message.empty()) return spd.message;
  if (s.criterion != Criterion::kCoulomb)
    return "the N-point step supports only the Coulomb criterion (38)";
  for (int i = 0; i < N; ++i) {
    StepProblem sp = point_step_problem(*this, i);
    std::string m = sp.validate();
    if (!m.empty()) {
      o << "point " << i + 1 << ": " << m;
      return o.str();
    }
  }
  return {};
}

std::vector<StepValues> system_step_values(const SystemStepProblem& p, const Eigen::VectorXd& P_N1,
                                           const Eigen::VectorXd& xi) {
  const Maps m = make_maps(p);
  const int N = m.N;
  if (P_N1.size() != N || xi.size() != N)
    throw InputError("system_step_values: P_N1 and Dw_Ti need one value per point");
  Eigen::VectorXd u(2 * N);
  u << P_N1, xi;
  std::vector<StepValues> out(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    StepValues& v = out[static_cast<std::size_t>(i)];
    v.P_N1 = P_N1[i];
    v.DP_N = P_N1[i] - m.P0[i];
    v.P_T1 = m.pt0[i] + m.PT.row(i).dot(u);
    v.DP_T = v.P_T1 - m.PT0[i];
    v.Dw_Ti = xi[i];
    v.Dw_T = m.wt0[i] + m.WT.row(i).dot(u);
    v.Dw_N = m.wn0[i] + m.WN.row(i).dot(u);
    v.Dw_w = m.k[i] * std::max(v.P_N1, 0.0) * std::abs(xi[i]);
    v.g1 = m.g0[i] + v.Dw_N - v.Dw_w;
  }
  return out;
}

McpProblem system_step_as_mcp(const SystemStepProblem& p) {
  throw_if_invalid(p.validate(), "step");
  return make_mcp(make_maps(p));
}

SystemStepSolutionSet enumerate_system_step(const SystemStepProblem& p,
                                            const SystemStepOptions& opt) {
  throw_if_invalid(p.validate(), "step");
  if (!(opt.tol > 0) || !std::isfinite(opt.tol))
    throw InputError("step enumeration: tol must be finite and > 0");
  const int N = p.system.n_points();
  if (N > opt.max_points)
    throw InputError("the N-point step enumerates 4^N active sets; " + std::to_string(N) +
                     " points exceed the limit of " + std::to_string(opt.max_points));
  // Enumerate in the problem's own units (step_units), report in the caller's.
  const detail::Units units = step_units(p);
  const SystemStepProblem ps = to_units(p, units);
  const Maps m = make_maps(ps);
  const McpProblem mcp = make_mcp(m);
  SystemStepSolutionSet out;
  const double amax = ps.system.A.cwiseAbs().maxCoeff();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(ps.system.A, Eigen::EigenvaluesOnly);
  const double cond = eig.eigenvalues()(2 * N - 1) / eig.eigenvalues()(0);
  const double gray = kGray * std::numeric_limits<double>::epsilon() * cond;
  Enumerator e{ps, m, mcp, opt.tol, amax, cond, gray, out, {},
               std::vector<int>(static_cast<std::size_t>(N), 0)};
  long total = 1;
  for (int i = 0; i < N; ++i) total *= 4;
  for (long c = 0; c < total; ++c) {
    long r = c;
    for (int i = 0; i < N; ++i) {
      e.code[static_cast<std::size_t>(i)] = static_cast<int>(r % 4);
      r /= 4;
    }
    e.run_set();
  }
  out.active_sets = total;
  {
    if (!(cond <= kMaxProvedCond)) {
      std::ostringstream o;
      o << "A is ill-conditioned (cond(A) = " << cond << " > " << kMaxProvedCond
        << "): the listed solutions are verified, but the list is not proved complete";
      out.complete = false;
      out.notes.push_back(o.str());
    }
  }
  if (!out.notes.empty()) out.message = out.notes.front();
  for (auto& sol : out.solutions)
    for (auto& v : sol.values) from_units(v, units);
  return out;
}

}  // namespace cpkit::rate
