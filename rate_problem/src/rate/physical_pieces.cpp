// From the LCP solution set of the N-point rate problem to physical pieces: every extreme
// solution and every LCP piece mapped to physical rates, pieces of dimension >= 2 reported as
// such (complete = false), segments and rays split where a point's type changes, and the result
// deduplicated in physical space (distinct z can give one physical solution, docs/model of one
// point: every b-point solution with dP_N = 0 is a whole ray of z).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "physical_pieces.hpp"
#include "rate_laws_check.hpp"
#include "rounded.hpp"

namespace cpkit::rate::detail {
namespace {

/// Type tolerance in normalised coordinates (forces / force scale, displacement rates /
/// displacement scale) of classify_system_rates only, which has no error bounds (a single
/// solution of an iterative LCP solver); enumerate_system decides every sign and coincidence
/// against the rounding bound of its own values (RoundBound below).
constexpr double kGeoTol = 1e-9;
/// Rounding of one coordinate of the physical rates y = Pf dF + Pz z, relative to the size of its
/// terms (|Pf| |dF| + |Pz| |z|): the data Pf, Pz, M, q are formed from A by eliminations
/// (Schur complements) whose rounding grows with cond(A), and z is a solve of a block of M (at
/// most a few dozen operations, blocks closer to singular than 1e-8 of their terms are left
/// to the enumeration's ambiguous count). Bound: kRoundUnits ulps x cond(A) x the terms. An
/// estimate, not a proof (cond(A) bounds the growth of the eliminations, not every path of the
/// enumeration), but unit-free and from the data: a sign, a knot or a coincidence inside it is
/// not decided (the set is then not complete), outside it the data decide.
constexpr double kRoundUnits = 256;
/// Largest cond(A) (2-norm) for which the enumeration is called complete (measured: a seeded
/// sweep of 2- and 3-point systems against a long-double brute force is right up to 1e9).
constexpr double kMaxProvedCond = 1e8;

using Vec = Eigen::VectorXd;
using Kind = RateSolution::Kind;

struct Geo {
  Kind kind = Kind::kPoint;
  Vec a, b;  ///< point / segment ends / ray origin and unit direction (b)
  bool ca = true, cb = true;
  TypeTuple type = 0;
  Vec ea, eb;  ///< rounding bounds of a and b (coordinate-wise)
  Vec raw;     ///< a as computed, before rounding noise is printed as 0 (the sign tests' value)
};

struct Ctx {
  const SystemRatePrecomputed& pre;
  int N;
  Vec scale;  ///< 6N: the normalisation of every coordinate
  /// merges and knots: two normalised points are one when they differ by at most `tol` (the
  /// largest rounding bound of the listed values; kGeoTol for classify_system_rates)
  double tol = kGeoTol;
};

/// A normalised point with the rounding bound of each coordinate (same units).
struct Bounded {
  Vec y, e;
};

/// The types at y, a coordinate's sign judged against its bound e (a value within it is zero:
/// a stick's dw_T^i and dw_N are zero by structure, computed as rounding noise).
std::vector<SolutionType> types_at(const Ctx& c, const Vec& y, const Vec& e) {
  std::vector<SolutionType> t(static_cast<std::size_t>(c.N));
  for (int i = 0; i < c.N; ++i) {
    const StateLabel l = c.pre.system.points[static_cast<std::size_t>(i)].state.label;
    SolutionType& x = t[static_cast<std::size_t>(i)];
    if (l == StateLabel::kA) { x = SolutionType::kOpen; continue; }
    if (l == StateLabel::kC) { x = SolutionType::kStick; continue; }
    const int n = 3 * c.N + i, s = 4 * c.N + i;
    if (l == StateLabel::kB && y(n) < -e(n)) { x = SolutionType::kSeparation; continue; }
    const double xi = y(s);
    x = xi > e(s) ? SolutionType::kSlipPlus
                  : (xi < -e(s) ? SolutionType::kSlipMinus : SolutionType::kStick);
  }
  return t;
}
TypeTuple tuple_at(const Ctx& c, const Bounded& b) { return encode_types(types_at(c, b.y, b.e)); }

/// m <= 4: the fixed-size enumeration (the path enumerate_all takes for these sizes, without
/// its copies and allocations). Fills the extreme solutions and the pieces.
template <int K>
void small_lcp(const SystemRatePrecomputed& pre, const Vec& q, std::vector<Vec>& zs,
               std::vector<std::pair<std::vector<int>, std::vector<Vec>>>& pieces, int& ambiguous,
               int& dropped) {
  const Eigen::Matrix<double, K, K> M = pre.M;
  const Eigen::Matrix<double, K, 1> qq = q;
  lcp::SmallSolutionSet<K> set;
  lcp::enumerate_small<K>(M, qq, set, 1e-12);
  ambiguous = set.ambiguous;
  dropped = set.dropped;
  for (int k = 0; k < set.num_points; ++k) zs.push_back(set.z[static_cast<std::size_t>(k)]);
  for (int i = 0; i < set.num_pieces; ++i) {
    const auto& pc = set.pieces[static_cast<std::size_t>(i)];
    std::pair<std::vector<int>, std::vector<Vec>> p;
    for (int k = 0; k < set.num_points; ++k)
      if (pc.vertex_mask & (1u << k)) p.first.push_back(k);
    for (int r = 0; r < pc.num_rays; ++r) p.second.push_back(pc.rays[static_cast<std::size_t>(r)]);
    pieces.push_back(std::move(p));
  }
}

/// Rows whose sign decides a type: dw_N of b points, dw_T^i of b and d points.
std::vector<int> type_rows(const Ctx& c) {
  std::vector<int> r;
  for (int i = 0; i < c.N; ++i) {
    const StateLabel l = c.pre.system.points[static_cast<std::size_t>(i)].state.label;
    if (l == StateLabel::kB) r.push_back(3 * c.N + i);
    if (l == StateLabel::kB || l == StateLabel::kD) r.push_back(4 * c.N + i);
  }
  return r;
}

double dist(const Vec& a, const Vec& b) { return (a - b).lpNorm<Eigen::Infinity>(); }

/// Splits the segment a-b (ray: a + t b, t >= 0, when `ray`) where a type changes; every end
/// of a sub-piece is also emitted as a point (absorbed later when its type is the piece's).
/// A type changes inside only where a row's sign is decided at both ends (or at the origin and
/// along the direction) and differs: a row within its bound at an end changes type there.
void split(const Ctx& c, const Bounded& a, const Bounded& b, bool ray, std::vector<Geo>& out) {
  std::vector<double> ts;
  for (int r : type_rows(c)) {
    const double f0 = a.y(r), f1 = b.y(r), e0 = a.e(r), e1 = b.e(r);
    const bool change = (f0 < -e0 && f1 > e1) || (f0 > e0 && f1 < -e1);
    if (change) ts.push_back(ray ? -f0 / f1 : f0 / (f0 - f1));
  }
  std::sort(ts.begin(), ts.end());
  auto at = [&](double t) -> Bounded {
    if (ray) return {Vec(a.y + t * b.y), Vec(a.e + t * b.e)};
    return {Vec(a.y + t * (b.y - a.y)), Vec((1 - t) * a.e + t * b.e)};
  };
  std::vector<double> knots{0.0};
  for (double t : ts)
    if (dist(at(t).y, at(knots.back()).y) > c.tol) knots.push_back(t);
  if (!ray) {
    if (dist(at(1.0).y, at(knots.back()).y) > c.tol) knots.push_back(1.0);
    else knots.back() = 1.0;
  }
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const Bounded p = at(knots[k]);
    out.push_back(Geo{Kind::kPoint, p.y, {}, true, true, tuple_at(c, p), p.e, {}, {}});
  }
  const std::size_t nseg = ray ? knots.size() : knots.size() - 1;
  for (std::size_t k = 0; k < nseg; ++k) {
    const bool last_ray = ray && k + 1 == knots.size();
    const double t0 = knots[k];
    const double t1 = last_ray ? t0 + 1.0 : knots[k + 1];
    Geo g;
    g.type = tuple_at(c, last_ray ? at(t0 + 1.0) : at(0.5 * (t0 + t1)));
    const Bounded p0 = at(t0);
    g.a = p0.y;
    g.ea = p0.e;
    g.ca = tuple_at(c, p0) == g.type;
    if (last_ray) {
      g.kind = Kind::kRay;
      g.b = b.y;
      g.eb = b.e;
    } else {
      const Bounded p1 = at(t1);
      g.kind = Kind::kSegment;
      g.b = p1.y;
      g.eb = p1.e;
      g.cb = tuple_at(c, p1) == g.type;
    }
    out.push_back(std::move(g));
  }
}

/// Parameter of y on the line of g (segment: 0..1 between the ends; ray: along the unit
/// direction) and its distance from the line.
void on_line(const Geo& g, const Vec& y, double& t, double& d) {
  const Vec dir = g.kind == Kind::kRay ? g.b : Vec(g.b - g.a);
  const double dd = dir.squaredNorm();
  t = dd > 0 ? (y - g.a).dot(dir) / dd : 0.0;
  d = dist(y, g.a + t * dir);
}

/// Is y on the closed hull of the piece g (ends included whatever their closedness)?
bool on_piece(const Geo& g, const Vec& y, double tol) {
  if (g.kind == Kind::kPoint) return dist(g.a, y) <= tol;
  double t, d;
  on_line(g, y, t, d);
  if (d > tol) return false;
  const double len = g.kind == Kind::kRay ? 1.0 : dist(g.a, g.b);
  const double slack = len > 0 ? tol / len : 0.0;
  return t >= -slack && (g.kind == Kind::kRay || t <= 1 + slack);
}

/// Merges collinear overlapping segments/rays of one type tuple; drops duplicates.
void merge_pieces(std::vector<Geo>& pcs, double tol) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < pcs.size() && !changed; ++i) {
      for (std::size_t j = 0; j < pcs.size() && !changed; ++j) {
        if (i == j || pcs[i].type != pcs[j].type) continue;
        Geo& g = pcs[i];
        const Geo& h = pcs[j];
        // h within the line of g and overlapping it
        const bool hb_on_line = [&] {
          double t, d;
          if (h.kind == Kind::kRay) {
            on_line(g, h.a + h.b, t, d);
          } else {
            on_line(g, h.b, t, d);
          }
          return d <= tol;
        }();
        double ta, da;
        on_line(g, h.a, ta, da);
        if (da > tol || !hb_on_line) continue;
        if (!(on_piece(g, h.a, tol) || (h.kind != Kind::kRay && on_piece(g, h.b, tol)) ||
              on_piece(h, g.a, tol)))
          continue;
        // union on g's line: parameters of all ends
        const Vec dir = g.kind == Kind::kRay ? g.b : Vec(g.b - g.a);
        auto param = [&](const Vec& y) { return (y - g.a).dot(dir) / dir.squaredNorm(); };
        struct End { double t; Vec y; bool closed; Vec e; };
        std::vector<End> ends{{0.0, g.a, g.ca, g.ea}, {param(h.a), h.a, h.ca, h.ea}};
        bool is_ray = false;
        double ray_sign = 0;
        if (g.kind == Kind::kRay) { is_ray = true; ray_sign = 1; } else ends.push_back({1.0, g.b, g.cb, g.eb});
        if (h.kind == Kind::kRay) {
          const double s = h.b.dot(dir) > 0 ? 1 : -1;
          if (is_ray && s != ray_sign) continue;  // opposite rays: a line, leave both
          is_ray = true;
          ray_sign = s;
        } else {
          ends.push_back({param(h.b), h.b, h.cb, h.eb});
        }
        std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) { return x.t < y.t; });
        Geo u;
        u.type = g.type;
        if (is_ray) {
          const End& o = ray_sign > 0 ? ends.front() : ends.back();
          u.kind = Kind::kRay;
          u.a = o.y;
          u.ca = o.closed;
          u.ea = o.e;
          for (const End& e : ends) if (dist(e.y, o.y) <= tol) u.ca = u.ca || e.closed;
          u.b = g.kind == Kind::kRay ? g.b : h.b;
          u.eb = g.kind == Kind::kRay ? g.eb : h.eb;
        } else {
          u.kind = Kind::kSegment;
          u.a = ends.front().y;
          u.b = ends.back().y;
          u.ea = ends.front().e;
          u.eb = ends.back().e;
          u.ca = u.cb = false;
          for (const End& e : ends) {
            if (dist(e.y, u.a) <= tol) u.ca = u.ca || e.closed;
            if (dist(e.y, u.b) <= tol) u.cb = u.cb || e.closed;
          }
        }
        pcs[i] = u;
        pcs.erase(pcs.begin() + static_cast<std::ptrdiff_t>(j));
        changed = true;
      }
    }
  }
}

}  // namespace

SystemRates to_rates(const SystemRatePrecomputed& pre, const Eigen::VectorXd& x) {
  const int N = pre.system.n_points();
  SystemRates r;
  r.dP_T = x.segment(0, N);
  r.dP_N = x.segment(N, N);
  r.dw_T = x.segment(2 * N, N);
  r.dw_N = x.segment(3 * N, N);
  r.dw_Ti = x.segment(4 * N, N);
  r.dw_w = x.segment(5 * N, N);
  return r;
}

namespace {
Vec stack(const SystemRates& r) {
  const Eigen::Index N = r.dP_T.size();
  Vec x(6 * N);
  x << r.dP_T, r.dP_N, r.dw_T, r.dw_N, r.dw_Ti, r.dw_w;
  return x;
}
Vec scale_vector(int N, double sF, double sW) {
  Vec s(6 * N);
  s.head(2 * N).setConstant(sF);
  s.tail(4 * N).setConstant(sW);
  return s;
}
}  // namespace

std::vector<SolutionType> classify_system_rates(const SystemRatePrecomputed& pre,
                                                const SystemRates& r, double force_scale,
                                                double disp_scale) {
  const int N = pre.system.n_points();
  Ctx c{pre, N, scale_vector(N, force_scale, disp_scale)};
  return types_at(c, Vec(stack(r).cwiseQuotient(c.scale)), Vec::Constant(6 * N, kGeoTol));
}

/// Is the isolated point g admissible for its type? Every inequality of its points' laws
/// (dP_N >= 0, |dP_T| <= mu dP_N, s dw_T^i >= 0, dw_N <= 0 of a separation, the state-d
/// cone) is judged against the rounding bound of its value: 1 all decided true, 0 one decided
/// false, kUndecided when one lies within its bound (a knife edge: a critical load).
int admissible(const Ctx& c, const Geo& g) {
  const int N = c.N;
  const std::vector<SolutionType> t = decode_types(g.type, N);
  int verdict = 1;
  // v >= 0 with bound e
  // structural: v is one coordinate, or a combination of coordinates that are all exactly 0.0;
  // its exact 0.0 then comes from a zero z entry or load (the inequality holds with equality),
  // while a 0.0 by cancellation of nonzero terms (mu dP_N = |dP_T| to the last bit) is not
  // decided
  auto ge0 = [&](double v, double e, bool structural = true) {
    const int s = v == 0 && structural ? 0 : sign3(Rounded{v, e});
    if (s == -1) verdict = 0;
    else if (s == kUndecided && verdict == 1) verdict = kUndecided;
  };
  const Vec& y = g.raw;
  const Vec& e = g.ea;
  const double u = 0x1p-52;
  for (int i = 0; i < N; ++i) {
    const SystemPoint& P = c.pre.system.points[static_cast<std::size_t>(i)];
    const int iT = i, iN = N + i, iwN = 3 * N + i, iTi = 4 * N + i;
    const SolutionType ti = t[static_cast<std::size_t>(i)];
    const double s = ti == SolutionType::kSlipPlus ? 1.0 : -1.0;
    // forces are normalised by one scale: mu dP_N - |dP_T| is a unit-free combination
    auto cone = [&](double m, double sg) {
      const double v = m * y(iN) - sg * y(iT);
      ge0(v, std::abs(m) * e(iN) + e(iT) + 4 * u * (std::abs(m * y(iN)) + std::abs(y(iT))),
          y(iN) == 0 && y(iT) == 0);
    };
    if (P.state.label == StateLabel::kB) {
      if (ti == SolutionType::kSeparation) {
        ge0(-y(iwN), e(iwN));
      } else {
        ge0(y(iN), e(iN));
        // no force rate and dw_N = 0 only within its rounding: contact or separation is not
        // decided (an exact 0.0 of dP_N is the vertex's, not the data's)
        if (std::abs(y(iN)) <= e(iN) && y(iwN) != 0 && std::abs(y(iwN)) <= e(iwN) &&
            verdict == 1)
          verdict = kUndecided;
        if (ti == SolutionType::kStick) {
          cone(P.mu, y(iT) >= 0 ? 1.0 : -1.0);
        } else {
          ge0(s * y(iTi), e(iTi));
        }
      }
    } else if (P.state.label == StateLabel::kD) {
      const double sg = P.state.sgn_PT;
      if (ti == SolutionType::kStick) {
        const ContactParameters par = c.pre.system.point_parameters(i);
        const double kappa = par.kappa(P.state.P_N);
        cone(c.pre.system.criterion == Criterion::kSoftening ? P.mu - 2.0 * kappa : P.mu, sg);
      } else {
        ge0(sg * y(iTi), e(iTi));
      }
    }
  }
  return verdict;
}

/// Keeps the pieces whose points (every point, the ends and the middle of a segment, a ray's
/// start, a point along it and its direction) satisfy the rate laws from the data
/// (rate_laws_check.hpp); returns how many were dropped and the worst violation seen.
int keep_verified(const SystemRatePrecomputed& pre, const Ctx& c, const Vec& dF, double sF,
                  double sW, std::vector<Geo>& kept, double& worst) {
  const int N = pre.system.n_points();
  int rejected = 0;
  std::vector<Geo> verified;
  const Vec zero = Vec::Zero(dF.size());
  auto phys = [&](const Vec& yy) { return Vec(yy.cwiseProduct(c.scale)); };
  auto check = [&](const Vec& yy, TypeTuple t, const Vec& load, double f, double w) {
    const double v = rate_laws_violation(pre.system, load, phys(yy), decode_types(t, N), f, w);
    worst = std::max(worst, v);
    return v <= kRateLawTol;
  };
  for (Geo& g : kept) {
    bool ok = check(g.a, g.kind == Kind::kPoint ? g.type : tuple_at(c, {g.a, g.ea}), dF, sF, sW);
    if (g.kind == Kind::kSegment)
      ok = ok && check(g.b, tuple_at(c, {g.b, g.eb}), dF, sF, sW) &&
           check(Vec(0.5 * (g.a + g.b)), g.type, dF, sF, sW);
    if (g.kind == Kind::kRay) {
      const Vec d = phys(g.b);
      const double fd = d.head(2 * N).lpNorm<Eigen::Infinity>(),
                   wd = d.tail(4 * N).lpNorm<Eigen::Infinity>();
      ok = ok && check(Vec(g.a + g.b), g.type, dF, sF, sW) &&
           check(g.b, g.type, zero, fd > 0 ? fd : 1.0, wd > 0 ? wd : 1.0);
    }
    if (ok) verified.push_back(std::move(g));
    else ++rejected;
  }
  kept = std::move(verified);
  return rejected;
}

namespace {

/// |P| |x| (the sizes of the terms of P x) without a temporary |P|: called per map cell.
Vec term_sizes(const Eigen::MatrixXd& P, const Eigen::Ref<const Vec>& x) {
  Vec t = Vec::Zero(P.rows());
  for (Eigen::Index k = 0; k < P.cols(); ++k) {
    const double a = std::abs(x(k));
    if (a != 0)
      for (Eigen::Index r = 0; r < P.rows(); ++r) t(r) += std::abs(P(r, k)) * a;
  }
  return t;
}

/// An LCP piece: its vertices (indices) and its rays mapped to physical rates, with the sizes
/// of their terms (|Pz| |d|).
struct ZPiece {
  std::vector<int> v;
  std::vector<Vec> rays, mag;
};
template <class Rays>
ZPiece z_piece(const SystemRatePrecomputed& pre, const std::vector<int>& v, const Rays& rays) {
  ZPiece z;
  z.v = v;
  for (const auto& d : rays) {
    z.rays.push_back(pre.Pz * d);
    z.mag.push_back(term_sizes(pre.Pz, d));
  }
  return z;
}

/// The physical pieces of one LCP piece: a segment or a ray (split by type), a face of
/// dimension >= 2 or a whole line (reported, not listed: out.complete = false), or nothing
/// new (one physical point). kr: the relative rounding bound (kRoundUnits ulps x cond(A)).
void piece_to_geo(const Ctx& c, double kr, const std::vector<Bounded>& y, const ZPiece& p,
                  std::vector<Geo>& cand, SystemRateSolutionSet& out, std::ostringstream& msg) {
  const int N = c.N;
  if (p.v.empty()) return;  // a piece always has a vertex (pointed polyhedron)
  std::vector<Bounded> rays;
  for (std::size_t k = 0; k < p.rays.size(); ++k) {
    const Vec rn = p.rays[k].cwiseQuotient(c.scale);
    const Vec en = kRoundUnits * 0x1p-52 * p.mag[k].cwiseQuotient(c.scale);
    const double n = rn.lpNorm<Eigen::Infinity>();
    // a z-direction whose physical image is rounding (a b point's z1 = z2 ray) adds no point
    if (n > en.maxCoeff() + kr * n) rays.push_back({rn / n, Vec((en / n).array() + kr)});
  }
  const Vec& y0 = y[static_cast<std::size_t>(p.v[0])].y;
  Eigen::MatrixXd D(6 * N, static_cast<Eigen::Index>(p.v.size() - 1 + rays.size()));
  Eigen::Index col = 0;
  for (std::size_t k = 1; k < p.v.size(); ++k) D.col(col++) = y[static_cast<std::size_t>(p.v[k])].y - y0;
  for (const Bounded& r : rays) D.col(col++) = r.y;
  if (D.cols() == 0 || D.lpNorm<Eigen::Infinity>() <= c.tol) return;  // one physical point
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(D, Eigen::ComputeThinU);
  const auto sv = svd.singularValues();
  // rank: singular values above 1e-7 of the largest; between that and the rounding of D's
  // entries the dimension is not decided by the data
  const double noise = std::max(c.tol, kr) * std::sqrt(static_cast<double>(D.rows() * D.cols()));
  int rank = 0;
  bool gray = false;
  for (Eigen::Index k = 0; k < sv.size(); ++k) {
    const bool big = sv(k) > 1e-7 * std::max(1.0, sv(0));
    rank += big ? 1 : 0;
    gray = gray || (!big && sv(k) > noise);
  }
  if (gray) {
    out.complete = false;
    msg << "the dimension of a piece of the solution set is within its rounding: not proved; ";
  }
  if (rank == 0) return;
  if (rank >= 2) {
    out.complete = false;
    out.infinite = true;
    msg << "the solution set has a piece of dimension " << rank
        << " (a face of physical solutions, e.g. two degenerate points): it is not listed; ";
    return;
  }
  const Vec u = svd.matrixU().col(0);
  double tmin = 0, tmax = 0;
  std::size_t imin = 0, imax = 0;
  for (std::size_t k = 0; k < p.v.size(); ++k) {
    const double t = u.dot(y[static_cast<std::size_t>(p.v[k])].y - y0);
    if (t < tmin) { tmin = t; imin = k; }
    if (t > tmax) { tmax = t; imax = k; }
  }
  bool pos = false, neg = false;
  Vec edir = Vec::Constant(6 * N, kr);
  for (const Bounded& r : rays) {
    (u.dot(r.y) > 0 ? pos : neg) = true;
    edir = edir.cwiseMax(r.e);
  }
  if (pos && neg) {
    out.complete = false;
    out.infinite = true;
    msg << "the solution set contains a whole line: it is not listed; ";
    return;
  }
  const Bounded& ya = y[static_cast<std::size_t>(p.v[imin])];
  const Bounded& yb = y[static_cast<std::size_t>(p.v[imax])];
  if (pos || neg) {
    Vec dir = pos ? u : Vec(-u);
    dir /= dir.lpNorm<Eigen::Infinity>();
    split(c, pos ? ya : yb, Bounded{dir, edir}, true, cand);
  } else {
    split(c, ya, yb, false, cand);
  }
}

/// Pieces merged, points deduplicated and absorbed by the pieces of their type. Two points of
/// different type tuples within the merge tolerance are one point to the rounding but not to the
/// data (a critical load: a stick and a slip one ulp apart): counted in `unsure`.
std::vector<Geo> assemble(const Ctx& c, std::vector<Geo>& cand, int& unsure) {
  std::vector<Geo> pcs, pts;
  for (Geo& g : cand) (g.kind == Kind::kPoint ? pts : pcs).push_back(std::move(g));
  merge_pieces(pcs, c.tol);
  std::vector<Geo> kept;
  for (const Geo& p : pts) {
    bool drop = false;
    for (const Geo& k : kept) {
      const bool same = dist(k.a, p.a) <= c.tol;
      drop = drop || same;
      unsure += same && k.type != p.type ? 1 : 0;
    }
    for (const Geo& g : pcs) drop = drop || (g.type == p.type && on_piece(g, p.a, c.tol));
    if (!drop) kept.push_back(p);
  }
  for (const Geo& g : pcs) kept.push_back(g);
  return kept;
}

}  // namespace

SystemRateSolutionSet enumerate_system(const SystemRatePrecomputed& pre, const Eigen::VectorXd& dF,
                                       bool on_critical) {
  const int N = pre.system.n_points();
  SystemRateSolutionSet out;
  const Vec base = pre.Pf * dF;
  const Vec base_mag = term_sizes(pre.Pf, dF);
  std::vector<Vec> verts, vmag;  // vertices and the sizes of their terms
  std::vector<ZPiece> zp;
  std::ostringstream msg;
  constexpr int kMaxLcp = 24;  // EnumerationOptions::max_size's default
  if (pre.m == 0) {
    verts.push_back(base);
    vmag.push_back(base_mag);
  } else if (pre.m > kMaxLcp) {
    out.complete = false;
    msg << "the rate LCP has size " << pre.m << " (3 per point in state b, 1 per point in state d), "
        << "beyond the complete enumeration's limit " << kMaxLcp << ": nothing is listed; ";
  } else if (pre.m <= 4) {
    const Vec q = system_q(pre, dF);
    std::vector<Vec> zs;
    std::vector<std::pair<std::vector<int>, std::vector<Vec>>> pieces;
    int ambiguous = 0, dropped = 0;
    switch (pre.m) {
      case 1: small_lcp<1>(pre, q, zs, pieces, ambiguous, dropped); break;
      case 2: small_lcp<2>(pre, q, zs, pieces, ambiguous, dropped); break;
      case 3: small_lcp<3>(pre, q, zs, pieces, ambiguous, dropped); break;
      default: small_lcp<4>(pre, q, zs, pieces, ambiguous, dropped); break;
    }
    if (ambiguous > 0) {
      out.complete = false;
      msg << ambiguous << " sign tests of the enumeration were too close to call; ";
    }
    if (dropped > 0) {
      out.complete = false;
      msg << dropped << " candidates of the enumeration could not be represented; ";
    }
    for (const Vec& z : zs) {
      verts.push_back(base + pre.Pz * z);
      vmag.push_back(base_mag + term_sizes(pre.Pz, z));
    }
    for (const auto& p : pieces) zp.push_back(z_piece(pre, p.first, p.second));
  } else {
    lcp::EnumerationOptions opt;
    opt.time_limit_s = 30;
    opt.max_size = kMaxLcp;
    const lcp::SolutionSet set = lcp::enumerate_all(LcpProblem(pre.M, system_q(pre, dF)), opt);
    if (!set.complete) {
      out.complete = false;
      msg << "the enumeration is incomplete: " << set.message << "; ";
    }
    if (set.ambiguous > 0) {
      out.complete = false;
      msg << set.ambiguous << " sign tests of the enumeration were too close to call; ";
    }
    for (const auto& s : set.solutions) {
      verts.push_back(base + pre.Pz * s.z);
      vmag.push_back(base_mag + term_sizes(pre.Pz, s.z));
    }
    for (const auto& p : set.pieces) zp.push_back(z_piece(pre, p.vertices, p.rays));
  }
  // scales: the load, the stiffness, and the solutions' own magnitudes
  double sF = dF.lpNorm<1>();
  for (const Vec& v : verts) sF = std::max(sF, v.head(2 * N).lpNorm<Eigen::Infinity>());
  if (!(sF > 0)) sF = 1;
  // The floor of the displacement scale is the stiff compliance 1/max eig(A): with the soft one
  // (1/min eig) an ill-conditioned A makes every real slip rate of a stiff direction look like
  // rounding (a slip listed as stick at cond(A) = 1e9); the solutions' own sizes come on top.
  double sW = sF * (pre.max_C_T + pre.inv_max_eig);
  for (const Vec& v : verts) sW = std::max(sW, v.tail(4 * N).lpNorm<Eigen::Infinity>());
  out.force_scale = sF;
  out.disp_scale = sW;
  Ctx c{pre, N, scale_vector(N, sF, sW)};
  const double cond = pre.inv_min_eig / pre.inv_max_eig;
  const double kr = kRoundUnits * 0x1p-52 * std::max(1.0, cond);
  std::vector<Bounded> y;
  c.tol = 0;
  for (std::size_t k = 0; k < verts.size(); ++k) {
    Bounded b{verts[k].cwiseQuotient(c.scale), {}};
    b.e = (kRoundUnits * 0x1p-52 * vmag[k].cwiseQuotient(c.scale)).array() +
          kr * b.y.lpNorm<Eigen::Infinity>();
    c.tol = std::max(c.tol, std::min(b.e.maxCoeff(), kGeoTol));
    y.push_back(std::move(b));
  }
  std::vector<Geo> cand;
  for (const Bounded& v : y) cand.push_back(Geo{Kind::kPoint, v.y, {}, true, true, tuple_at(c, v), v.e, {}, {}});
  for (const ZPiece& p : zp) piece_to_geo(c, kr, y, p, cand, out, msg);
  int unsure = 0;
  std::vector<Geo> kept = assemble(c, cand, unsure);
  if (unsure > 0 && !on_critical) {
    out.complete = false;
    msg << unsure << " pair(s) of candidate points of different types coincide within their "
        << "rounding (a critical load): merged, the set is not proved; ";
  }
  // rounding noise of exact zeros (e.g. dP_T of a separating point) printed as 0
  auto clean = [](Vec v, const Vec& e) {
    for (Eigen::Index k = 0; k < v.size(); ++k)
      if (std::abs(v(k)) <= e(k)) v(k) = 0;
    return v;
  };
  for (Geo& g : kept) {
    g.raw = g.a;
    g.a = clean(g.a, g.ea);
    if (g.kind == Kind::kSegment) g.b = clean(g.b, g.eb);
  }
  // Every listed point, every end (and the inside) of a segment and every ray must satisfy the
  // rate laws from the data (rate_laws_check.hpp): what the LCP route cannot vouch for (e.g. a
  // vertex from a numerically singular basis, a direction that is not a null vector of the
  // true problem) is not listed, and the answer is then not complete.
  double worst = 0;
  const int rejected = keep_verified(pre, c, dF, sF, sW, kept, worst);
  if (rejected > 0) {
    out.complete = false;
    msg << rejected << " candidate piece(s) of the LCP route violate the rate laws (unit-free "
        << "violation up to " << worst << " > " << kRateLawTol
        << ": an ill-conditioned or degenerate case): not listed; ";
  }
  // Every isolated point's inequalities judged against their rounding: a point on a knife
  // edge (one ulp past a critical load the data may exclude it) is listed, but the set is not
  // proved; one the data exclude is not listed (issue 24).
  int undecided = 0, excluded = 0;
  for (std::size_t k = 0; k < kept.size();) {
    // the end of a listed piece has an active inequality by construction (the piece ends there)
    bool end = false;
    for (const Geo& g : kept) end = end || (g.kind != Kind::kPoint && on_piece(g, kept[k].a, c.tol));
    const int a = kept[k].kind == Kind::kPoint && !end ? admissible(c, kept[k]) : 1;
    undecided += a == kUndecided && !on_critical ? 1 : 0;
    if (a == 0) {
      ++excluded;
      kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(k));
    } else {
      ++k;
    }
  }
  if (undecided > 0) {
    out.complete = false;
    msg << undecided << " listed point(s) satisfy an inequality of their type only within its "
        << "rounding (a critical load): the set is not proved; ";
  }
  if (excluded > 0) {
    out.complete = false;
    msg << excluded << " candidate point(s) of the LCP route violate an inequality of their type "
        << "beyond its rounding: not listed; ";
  }
  for (const Geo& g : kept) {
    SystemRateSolution s;
    s.types = decode_types(g.type, N);
    s.kind = g.kind;
    s.start = to_rates(pre, g.a.cwiseProduct(c.scale));
    s.start_closed = g.ca;
    if (g.kind == Kind::kSegment) {
      s.end = to_rates(pre, g.b.cwiseProduct(c.scale));
      s.end_closed = g.cb;
    } else if (g.kind == Kind::kRay) {
      Vec d = g.b.cwiseProduct(c.scale);
      const double f = d.head(2 * N).lpNorm<Eigen::Infinity>();
      d /= f > 0 ? f : d.lpNorm<Eigen::Infinity>();
      s.direction = to_rates(pre, d);
    }
    if (g.kind != Kind::kPoint) out.infinite = true;
    out.solutions.push_back(std::move(s));
  }
  // Beyond cond(A) = 1e8 the reduced LCP's data (Schur complements of A) carry rounding errors
  // that can hide a solution (a full separation missed at cond 1e10, found by a long-double
  // brute force): what is listed is verified above, but the list is not proved complete.
  if (!(cond <= kMaxProvedCond)) {
    out.complete = false;
    msg << "A is ill-conditioned (cond(A) = " << cond << " > " << kMaxProvedCond
        << "): the listed solutions are verified, but the list is not proved complete; ";
  }
  out.message = msg.str();
  if (out.message.size() >= 2) out.message.resize(out.message.size() - 2);
  return out;
}

}  // namespace cpkit::rate::detail

namespace cpkit::rate {

bool contains(const SystemRateSolutionSet& set, const SystemRates& r, double rel_tol) {
  const Eigen::Index N = r.dP_T.size();
  const Eigen::VectorXd s = detail::scale_vector(static_cast<int>(N), set.force_scale, set.disp_scale);
  auto norm = [&](const SystemRates& x) -> Eigen::VectorXd { return detail::stack(x).cwiseQuotient(s); };
  if (set.solutions.empty() || set.solutions.front().start.dP_T.size() != N) return false;
  const Eigen::VectorXd y = norm(r);
  const double tol = rel_tol * std::max(1.0, y.lpNorm<Eigen::Infinity>());
  for (const auto& p : set.solutions) {
    const Eigen::VectorXd a = norm(p.start);
    Eigen::VectorXd d = Eigen::VectorXd::Zero(6 * N);
    if (p.kind == RateSolution::Kind::kSegment) d = norm(p.end) - a;
    if (p.kind == RateSolution::Kind::kRay) d = norm(p.direction);
    double t = 0;
    const double dd = d.squaredNorm();
    if (dd > 0) {
      t = std::max(0.0, (y - a).dot(d) / dd);
      if (p.kind == RateSolution::Kind::kSegment) t = std::min(t, 1.0);
    }
    if ((y - a - t * d).lpNorm<Eigen::Infinity>() <= tol) return true;
  }
  return false;
}

}  // namespace cpkit::rate
