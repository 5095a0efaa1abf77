#include "small_lcp.hpp"

#include "cpkit/core/finalize.hpp"
#include "cpkit/lcp/enumerate_small.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::capi {
namespace {

/// The unique solution of the N x N problem into z; false when there is not exactly one.
template <int N>
bool unique_solution(const LcpProblem& p, Vec& z) {
  const Eigen::Matrix<double, N, N> M = p.M;
  const Eigen::Matrix<double, N, 1> q = p.q;
  lcp::SmallSolutionSet<N> set;
  lcp::enumerate_small<N>(M, q, set);
  if (set.num_points != 1 || set.infinite || set.ambiguous != 0 || set.dropped != 0) return false;
  z = set.z[0];
  return true;
}

bool unique_solution(const LcpProblem& p, Vec& z) {
  switch (p.size()) {
    case 1: return unique_solution<1>(p, z);
    case 2: return unique_solution<2>(p, z);
    case 3: return unique_solution<3>(p, z);
    case 4: return unique_solution<4>(p, z);
    default: return false;
  }
}

}  // namespace

bool solve_small_unique(const LcpProblem& p, const SolverEntry& entry, const CommonOptions& o,
                        SolveResult& r) {
  static const SolverEntry* const lemke = lcp::solvers().find("lemke");
  static const SolverEntry* const automatic = lcp::solvers().find("auto");
  if (p.size() > 4 || p.is_sparse() || (&entry != lemke && &entry != automatic)) return false;
  if (!unique_solution(p, r.z)) return false;
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
