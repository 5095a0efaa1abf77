#pragma once
// Internal (route 2): the image of an LCP solution set in the plane of the two coordinates that
// determine the physical rates, (u, v) = (dP_N, dw_T^i), split into typed pieces.
//
// Physical rates are an injective affine function of (u, v) (dP_N = u and dw_T^i = v are two of
// them), so deduplicating and splitting in (u, v) is exactly deduplicating and splitting in
// physical space. Everything here is fixed-size and allocation-free.
#include <array>
#include <cmath>

#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate::detail {

struct P2 {
  double u = 0, v = 0;
};

/// One typed piece in the plane: a point (kind kPoint), a segment [a, a + t1 d] or a ray
/// a + t d, t >= 0, with open/closed ends.
struct TypedPiece2 {
  SolutionType type = SolutionType::kStick;
  RateSolution::Kind kind = RateSolution::Kind::kPoint;
  P2 a, d;
  double t1 = 0;
  bool a_closed = true, b_closed = true;
};

/// Collects vertex images and 1-D pieces, then splits by type. `TypeFn` maps a point to its
/// SolutionType; `U`, `V` are the coordinate scales and `tol` the relative tolerance used to
/// decide that two points coincide or that a point lies on a line.
class PlaneSet {
 public:
  static constexpr int kCap = 16;
  PlaneSet(double U, double V, double tol) noexcept : U_(U), V_(V), tol_(tol) {}

  /// Adds a point (deduplicated).
  void add_point(P2 p) noexcept {
    for (int i = 0; i < np_; ++i)
      if (same(pts_[i], p)) return;
    if (np_ < kCap) pts_[np_++] = p; else bad_ = true;
  }

  /// Adds the image of one polyhedral piece: vertex images `vert` (n of them) and ray images
  /// `ray` (m of them; zero images allowed). Points are added too.
  void add_piece(const P2* vert, int n, const P2* ray, int m) noexcept {
    if (n <= 0) {  // a piece of an LCP lies in the orthant and always has a vertex
      bad_ = true;
      return;
    }
    for (int i = 0; i < n; ++i) add_point(vert[i]);
    int rr = -1;
    for (int j = 0; j < m; ++j)
      if (!is_zero_dir(ray[j])) { rr = j; break; }
    if (rr >= 0) {
      const P2 d = unit(ray[rr]);
      for (int j = 0; j < m; ++j) {
        if (is_zero_dir(ray[j])) continue;
        const P2 e = unit(ray[j]);
        if (std::abs(cross(d, e)) > tol_ || dot(d, e) < 0) bad_ = true;  // 2-D or a line
      }
      // start: the vertex with the smallest projection on d; all vertices on that line.
      int k0 = 0;
      for (int i = 1; i < n; ++i)
        if (dot(vert[i], d) < dot(vert[k0], d)) k0 = i;
      for (int i = 0; i < n; ++i)
        if (std::abs(cross(d, sub(vert[i], vert[k0]))) > tol_) bad_ = true;
      add_line(vert[k0], d, 0.0, true);
      return;
    }
    // bounded: the two vertices farthest apart
    int ia = 0, ib = 0;
    double best = 0;
    for (int i = 0; i < n; ++i)
      for (int k = i + 1; k < n; ++k) {
        const double dd = norm(sub(vert[k], vert[i]));
        if (dd > best) { best = dd; ia = i; ib = k; }
      }
    if (n < 2 || same(vert[ia], vert[ib])) return;  // a point
    const P2 diff = sub(vert[ib], vert[ia]);
    const double len = norm(diff);
    const P2 d{diff.u / len, diff.v / len};
    for (int i = 0; i < n; ++i)
      if (std::abs(cross(d, sub(vert[i], vert[ia]))) > tol_) bad_ = true;
    add_line(vert[ia], d, len, false);
  }

  /// Merges collinear overlapping lines, drops points on lines, splits by type into `out`.
  template <class TypeFn>
  int finish(const TypeFn& type_of, std::array<TypedPiece2, kCap>& out) noexcept {
    merge_lines();
    int n = 0;
    auto emit = [&](const TypedPiece2& p) {
      if (n < kCap) out[n++] = p; else bad_ = true;
    };
    // isolated points: those not on any line
    P2 extra[kCap];
    int nextra = 0;
    for (int i = 0; i < np_; ++i) {
      bool on = false;
      for (int l = 0; l < nl_ && !on; ++l) on = on_line(l, pts_[i]);
      if (!on) {
        if (type_of.undecided(pts_[i])) ++undecided_;
        TypedPiece2 p;
        p.type = type_of(pts_[i]);
        p.a = pts_[i];
        emit(p);
      }
    }
    for (int l = 0; l < nl_; ++l) split_line(l, type_of, emit, extra, nextra);
    // breakpoints that are points of their own type, deduplicated against each other and
    // against closed ends of pieces already emitted
    for (int i = 0; i < nextra; ++i) {
      bool dup = false;
      for (int k = 0; k < n && !dup; ++k) {
        const TypedPiece2& q = out[k];
        if (q.kind == RateSolution::Kind::kPoint) dup = same(q.a, extra[i]);
        else {
          dup = (q.a_closed && same(q.a, extra[i])) ||
                (q.kind == RateSolution::Kind::kSegment && q.b_closed &&
                 same(at(q.a, q.d, q.t1), extra[i]));
        }
      }
      if (!dup) {
        TypedPiece2 p;
        p.type = type_of(extra[i]);
        p.a = extra[i];
        emit(p);
      }
    }
    return n;
  }

  bool bad() const noexcept { return bad_; }
  /// Isolated points whose type the type function could not decide (TypeFn::undecided).
  int undecided() const noexcept { return undecided_; }
  int num_lines() const noexcept { return nl_; }

 private:
  struct Line {
    P2 a, d;      // unit d (scaled coordinates are used only for comparisons)
    double t1;    // segment length (ignored for a ray)
    bool ray;
  };

  // Scaled coordinates: comparisons are made in (u / U, v / V).
  P2 sc(P2 p) const noexcept { return {p.u / U_, p.v / V_}; }
  static P2 sub(P2 a, P2 b) noexcept { return {a.u - b.u, a.v - b.v}; }
  static P2 at(P2 a, P2 d, double t) noexcept { return {a.u + t * d.u, a.v + t * d.v}; }
  double dot(P2 a, P2 b) const noexcept { return a.u * b.u / (U_ * U_) + a.v * b.v / (V_ * V_); }
  double cross(P2 a, P2 b) const noexcept { return (a.u * b.v - a.v * b.u) / (U_ * V_); }
  double norm(P2 a) const noexcept { return std::sqrt(dot(a, a)); }
  P2 unit(P2 a) const noexcept {
    const double n = norm(a);
    return {a.u / n, a.v / n};
  }
  bool same(P2 a, P2 b) const noexcept {
    return std::abs(a.u - b.u) <= tol_ * U_ && std::abs(a.v - b.v) <= tol_ * V_;
  }
  bool is_zero_dir(P2 r) const noexcept {
    // rays come normalised in z (||d||_inf = 1) and the maps have O(1) gains per unit scale
    return std::abs(r.u) <= tol_ * U_ && std::abs(r.v) <= tol_ * V_;
  }

  void add_line(P2 a, P2 d, double t1, bool ray) noexcept {
    if (nl_ < kCap) lines_[nl_++] = Line{a, d, t1, ray}; else bad_ = true;
  }

  /// Parameter of p along line l (in scaled length units).
  double param(int l, P2 p) const noexcept { return dot(sub(p, lines_[l].a), lines_[l].d); }
  bool on_line(int l, P2 p) const noexcept {
    const Line& L = lines_[l];
    const P2 r = sub(p, L.a);
    if (std::abs(cross(L.d, r)) > tol_) return false;
    const double t = dot(r, L.d);
    if (t < -tol_) return false;
    return L.ray || t <= L.t1 + tol_;
  }

  void merge_lines() noexcept {
    bool changed = true;
    while (changed) {
      changed = false;
      for (int i = 0; i < nl_ && !changed; ++i)
        for (int k = i + 1; k < nl_ && !changed; ++k) {
          Line& A = lines_[i];
          const Line& B = lines_[k];
          if (std::abs(cross(A.d, B.d)) > tol_ || std::abs(cross(A.d, sub(B.a, A.a))) > tol_)
            continue;
          // B on A's line: B's parameter interval along A
          const double s0 = param(i, B.a);
          const double dir = dot(B.d, A.d) > 0 ? 1.0 : -1.0;
          double b_lo, b_hi;
          bool b_inf_hi = false, b_inf_lo = false;
          if (B.ray) {
            if (dir > 0) { b_lo = s0; b_hi = 0; b_inf_hi = true; }
            else { b_hi = s0; b_lo = 0; b_inf_lo = true; }
          } else {
            b_lo = std::fmin(s0, s0 + dir * B.t1);
            b_hi = std::fmax(s0, s0 + dir * B.t1);
          }
          if (b_inf_lo) { bad_ = true; continue; }  // opposite rays: a line (never expected)
          const double a_hi = A.ray ? 0 : A.t1;
          const bool a_inf = A.ray;
          // overlap test
          const bool overlap = (a_inf || b_lo <= a_hi + tol_) && (b_inf_hi || b_hi >= -tol_);
          if (!overlap) continue;
          const double lo = std::fmin(0.0, b_lo);
          const P2 na = at(A.a, A.d, lo);
          if (a_inf || b_inf_hi) {
            A = Line{na, A.d, 0.0, true};
          } else {
            A = Line{na, A.d, std::fmax(a_hi, b_hi) - lo, false};
          }
          lines_[k] = lines_[--nl_];
          changed = true;
        }
    }
  }

  template <class TypeFn, class Emit>
  void split_line(int l, const TypeFn& type_of, Emit& emit, P2* extra, int& nextra) noexcept {
    const Line& L = lines_[l];
    // Breakpoints: the ends, every listed point on the line, and the zero crossings of the
    // affine functions whose signs define the type (registered with add_affine). Between two
    // consecutive breakpoints the type is constant; it is sampled at the midpoint.
    double t[kCap + 4];
    int nt = 0;
    t[nt++] = 0;
    if (!L.ray) t[nt++] = L.t1;
    for (int k = 0; k < nf_; ++k) {
      const Affine& f = fn_[k];
      const double slope = f.cu * L.d.u + f.cv * L.d.v;
      const double f0 = f.c0 + f.cu * L.a.u + f.cv * L.a.v;
      if (slope == 0) continue;
      const double s = -f0 / slope;
      if (s > 0 && (L.ray || s < L.t1) && nt < kCap + 3) t[nt++] = s;
    }
    for (int i = 0; i < np_ && nt < kCap + 3; ++i)
      if (on_line(l, pts_[i])) t[nt++] = param(l, pts_[i]);
    // sort and unique
    for (int i = 1; i < nt; ++i)
      for (int k = i; k > 0 && t[k] < t[k - 1]; --k) std::swap(t[k], t[k - 1]);
    int m = 0;
    for (int i = 0; i < nt; ++i)
      if (m == 0 || t[i] - t[m - 1] > tol_) t[m++] = t[i];
    if (!L.ray && m >= 2) t[m - 1] = L.t1;
    // pieces: open intervals (t[i], t[i+1]) (and (t[m-1], inf) for a ray)
    const int nint = L.ray ? m : m - 1;
    int i = 0;
    while (i < nint) {
      const double mid_i = i + 1 < m ? 0.5 * (t[i] + t[i + 1]) : t[i] + 1.0;
      const SolutionType ty = type_of(at(L.a, L.d, mid_i));
      int j = i;  // extend the run while the breakpoint and the next interval have type ty
      while (j + 1 < nint) {
        const double midn = j + 2 < m ? 0.5 * (t[j + 1] + t[j + 2]) : t[j + 1] + 1.0;
        if (type_of(at(L.a, L.d, t[j + 1])) == ty && type_of(at(L.a, L.d, midn)) == ty) ++j;
        else break;
      }
      TypedPiece2 p;
      p.type = ty;
      p.a = at(L.a, L.d, t[i]);
      p.d = L.d;
      p.a_closed = type_of(p.a) == ty;
      if (!p.a_closed && nextra < kCap) extra[nextra++] = p.a;
      if (L.ray && j == nint - 1) {
        p.kind = RateSolution::Kind::kRay;
      } else {
        p.kind = RateSolution::Kind::kSegment;
        p.t1 = t[j + 1] - t[i];
        const P2 b = at(L.a, L.d, t[j + 1]);
        p.b_closed = type_of(b) == ty;
        if (!p.b_closed && nextra < kCap) extra[nextra++] = b;
      }
      emit(p);
      i = j + 1;
    }
    if (nint == 0 && nextra < kCap) extra[nextra++] = L.a;  // degenerate (never expected)
  }

 public:
  /// Registers an affine function c0 + cu u + cv v whose sign enters the type function; its
  /// zero crossings on a line are breakpoints of the split.
  void add_affine(double c0, double cu, double cv) noexcept {
    if (nf_ < 4) fn_[nf_++] = Affine{c0, cu, cv}; else bad_ = true;
  }

 private:
  double U_, V_, tol_;
  std::array<P2, kCap> pts_{};
  int np_ = 0;
  std::array<Line, kCap> lines_{};
  int nl_ = 0;
  struct Affine {
    double c0, cu, cv;
  };
  std::array<Affine, 4> fn_{};
  int nf_ = 0;
  bool bad_ = false;
  int undecided_ = 0;
};

}  // namespace cpkit::rate::detail
