// enumerate_small<N> and SmallPreparedLcp<N> (cpkit/lcp/enumerate_small.hpp,
// cpkit/lcp/enumerate_small_prepared.hpp), compiled once for the sizes N = 1, 2, 3, 4 (explicit
// instantiations at the end; the headers declare them extern). Both run the one kernel of
// small_enumerator.hpp; the prepared variant differs only in how a basic solution is obtained
// (the elimination recorded in the constructor, replayed on q).
#include "cpkit/lcp/enumerate_small.hpp"

#include "cpkit/lcp/enumerate_small_prepared.hpp"
#include "small_enumerator.hpp"

namespace cpkit::lcp {

namespace {

/// Everything of support S that depends on M only (the data of SmallPreparedSupport): the
/// decisions and values of SmallEnumerator::run / singular_piece that do not involve q. Kept
/// out of line (as it was as a member): inlined into the constructor's loop it is slower.
template <int N>
CPKIT_SMALL_NOINLINE void prepare_support(const Eigen::Matrix<double, N, N>& M, double tol,
                                          unsigned S, detail::SmallPreparedSupport<N>& s) {
  using detail::small_abs;
  using detail::small_max;
  constexpr unsigned kAll = (1u << N) - 1;
  s.k = 0;
  for (int j = 0; j < N; ++j)
    if (S & (1u << j)) s.idx[s.k++] = j;
  const int k = s.k;
  if (k == 0) { s.kind = 0; return; }
  if (k <= 3) {
    double det, perm;
    detail::small_det(M, s.idx, s.idx, k, det, perm);
    if (detail::small_det_ok(det, perm, tol)) {
      s.kind = 1;
      s.det = det;
      s.inv = 1.0 / det;
      return;
    }
  }
  s.kind = 2;
  const int* idx = s.idx;
  double a[4][5] = {};
  double amax = 0;
  for (int r = 0; r < k; ++r)
    for (int c = 0; c < k; ++c) {
      a[r][c] = M(idx[r], idx[c]);
      amax = small_max(amax, small_abs(a[r][c]));
    }
  bool gray = false;
  const int r = detail::small_eliminate(a, k, k, s.el.perm, tol * amax, gray, &s.el);
  s.pre_ambiguous = gray ? 1 : 0;
  s.r = r;
  const int m = k - r;
  s.m = m;
  detail::small_null_basis<N>(s.el.a, r, k, s.el.perm, idx, s.nb);
  // z0 is linear in q: its operator P is the recorded elimination applied to -e_i
  for (int ii = 0; ii < N; ++ii) {
    double rhs[4] = {};
    for (int c = 0; c < k; ++c) rhs[c] = idx[c] == ii ? -1.0 : 0.0;
    detail::small_replay_rhs(s.el, k, rhs);
    double x[4] = {};
    detail::small_back_substitute(s.el.a, r, s.el.perm, [&](int p) { return rhs[p]; }, x);
    for (int c = 0; c < k; ++c) s.P[idx[c]][ii] = x[c];
  }
  for (int j = 0; j < N; ++j) {
    for (int f = 0; f < m; ++f) s.overflow = s.overflow || !detail::small_finite(s.nb[f][j]);
    for (int i = 0; i < N; ++i) s.overflow = s.overflow || !detail::small_finite(s.P[j][i]);
  }
  if (s.overflow) return;
  if (!detail::small_constraint_dirs<N>(M, S, s.nb, m, tol, s.A)) { s.overflow = true; return; }
  if (m == 1) {
    for (int i = 0; i < N; ++i) {
      if (small_abs(s.A[i][0]) > tol * detail::small_line_scale<N>(M, S, i, s.nb)) {
        s.line_mask |= 1u << i;
        s.inv_a[i] = 1.0 / s.A[i][0];
      }
    }
  } else {  // vertices: m active constraints
    for (unsigned act = 0; act <= kAll; ++act) {
      if (detail::small_popcount(act) != m) continue;
      if (m == 0) {
        s.acts[s.num_acts++] = act;
        continue;
      }
      double e[4][5] = {};
      if (!detail::small_equilibrated_rows<N>(s.A, nullptr, act, m, e, s.act_rmax[s.num_acts]))
        continue;
      bool g2 = false;
      detail::SmallElimRecord& rec = s.act_el[s.num_acts];
      if (detail::small_eliminate(e, m, m, rec.perm, tol, g2, &rec) < m) {
        rec = detail::SmallElimRecord{};
        continue;
      }
      if (g2) ++s.post_ambiguous;
      s.acts[s.num_acts++] = act;
    }
  }
  if (m == 0) return;
  // rays: add_ray's tests depend on M only
  detail::small_ray_candidates<N>(s.A, s.nb, m, tol, s.post_ambiguous, [&](double (&d)[N]) {
    unsigned zd = 0, zmd = 0;
    switch (detail::small_judge_ray<N>(M, S, d, tol, zd, zmd)) {
      case detail::kRayAccepted:
        for (int j = 0; j < N; ++j) s.rays[s.num_rays][j] = d[j];
        s.ray_zero_d[s.num_rays] = zd;
        s.ray_zero_md[s.num_rays] = zmd;
        ++s.num_rays;
        return;
      case detail::kRayAmbiguous: ++s.ray_ambiguous; return;
      case detail::kRayNotFinite: s.overflow = true; return;
      default: return;
    }
  });
}

/// The q-dependent part of SmallEnumerator::singular_piece, same operations in the same order.
template <int N>
void prepared_singular_piece(detail::SmallEnumerator<N>& en, unsigned S,
                             const detail::SmallPreparedSupport<N>& s,
                             const Eigen::Matrix<double, N, 1>& q, SmallSolutionSet<N>& out) {
  using detail::small_abs;
  using detail::small_max;
  const int k = s.k, m = s.m;
  const int* idx = s.idx;
  double z0[N];
  for (int j = 0; j < N; ++j) {
    double v = 0;
    for (int i = 0; i < N; ++i) v += s.P[j][i] * q(i);
    z0[j] = v;
  }
  if (!en.all_finite(z0)) {  // overflow of P q: decide from the data as enumerate_small does
    en.singular_piece_cold(S, idx, k);
    return;
  }
  out.ambiguous += s.pre_ambiguous;
  double z0n = 0;
  for (int j = 0; j < N; ++j) z0n = small_max(z0n, small_abs(z0[j]));
  if (!en.piece_consistent(idx, k, z0, z0n)) return;
  out.ambiguous += s.post_ambiguous;
  double b[N];
  if (!en.constraint_offsets(S, z0, z0n, b)) { en.unrepresentable(); return; }
  const auto& nb = s.nb;
  if (m == 1) {
    for (int i = 0; i < N; ++i) {
      if (!(s.line_mask & (1u << i))) continue;
      const double t = -b[i] * s.inv_a[i];
      double z[N];
      for (int j = 0; j < N; ++j) z[j] = z0[j] + t * nb[0][j];
      en.add_point(S, z);
    }
  } else {
    for (int a = 0; a < s.num_acts; ++a) {
      double z[N];
      for (int j = 0; j < N; ++j) z[j] = z0[j];
      if (m > 0) {  // the vertex system's elimination replayed on its right-hand side
        const detail::SmallElimRecord& rec = s.act_el[a];
        double e4[4] = {};
        int t = 0;
        for (int i = 0; i < N; ++i)
          if (s.acts[a] & (1u << i)) { e4[t] = -b[i] / s.act_rmax[a][t]; ++t; }
        detail::small_replay_rhs(rec, m, e4);
        en.vertex_from(rec.a, rec.perm, m, [&](int p) { return e4[p]; }, nb, z);
      }
      en.add_point(S, z);
    }
  }
  out.ambiguous += s.ray_ambiguous;
  for (int c = 0; c < s.num_rays; ++c)
    en.store_ray(s.rays[c], s.ray_zero_d[c], s.ray_zero_md[c]);
}

}  // namespace

template <int N>
void enumerate_small(const Eigen::Matrix<double, N, N>& M, const Eigen::Matrix<double, N, 1>& q,
                     SmallSolutionSet<N>& out, double tol) {
  if (!M.allFinite() || !q.allFinite())
    throw InputError("enumerate_small: M or q has a non-finite entry");
  detail::small_check_tol("enumerate_small", tol);
  detail::SmallEnumerator<N> en(M, q, out, tol);
  en.run();
  detail::small_finish<N>(en, out);
}

template <int N>
SmallPreparedLcp<N>::SmallPreparedLcp(const Mat& M, double tol) : M_(M), tol_(tol) {
  if (!M.allFinite()) throw InputError("SmallPreparedLcp: M has a non-finite entry");
  detail::small_check_tol("SmallPreparedLcp", tol);
  for (unsigned S = 0; S <= kAll; ++S) {
    Sup& s = sup_[S];
    prepare_support<N>(M_, tol_, S, s);
    if (s.overflow) {  // decided per call from the data, exactly as enumerate_small does
      Sup t;
      t.k = s.k;
      for (int c = 0; c < 4; ++c) t.idx[c] = s.idx[c];
      t.kind = 3;
      s = t;
    }
  }
}

template <int N>
void SmallPreparedLcp<N>::enumerate(const Vec& q, SmallSolutionSet<N>& out, double tol) const {
  if (!q.allFinite()) throw InputError("SmallPreparedLcp::enumerate: q has a non-finite entry");
  detail::small_check_tol("SmallPreparedLcp::enumerate", tol);
  if (tol != tol_) {  // the preparation holds for tol_ only
    enumerate_small<N>(M_, q, out, tol);
    return;
  }
  detail::SmallEnumerator<N> en(M_, q, out, tol);
  for (unsigned S = 0; S <= kAll; ++S) {
    const auto& s = sup_[S];
    if (s.kind == 2) {
      prepared_singular_piece<N>(en, S, s, q, out);
      continue;
    }
    if (s.kind == 3) {
      en.singular_piece_cold(S, s.idx, s.k);
      continue;
    }
    double z[N] = {};
    if (s.kind == 1) {
      detail::small_cramer_inv(M_, q, s.idx, s.idx, s.k, s.inv, s.idx, z);
      if (!en.all_finite(z)) {  // as enumerate_small: overflow in Cramer's products
        en.singular_piece_cold(S, s.idx, s.k);
        continue;
      }
    }
    en.add_point(S, z);
  }
  detail::small_finish<N>(en, out);
}

// The sizes the library provides (the public headers declare exactly these as extern).
#define CPKIT_ENUMERATE_SMALL_INSTANTIATE(N)                                                   \
  template void enumerate_small<N>(const Eigen::Matrix<double, N, N>&,                         \
                                   const Eigen::Matrix<double, N, 1>&, SmallSolutionSet<N>&,   \
                                   double);                                                    \
  template class SmallPreparedLcp<N>;
CPKIT_ENUMERATE_SMALL_INSTANTIATE(1)
CPKIT_ENUMERATE_SMALL_INSTANTIATE(2)
CPKIT_ENUMERATE_SMALL_INSTANTIATE(3)
CPKIT_ENUMERATE_SMALL_INSTANTIATE(4)
#undef CPKIT_ENUMERATE_SMALL_INSTANTIATE

}  // namespace cpkit::lcp
