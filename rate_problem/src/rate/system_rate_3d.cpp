// The faceted rate problem of N coupled 3-D points (system_rate_3d.hpp, docs/contact_3d.md).
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate3d {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num_text(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}
constexpr double kTol = 1e-10;

/// The inscribed polygon of a point's ellipse: outward unit facet normals and supports.
struct Polygon {
  Eigen::Matrix<double, 2, Eigen::Dynamic> N;
  Eigen::VectorXd h;
};

Polygon polygon(const Eigen::Vector2d& alpha, int k) {
  Polygon p;
  p.N.resize(2, k);
  p.h.resize(k);
  std::vector<Eigen::Vector2d> v(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i)
    v[i] = alpha.asDiagonal() * Eigen::Vector2d(std::cos(2 * kPi * i / k), std::sin(2 * kPi * i / k));
  for (int j = 0; j < k; ++j) {
    const Eigen::Vector2d e = v[(j + 1) % k] - v[j];
    p.N.col(j) = Eigen::Vector2d(e(1), -e(0)).normalized();
    p.h(j) = p.N.col(j).dot(v[j]);
  }
  return p;
}

}  // namespace

SystemRateSet3d solve_system_rate_3d_faceted(const ContactSystem3d& user_sys,
                                             const Eigen::VectorXd& user_dF, int k,
                                             double time_limit_s) {
  // Every point's friction ellipse in its own unit (the rates hold no multiplier).
  ContactSystem3d sys = user_sys;
  for (SystemPoint3d& pt : sys.points) detail::normalize_ellipse(pt);
  const int n = sys.n_points();
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
    const Point3dParameters p = sys.point_parameters(i);
    if (const std::string e = p.validate(); !e.empty())
      throw InputError("point " + std::to_string(i + 1) + ": " + e);
    if (const std::string e = sys.points[i].state.validate(p); !e.empty())
      throw InputError("point " + std::to_string(i + 1) + ": " + e);
  }
  std::vector<int> grazing, sliding;
  for (int i = 0; i < n; ++i) {
    if (sys.points[i].state.state == 'b') grazing.push_back(i);
    if (sys.points[i].state.state == 'd') sliding.push_back(i);
  }
  const int nb = static_cast<int>(grazing.size());
  if (nb > kMaxGrazing3d)
    throw InputError(std::to_string(nb) + " grazing points: at most " + std::to_string(kMaxGrazing3d) +
                     " (2^n_b separation cases)");
  if (static_cast<int>(sliding.size()) + k * nb > lcp::kMaxEnumerationSize)
    throw InputError("the faceted LCP would have size n_d + k n_b = " +
                     std::to_string(sliding.size() + static_cast<std::size_t>(k) * nb) +
                     " > " + std::to_string(lcp::kMaxEnumerationSize) + ": use fewer facets");

  // Normalized units (as unit_scaling.hpp for one point): A / |A|, C_T |A|, dF / |dF|.
  const double a = sys.A.cwiseAbs().maxCoeff();
  double f = user_dF.cwiseAbs().maxCoeff();
  if (f == 0) f = 1;
  const Eigen::MatrixXd A = sys.A / a;
  const Eigen::VectorXd dF = user_dF / f;
  const double force_back = f, disp_back = f / a;

  std::vector<Polygon> poly(static_cast<std::size_t>(n));
  for (int i : grazing) poly[i] = polygon(sys.points[i].alpha, k);

  SystemRateSet3d out;
  out.facets = k;
  // One deadline for the whole solve (every separation case), not one per enumeration: 2^n_b
  // cases of up to the limit each would not end (issue 24, item 11).
  const Stopwatch clock;
  const int dim = 6 * n;  // x = (dP (3N), dw (3N))
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
    auto separated = [&](int i) {
      for (int b = 0; b < nb; ++b)
        if (grazing[b] == i) return ((mask >> b) & 1u) != 0;
      return false;
    };
    // multipliers: one per sliding point, k per grazing point in contact
    std::vector<int> z_of(static_cast<std::size_t>(n), -1);
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const char s = sys.points[i].state.state;
      if (s == 'd') z_of[i] = m, m += 1;
      if (s == 'b' && !separated(i)) z_of[i] = m, m += k;
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dim, dim), R = Eigen::MatrixXd::Zero(dim, m);
    Eigen::VectorXd r0 = Eigen::VectorXd::Zero(dim);
    // equilibrium dP + A dw = dF
    K.topLeftCorner(3 * n, 3 * n).setIdentity();
    K.topRightCorner(3 * n, 3 * n) = A;
    r0.head(3 * n) = dF;
    std::vector<Eigen::Vector2d> n0(static_cast<std::size_t>(n));
    std::vector<double> kappa(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
      const SystemPoint3d& pt = sys.points[i];
      const int row = 3 * n + 3 * i, P = 3 * i, W = 3 * n + 3 * i;
      const double C_T = pt.C_T * a;
      const char s = pt.state.state;
      if (s == 'a' || (s == 'b' && separated(i))) {
        for (int c = 0; c < 3; ++c) K(row + c, P + c) = 1;  // dP_i = 0
        continue;
      }
      for (int c = 0; c < 2; ++c) K(row + c, W + c) = 1, K(row + c, P + c) = -C_T;  // dw_T - C_T dP_T
      K(row + 2, W + 2) = 1;                                                      // dw_N
      if (s == 'd') {
        const Eigen::Vector2d t0 = pt.state.P_T.cwiseQuotient(pt.alpha).normalized();
        n0[i] = t0.cwiseQuotient(pt.alpha);
        kappa[i] = pt.k_a / (3 * pt.P_s) * pt.state.P_N;
        R(row, z_of[i]) = n0[i](0);
        R(row + 1, z_of[i]) = n0[i](1);
        R(row + 2, z_of[i]) = kappa[i];
      } else if (s == 'b') {
        R.block(row, z_of[i], 2, k) = poly[i].N;
      }
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
    const Eigen::VectorXd x0 = lu.solve(r0);
    // (no solve with an empty right-hand side: Eigen's triangular solve binds a reference to
    // its null data, which UBSan reports)
    const Eigen::MatrixXd X = m > 0 ? Eigen::MatrixXd(lu.solve(R)) : Eigen::MatrixXd(dim, 0);
    if (!x0.allFinite() || !X.allFinite() ||
        (K * x0 - r0).cwiseAbs().maxCoeff() > 1e-9 * (1 + r0.cwiseAbs().maxCoeff())) {
      note("the rate equations are singular for a separation case: not resolved");
      continue;
    }
    // complementarity: d points mu dP_N - n0 . dP_T; grazing contact points per facet
    // mu h_j dP_N - n_j . dP_T
    LcpProblem lcp;
    lcp.M = Mat::Zero(m, m);
    lcp.q = Vec::Zero(m);
    for (int i = 0; i < n; ++i) {
      if (z_of[i] < 0) continue;
      const double mu = sys.points[i].mu;
      const int P = 3 * i;
      if (sys.points[i].state.state == 'd') {
        lcp.M.row(z_of[i]) = mu * X.row(P + 2) - n0[i](0) * X.row(P) - n0[i](1) * X.row(P + 1);
        lcp.q(z_of[i]) = mu * x0(P + 2) - n0[i](0) * x0(P) - n0[i](1) * x0(P + 1);
      } else {
        for (int j = 0; j < k; ++j) {
          const Eigen::Vector2d nj = poly[i].N.col(j);
          lcp.M.row(z_of[i] + j) = mu * poly[i].h(j) * X.row(P + 2) - nj(0) * X.row(P) - nj(1) * X.row(P + 1);
          lcp.q(z_of[i] + j) = mu * poly[i].h(j) * x0(P + 2) - nj(0) * x0(P) - nj(1) * x0(P + 1);
        }
      }
    }
    std::vector<Eigen::VectorXd> zs;
    if (m == 0) {
      zs.push_back(Eigen::VectorXd());
    } else {
      lcp::EnumerationOptions opt;
      opt.time_limit_s = std::max(1e-3, time_limit_s - clock.seconds());  // what is left
      const lcp::SolutionSet set = lcp::enumerate_all(lcp, opt);
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
      // separated grazing points must open: dw_N < 0, read outside the rounding band of the
      // solve K x = r (backward stable: eps |K| |x| + |r|, carried by the row of K^-1 that
      // gives dw_N; faceted_rate_3d.cpp, commit 3197885): no fixed band, no "1 +" (issue 24)
      bool ok = true, undecided = false;
      for (int b = 0; b < nb && ok; ++b) {
        if (!((mask >> b) & 1u)) continue;
        const int iN = 3 * n + 3 * grazing[b] + 2;
        const Eigen::VectorXd rowN = lu.transpose().solve(Eigen::VectorXd::Unit(dim, iN));
        Eigen::VectorXd terms = K.cwiseAbs() * x.cwiseAbs() + r0.cwiseAbs();
        if (m > 0) terms += R.cwiseAbs() * z.cwiseAbs();
        const double band = 64 * 2.220446049250313e-16 * rowN.cwiseAbs().dot(terms);
        const double dwN = x(iN);
        if (dwN < -band) continue;
        if (dwN <= band) undecided = true; else ok = false;
      }
      if (!ok) continue;
      SystemSolution3d sol;
      for (int i = 0; i < n; ++i) {
        const SystemPoint3d& pt = sys.points[i];
        Rates3d r;
        r.dP_T = x.segment<2>(3 * i) * force_back;
        r.dP_N = x(3 * i + 2) * force_back;
        r.dw_T = x.segment<2>(3 * n + 3 * i) * disp_back;
        r.dw_N = x(3 * n + 3 * i + 2) * disp_back;
        r.dw_Ti = r.dw_T - pt.C_T * r.dP_T;
        const char s = pt.state.state;
        Type3d type = Type3d::kStick;
        if (s == 'a' || (s == 'b' && separated(i))) {
          type = s == 'a' ? Type3d::kOpen : Type3d::kSeparation;
          r.dP_T.setZero();  // constrained to 0 (the solve leaves rounding noise)
          r.dP_N = 0;
          r.dw_Ti = r.dw_T;
        }
        else if (s == 'd') {
          const double lambda = z(z_of[i]);
          r.dw_w = kappa[i] * lambda * disp_back;
          if (lambda > kTol) type = Type3d::kSlip;
          r.dw_Ti = lambda * n0[i] * disp_back;  // exactly along the normal
        } else if (s == 'b') {
          const Eigen::Vector2d slip = poly[i].N * z.segment(z_of[i], k);
          r.dw_Ti = slip * disp_back;
          if (slip.cwiseAbs().maxCoeff() > 1e-9) type = Type3d::kSlip;
        } else {
          r.dw_Ti.setZero();
        }
        sol.types.push_back(type);
        sol.rates.push_back(r);
      }
      // deduplicate (the same physical rates from another basis or case)
      bool seen = false;
      for (const auto& o : out.solutions) {
        double d = 0;
        for (int i = 0; i < n; ++i) {
          d = std::max({d, (o.rates[i].dP_T - sol.rates[i].dP_T).cwiseAbs().maxCoeff() / force_back,
                        std::abs(o.rates[i].dP_N - sol.rates[i].dP_N) / force_back,
                        (o.rates[i].dw_T - sol.rates[i].dw_T).cwiseAbs().maxCoeff() / disp_back,
                        std::abs(o.rates[i].dw_N - sol.rates[i].dw_N) / disp_back});
        }
        seen = seen || d <= 1e-8;
      }
      if (undecided) {
        // decided only if the same rates come from the contact case (the point closed with
        // dP = 0 and dw_N = 0); checked once every case is done
        pending.push_back(std::move(sol));
        continue;
      }
      if (!seen) out.solutions.push_back(std::move(sol));
    }
  }
  for (const SystemSolution3d& sol : pending) {
    bool seen = false;
    for (const auto& o : out.solutions) {
      double d = 0;
      for (int i = 0; i < n; ++i)
        d = std::max({d, (o.rates[i].dP_T - sol.rates[i].dP_T).cwiseAbs().maxCoeff() / force_back,
                      std::abs(o.rates[i].dP_N - sol.rates[i].dP_N) / force_back,
                      (o.rates[i].dw_T - sol.rates[i].dw_T).cwiseAbs().maxCoeff() / disp_back,
                      std::abs(o.rates[i].dw_N - sol.rates[i].dw_N) / disp_back});
      seen = seen || d <= 1e-8;
    }
    if (!seen) {
      out.complete = false;
      if (out.message.empty())
        out.message = "a separated point's normal rate dw_N is zero within the rounding of the "
                      "rate equations and no contact solution has the same rates: not decided";
    }
  }
  return out;
}

}  // namespace cpkit::rate3d
