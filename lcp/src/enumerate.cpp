#include "cpkit/lcp/enumerate.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/residuals.hpp"
#include "enumerate_detail.hpp"
#include "rounding_ties.hpp"
#include "cpkit/lcp/enumerate_small.hpp"

namespace cpkit::lcp {

std::string EnumerationOptions::validate() const {
  if (!(tol > 0 && tol <= 1e-3))
    return "EnumerationOptions::tol must lie in (0, 1e-3], got " + std::to_string(tol);
  if (max_size < 1 || max_size > kMaxEnumerationSize)
    return "EnumerationOptions::max_size must lie in [1, " + std::to_string(kMaxEnumerationSize) +
           "], got " + std::to_string(max_size);
  if (!(time_limit_s > 0)) return "EnumerationOptions::time_limit_s must be > 0";
  if (max_piece_dim < 1 || max_piece_dim > 8)
    return "EnumerationOptions::max_piece_dim must lie in [1, 8], got " +
           std::to_string(max_piece_dim);
  return {};
}

namespace {

using detail::basis_of;
using detail::Deadline;
using detail::finite;
using detail::indices_of;
using detail::kGray;
using detail::Structured;

/// Directions of the pieces: rays, and vertex-pair differences (deduplicated, ||d||_inf = 1;
/// two directions are the same when they differ by <= 1e4 tol, relative to ||d|| = 1).
/// False when the deadline stopped it (the list is then partial).
bool fill_directions(SolutionSet& out, Deadline& deadline) {
  const double same = kGray * out.tol;
  auto add = [&](Vec d) {
    const double big = d.cwiseAbs().maxCoeff();
    if (!(big > 0) || !finite(big)) return;
    d /= big;
    for (const Vec& e : out.directions)
      if ((e - d).cwiseAbs().maxCoeff() <= same || (e + d).cwiseAbs().maxCoeff() <= same) return;
    out.directions.push_back(d);
  };
  for (const SolutionPiece& p : out.pieces) {
    for (const Vec& r : p.rays) add(r);
    for (size_t a = 0; a < p.vertices.size(); ++a) {
      if (deadline.passed()) return false;
      for (size_t b = a + 1; b < p.vertices.size(); ++b)
        add(out.solutions[p.vertices[b]].z - out.solutions[p.vertices[a]].z);
    }
  }
  return true;
}

template <int N>
void run_small(SolutionSet& out) {
  const Eigen::Matrix<double, N, N> M = out.M;
  const Eigen::Matrix<double, N, 1> q = out.q;
  SmallSolutionSet<N> s;
  enumerate_small<N>(M, q, s, out.tol);
  for (int k = 0; k < s.num_points; ++k) {
    ExtremeSolution e;
    e.z = s.z[k];
    e.w = s.w[k];
    e.basis = basis_of(s.support[k], N);
    out.solutions.push_back(std::move(e));
  }
  for (int k = 0; k < s.num_pieces; ++k) {
    SolutionPiece p;
    p.support = indices_of(s.pieces[k].support, N);
    for (int v = 0; v < s.num_points; ++v)
      if ((s.pieces[k].vertex_mask >> v) & 1u) p.vertices.push_back(v);
    for (int r = 0; r < s.pieces[k].num_rays; ++r) p.rays.push_back(s.pieces[k].rays[r]);
    out.pieces.push_back(std::move(p));
  }
  out.infinite = s.infinite;
  out.ambiguous = s.ambiguous;
  out.unrepresentable = s.unrepresentable;
  out.complete = s.dropped == 0 && s.ambiguous == 0;  // an ambiguous candidate was left out
  if (s.ambiguous > 0)
    out.message = std::to_string(s.ambiguous) +
                  " candidate(s) with a sign test too close to call: not listed";
  if (s.dropped > s.unrepresentable)
    out.message = "fixed-size capacity exceeded (" + std::to_string(s.dropped - s.unrepresentable) +
                  " dropped)";
}

}  // namespace

bool SolutionSet::contains(const Vec& z, double ctol) const {
  const Eigen::Index n = q.size();
  if (z.size() != n || !z.allFinite()) return false;
  // The acceptance test's own units (residuals.hpp): a point finalize() accepts at tolerance
  // ctol is judged here by the same numbers, whatever the problem's units.
  Vec w;
  const UnitFreePoint u = unit_free_point(LcpProblem(M, q), z, w);
  if (!u.finite) return false;
  for (Eigen::Index i = 0; i < n; ++i)
    if (u.to_lower[i] < -ctol || u.w[i] < -ctol) return false;
  const double zn = n ? z.cwiseAbs().maxCoeff() : 0.0;
  for (const ExtremeSolution& e : solutions)
    if (n == 0 || (e.z - z).cwiseAbs().maxCoeff() <=
                      ctol * std::max(zn, e.z.cwiseAbs().maxCoeff()))
      return true;
  // Row i "free in z" must have w_i ~ 0, otherwise z_i ~ 0: the complementarity pattern of a
  // listed basis or piece, met within ctol in the test's units.
  auto fits = [&](auto z_free) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (z_free(i) ? !(std::abs(u.w[i]) <= ctol) : !(std::abs(u.z[i]) <= ctol)) return false;
    return true;
  };
  for (const ExtremeSolution& e : solutions)
    if (static_cast<Eigen::Index>(e.basis.size()) == n &&
        fits([&](Eigen::Index i) { return e.basis[static_cast<size_t>(i)] >= 0; }))
      return true;
  for (const SolutionPiece& p : pieces) {
    std::vector<char> in(static_cast<size_t>(n), 0);
    for (int i : p.support) in[static_cast<size_t>(i)] = 1;
    if (fits([&](Eigen::Index i) { return in[static_cast<size_t>(i)] != 0; })) return true;
  }
  return false;
}

namespace {

/// Power-of-two scale 2^e with x / 2^e in [0.5, 1) (e = 0 for x = 0).
int scale_exponent(double x) {
  if (!(x > 0)) return 0;
  int e = 0;
  std::frexp(x, &e);
  return e;
}

/// Powers of two that put the data in one unit per row, per column and for q: M~_ij =
/// M_ij 2^-(r_i + c_j) (every row, then every column, of largest entry in [0.5, 1)), q~_i =
/// q_i 2^-(r_i + e) (largest in [0.5, 1)). LCP(M~, q~) has the solutions z~_j = z_j 2^(c_j - e),
/// w~_i = w_i 2^-(r_i + e): the same problem with each z_j and each w_i in its own unit.
struct Equilibration {
  std::vector<int> r, c;
  int e = 0;
  bool exact = true;  // false: an entry would lose bits (subnormal); the data are used as given
};

Equilibration equilibrate(const Mat& M, const Vec& q, Mat& Mn, Vec& qn) {
  const Eigen::Index n = q.size();
  Equilibration s;
  s.r.assign(size_t(n), 0);
  s.c.assign(size_t(n), 0);
  Mn = M;
  qn = q;
  auto scale = [&](double& x, int e) {
    const double y = std::ldexp(x, -e);
    s.exact = s.exact && std::ldexp(y, e) == x;
    x = y;
  };
  for (Eigen::Index i = 0; i < n; ++i) {
    s.r[size_t(i)] = scale_exponent(Mn.row(i).cwiseAbs().maxCoeff());
    for (Eigen::Index j = 0; j < n; ++j) scale(Mn(i, j), s.r[size_t(i)]);
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    s.c[size_t(j)] = scale_exponent(Mn.col(j).cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < n; ++i) scale(Mn(i, j), s.c[size_t(j)]);
  }
  // q_i 2^-(r_i + e) in one step (q_i 2^-r_i alone may overflow): e from the exponents
  bool any = false;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (q(i) == 0) continue;
    const int x = scale_exponent(std::abs(q(i))) - s.r[size_t(i)];
    s.e = any ? std::max(s.e, x) : x;
    any = true;
  }
  for (Eigen::Index i = 0; i < n; ++i) scale(qn(i), s.r[size_t(i)] + s.e);
  if (!s.exact) {
    Mn = M;
    qn = q;
    std::fill(s.r.begin(), s.r.end(), 0);
    std::fill(s.c.begin(), s.c.end(), 0);
    s.e = 0;
  }
  return s;
}

/// The final check of every listed solution against the original data (M, q), with the
/// unit-free componentwise test: z finite and >= 0, w = M z + q finite; with
/// W_i = |q_i| + sum_j |M_ij z_j|, every listed w_i = 0 has |w_i| <= 1e4 tol W_i and every
/// other w_i > 0 agrees with the data to 1e4 tol W_i, and z_i w_i = 0 as listed. Solutions
/// that fail (values double cannot represent, e.g. z = 1e320 after scaling back) are removed.
/// Returns the number removed.
int recheck(SolutionSet& out) {
  const Mat& M = out.M;
  const Vec& q = out.q;
  const int n = static_cast<int>(q.size());
  const double band = kGray * out.tol;
  std::vector<int> new_index(out.solutions.size(), -1);
  std::vector<ExtremeSolution> kept;
  for (size_t p = 0; p < out.solutions.size(); ++p) {
    const ExtremeSolution& e = out.solutions[p];
    bool ok = e.z.allFinite() && e.w.allFinite() && (n == 0 || e.z.minCoeff() >= 0);
    for (int i = 0; i < n && ok; ++i) {
      double v = q(i), sc = std::abs(q(i));
      for (int j = 0; j < n; ++j) {
        v += M(i, j) * e.z(j);
        sc += std::abs(M(i, j) * e.z(j));
      }
      ok = finite(v) && finite(sc) && (e.z(i) == 0 || e.w(i) == 0);
      if (!ok) break;
      ok = e.w(i) == 0 ? std::abs(v) <= band * sc
                       : e.w(i) > 0 && std::abs(v - e.w(i)) <= band * sc;
    }
    if (!ok) continue;
    new_index[p] = static_cast<int>(kept.size());
    kept.push_back(e);
  }
  const int removed = static_cast<int>(out.solutions.size() - kept.size());
  if (removed == 0) return 0;
  out.solutions = std::move(kept);
  for (SolutionPiece& pc : out.pieces) {
    std::vector<int> v;
    for (int k : pc.vertices)
      if (new_index[k] >= 0) v.push_back(new_index[k]);
    pc.vertices = std::move(v);
  }
  return removed;
}

}  // namespace

SolutionSet enumerate_all(const LcpProblem& problem, const EnumerationOptions& options) {
  throw_if_invalid(problem.validate(), "enumerate_all");
  throw_if_invalid(options.validate(), "enumerate_all");
  const Eigen::Index n = problem.size();
  Stopwatch clock;
  Deadline deadline(options.time_limit_s);
  SolutionSet out;
  out.M = problem.dense_M();
  out.q = problem.q;
  out.tol = options.tol;
  if (n == 0) {
    out.complete = true;
    out.solutions.push_back({Vec(), Vec(), {}});
    out.seconds = clock.seconds();
    return out;
  }
  // Every decision is made on the equilibrated data (equilibrate(): each row w_i, each z_j and
  // q in a unit of their own, by powers of two): the same problem in other units (q -> a q,
  // (M, q) -> b (M, q), any row or column scaling) then takes the same decisions, bit for bit
  // when the factors are powers of two. With only one scale for M and one for q, a problem
  // whose rows were in units 1e-10..1e10 of each other (a bimatrix game, each w_i in its own
  // unit) lost solutions in the search and said complete (issue 24, item 7 class). The results
  // are scaled back exactly unless they overflow or underflow, which the final check catches.
  SolutionSet work;
  work.tol = options.tol;
  const Equilibration eq = equilibrate(out.M, out.q, work.M, work.q);
  const bool exact = eq.exact;
  switch (n) {
    case 1: run_small<1>(work); break;
    case 2: run_small<2>(work); break;
    case 3: run_small<3>(work); break;
    case 4: run_small<4>(work); break;
    default: {
      if (options.use_structure &&
          detail::try_bipartite(options, work, deadline) != Structured::kUndecided)
        break;
      if (n > options.max_size) {  // beyond the general engine's supports: say so, not throw
        work.complete = false;
        work.message = "n = " + std::to_string(n) + " exceeds the general engine's limit " +
                       std::to_string(options.max_size) +
                       " (max_size, the CLI's --max-size, at most " +
                       std::to_string(kMaxEnumerationSize) +
                       "); only bimatrix games (block-bipartite LCPs) are enumerated beyond it";
        break;
      }
      detail::run_engine(options, work, deadline, exact);
    }
  }
  out.solutions = std::move(work.solutions);
  out.pieces = std::move(work.pieces);
  out.complete = work.complete;
  out.infinite = work.infinite;
  out.ambiguous = work.ambiguous;
  out.unrepresentable = work.unrepresentable;
  out.nodes = work.nodes;
  // a candidate whose sign test was too close to call was left out: the list may lack it
  // (issue 24: the DART 12-D LCP printed ambiguous: 1 with complete: true)
  if (work.ambiguous > 0) {
    out.complete = false;
    const std::string msg = std::to_string(work.ambiguous) +
                            " candidate(s) with a sign test too close to call: not listed";
    work.message = work.message.empty() ? msg : work.message + "; " + msg;
  }
  out.leaves = work.leaves;
  out.structured = work.structured;
  out.message = work.message;
  for (ExtremeSolution& e : out.solutions) {
    for (Eigen::Index j = 0; j < n; ++j) {
      e.z(j) = std::ldexp(e.z(j), eq.e - eq.c[size_t(j)]);
      e.w(j) = std::ldexp(e.w(j), eq.e + eq.r[size_t(j)]);
    }
  }
  for (SolutionPiece& pc : out.pieces)
    for (Vec& d : pc.rays) {  // directions of z: per column, then ||d||_inf = 1 again
      for (Eigen::Index j = 0; j < n; ++j) d(j) = std::ldexp(d(j), -eq.c[size_t(j)]);
      const double big = d.cwiseAbs().maxCoeff();
      if (big > 0 && std::isfinite(big)) d /= big;
    }
  out.unrepresentable += recheck(out);
  if (out.unrepresentable > 0) {
    out.complete = false;
    const std::string msg = std::to_string(out.unrepresentable) +
                            " candidate(s) not representable in double precision (a value of z or "
                            "w = M z + q overflows or underflows, e.g. z = 1e320): not listed";
    out.message = out.message.empty() ? msg : out.message + "; " + msg;
  }
  if (!fill_directions(out, deadline)) out.complete = false;
  if (deadline.hit()) {
    out.complete = false;
    if (out.message.find("time limit") == std::string::npos) {
      const std::string msg = "time limit of " + std::to_string(options.time_limit_s) +
                              " s reached (the lists may be partial)";
      out.message = out.message.empty() ? msg : out.message + "; " + msg;
    }
  }
  out.seconds = clock.seconds();
  return out;
}

}  // namespace cpkit::lcp
