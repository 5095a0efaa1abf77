// Route 2: the state's LCP (docs/model.md) solved completely by cpkit::lcp::enumerate_small,
// every extreme solution and every piece mapped to physical rates, deduplicated and split by
// type there. [Stromberg et al. 1996, Sec. 4.3]
#include <algorithm>
#include <array>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/rate_lcp.hpp"
#include "certified_b.hpp"
#include "exact_signs.hpp"
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
  /// A vertex typed stick with a nonzero v: its slip rate is within the band, not a proved 0
  /// (at a vertex v is either basic, a computed value, or exactly 0).
  bool undecided(detail::P2 x) const noexcept {
    return x.v != 0 && std::abs(x.v) <= kGeoTol * V && !(S - c1 * x.u - a12 * x.v <
                                                          -kGeoTol * (S_terms + c1 * std::abs(x.u) +
                                                                      std::abs(a12 * x.v)));
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
  bool undecided(detail::P2 x) const noexcept { return x.v != 0 && std::abs(x.v) <= kGeoTol * V; }
};

double load_scale(const LoadRate& f) noexcept {
  const double s = std::abs(f.dF_T) + std::abs(f.dF_N);
  return s > 0 ? s : 1.0;
}

/// The (dP_N, dw_T^i) plane set of an enumerated small LCP: `vertex` maps a solution z to its
/// plane point, `ray` a unit ray (with the plane's extents U, V) to a plane direction of the
/// problem's size. The extents start at the load's scales (sU, sV) and grow with the vertices.
template <int N, class Vertex, class Ray>
detail::PlaneSet enumerated_plane(const lcp::SmallSolutionSet<N>& set, double sU, double sV,
                                  Vertex vertex, Ray ray) {
  double U = sU, V = sV;
  detail::P2 vert[lcp::SmallSolutionSet<N>::kMax];
  for (int k = 0; k < set.num_points; ++k) {
    vert[k] = vertex(set.z[k]);
    U = std::max(U, std::abs(vert[k].u));
    V = std::max(V, std::abs(vert[k].v));
  }
  detail::PlaneSet plane(U, V, kGeoTol);
  for (int k = 0; k < set.num_points; ++k) plane.add_point(vert[k]);
  for (int i = 0; i < set.num_pieces; ++i) {
    const auto& pc = set.pieces[i];
    detail::P2 pv[lcp::SmallSolutionSet<N>::kMax], pr[lcp::SmallSolutionSet<N>::kMax];
    int nv = 0;
    for (int k = 0; k < set.num_points; ++k)
      if (pc.vertex_mask & (1u << k)) pv[nv++] = vert[k];
    for (int j = 0; j < pc.num_rays; ++j) pr[j] = ray(pc.rays[j], U, V);
    plane.add_piece(pv, nv, pr, pc.num_rays);
  }
  return plane;
}

/// Registers the slip boundary v = dw_T^i = 0, splits the plane set by `type` into res.pieces
/// and records its verdicts (infinite, bad geometry, undecided types) in res.
template <class Type>
void finish_plane(detail::PlaneSet& plane, const Type& type, PlaneResult& res) {
  plane.add_affine(0.0, 0.0, 1.0);
  res.infinite = plane.num_lines() > 0;
  res.n = plane.finish(type, res.pieces);
  res.bad = plane.bad();
  res.ambiguous += plane.undecided();
}

void plane_b(const ContactParameters& p, const LoadRate& f, PlaneResult& res) {
  const StateBLcp l = state_b_lcp(p, f);
  lcp::SmallSolutionSet<3> set;
  lcp::enumerate_small<3>(l.M, l.q, set, kEnumTol);
  res.ambiguous = set.ambiguous;
  res.dropped = set.dropped;
  const double sF = load_scale(f);
  // V0: the load's own displacement scale. Type decisions use it, not V (which grows with the
  // largest vertex): a separation vertex of 1e11 must not make a slip of 1 look like stick.
  const double V0 = sF * (p.C_T + 1.0 / p.a11);
  detail::PlaneSet plane = enumerated_plane(
      set, sF, V0, [](const Eigen::Vector3d& z) { return detail::P2{z(0), z(1) - z(2)}; },
      // rays come with ||d||_inf = 1; scale them to the problem's size before judging them zero
      [](const Eigen::Vector3d& d, double U, double V) {
        return detail::P2{U * d(0), U * (d(1) - d(2)) * (V / U)};
      });
  const double c1 = 1.0 + p.a11 * p.C_T;
  TypeB type{c1 * f.dF_N - p.a12 * p.C_T * f.dF_T, c1, p.a12,
             c1 * std::abs(f.dF_N) + std::abs(p.a12 * p.C_T * f.dF_T), V0};
  plane.add_affine(type.S, -c1, -p.a12);  // the separation boundary dw_N = 0
  finish_plane(plane, type, res);
}

void plane_d(const ContactParameters& p, const ContactState& st, const LoadRate& f,
             PlaneResult& res) {
  const StateDLcp l = state_d_lcp(p, st, f);
  lcp::SmallSolutionSet<1> set;
  lcp::enumerate_small<1>(Eigen::Matrix<double, 1, 1>(l.M), Eigen::Matrix<double, 1, 1>(l.q), set,
                          kEnumTol);
  res.ambiguous = set.ambiguous + (l.snapped ? 1 : 0);
  res.dropped = set.dropped;
  const int s = st.sgn_PT;
  // u = dP_N is affine in lambda: u = u0 + u1 lambda.
  const double u0 = state_d_rates(p, st, f, 0.0).dP_N;
  const double u1 = state_d_rates(p, st, LoadRate{}, 1.0).dP_N;
  const double sF = load_scale(f);
  const double V0 = sF * (p.C_T + 1.0 / p.a11);  // type scale (see plane_b)
  detail::PlaneSet plane = enumerated_plane(
      set, sF, V0,
      [&](const Eigen::Matrix<double, 1, 1>& z) { return detail::P2{u0 + u1 * z(0), s * z(0)}; },
      // scale the unit ray so that its lambda-extent is of the problem's size
      [&](const Eigen::Matrix<double, 1, 1>& d, double, double V) {
        return detail::P2{u1 * d(0) * V, s * d(0) * V};
      });
  finish_plane(plane, TypeD{V0}, res);
}

/// Physical rates of the plane point x (affine) and of a plane direction (linear part).
Rates plane_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                  detail::P2 x) {
  if (st.label == StateLabel::kB) return state_b_rates(p, f, Eigen::Vector3d(x.u, x.v, 0.0));
  return state_d_rates(p, st, f, st.sgn_PT * x.v);
}

/// Rates of a point of the given type: quantities the type decision judged zero (within the
/// route's tolerance) are set to exact zeros (dw_N off separation in b; dw_T^i, dw_N, dw^w at
/// stick), so that rounding noise of order 1e-17 is not printed as a rate.
Rates typed_rates(const ContactParameters& p, const ContactState& st, const LoadRate& f,
                  detail::P2 x, SolutionType type) {
  Rates r = plane_rates(p, st, f, x);
  if (st.label == StateLabel::kB && type != SolutionType::kSeparation) r.dw_N = 0;
  if (type == SolutionType::kStick) {
    r.dw_T -= r.dw_Ti;
    r.dw_Ti = 0;
    r.dw_N = 0;
    r.dw_w = 0;
  }
  return r;
}

// The certified state-b summary (certified_b.hpp) enumerates the LCP by complementary
// supports, using two facts about this M (docs/contact_model.md, Sec. 5):
//  (i) a solution with l+ > 0 and l- > 0 has w2 = w3 = 0, i.e. dP_T = dP_N = 0 (mu > 0); its
//      physical rates depend on l+ - l- only, so z' = (0, max(xi,0), max(-xi,0)) is a solution
//      with the same rates: supports holding both 2 and 3 add no physical solution;
// (ii) the other principal blocks are M11 = 1 + a11 C_T > 0, M22 = M33 = det A > 0 and the
//      2x2 blocks {1,2}, {1,3} with determinants D0 D_+ and D0 D_-.
// So when D_+ and D_- are clearly nonzero, every solution is the unique basic solution of one
// of the supports {}, {1}, {2}, {3}, {1,2}, {1,3}, and the set is finite;
// near-singular blocks go to the general engine.

/// The summary (count, types) of decided certified points.
RateSummary summary_of(const detail::CertifiedB& c) noexcept {
  RateSummary sum;
  sum.count = c.n;
  for (int k = 0; k < c.n; ++k) sum.types |= 1u << static_cast<unsigned>(c.type[k]);
  sum.reliable = true;
  return sum;
}

/// The summary of state b from the certified support enumeration (certified_b.hpp): every
/// sign judged against its own rounding; false when its structure does not apply (the caller
/// then runs the general engine).
bool summarize_b_certified(const ContactParameters& p, const LoadRate& f,
                           RateSummary& sum) noexcept {
  const detail::CertifiedB c = detail::certified_b<false, false>(p, f);  // types only
  if (!c.applies) return false;
  if (!c.undecided) {
    sum = summary_of(c);
    return true;
  }
  // A sign the data cannot decide (a load on a critical direction, computed in double): the
  // general engine's count is the summary, marked not reliable. Dropping the undecided
  // candidates instead printed count 0 on critical directions, where state b always has a
  // solution [paper, Sec. 4.3].
  sum.reliable = false;
  return false;
}

/// Whether the typed plane pieces are the n certified points of the given types.
bool same_set(const PlaneResult& res, const SolutionType* types, int n) noexcept {
  if (res.infinite || res.bad || res.n != n) return false;
  int count[8] = {};
  for (int i = 0; i < res.n; ++i) {
    if (res.pieces[i].kind != RateSolution::Kind::kPoint) return false;
    ++count[static_cast<unsigned>(res.pieces[i].type)];
  }
  for (int k = 0; k < n; ++k) --count[static_cast<unsigned>(types[k])];
  for (const int x : count)
    if (x != 0) return false;
  return true;
}

/// State d's solution points decided by the exact signs of L_s and Lambda (exact_signs.hpp;
/// the 1x1 LCP has q = -L_s and M of the sign of Lambda, docs/model.md): stick iff L_s <= 0,
/// slip iff Lambda != 0 and lambda = L_s / Lambda > 0. `decided` is false when a sign is out
/// of the exact range or Lambda = L_s = 0 (the ray: the general engine's geometry).
struct CertifiedD {
  bool decided = false;
  int n = 0;
  SolutionType type[2] = {};
  double lambda[2] = {};
};

CertifiedD certified_d(const ContactParameters& p, const ContactState& st,
                       const LoadRate& f) noexcept {
  CertifiedD c;
  const int sL = detail::exact_sign_L(p, st, f, st.sgn_PT);
  const int sLam = detail::exact_sign_Lambda(p, st);
  if (sL == detail::kUndecided || sLam == detail::kUndecided || (sL == 0 && sLam == 0)) return c;
  c.decided = true;
  if (sL <= 0) c.type[c.n++] = SolutionType::kStick;
  if (sLam != 0 && sL == sLam) {
    // lambda = -q / M of the unsnapped LCP (state_d_lcp's q and M before its band)
    const double c1 = 1.0 + p.a11 * p.C_T;
    const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * p.kappa(st.P_N) : p.mu;
    const Rates r0 = state_d_rates(p, st, f, 0.0), r1 = state_d_rates(p, st, LoadRate{}, 1.0);
    const double q = c1 * (m * r0.dP_N - st.sgn_PT * r0.dP_T);
    const double M = c1 * (m * r1.dP_N - st.sgn_PT * r1.dP_T);
    c.lambda[c.n] = M != 0 && -q / M > 0 ? -q / M : 0.0;
    c.type[c.n++] = st.sgn_PT > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
  }
  return c;
}

/// State d's 1x1 LCP enumerated inline for the summary: support {} (lambda = 0, stick) is a
/// solution iff q >= 0; support {1} (lambda = -q/M) iff M != 0 and -q/M > 0; M = q = 0 makes
/// every lambda >= 0 a solution (the ray). M and q arrive snapped (state_d_lcp).
RateSummary summarize_d_core(const ContactState& st, const StateDLcp& l) noexcept {
  const unsigned stick = 1u << static_cast<unsigned>(SolutionType::kStick);
  const unsigned slip = 1u << static_cast<unsigned>(st.sgn_PT > 0 ? SolutionType::kSlipPlus
                                                                   : SolutionType::kSlipMinus);
  RateSummary sum;
  sum.reliable = !l.snapped;
  if (l.M == 0) {
    if (l.q == 0) {
      sum.count = -1;
      sum.types = stick | slip;
    } else if (l.q > 0) {
      sum.count = 1;
      sum.types = stick;
    }
    return sum;
  }
  if (l.q >= 0) {
    sum.count = 1;
    sum.types = stick;
  }
  const double lambda = -l.q / l.M;
  if (lambda > 0) {  // distinct from lambda = 0 (q != 0 here since lambda > 0)
    ++sum.count;
    sum.types |= slip;
  }
  return sum;
}

RateSummary summarize_d_fast(const ContactParameters& p, const ContactState& st,
                             const LoadRate& f) noexcept {
  const StateDLcp l = state_d_lcp(p, st, f);
  return summarize_d_core(st, l);
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
    // an open end is a point of another type: its rates are not snapped
    s.start = t.a_closed ? typed_rates(p, st, f, t.a, t.type) : plane_rates(p, st, f, t.a);
    s.start_closed = t.a_closed;
    if (t.kind == RateSolution::Kind::kSegment) {
      const detail::P2 b{t.a.u + t.t1 * t.d.u, t.a.v + t.t1 * t.d.v};
      s.end = t.b_closed ? typed_rates(p, st, f, b, t.type) : plane_rates(p, st, f, b);
      s.end_closed = t.b_closed;
    } else if (t.kind == RateSolution::Kind::kRay) {
      s.direction = plane_rates(p, st, LoadRate{}, t.d);
    }
    list.push(s);
  }
  list.infinite = res.infinite;
  bool certified = false;
  if (st.label == StateLabel::kB) {
    // the tolerance-based set is checked against the certified support enumeration: a sign
    // the data do not decide -> not complete; a different set -> the certified one (issue 24)
    const detail::CertifiedB c = detail::certified_b(p, f);
    if (c.applies && c.undecided) {
      RateSolutionSet out = detail::make_solution_set(p, st, f, list, false);
      out.message = "enumeration: a sign within the rounding error of the data";
      return out;
    }
    if (c.applies && !same_set(res, c.type, c.n)) {
      detail::PieceList cl;
      for (int k = 0; k < c.n; ++k) {
        RateSolution s;
        s.type = c.type[k];
        s.start = typed_rates(p, st, f, detail::P2{c.u[k], c.xi[k]}, c.type[k]);
        cl.push(s);
      }
      return detail::make_solution_set(p, st, f, cl, true);
    }
    certified = c.applies;  // the same set, every sign of it decided
  }
  if (st.label == StateLabel::kD) {
    // the tolerance-based set (q snapped within 1e-10 of its terms) is checked against the
    // exact signs: a load ON a critical direction is decided, a different set -> the exact one
    const CertifiedD c = certified_d(p, st, f);
    if (c.decided && !same_set(res, c.type, c.n)) {
      const double u0 = state_d_rates(p, st, f, 0.0).dP_N;
      const double u1 = state_d_rates(p, st, LoadRate{}, 1.0).dP_N;
      detail::PieceList cl;
      for (int k = 0; k < c.n; ++k) {
        RateSolution s;
        s.type = c.type[k];
        s.start = typed_rates(p, st, f, detail::P2{u0 + u1 * c.lambda[k], st.sgn_PT * c.lambda[k]},
                              c.type[k]);
        cl.push(s);
      }
      return detail::make_solution_set(p, st, f, cl, true);
    }
    certified = c.decided;  // the same set, every sign of it decided
  }
  if (certified) res.ambiguous = 0;
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

namespace detail {

bool enumeration_certified(const ContactParameters& p, const ContactState& st,
                           const LoadRate& f) noexcept {
  if (st.label == StateLabel::kA || st.label == StateLabel::kC) return true;
  if (st.label == StateLabel::kD) return certified_d(p, st, f).decided;
  const CertifiedB c = certified_b(p, f);
  return c.applies && !c.undecided;
}

}  // namespace detail

RateSummary summarize_rate_enumerate(const ContactParameters& p, const ContactState& st,
                                     const LoadRate& f) noexcept {
  RateSummary sum;
  if (st.label == StateLabel::kA || st.label == StateLabel::kC) {
    sum.count = 1;
    sum.types = 1u << static_cast<unsigned>(st.label == StateLabel::kA ? SolutionType::kOpen
                                                                       : SolutionType::kStick);
    return sum;
  }
  if (st.label == StateLabel::kB && summarize_b_certified(p, f, sum)) return sum;
  const bool certified_undecided = !sum.reliable;  // state b: a sign the data do not decide
  if (st.label == StateLabel::kD) return summarize_d_fast(p, st, f);
  PlaneResult res;
  try {
    if (st.label == StateLabel::kB) plane_b(p, f, res); else plane_d(p, st, f, res);
  } catch (...) {  // non-finite data (inputs are documented to be valid)
    sum.reliable = false;
    return sum;
  }
  for (int i = 0; i < res.n; ++i) sum.types |= 1u << static_cast<unsigned>(res.pieces[i].type);
  sum.count = res.infinite ? -1 : res.n;
  sum.reliable = !(certified_undecided || res.ambiguous > 0 || res.dropped > 0 || res.bad);
  return sum;
}

RatePrecomputed precompute_rate_problem(const ContactParameters& params,
                                        const ContactState& state) {
  detail::validate_inputs(params, state, LoadRate{});
  RatePrecomputed pre;
  pre.params = params;
  pre.state = state;
  // the LCP data in the normalised units of the summaries (rate_detail.hpp: normalise)
  ContactParameters pn;
  LoadRate unused;
  int eA = 0, eF = 0;
  detail::normalise(params, LoadRate{}, pn, unused, eA, eF);
  pre.params_n = pn;
  if (state.label == StateLabel::kB) {
    pre.b_terms = detail::b_terms<detail::Mag>(pn);
  } else if (state.label == StateLabel::kD) {
    const StateDLcp l0 = state_d_lcp(pn, state, LoadRate{});  // M: load-independent
    pre.M_d = l0.M;
    pre.d_snapped = l0.snapped;
    const Rates rT = state_d_rates(pn, state, LoadRate{1.0, 0.0}, 0.0);
    const Rates rN = state_d_rates(pn, state, LoadRate{0.0, 1.0}, 0.0);
    pre.dPN_T = rT.dP_N;
    pre.dPN_N = rN.dP_N;
    pre.dPT_T = rT.dP_T;
    pre.dPT_N = rN.dP_T;
  }
  return pre;
}

RateSummary summarize_rate_problem(const RatePrecomputed& pre, const LoadRate& load,
                                   RateMethod method) noexcept {
  const ContactState& st = pre.state;
  if (method != RateMethod::kEnumerate) return summarize_rate_problem(pre.params, st, load, method);
  // judged in normalised units, as the terms were precomputed (exact powers of two)
  LoadRate f;
  int eF = 0;
  detail::normalise_load(load, f, eF);
  const ContactParameters& pn = pre.params_n;
  RateSummary sum;
  if (st.label == StateLabel::kB) {
    // the load-independent terms were formed once (precompute_rate_problem): only the
    // load's five products per cell; undecided here -> the full certified pass below
    const detail::CertifiedB c = detail::certified_b_with<detail::Mag, false>(pre.b_terms, pn, f);
    if (c.applies && !c.undecided) return summary_of(c);
    if (summarize_b_certified(pn, f, sum)) return sum;
  }
  if (st.label == StateLabel::kD) {
    // q = (1 + a11 C_T)(mu_eff dP_N - s dP_T) at lambda = 0, snapped as in state_d_lcp
    const double c1 = 1.0 + pn.a11 * pn.C_T;
    const double m =
        pn.criterion == Criterion::kSoftening ? pn.mu - 2.0 * pn.kappa(st.P_N) : pn.mu;
    const double dPN = pre.dPN_T * f.dF_T + pre.dPN_N * f.dF_N;
    const double dPT = pre.dPT_T * f.dF_T + pre.dPT_N * f.dF_N;
    StateDLcp l;
    l.M = pre.M_d;
    l.q = c1 * (m * dPN - st.sgn_PT * dPT);
    if (std::abs(l.q) <= 1e-10 * c1 * (std::abs(m * dPN) + std::abs(dPT))) {
      l.snapped = l.q != 0;
      l.q = 0;
    }
    l.snapped = l.snapped || pre.d_snapped;
    return summarize_d_core(st, l);
  }
  return summarize_rate_problem(pre.params, st, load, method);
}

}  // namespace cpkit::rate
