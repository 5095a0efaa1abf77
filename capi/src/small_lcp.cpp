#include "small_lcp.hpp"

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::capi {
namespace {

/// The unique solution of the N x N problem (M column-major) into z; false when there is not
/// exactly one (a finite set, complete, nothing ambiguous or dropped).
template <int N>
bool unique_solution(const double* M, const double* q, double* z) {
  const Eigen::Matrix<double, N, N> Mf = Eigen::Map<const Eigen::Matrix<double, N, N>>(M);
  const Eigen::Matrix<double, N, 1> qf = Eigen::Map<const Eigen::Matrix<double, N, 1>>(q);
  lcp::SmallSolutionSet<N> set;
  lcp::enumerate_small<N>(Mf, qf, set);
  if (set.num_points != 1 || set.infinite || set.ambiguous != 0 || set.dropped != 0) return false;
  for (int i = 0; i < N; ++i) z[i] = set.z[0][i];
  return true;
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
  static const SolverEntry* const lemke = lcp::solvers().find("lemke");
  static const SolverEntry* const automatic = lcp::solvers().find("auto");
  return n >= 1 && n <= kSmallLcpMax && (&entry == lemke || &entry == automatic);
}

bool solve_small_fast(int n, const double* M, const double* q, double tol, double* z, double* w,
                      double& natural) {
  double zc[kSmallLcpMax], wc[kSmallLcpMax];
  if (!unique_solution(n, M, q, zc)) return false;
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
  // The claim, with the scratch result's other fields cleared (their storage is kept).
  r.status = Status::kSolved;
  r.solver = "enumerate";
  r.iterations = r.function_evals = r.jacobian_evals = r.line_search_steps = r.gradient_steps = 0;
  r.seconds = 0;
  r.certificate.reset();
  r.ray.reset();
  r.basis.clear();
  r.trace.clear();
  r.attempts.clear();
  r.message.clear();
  r = finalize(p, std::move(r), o);
  return is_solution(r.status);
}

}  // namespace cpkit::capi
