// The faceted state-b rate problem of one 3-D point: docs/contact_3d.md, "The faceted problem".
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "facet_polygon.hpp"
#include "rate_3d_units.hpp"

namespace cpkit::rate {
namespace {

using detail::rates_distance;

constexpr double kTol = 1e-10;  // relative "zero", as in point_rate_3d.cpp

/// Contact (dw_N = 0): lambda (one slip multiplier per facet) -> physical rates, affine:
/// dP_T = p0 + Pt lambda, dP_N = n0 + Pn lambda, dw_T^i = N lambda (docs/contact_3d.md,
/// (3D.14)).
struct FacetedMap {
  Eigen::Vector2d p0;
  double n0 = 0;
  Eigen::Matrix<double, 2, Eigen::Dynamic> Pt, N;
  Eigen::Matrix<double, 1, Eigen::Dynamic> Pn;
  double C_T = 0;

  Rates3d rates(const Eigen::VectorXd& lambda, bool affine) const {
    Rates3d r;
    r.dP_T = (affine ? p0 : Eigen::Vector2d::Zero()) + Pt * lambda;
    r.dP_N = (affine ? n0 : 0.0) + Pn.dot(lambda);
    r.dw_Ti = N * lambda;
    r.dw_T = C_T * r.dP_T + r.dw_Ti;
    return r;
  }
};

}  // namespace

RateSolutionSet3d solve_rate_3d_faceted(const ContactParameters3d& user_params,
                                        const Eigen::Vector3d& user_dF, int k,
                                        double time_limit_s) {
  if (const std::string e = user_params.validate(); !e.empty()) throw InputError("parameters: " + e);
  if (!user_dF.allFinite()) throw InputError("dF must be finite");
  if (k < 3 || k > kMaxFacets)
    throw InputError("facets must be in [3, " + std::to_string(kMaxFacets) + "], got " +
                     std::to_string(k));
  ContactParameters3d p = user_params;
  Eigen::Vector3d dF = user_dF;
  detail::normalize_ellipse(p);  // the rates hold no multiplier: nothing to scale back
  const detail::Units scaling = detail::normalize(p, dF);
  const detail::FacetPolygon poly = detail::facet_polygon(p.alpha, k);
  FacetedMap map;
  map.C_T = p.C_T;
  map.N = poly.N;
  const Eigen::VectorXd& h = poly.h;
  // In contact, dF - dP = A (C_T dP_T + N lambda, 0): dP_T = K^-1 (dF_T - A_TT N lambda) with
  // K = I + C_T A_TT, dP_N = dF_N - A_NT (C_T dP_T + N lambda).
  const Eigen::Matrix2d ATT = p.A.topLeftCorner<2, 2>();
  const Eigen::Vector2d ATN = p.A.topRightCorner<2, 1>();
  const Eigen::LDLT<Eigen::Matrix2d> K = (Eigen::Matrix2d::Identity() + p.C_T * ATT).ldlt();
  map.p0 = K.solve(dF.head<2>());
  map.Pt = -K.solve(ATT * map.N);
  map.n0 = dF(2) - p.C_T * ATN.dot(map.p0);
  map.Pn = -p.C_T * ATN.transpose() * map.Pt - ATN.transpose() * map.N;

  // w_j = mu h_j dP_N - n_j . dP_T >= 0, lambda_j >= 0, complementary: w = M lambda + q.
  // (dP_N >= 0 follows: the polygon holds 0 inside, so no dP_T fits a negative dP_N.)
  LcpProblem lcp;
  lcp.M = p.mu * h * map.Pn - map.N.transpose() * map.Pt;
  lcp.q = p.mu * map.n0 * h - map.N.transpose() * map.p0;

  lcp::EnumerationOptions opt;
  opt.time_limit_s = time_limit_s;
  const lcp::SolutionSet zs = lcp::enumerate_all(lcp, opt);

  RateSolutionSet3d set;
  set.facets = k;
  set.nodes = zs.nodes;
  set.complete = zs.complete;
  set.message = zs.message;
  const double force = std::max(dF.cwiseAbs().maxCoeff(), 1e-300);
  const double disp = force / p.A.cwiseAbs().maxCoeff();
  auto add = [&](const Rates3d& r) {
    for (const auto& s : set.solutions)
      if (rates_distance(s.at, r, force, disp) <= 1e-8) return;
    SolutionType type = SolutionType::kSlip;
    if (r.dw_Ti.cwiseAbs().maxCoeff() <= 1e-9 * disp)
      type = SolutionType::kStick;
    RateSolution3d s;
    s.type = type;
    s.at = r;
    if (type == SolutionType::kSlip) {
      s.slip_direction = r.dw_Ti.normalized();
      s.slip_angle = std::atan2(s.slip_direction(1), s.slip_direction(0));
    }
    set.solutions.push_back(s);
  };
  // Separation (dP = 0, dw = A^-1 dF, dw_N < 0): outside the contact LCP, whose multipliers
  // would all be free there.
  // dw_N is a forward result: its sign is read outside the rounding band of the solve
  // (backward stable: eps |A| |dw|, carried by the row N of A^-1); inside it the separation is
  // the contact solution with dP = 0 or undecided (as in point_rate_3d.cpp).
  bool separation_undecided = false;
  {
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(p.A);
    const Eigen::Vector3d dw = ldlt.solve(dF);
    const Eigen::Vector3d row_N = ldlt.solve(Eigen::Vector3d::UnitZ());
    const double band = std::max(kTol * dw.cwiseAbs().maxCoeff(),
                                 64 * 2.220446049250313e-16 * row_N.cwiseAbs().sum() *
                                     (p.A.cwiseAbs() * dw.cwiseAbs()).maxCoeff());
    if (dw(2) >= -band && dw(2) <= band) separation_undecided = true;
    if (dw(2) < -band) {
      RateSolution3d s;
      s.type = SolutionType::kSeparation;
      s.at.dw_T = dw.head<2>();
      s.at.dw_N = dw(2);
      s.at.dw_Ti = s.at.dw_T;
      set.solutions.push_back(s);
    }
  }
  for (const auto& e : zs.solutions) add(map.rates(e.z, true));
  if (separation_undecided &&
      !std::any_of(set.solutions.begin(), set.solutions.end(), [&](const RateSolution3d& x) {
        return std::max(x.at.dP_T.cwiseAbs().maxCoeff(), std::abs(x.at.dP_N)) <= 1e-8 * force;
      })) {
    set.complete = false;
    if (set.message.empty())
      set.message = "the separation's normal rate dw_N is zero within the rounding of the "
                    "stiffness: not decided";
  }
  // A piece of the LCP's set is one physical point when its vertices coincide physically and
  // its rays move nothing physical (the non-unique facet weights of a slip with dP = 0).
  for (const auto& piece : zs.pieces) {
    bool one_point = true;
    for (std::size_t v = 1; v < piece.vertices.size(); ++v)
      one_point = one_point &&
                  rates_distance(map.rates(zs.solutions[piece.vertices[v]].z, true),
                                 map.rates(zs.solutions[piece.vertices[0]].z, true), force,
                                 disp) <= 1e-8;
    for (const auto& ray : piece.rays)
      one_point = one_point && rates_distance(map.rates(ray, false), Rates3d{}, force, disp) <= 1e-8;
    if (!one_point) {
      set.complete = false;
      if (set.message.empty())
        set.message = "the faceted problem has a continuum of physical solutions (a polygon "
                      "face aligned with the load): listed by its extreme points only";
    }
  }
  detail::rescale(set, scaling);
  return set;
}

}  // namespace cpkit::rate
