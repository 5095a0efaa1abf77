// Many small LCPs in one call: cpkit._cpkit.solve_batch(Ms (k, n, n), qs (k, n), solver, ...)
// (issue 27: a stack of M and q, e.g. one per contact). Every problem is checked before any is
// solved (the message names the first bad one); the loop runs without the GIL and without
// Python objects per problem; each answer is decided by the registry solver's finalize(), as
// for a single call.
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

using Array = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>;

std::string shape_text(const pyb::array& a) {
  std::string s = "(";
  for (pyb::ssize_t d = 0; d < a.ndim(); ++d)
    s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

pyb::dict solve_batch(const Array& Ms, const Array& qs, const std::string& solver, double tol,
                      double tol_acceptable, int max_iterations, double time_limit) {
  if (Ms.ndim() != 3 || Ms.shape(1) != Ms.shape(2))
    throw InputError("Ms must have shape (k, n, n) (a stack of k square matrices), got shape " +
                     shape_text(Ms));
  const pyb::ssize_t k = Ms.shape(0), n = Ms.shape(1);
  if (qs.ndim() != 2 || qs.shape(0) != k || qs.shape(1) != n)
    throw InputError("qs must have shape (k, n) = (" + std::to_string(k) + ", " +
                     std::to_string(n) + ") to match Ms " + shape_text(Ms) + ", got shape " +
                     shape_text(qs));
  if (n < 1 && k > 0) throw InputError("Ms: the problems are empty (n = 0)");
  const CommonOptions o = common_options(tol, tol_acceptable, max_iterations, time_limit);
  const SolverEntry* e = &find_solver(solver, ProblemKind::kLcp);
  check_memory(static_cast<double>(k) * static_cast<double>(n) * 16.0 + 16.0 * k, "solve_batch");
  const double* M = Ms.data();
  const double* q = qs.data();
  // Every value checked first: a NaN in problem 900 must not leave 899 answers half-returned.
  const std::size_t nn = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  for (pyb::ssize_t i = 0; i < k; ++i) {
    for (std::size_t t = 0; t < nn; ++t)
      if (!std::isfinite(M[i * nn + t]))
        throw InputError("Ms[" + std::to_string(i) + "] has a non-finite entry (NaN or Inf) at (" +
                         std::to_string(t / n) + ", " + std::to_string(t % n) + ")");
    for (pyb::ssize_t t = 0; t < n; ++t)
      if (!std::isfinite(q[i * n + t]))
        throw InputError("qs[" + std::to_string(i) + "] has a non-finite entry (NaN or Inf) at " +
                         std::to_string(t));
  }
  pyb::array_t<double> z({k, n}), w({k, n});
  pyb::array_t<double> residual(k);
  pyb::array_t<signed char> status(k);
  double* zp = z.mutable_data();
  double* wp = w.mutable_data();
  double* rp = residual.mutable_data();
  signed char* sp = status.mutable_data();
  {
    pyb::gil_scoped_release release;
    const auto ni = static_cast<Eigen::Index>(n);
    LcpProblem p;
    p.M.resize(ni, ni);
    p.q.resize(ni);
    for (pyb::ssize_t i = 0; i < k; ++i) {
      // Row-major numpy block -> Eigen (column-major): the transpose of the mapped block.
      p.M = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          M + i * nn, ni, ni);
      p.q = Eigen::Map<const Vec>(q + i * n, ni);
      const SolveResult r = e->accepts(p) ? e->solve_lcp(p, o) : SolveResult{};
      const bool full = r.z.size() == ni && r.w.size() == ni;
      for (Eigen::Index t = 0; t < ni; ++t) {
        zp[i * n + t] = full ? r.z[t] : NAN;
        wp[i * n + t] = full ? r.w[t] : NAN;
      }
      rp[i] = r.residuals.natural;
      sp[i] = static_cast<signed char>(e->accepts(p) ? r.status : Status::kUnsupported);
    }
  }
  pyb::dict d;
  d["z"] = z;
  d["w"] = w;
  d["residual"] = residual;
  d["status_code"] = status;
  d["solver"] = e->info.name;
  return d;
}

}  // namespace

void bind_lcp_batch(pyb::module_& m) {
  m.def("solve_batch", &solve_batch);
  pyb::list names;
  for (int s = 0; s <= static_cast<int>(Status::kCycleDetected); ++s)
    names.append(std::string(to_string(static_cast<Status>(s))));
  m.attr("STATUS_NAMES") = names;  // status_code -> name
}

}  // namespace cpkit::py
