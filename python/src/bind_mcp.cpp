// NCP/MCP with Python callables F(x) and J(x).
//
// The solvers run without the GIL; each callback takes it back while Python runs. A Python
// exception (or a result of the wrong shape) inside F or J aborts the solve: the adapter stores
// it, throws CallbackAborted through the solver (and makes every later callback throw at once,
// since some drivers - Ipopt, the auto chain - catch exceptions and go on), and the binding
// re-raises the stored Python exception once the solver has returned. Nothing reaches
// std::terminate and no status hides the error.
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "sparse_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

struct CallbackAborted : std::runtime_error {
  CallbackAborted() : std::runtime_error("a Python callback raised an exception") {}
};

/// Shared between the callbacks of one solve. The solvers copy McpProblem (and so the
/// std::functions) without the GIL: the callables live here, behind one shared_ptr, so that a
/// copy touches no Python reference count. The binding's own McpProblem outlives every copy
/// and is destroyed with the GIL held.
struct CallbackState {
  pyb::function F, J;
  std::exception_ptr error;  ///< the first Python exception (re-raised after the solve)
  Eigen::Index n = 0;
};

/// Calls fn(x) with the GIL held and hands a non-None result to `convert` (still under the
/// GIL; it may throw pybind11 exceptions for a wrong shape). None means "x is outside the
/// domain" (returns false). Any exception is stored and aborts the solve.
template <class Convert>
bool invoke(CallbackState& st, const pyb::function& fn, const Vec& x, Convert&& convert) {
  if (st.error) throw CallbackAborted();
  {
    pyb::gil_scoped_acquire gil;
    try {
      pyb::object r = fn(to_numpy(x));
      if (r.is_none()) return false;
      convert(r);
      return true;
    } catch (...) {
      st.error = std::current_exception();
    }
  }
  throw CallbackAborted();
}

using DoubleArray = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>;

FunctionCallback function_adapter(std::shared_ptr<CallbackState> st) {
  return [st](const Vec& x, Vec& out) -> bool {
    return invoke(*st, st->F, x, [&](const pyb::object& r) {
      auto a = DoubleArray::ensure(r);
      if (!a || a.ndim() != 1 || a.shape(0) != st->n)
        throw pyb::value_error("F(x) must return a 1-D array of length " +
                               std::to_string(st->n) + " (or None outside its domain)");
      out.resize(st->n);
      for (Eigen::Index i = 0; i < st->n; ++i) out[i] = a.at(i);
    });
  };
}

JacobianCallback dense_jacobian_adapter(std::shared_ptr<CallbackState> st) {
  return [st](const Vec& x, Mat& out) -> bool {
    return invoke(*st, st->J, x, [&](const pyb::object& r) {
      auto a = DoubleArray::ensure(r);
      if (!a || a.ndim() != 2 || a.shape(0) != st->n || a.shape(1) != st->n)
        throw pyb::value_error("J(x) must return an n x n array, n = " + std::to_string(st->n));
      out.resize(st->n, st->n);
      for (Eigen::Index i = 0; i < st->n; ++i)
        for (Eigen::Index j = 0; j < st->n; ++j) out(i, j) = a.at(i, j);
    });
  };
}

SparseJacobianCallback sparse_jacobian_adapter(std::shared_ptr<CallbackState> st) {
  return [st](const Vec& x, SparseMat& out) -> bool {
    return invoke(*st, st->J, x, [&](const pyb::object& r) {
      SparseMat m = sparse_from(r, "J(x)");  // every index checked
      if (m.rows() != st->n || m.cols() != st->n)
        throw pyb::value_error("J(x) must return an n x n matrix, n = " + std::to_string(st->n));
      out = std::move(m);
    });
  };
}

pyb::dict solve_mcp(pyb::function F, pyb::object J, bool sparse_jacobian, const Vec& x0,
                    const Vec& lower, const Vec& upper, const std::string& solver, double tol,
                    double tol_acceptable, int max_iterations, double time_limit) {
  auto st = std::make_shared<CallbackState>();
  st->n = x0.size();
  McpProblem p;
  p.n = x0.size();
  p.x0 = x0;
  p.lower = lower;
  p.upper = upper;
  st->F = std::move(F);
  p.F = function_adapter(st);
  if (!J.is_none()) {
    st->J = J.cast<pyb::function>();
    if (sparse_jacobian)
      p.sparse_jacobian = sparse_jacobian_adapter(st);
    else
      p.jacobian = dense_jacobian_adapter(st);
  }
  throw_if_invalid(p.validate(), "MCP");
  const CommonOptions o = common_options(tol, tol_acceptable, max_iterations, time_limit);
  const SolverEntry* e = &find_solver(solver, ProblemKind::kMcp, "MCP solver");
  SolveResult r;
  std::exception_ptr solver_error;
  {
    pyb::gil_scoped_release release;
    try {
      r = e->solve_mcp(p, o);
    } catch (...) {
      solver_error = std::current_exception();
    }
  }
  // The Python exception first: it is the cause of any CallbackAborted seen by the solver.
  if (st->error) std::rethrow_exception(st->error);
  if (solver_error) std::rethrow_exception(solver_error);
  if (r.solver.empty()) r.solver = e->info.name;
  return to_dict(r);
}

}  // namespace

void bind_mcp(pyb::module_& m) { m.def("solve_mcp", &solve_mcp); }

}  // namespace cpkit::py
