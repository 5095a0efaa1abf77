// Route 2: the state's LCP (docs/model.md) solved completely by cpkit::lcp::enumerate_small,
// every extreme solution and every piece mapped to physical rates, deduplicated and split by
// type there. [Stromberg et al. 1996, Sec. 4.3]
#include <algorithm>
#include <array>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/rate_problem/analytic.hpp"
#include "cpkit/rate_problem/rate_lcp.hpp"
#include "piece_geometry.hpp"
#include "rate_detail.hpp"

namespace cpkit::rate {
namespace {

constexpr double kEnumTol = 1e-12;  ///< enumerate_small's relative tolerance
constexpr double kGeoTol = 1e-9;    ///< coincidence / type tolerance in the (dP_N, dw_T^i) plane

/// Typed pieces in the (u, v) = (dP_N, dw_T^i) plane.
struct PlaneResult {
  std::array<detail::TypedPiece2, detail::PlaneSet::kCap> pieces;
  int n = 0;
  bool infinite = false;
  bool bad = false;    ///< the geometry was not a union of points, segments and rays
  int ambiguous = 0;   ///< enumerate_small's sign tests too close to call
  int dropped = 0;
};

/// State b: type of the point (u, v) from D0 dw_N = S - (1 + a11 C_T) u - a12 v and v.
struct TypeB {
  double S, c1, a12, S_terms, V;
  SolutionType operator()(detail::P2 x) const noexcept {
    const double g = S - c1 * x.u - a12 * x.v;
    const double gs = S_terms + c1 * std::abs(x.u) + std::abs(a12 * x.v);
    if (g < -kGeoTol * gs) return SolutionType::kSeparation;
    if (x.v > kGeoTol * V) return SolutionType::kSlipPlus;
    if (x.v < -kGeoTol * V) return SolutionType::kSlipMinus;
    return SolutionType::kStick;
  }
};

/// State d: type from the sign of v = dw_T^i = s lambda.
struct TypeD {
  double V;
  SolutionType operator()(detail::P2 x) const noexcept {
    if (x.v > kGeoTol * V) return SolutionType::kSlipPlus;
    if (x.v < -kGeoTol * V) return SolutionType::kSlipMinus;
    return SolutionType::kStick;
  }
};

double load_scale(const LoadRate& f) noexcept {
  const double s = std::abs(f.dF_T) + std::abs(f.dF_N);
  return s > 0 ? s : 1.0;
}

void plane_b(const ContactParameters& p, const LoadRate& f, PlaneResult& res) {
  const StateBLcp l = state_b_lcp(p, f);
  lcp::SmallSolutionSet<3> set;
  lcp::enumerate_small<3>(l.M, l.q, set, kEnumTol);
  res.ambiguous = set.ambiguous;
  res.dropped = set.dropped;
  const double sF = load_scale(f);
  double U = sF, V = sF * (p.C_T + 1.0 / p.a11);
  detail::P2 vert[8];
  for (int k = 0; k < set.num_points; ++k) {
    vert[k] = detail::P2{set.z[k](0), set.z[k](1) - set.z[k](2)};
    U = std::max(U, std::abs(vert[k].u));
    V = std::max(V, std::abs(vert[k].v));
  }
  detail::PlaneSet plane(U, V, kGeoTol);
  for (int k = 0; k < set.num_points; ++k) plane.add_point(vert[k]);
  for (int i = 0; i < set.num_pieces; ++i) {
    const auto& pc = set.pieces[i];
    detail::P2 pv[8], pr[8];
    int nv = 0;
    for (int k = 0; k < set.num_points; ++k)
      if (pc.vertex_mask & (1u << k)) pv[nv++] = vert[k];
    // rays come with ||d||_inf = 1; scale them to the problem's size before judging them zero
    for (int j = 0; j < pc.num_rays; ++j)
      pr[j] = detail::P2{U * pc.rays[j](0), U * (pc.rays[j](1) - pc.rays[j](2)) * (V / U)};
    plane.add_piece(pv, nv, pr, pc.num_rays);
  }
  const double c1 = 1.0 + p.a11 * p.C_T;
  TypeB type{c1 * f.dF_N - p.a12 * p.C_T * f.dF_T, c1, p.a12,
             c1 * std::abs(f.dF_N) + std::abs(p.a12 * p.C_T * f.dF_T), V};
  plane.add_affine(type.S, -c1, -p.a12);
  plane.add_affine(0.0, 0.0, 1.0);
  res.infinite = plane.num_lines() > 0;
  res.n = plane.finish(type, res.pieces);
  res.bad = plane.bad();
}

void plane_d(const ContactParameters& p, const ContactState& st, const LoadRate& f,
             PlaneResult& res) {
  const StateDLcp l = state_d_lcp(p, st, f);
  lcp::SmallSolutionSet<1> set;
  lcp::enumerate_small<1>(Eigen::Matrix<double, 1, 1>(l.M), Eigen::Matrix<double, 1, 1>(l.q), set,
                          kEnumTol);
  res.ambiguous = set.ambiguous;
  res.dropped = set.dropped;
  const int s = st.sgn_PT;
  // u = dP_N is affine in lambda: u = u0 + u1 lambda.
  const double u0 = state_d_rates(p, st, f, 0.0).dP_N;
  const double u1 = state_d_rates(p, st, LoadRate{}, 1.0).dP_N;
  const double sF = load_scale(f);
  double U = sF, V = sF * (p.C_T + 1.0 / p.a11);
  detail::P2 vert[2];
  for (int k = 0; k < set.num_points; ++k) {
    const double lam = set.z[k](0);
    vert[k] = detail::P2{u0 + u1 * lam, s * lam};
    U = std::max(U, std::abs(vert[k].u));
    V = std::max(V, std::abs(vert[k].v));
  }
  detail::PlaneSet plane(U, V, kGeoTol);
  for (int k = 0; k < set.num_points; ++k) plane.add_point(vert[k]);
  for (int i = 0; i < set.num_pieces; ++i) {
    const auto& pc = set.pieces[i];
    detail::P2 pv[2], pr[2];
    int nv = 0;
    for (int k = 0; k < set.num_points; ++k)
      if (pc.vertex_mask & (1u << k)) pv[nv++] = vert[k];
    for (int j = 0; j < pc.num_rays; ++j) {
      const double dl = pc.rays[j](0);
      // scale the unit ray so that its lambda-extent is of the problem's size
      pr[j] = detail::P2{u1 * dl * V, s * dl * V};
    }
    plane.add_piece(pv, nv, pr, pc.num_rays);
  }
  TypeD type{V};
  plane.add_affine(0.0, 0.0, 1.0);
  res.infinite = plane.num_lines() > 0;
  res.n = plane.finish(type, res.pieces);
  res.bad = plane.bad();
}

/// Physical rates of the plane point x (affine) and of a plane direction (linear part).
Rates plane_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                  detail::P2 x) {
  if (st.label == StateLabel::kB) return state_b_rates(p, f, Eigen::Vector3d(x.u, x.v, 0.0));
  return state_d_rates(p, st, f, st.sgn_PT * x.v);
}

}  // namespace

RateSolutionSet solve_rate_enumerate(const ContactParameters& p, const ContactState& st,
                                     const LoadRate& f) {
  detail::validate_inputs(p, st, f);
  detail::PieceList list;
  if (st.label == StateLabel::kA || st.label == StateLabel::kC) {
    RateSolution s;
    s.type = st.label == StateLabel::kA ? SolutionType::kOpen : SolutionType::kStick;
    s.start = detail::linear_state_rates(p, st, f);
    list.push(s);
    return detail::make_solution_set(p, st, f, list, true);
  }
  PlaneResult res;
  if (st.label == StateLabel::kB) plane_b(p, f, res); else plane_d(p, st, f, res);
  for (int i = 0; i < res.n; ++i) {
    const detail::TypedPiece2& t = res.pieces[i];
    RateSolution s;
    s.type = t.type;
    s.kind = t.kind;
    s.start = plane_rates(p, st, f, t.a);
    s.start_closed = t.a_closed;
    if (t.kind == RateSolution::Kind::kSegment) {
      s.end = plane_rates(p, st, f, detail::P2{t.a.u + t.t1 * t.d.u, t.a.v + t.t1 * t.d.v});
      s.end_closed = t.b_closed;
    } else if (t.kind == RateSolution::Kind::kRay) {
      s.direction = plane_rates(p, st, LoadRate{}, t.d);
    }
    list.push(s);
  }
  list.infinite = res.infinite;
  RateSolutionSet out = detail::make_solution_set(p, st, f, list, true);
  if (res.ambiguous > 0 || res.dropped > 0 || res.bad || list.overflow) {
    out.complete = false;
    out.message = "enumeration: " + std::to_string(res.ambiguous) +
                  " sign test(s) too close to call" +
                  (res.bad ? "; unexpected geometry of the solution set" : "") +
                  (res.dropped > 0 ? "; capacity exceeded" : "");
  }
  return out;
}

RateSummary summarize_rate_enumerate(const ContactParameters& p, const ContactState& st,
                                     const LoadRate& f) noexcept {
  RateSummary sum;
  if (st.label == StateLabel::kA || st.label == StateLabel::kC) {
    sum.count = 1;
    sum.types = 1u << static_cast<unsigned>(st.label == StateLabel::kA ? SolutionType::kOpen
                                                                       : SolutionType::kStick);
    return sum;
  }
  PlaneResult res;
  try {
    if (st.label == StateLabel::kB) plane_b(p, f, res); else plane_d(p, st, f, res);
  } catch (...) {  // non-finite data (inputs are documented to be valid)
    sum.reliable = false;
    return sum;
  }
  for (int i = 0; i < res.n; ++i) sum.types |= 1u << static_cast<unsigned>(res.pieces[i].type);
  sum.count = res.infinite ? -1 : res.n;
  sum.reliable = !(res.ambiguous > 0 || res.dropped > 0 || res.bad);
  return sum;
}

}  // namespace cpkit::rate
