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

namespace cpkit::rate::detail {
namespace {

/// Coincidence and type tolerance in normalised coordinates (forces / force scale, displacement
/// rates / displacement scale), as the one-point enumeration route's kGeoTol.
constexpr double kGeoTol = 1e-9;
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
};

struct Ctx {
  const SystemRatePrecomputed& pre;
  int N;
  Vec scale;  ///< 6N: the normalisation of every coordinate
};

std::vector<SolutionType> types_at(const Ctx& c, const Vec& y) {
  std::vector<SolutionType> t(static_cast<std::size_t>(c.N));
  for (int i = 0; i < c.N; ++i) {
    const StateLabel l = c.pre.system.points[static_cast<std::size_t>(i)].state.label;
    SolutionType& x = t[static_cast<std::size_t>(i)];
    if (l == StateLabel::kA) { x = SolutionType::kOpen; continue; }
    if (l == StateLabel::kC) { x = SolutionType::kStick; continue; }
    if (l == StateLabel::kB && y(3 * c.N + i) < -kGeoTol) { x = SolutionType::kSeparation; continue; }
    const double xi = y(4 * c.N + i);
    x = xi > kGeoTol ? SolutionType::kSlipPlus
                     : (xi < -kGeoTol ? SolutionType::kSlipMinus : SolutionType::kStick);
  }
  return t;
}
TypeTuple tuple_at(const Ctx& c, const Vec& y) { return encode_types(types_at(c, y)); }

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
void split(const Ctx& c, const Vec& a, const Vec& b, bool ray, std::vector<Geo>& out) {
  std::vector<double> ts;
  for (int r : type_rows(c)) {
    if (!ray) {
      const double f0 = a(r), f1 = b(r);
      if ((f0 < -kGeoTol && f1 > kGeoTol) || (f0 > kGeoTol && f1 < -kGeoTol)) ts.push_back(f0 / (f0 - f1));
    } else {
      const double f0 = a(r), g = b(r);
      if ((f0 < -kGeoTol && g > kGeoTol) || (f0 > kGeoTol && g < -kGeoTol)) ts.push_back(-f0 / g);
    }
  }
  std::sort(ts.begin(), ts.end());
  auto at = [&](double t) -> Vec { return ray ? Vec(a + t * b) : Vec(a + t * (b - a)); };
  std::vector<double> knots{0.0};
  for (double t : ts)
    if (dist(at(t), at(knots.back())) > kGeoTol) knots.push_back(t);
  if (!ray) {
    if (dist(at(1.0), at(knots.back())) > kGeoTol) knots.push_back(1.0);
    else knots.back() = 1.0;
  }
  for (std::size_t k = 0; k < knots.size(); ++k) out.push_back(Geo{Kind::kPoint, at(knots[k]), {}, true, true, tuple_at(c, at(knots[k]))});
  const std::size_t nseg = ray ? knots.size() : knots.size() - 1;
  for (std::size_t k = 0; k < nseg; ++k) {
    const bool last_ray = ray && k + 1 == knots.size();
    const double t0 = knots[k];
    const double t1 = last_ray ? t0 + 1.0 : knots[k + 1];
    const Vec mid = at(0.5 * (t0 + t1));
    Geo g;
    g.type = tuple_at(c, last_ray ? at(t0 + 1.0) : mid);
    g.a = at(t0);
    g.ca = tuple_at(c, g.a) == g.type;
    if (last_ray) {
      g.kind = Kind::kRay;
      g.b = b;
    } else {
      g.kind = Kind::kSegment;
      g.b = at(t1);
      g.cb = tuple_at(c, g.b) == g.type;
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
void merge_pieces(std::vector<Geo>& pcs) {
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
          return d <= kGeoTol;
        }();
        double ta, da;
        on_line(g, h.a, ta, da);
        if (da > kGeoTol || !hb_on_line) continue;
        if (!(on_piece(g, h.a, kGeoTol) || (h.kind != Kind::kRay && on_piece(g, h.b, kGeoTol)) ||
              on_piece(h, g.a, kGeoTol)))
          continue;
        // union on g's line: parameters of all ends
        const Vec dir = g.kind == Kind::kRay ? g.b : Vec(g.b - g.a);
        auto param = [&](const Vec& y) { return (y - g.a).dot(dir) / dir.squaredNorm(); };
        struct End { double t; Vec y; bool closed; };
        std::vector<End> ends{{0.0, g.a, g.ca}, {param(h.a), h.a, h.ca}};
        bool is_ray = false;
        double ray_sign = 0;
        if (g.kind == Kind::kRay) { is_ray = true; ray_sign = 1; } else ends.push_back({1.0, g.b, g.cb});
        if (h.kind == Kind::kRay) {
          const double s = h.b.dot(dir) > 0 ? 1 : -1;
          if (is_ray && s != ray_sign) continue;  // opposite rays: a line, leave both
          is_ray = true;
          ray_sign = s;
        } else {
          ends.push_back({param(h.b), h.b, h.cb});
        }
        std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) { return x.t < y.t; });
        Geo u;
        u.type = g.type;
        if (is_ray) {
          const End& o = ray_sign > 0 ? ends.front() : ends.back();
          u.kind = Kind::kRay;
          u.a = o.y;
          u.ca = o.closed;
          for (const End& e : ends) if (dist(e.y, o.y) <= kGeoTol) u.ca = u.ca || e.closed;
          u.b = g.kind == Kind::kRay ? g.b : h.b;
        } else {
          u.kind = Kind::kSegment;
          u.a = ends.front().y;
          u.b = ends.back().y;
          u.ca = u.cb = false;
          for (const End& e : ends) {
            if (dist(e.y, u.a) <= kGeoTol) u.ca = u.ca || e.closed;
            if (dist(e.y, u.b) <= kGeoTol) u.cb = u.cb || e.closed;
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
  return types_at(c, Vec(stack(r).cwiseQuotient(c.scale)));
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
    bool ok = check(g.a, g.kind == Kind::kPoint ? g.type : tuple_at(c, g.a), dF, sF, sW);
    if (g.kind == Kind::kSegment)
      ok = ok && check(g.b, tuple_at(c, g.b), dF, sF, sW) &&
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

SystemRateSolutionSet enumerate_system(const SystemRatePrecomputed& pre, const Eigen::VectorXd& dF) {
  const int N = pre.system.n_points();
  SystemRateSolutionSet out;
  const Vec base = pre.Pf * dF;
  std::vector<Vec> verts;
  struct ZPiece { std::vector<int> v; std::vector<Vec> rays; };
  std::vector<ZPiece> zp;
  std::ostringstream msg;
  constexpr int kMaxLcp = 24;  // EnumerationOptions::max_size's default
  if (pre.m == 0) {
    verts.push_back(base);
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
    for (const Vec& z : zs) verts.push_back(base + pre.Pz * z);
    for (const auto& p : pieces) {
      ZPiece z;
      z.v = p.first;
      for (const Vec& d : p.second) z.rays.push_back(pre.Pz * d);
      zp.push_back(std::move(z));
    }
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
    for (const auto& s : set.solutions) verts.push_back(base + pre.Pz * s.z);
    for (const auto& p : set.pieces) {
      ZPiece z;
      z.v = p.vertices;
      for (const auto& d : p.rays) z.rays.push_back(pre.Pz * d);
      zp.push_back(std::move(z));
    }
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
  std::vector<Vec> y;
  for (const Vec& v : verts) y.push_back(v.cwiseQuotient(c.scale));
  std::vector<Geo> cand;
  for (const Vec& v : y) cand.push_back(Geo{Kind::kPoint, v, {}, true, true, tuple_at(c, v)});
  for (const ZPiece& p : zp) {
    std::vector<Vec> rays;
    for (const Vec& r : p.rays) {
      const Vec rn = r.cwiseQuotient(c.scale);
      const double n = rn.lpNorm<Eigen::Infinity>();
      if (n > kGeoTol) rays.push_back(rn / n);
    }
    const Vec& y0 = y[static_cast<std::size_t>(p.v.empty() ? 0 : p.v[0])];
    if (p.v.empty()) continue;  // a piece always has a vertex (pointed polyhedron)
    Eigen::MatrixXd D(6 * N, static_cast<Eigen::Index>(p.v.size() - 1 + rays.size()));
    Eigen::Index col = 0;
    for (std::size_t k = 1; k < p.v.size(); ++k) D.col(col++) = y[static_cast<std::size_t>(p.v[k])] - y0;
    for (const Vec& r : rays) D.col(col++) = r;
    if (D.cols() == 0 || D.lpNorm<Eigen::Infinity>() <= kGeoTol) continue;  // one physical point
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(D, Eigen::ComputeThinU);
    const auto sv = svd.singularValues();
    int rank = 0;
    for (Eigen::Index k = 0; k < sv.size(); ++k) rank += sv(k) > 1e-7 * std::max(1.0, sv(0)) ? 1 : 0;
    if (rank == 0) continue;
    if (rank >= 2) {
      out.complete = false;
      out.infinite = true;
      msg << "the solution set has a piece of dimension " << rank
          << " (a face of physical solutions, e.g. two degenerate points): it is not listed; ";
      continue;
    }
    const Vec u = svd.matrixU().col(0);
    double tmin = 0, tmax = 0;
    std::size_t imin = 0, imax = 0;
    for (std::size_t k = 0; k < p.v.size(); ++k) {
      const double t = u.dot(y[static_cast<std::size_t>(p.v[k])] - y0);
      if (t < tmin) { tmin = t; imin = k; }
      if (t > tmax) { tmax = t; imax = k; }
    }
    bool pos = false, neg = false;
    for (const Vec& r : rays) (u.dot(r) > 0 ? pos : neg) = true;
    if (pos && neg) {
      out.complete = false;
      out.infinite = true;
      msg << "the solution set contains a whole line: it is not listed; ";
      continue;
    }
    const Vec& ya = y[static_cast<std::size_t>(p.v[imin])];
    const Vec& yb = y[static_cast<std::size_t>(p.v[imax])];
    if (pos || neg) {
      Vec dir = pos ? u : Vec(-u);
      dir /= dir.lpNorm<Eigen::Infinity>();
      split(c, pos ? ya : yb, dir, true, cand);
    } else {
      split(c, ya, yb, false, cand);
    }
  }
  // assemble: pieces merged, points deduplicated and absorbed by the pieces of their type
  std::vector<Geo> pcs, pts;
  for (Geo& g : cand) (g.kind == Kind::kPoint ? pts : pcs).push_back(std::move(g));
  merge_pieces(pcs);
  std::vector<Geo> kept;
  for (const Geo& p : pts) {
    bool drop = false;
    for (const Geo& k : kept) drop = drop || dist(k.a, p.a) <= kGeoTol;
    for (const Geo& g : pcs) drop = drop || (g.type == p.type && on_piece(g, p.a, kGeoTol));
    if (!drop) kept.push_back(p);
  }
  for (const Geo& g : pcs) kept.push_back(g);
  // rounding noise of exact zeros (e.g. dP_T of a separating point) printed as 0
  auto clean = [](Vec v) {
    for (Eigen::Index k = 0; k < v.size(); ++k)
      if (std::abs(v(k)) <= 1e-3 * kGeoTol) v(k) = 0;
    return v;
  };
  for (Geo& g : kept) {
    g.a = clean(g.a);
    if (g.kind == Kind::kSegment) g.b = clean(g.b);
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
  const double cond = pre.inv_min_eig / pre.inv_max_eig;
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
  const Eigen::VectorXd s = [&] {
    Eigen::VectorXd v(6 * N);
    v.head(2 * N).setConstant(set.force_scale);
    v.tail(4 * N).setConstant(set.disp_scale);
    return v;
  }();
  auto norm = [&](const SystemRates& x) -> Eigen::VectorXd {
    Eigen::VectorXd v(6 * N);
    v << x.dP_T, x.dP_N, x.dw_T, x.dw_N, x.dw_Ti, x.dw_w;
    return v.cwiseQuotient(s);
  };
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
