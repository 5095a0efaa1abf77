// The faceted rate problem of N coupled 3-D points (system_rate_3d.hpp, docs/contact_3d.md).
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "../model/unit_scaling.hpp"
#include "facet_polygon.hpp"
#include "rate_3d_units.hpp"

namespace cpkit::rate {
namespace {

constexpr double kTol = 1e-10;

/// The problem in normalized units (as unit_scaling.hpp for one point: A / |A|, C_T |A|,
/// dF / |dF|), checked, with the facets of every grazing point.
struct Faceted {
  ContactSystem3d sys;  ///< every point's friction ellipse in its own unit
  int n = 0, k = 0;
  std::vector<int> grazing, sliding;
  Eigen::MatrixXd A;
  Eigen::VectorXd dF;
  double a = 1, force_back = 1, disp_back = 1;
  std::vector<detail::FacetPolygon> poly;
  int nb() const { return static_cast<int>(grazing.size()); }
  /// Whether point i is a grazing point that separates in case `mask` (bit b: grazing point b).
  bool separated(unsigned mask, int i) const {
    for (int b = 0; b < nb(); ++b)
      if (grazing[b] == i) return ((mask >> b) & 1u) != 0;
    return false;
  }
};

Faceted prepare(const ContactSystem3d& user_sys, const Eigen::VectorXd& user_dF, int k,
                double time_limit_s) {
  Faceted f;
  // Every point's friction ellipse in its own unit (the rates hold no multiplier).
  f.sys = user_sys;
  for (SystemPoint3d& pt : f.sys.points) detail::normalize_ellipse(pt);
  const ContactSystem3d& sys = f.sys;
  const int n = f.n = sys.n_points();
  f.k = k;
  if (n < 1 || sys.A.rows() != 3 * n || sys.A.cols() != 3 * n)
    throw InputError("system: A must be 3N x 3N for its N points");
  if (user_dF.size() != 3 * n || !user_dF.allFinite())
    throw InputError("dF must have 3N = " + std::to_string(3 * n) + " finite entries");
  if (k < 3 || k > kMaxFacets)
    throw InputError("facets must be in [3, " + std::to_string(kMaxFacets) + "], got " + std::to_string(k));
  if (!(time_limit_s > 0))
    throw InputError("the time limit must be a positive number of seconds, got " +
                     num_text(time_limit_s));
  for (int i = 0; i < n; ++i) {
    const ContactParameters3d p = sys.point_parameters(i);
    if (const std::string e = p.validate(); !e.empty())
      throw InputError("point " + std::to_string(i + 1) + ": " + e);
    if (const std::string e = sys.points[i].state.validate(p); !e.empty())
      throw InputError("point " + std::to_string(i + 1) + ": " + e);
  }
  for (int i = 0; i < n; ++i) {
    if (sys.points[i].state.state == 'b') f.grazing.push_back(i);
    if (sys.points[i].state.state == 'd') f.sliding.push_back(i);
  }
  const int nb = f.nb();
  if (nb > kMaxGrazing3d)
    throw InputError(std::to_string(nb) + " grazing points: at most " + std::to_string(kMaxGrazing3d) +
                     " (2^n_b separation cases)");
  if (static_cast<int>(f.sliding.size()) + k * nb > lcp::kMaxEnumerationSize)
    throw InputError("the faceted LCP would have size n_d + k n_b = " +
                     std::to_string(f.sliding.size() + static_cast<std::size_t>(k) * nb) +
                     " > " + std::to_string(lcp::kMaxEnumerationSize) + ": use fewer facets");
  f.a = sys.A.cwiseAbs().maxCoeff();
  double fs = user_dF.cwiseAbs().maxCoeff();
  if (fs == 0) fs = 1;
  f.A = sys.A / f.a;
  f.dF = user_dF / fs;
  f.force_back = fs;
  f.disp_back = fs / f.a;
  f.poly.resize(static_cast<std::size_t>(n));
  for (int i : f.grazing) f.poly[i] = detail::facet_polygon(sys.points[i].alpha, k);
  return f;
}

/// The rate equations of one separation case, K x = r0 + R z with x = (dP (3N), dw (3N)) and
/// the multipliers z: one per sliding point, k per grazing point in contact.
struct CaseEquations {
  std::vector<int> z_of;  ///< first multiplier of each point, -1 without
  int m = 0;
  Eigen::MatrixXd K, R;
  Eigen::VectorXd r0;
  std::vector<Eigen::Vector2d> n0;  ///< sliding points: the ellipse's normal at P_T
  std::vector<double> kappa;        ///< sliding points: k_a P_N / (3 P_s)
};

CaseEquations case_equations(const Faceted& f, unsigned mask) {
  const int n = f.n, k = f.k, dim = 6 * n;
  const ContactSystem3d& sys = f.sys;
  CaseEquations c;
  c.z_of.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    const char s = sys.points[i].state.state;
    if (s == 'd') c.z_of[i] = c.m, c.m += 1;
    if (s == 'b' && !f.separated(mask, i)) c.z_of[i] = c.m, c.m += k;
  }
  c.K = Eigen::MatrixXd::Zero(dim, dim);
  c.R = Eigen::MatrixXd::Zero(dim, c.m);
  c.r0 = Eigen::VectorXd::Zero(dim);
  // equilibrium dP + A dw = dF
  c.K.topLeftCorner(3 * n, 3 * n).setIdentity();
  c.K.topRightCorner(3 * n, 3 * n) = f.A;
  c.r0.head(3 * n) = f.dF;
  c.n0.resize(static_cast<std::size_t>(n));
  c.kappa.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    const SystemPoint3d& pt = sys.points[i];
    const int row = 3 * n + 3 * i, P = 3 * i, W = 3 * n + 3 * i;
    const double C_T = pt.C_T * f.a;
    const char s = pt.state.state;
    if (s == 'a' || (s == 'b' && f.separated(mask, i))) {
      for (int j = 0; j < 3; ++j) c.K(row + j, P + j) = 1;  // dP_i = 0
      continue;
    }
    for (int j = 0; j < 2; ++j) c.K(row + j, W + j) = 1, c.K(row + j, P + j) = -C_T;  // dw_T - C_T dP_T
    c.K(row + 2, W + 2) = 1;                                                          // dw_N
    if (s == 'd') {
      const Eigen::Vector2d t0 = pt.state.P_T.cwiseQuotient(pt.alpha).normalized();
      c.n0[i] = t0.cwiseQuotient(pt.alpha);
      c.kappa[i] = pt.k_a / (3 * pt.P_s) * pt.state.P_N;
      c.R(row, c.z_of[i]) = c.n0[i](0);
      c.R(row + 1, c.z_of[i]) = c.n0[i](1);
      c.R(row + 2, c.z_of[i]) = c.kappa[i];
    } else if (s == 'b') {
      c.R.block(row, c.z_of[i], 2, k) = f.poly[i].N;
    }
  }
  return c;
}

/// The complementarity of the case in the multipliers, x = x0 + X z: sliding points
/// mu dP_N - n0 . dP_T; grazing contact points per facet mu h_j dP_N - n_j . dP_T.
LcpProblem case_lcp(const Faceted& f, const CaseEquations& c, const Eigen::VectorXd& x0,
                    const Eigen::MatrixXd& X) {
  LcpProblem lcp;
  lcp.M = Mat::Zero(c.m, c.m);
  lcp.q = Vec::Zero(c.m);
  for (int i = 0; i < f.n; ++i) {
    if (c.z_of[i] < 0) continue;
    const double mu = f.sys.points[i].mu;
    const int P = 3 * i;
    if (f.sys.points[i].state.state == 'd') {
      const Eigen::Vector2d& n0 = c.n0[i];
      lcp.M.row(c.z_of[i]) = mu * X.row(P + 2) - n0(0) * X.row(P) - n0(1) * X.row(P + 1);
      lcp.q(c.z_of[i]) = mu * x0(P + 2) - n0(0) * x0(P) - n0(1) * x0(P + 1);
    } else {
      for (int j = 0; j < f.k; ++j) {
        const Eigen::Vector2d nj = f.poly[i].N.col(j);
        const double h = f.poly[i].h(j);
        lcp.M.row(c.z_of[i] + j) = mu * h * X.row(P + 2) - nj(0) * X.row(P) - nj(1) * X.row(P + 1);
        lcp.q(c.z_of[i] + j) = mu * h * x0(P + 2) - nj(0) * x0(P) - nj(1) * x0(P + 1);
      }
    }
  }
  return lcp;
}

/// Separated grazing points must open: dw_N < 0, read outside the rounding band of the solve
/// K x = r (backward stable: eps |K| |x| + |r|, carried by the row of K^-1 that gives dw_N;
/// faceted_rate_3d.cpp, commit 3197885): no fixed band, no "1 +" (issue 24). Returns false when
/// a separated point closes; `undecided` when one opens only within rounding.
bool separated_points_open(const Faceted& f, const CaseEquations& c,
                           const Eigen::PartialPivLU<Eigen::MatrixXd>& lu, unsigned mask,
                           const Eigen::VectorXd& x, const Eigen::VectorXd& z, bool& undecided) {
  const int n = f.n, dim = 6 * n;
  undecided = false;
  for (int b = 0; b < f.nb(); ++b) {
    if (!((mask >> b) & 1u)) continue;
    const int iN = 3 * n + 3 * f.grazing[b] + 2;
    const Eigen::VectorXd rowN = lu.transpose().solve(Eigen::VectorXd::Unit(dim, iN));
    Eigen::VectorXd terms = c.K.cwiseAbs() * x.cwiseAbs() + c.r0.cwiseAbs();
    if (c.m > 0) terms += c.R.cwiseAbs() * z.cwiseAbs();
    const double band = 64 * 2.220446049250313e-16 * rowN.cwiseAbs().dot(terms);
    const double dwN = x(iN);
    if (dwN < -band) continue;
    if (dwN <= band) undecided = true; else return false;
  }
  return true;
}

/// The rates and types of every point, in the caller's units, from x = (dP, dw) and z.
SystemSolution3d case_solution(const Faceted& f, const CaseEquations& c, unsigned mask,
                               const Eigen::VectorXd& x, const Eigen::VectorXd& z) {
  const int n = f.n;
  SystemSolution3d sol;
  for (int i = 0; i < n; ++i) {
    const SystemPoint3d& pt = f.sys.points[i];
    Rates3d r;
    r.dP_T = x.segment<2>(3 * i) * f.force_back;
    r.dP_N = x(3 * i + 2) * f.force_back;
    r.dw_T = x.segment<2>(3 * n + 3 * i) * f.disp_back;
    r.dw_N = x(3 * n + 3 * i + 2) * f.disp_back;
    r.dw_Ti = r.dw_T - pt.C_T * r.dP_T;
    const char s = pt.state.state;
    SolutionType type = SolutionType::kStick;
    if (s == 'a' || (s == 'b' && f.separated(mask, i))) {
      type = s == 'a' ? SolutionType::kOpen : SolutionType::kSeparation;
      r.dP_T.setZero();  // constrained to 0 (the solve leaves rounding noise)
      r.dP_N = 0;
      r.dw_Ti = r.dw_T;
    } else if (s == 'd') {
      const double lambda = z(c.z_of[i]);
      r.dw_w = c.kappa[i] * lambda * f.disp_back;
      if (lambda > kTol) type = SolutionType::kSlip;
      r.dw_Ti = lambda * c.n0[i] * f.disp_back;  // exactly along the normal
    } else if (s == 'b') {
      const Eigen::Vector2d slip = f.poly[i].N * z.segment(c.z_of[i], f.k);
      r.dw_Ti = slip * f.disp_back;
      if (slip.cwiseAbs().maxCoeff() > 1e-9) type = SolutionType::kSlip;
    } else {
      r.dw_Ti.setZero();
    }
    sol.types.push_back(type);
    sol.rates.push_back(r);
  }
  return sol;
}

/// Whether `sol` has the rates of a listed solution (to 1e-8 in the normalized units).
bool already_listed(const Faceted& f, const std::vector<SystemSolution3d>& listed,
                    const SystemSolution3d& sol) {
  for (const auto& o : listed) {
    double d = 0;
    for (int i = 0; i < f.n; ++i)
      d = std::max(d, detail::rates_distance(o.rates[i], sol.rates[i], f.force_back, f.disp_back));
    if (d <= 1e-8) return true;
  }
  return false;
}

}  // namespace

SystemRateSet3d solve_system_rate_3d_faceted(const ContactSystem3d& user_sys,
                                             const Eigen::VectorXd& user_dF, int k,
                                             double time_limit_s) {
  const Faceted f = prepare(user_sys, user_dF, k, time_limit_s);
  const int n = f.n, nb = f.nb(), dim = 6 * n;  // x = (dP (3N), dw (3N))
  SystemRateSet3d out;
  out.facets = k;
  // One deadline for the whole solve (every separation case), not one per enumeration: 2^n_b
  // cases of up to the limit each would not end (issue 24, item 11).
  const Stopwatch clock;
  auto note = [&](const std::string& m) {
    out.complete = false;
    if (out.message.empty()) out.message = m;
  };
  std::vector<SystemSolution3d> pending;  // separation candidates with an undecided dw_N
  for (unsigned mask = 0; mask < (1u << nb); ++mask) {  // bit b set: grazing point b separates
    if (clock.seconds() >= time_limit_s) {
      out.timed_out = true;
      out.complete = false;
      out.message = "time limit of " + num_text(time_limit_s) + " s reached after " +
                    std::to_string(mask) + " of " + std::to_string(1u << nb) +
                    " separation cases: the solutions found are not the whole set";
      break;
    }
    const CaseEquations c = case_equations(f, mask);
    const int m = c.m;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(c.K);
    const Eigen::VectorXd x0 = lu.solve(c.r0);
    // (no solve with an empty right-hand side: Eigen's triangular solve binds a reference to
    // its null data, which UBSan reports)
    const Eigen::MatrixXd X = m > 0 ? Eigen::MatrixXd(lu.solve(c.R)) : Eigen::MatrixXd(dim, 0);
    if (!x0.allFinite() || !X.allFinite() ||
        (c.K * x0 - c.r0).cwiseAbs().maxCoeff() > 1e-9 * (1 + c.r0.cwiseAbs().maxCoeff())) {
      note("the rate equations are singular for a separation case: not resolved");
      continue;
    }
    std::vector<Eigen::VectorXd> zs;
    if (m == 0) {
      zs.push_back(Eigen::VectorXd());
    } else {
      lcp::EnumerationOptions opt;
      opt.time_limit_s = std::max(1e-3, time_limit_s - clock.seconds());  // what is left
      const lcp::SolutionSet set = lcp::enumerate_all(case_lcp(f, c, x0, X), opt);
      out.nodes += set.nodes;
      if (!set.complete && clock.seconds() >= time_limit_s) {
        out.timed_out = true;
        out.complete = false;
        out.message = "time limit of " + num_text(time_limit_s) + " s reached in separation "
                      "case " + std::to_string(mask + 1) + " of " + std::to_string(1u << nb) +
                      ": the solutions found are not the whole set";
      }
      if (!set.complete) note(set.message);
      for (const auto& e : set.solutions) zs.push_back(e.z);
      for (const auto& piece : set.pieces) {
        bool one = true;
        for (std::size_t v = 1; v < piece.vertices.size(); ++v)
          one = one && (X * (set.solutions[piece.vertices[v]].z - set.solutions[piece.vertices[0]].z))
                               .cwiseAbs().maxCoeff() <= 1e-8;
        for (const auto& ray : piece.rays) one = one && (X * ray).cwiseAbs().maxCoeff() <= 1e-8;
        if (!one) note("a continuum of physical solutions (listed by its extreme points only)");
      }
    }
    for (const Eigen::VectorXd& z : zs) {
      const Eigen::VectorXd x = m == 0 ? x0 : Eigen::VectorXd(x0 + X * z);
      bool undecided = false;
      if (!separated_points_open(f, c, lu, mask, x, z, undecided)) continue;
      SystemSolution3d sol = case_solution(f, c, mask, x, z);
      if (undecided) {
        // decided only if the same rates come from the contact case (the point closed with
        // dP = 0 and dw_N = 0); checked once every case is done
        pending.push_back(std::move(sol));
        continue;
      }
      // deduplicate (the same physical rates from another basis or case)
      if (!already_listed(f, out.solutions, sol)) out.solutions.push_back(std::move(sol));
    }
  }
  for (const SystemSolution3d& sol : pending) {
    if (!already_listed(f, out.solutions, sol)) {
      out.complete = false;
      if (out.message.empty())
        out.message = "a separated point's normal rate dw_N is zero within the rounding of the "
                      "rate equations and no contact solution has the same rates: not decided";
    }
  }
  return out;
}

SystemRateRoute3d solve_system_rate_3d(const ContactSystem3d& system, const Eigen::VectorXd& dF,
                                       int facets, double time_limit_s) {
  SystemRateRoute3d out;
  out.facets = facets;
  if (system.n_points() != 1) {
    if (facets == 0)
      throw InputError("coupled 3-D points are solved with the faceted friction ellipses: "
                       "facets must be given (3.." + std::to_string(kMaxFacets) + ")");
    return solve_system_rate_3d_faceted(system, dF, facets, time_limit_s);
  }
  const ContactState3d& st = system.points[0].state;
  if (facets != 0 && st.state != 'b')
    throw InputError(std::string("the faceted rate problem is that of state b (grazing); state ") +
                     st.state + " has a linear rate problem, solved exactly");
  if (dF.size() != 3) throw InputError("dF must have 3 entries for one 3-D point");
  const ContactParameters3d p = system.point_parameters(0);
  const Eigen::Vector3d f = dF;
  const RateSolutionSet3d s = facets != 0 ? solve_rate_3d_faceted(p, f, facets, time_limit_s)
                                          : solve_rate_3d(p, st, f);
  out.complete = s.complete;
  out.message = s.message;
  for (const auto& x : s.solutions)
    out.solutions.push_back({{x.type}, {x.at}, {x.direction}, x.ray, x.origin_included});
  return out;
}

}  // namespace cpkit::rate
