#include "cpkit/lcp/small_lcp.hpp"

#include <cmath>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp {
namespace {

/// The unique solution of the N x N problem (M column-major) into z; false when there is not
/// exactly one (a finite set, complete, nothing ambiguous or dropped).
template <int N>
bool unique_solution(const double* M, const double* q, double* z) {
  const Eigen::Matrix<double, N, N> Mf = Eigen::Map<const Eigen::Matrix<double, N, N>>(M);
  const Eigen::Matrix<double, N, 1> qf = Eigen::Map<const Eigen::Matrix<double, N, 1>>(q);
  SmallSolutionSet<N> set;
  enumerate_small<N>(Mf, qf, set);
  if (set.num_points != 1 || set.infinite || set.ambiguous != 0 || set.dropped != 0) return false;
  for (int i = 0; i < N; ++i) z[i] = set.z[0][i];
  return true;
}

// --- The P-matrix route (n <= 3) -----------------------------------------------------------
// When every principal minor of M is positive (a P-matrix), LCP(M, q) has exactly one solution
// for every q [Cottle-Pang-Stone 1992, Thm. 3.3.7], and it is the complementary basic solution
// whose signs hold: z_S = -M_SS^{-1} q_S >= 0, z = 0 off S, w = M z + q >= 0 off S. The minors'
// signs are taken only when rounding cannot flip them: |det| above twice the error bound of its
// expansion (gamma_k times the sum of |terms| [Higham 2002, Sec. 3.1]); otherwise the
// enumeration decides. Cheaper than the enumeration (no rays, no other bases).

constexpr double kEps = 2.220446049250313e-16;

/// The principal minor of M on the index set S (bit i: index i), its expansion's sum of |terms|.
struct Minor {
  double det = 1, size = 1;
};
template <int n>
Minor principal_minor(const double* M, unsigned S) {
  int idx[3], k = 0;
  for (int i = 0; i < n; ++i)
    if (S >> i & 1u) idx[k++] = i;
  auto m = [&](int a, int b) { return M[idx[a] + n * idx[b]]; };
  Minor r;
  if (k == 1) {
    r.det = m(0, 0);
    r.size = std::abs(r.det);
  } else if (k == 2) {
    const double a = m(0, 0) * m(1, 1), b = m(0, 1) * m(1, 0);
    r.det = a - b;
    r.size = std::abs(a) + std::abs(b);
  } else if (k == 3) {
    const double t[6] = {m(0, 0) * m(1, 1) * m(2, 2), m(0, 1) * m(1, 2) * m(2, 0),
                         m(0, 2) * m(1, 0) * m(2, 1), m(0, 2) * m(1, 1) * m(2, 0),
                         m(0, 0) * m(1, 2) * m(2, 1), m(0, 1) * m(1, 0) * m(2, 2)};
    r.det = ((t[0] + t[1]) + t[2]) - ((t[3] + t[4]) + t[5]);
    r.size = 0;
    for (double x : t) r.size += std::abs(x);
  }
  return r;
}

/// True when every principal minor is positive beyond its rounding error (8 eps |terms| bounds
/// gamma_7 of a 3 x 3 expansion with a factor 2 to spare); minors[S] receives each one.
template <int n>
bool p_matrix(const double* M, Minor* minors) {
  for (unsigned S = 1; S < (1u << n); ++S) {
    minors[S] = principal_minor<n>(M, S);
    if (!(minors[S].det > 16 * kEps * minors[S].size)) return false;
  }
  return true;
}

/// z_S = -M_SS^{-1} q_S by Cramer's rule (det M_SS = minors[S].det), z = 0 off S.
template <int n>
void basic_solution(const double* M, const double* q, unsigned S, const Minor* minors, double* z) {
  int idx[3], k = 0;
  for (int i = 0; i < n; ++i) {
    z[i] = 0;
    if (S >> i & 1u) idx[k++] = i;
  }
  // Column c of M_SS replaced by -q_S: its determinant over det M_SS.
  double A[9];
  for (int c = 0; c < k; ++c) {
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) A[a + k * b] = b == c ? -q[idx[a]] : M[idx[a] + n * idx[b]];
    double d;
    if (k == 1) d = A[0];
    else if (k == 2) d = A[0] * A[3] - A[2] * A[1];
    else
      d = A[0] * (A[4] * A[8] - A[7] * A[5]) - A[3] * (A[1] * A[8] - A[7] * A[2]) +
          A[6] * (A[1] * A[5] - A[4] * A[2]);
    z[idx[c]] = d / minors[S].det;
  }
}

/// The unique solution of a P-matrix LCP (n <= 3) into z; false when M is not provably a
/// P-matrix or no basis passes its sign test exactly (a degenerate problem: the enumeration
/// decides it).
template <int n>
bool p_matrix_solution(const double* M, const double* q, double* z) {
  Minor minors[1u << n];
  if (!p_matrix<n>(M, minors)) return false;
  // First the basis of the rows with q_i < 0 (the guess of one principal pivoting step, right
  // whenever those rows are the active ones), then every other one.
  unsigned guess = 0;
  for (int i = 0; i < n; ++i)
    if (q[i] < 0) guess |= 1u << i;
  for (unsigned k = 0; k < (1u << n); ++k) {
    const unsigned S = k == 0 ? guess : (k == guess ? 0 : k);
    basic_solution<n>(M, q, S, minors, z);
    bool ok = true;
    for (int i = 0; i < n && ok; ++i) {
      double w = q[i];
      for (int j = 0; j < n; ++j) w += M[i + n * j] * z[j];
      ok = (S >> i & 1u) ? z[i] >= 0 : w >= 0;
    }
    if (ok) return true;
  }
  return false;
}

bool p_matrix_solution(int n, const double* M, const double* q, double* z) {
  switch (n) {  // the size as a constant: every loop unrolled
    case 1: return p_matrix_solution<1>(M, q, z);
    case 2: return p_matrix_solution<2>(M, q, z);
    case 3: return p_matrix_solution<3>(M, q, z);
    default: return false;
  }
}

bool unique_solution(int n, const double* M, const double* q, double* z) {
  switch (n) {
    case 1: return unique_solution<1>(M, q, z);
    case 2: return unique_solution<2>(M, q, z);
    case 3: return unique_solution<3>(M, q, z);
    case 4: return unique_solution<4>(M, q, z);
    default: return false;
  }
}

}  // namespace

bool small_lcp_route(int n, const SolverEntry& entry) {
  static const SolverEntry* const lemke = solvers().find("lemke");
  static const SolverEntry* const automatic = solvers().find("auto");
  return n >= 1 && n <= kSmallLcpMax && (&entry == lemke || &entry == automatic);
}

bool solve_small_fast(int n, const double* M, const double* q, double tol, double* z, double* w,
                      double& natural) {
  double zc[kSmallLcpMax] = {}, wc[kSmallLcpMax];
  if (!p_matrix_solution(n, M, q, zc) && !unique_solution(n, M, q, zc)) return false;
  natural = small_lcp_natural(n, M, q, zc, wc);
  if (!(natural <= tol)) return false;  // the general route decides (and explains) the rest
  for (int i = 0; i < n; ++i) {
    z[i] = zc[i];
    w[i] = wc[i];
  }
  return true;
}

bool solve_small_unique(const LcpProblem& p, const SolverEntry& entry, const CommonOptions& o,
                        SolveResult& r) {
  const int n = static_cast<int>(p.size());
  if (p.is_sparse() || !small_lcp_route(n, entry)) return false;
  r.z.resize(n);
  if (!unique_solution(n, p.M.data(), p.q.data(), r.z.data())) return false;
  reuse_as_claim(r, Status::kSolved, "enumerate");  // the scratch result's storage kept
  r = finalize(p, std::move(r), o);
  return is_solution(r.status);
}

}  // namespace cpkit::lcp
