// LCP bindings: solve (any registered solver, "auto" included), enumerate, cross_verify.
// Dense M arrives as an Eigen matrix, sparse M as a scipy.sparse matrix read by sparse_from
// (every index checked first); the C++ validators name every bad input (ValueError).
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "result_objects.hpp"
#include "sparse_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/lcp_request.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

SolveResult solve_checked(const LcpProblem& p, const std::string& solver, const CommonOptions& o) {
  throw_if_invalid(p.validate(), "LCP");
  const SolverEntry& e = find_solver(solver, ProblemKind::kLcp);
  if (!e.accepts(p))
    throw InputError("solver '" + solver + "' does not accept " +
                     std::string(p.is_sparse() ? "sparse" : "dense") + " LCPs");
  SolveResult r = without_gil([&] { return e.solve_lcp(p, o); });
  if (r.solver.empty()) r.solver = e.info.name;
  return r;
}

pyb::dict solve_problem(const LcpProblem& p, const std::string& solver, const CommonOptions& o) {
  return to_dict(solve_checked(p, solver, o));
}

/// The data of `h` when it is an aligned, C-contiguous, native float64 ndarray of rank `nd`
/// (read in place: no conversion object per call), else nullptr.
const double* direct_data(pyb::handle h, int nd, pyb::ssize_t* shape) {
  namespace d = pyb::detail;
  if (!d::npy_api::get().PyArray_Check_(h.ptr())) return nullptr;
  const d::PyArray_Proxy* a = d::array_proxy(h.ptr());
  if (a->nd != nd) return nullptr;
  const d::PyArrayDescr_Proxy* t = d::array_descriptor_proxy(a->descr);
  if (t->type_num != d::npy_api::NPY_DOUBLE_ || t->byteorder == '>') return nullptr;
  constexpr int need = d::npy_api::NPY_ARRAY_C_CONTIGUOUS_ | d::npy_api::NPY_ARRAY_ALIGNED_;
  if ((a->flags & need) != need) return nullptr;
  for (int k = 0; k < nd; ++k) shape[k] = a->dimensions[k];
  return reinterpret_cast<const double*>(a->data);
}

/// The quick route as a METH_FASTCALL function (pybind11's general dispatcher costs about as
/// much as the rest of a tiny call): solve_dense_fast(M, q, solver, tol, tol_acceptable,
/// max_iterations, time_limit) returns NotImplemented unless M and q are float64 ndarrays of
/// ranks 2 and 1 readable in place, solver a str, tol, tol_acceptable and time_limit floats and
/// max_iterations an int; cpkit.solve then takes its general route (same results, same errors).
PyObject* solve_dense_fast_raw(PyObject*, PyObject* const* args, Py_ssize_t nargs) {
  try {
    if (nargs != 7) throw InputError("solve_dense_fast takes 7 arguments");
    pyb::ssize_t ms[2] = {0, 0}, qs[1] = {0};
    const double* Md = direct_data(args[0], 2, ms);
    const double* qd = direct_data(args[1], 1, qs);
    if (Md == nullptr || qd == nullptr || !PyUnicode_CheckExact(args[2]) ||
        !PyFloat_CheckExact(args[3]) || !PyFloat_CheckExact(args[4]) ||
        !PyLong_CheckExact(args[5]) || !PyFloat_CheckExact(args[6]))
      Py_RETURN_NOTIMPLEMENTED;
    Py_ssize_t len = 0;
    const char* name = PyUnicode_AsUTF8AndSize(args[2], &len);
    if (name == nullptr) throw pyb::error_already_set();
    const long max_iterations = PyLong_AsLong(args[5]);
    if (max_iterations == -1 && PyErr_Occurred()) throw pyb::error_already_set();
    if (max_iterations < 0 || max_iterations > 2147483647L) Py_RETURN_NOTIMPLEMENTED;
    const CommonOptions o =
        common_options(PyFloat_AS_DOUBLE(args[3]), PyFloat_AS_DOUBLE(args[4]),
                       static_cast<int>(max_iterations), PyFloat_AS_DOUBLE(args[6]));
    // Small problems: one problem object per thread, its storage reused from call to call
    // (the GIL is released during the solve, so other threads need their own); a large one is
    // not kept alive after its call.
    thread_local LcpProblem small;
    std::optional<LcpProblem> large;
    LcpProblem& p = ms[0] <= 64 && ms[1] <= 64 ? small : large.emplace();
    p.M = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        Md, static_cast<Eigen::Index>(ms[0]), static_cast<Eigen::Index>(ms[1]));
    p.q = Eigen::Map<const Vec>(qd, static_cast<Eigen::Index>(qs[0]));
    return make_solve_result(
               solve_checked(p, std::string(name, static_cast<std::size_t>(len)), o))
        .release()
        .ptr();
  } catch (pyb::error_already_set& e) {
    e.restore();
  } catch (const std::invalid_argument& e) {  // InputError: ValueError, as pybind11 maps it
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const std::bad_alloc&) {
    PyErr_NoMemory();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

PyMethodDef kFastMethods[] = {
    {"solve_dense_fast", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&solve_dense_fast_raw)),
     METH_FASTCALL, "solve_dense_fast(M, q, solver, tol, tol_acceptable, max_iterations, "
                    "time_limit) -> cpkit.SolveResult, or NotImplemented when the arguments "
                    "need the general route (the quick route of cpkit.solve)"},
    {nullptr, nullptr, 0, nullptr}};

LcpProblem dense_problem(const Mat& M, const Vec& q) { return LcpProblem(M, q); }
LcpProblem sparse_problem(const pyb::handle& M, const Vec& q) {
  LcpProblem p;
  p.M_sparse = sparse_from(M, "M");
  p.q = q;
  return p;
}

pyb::dict set_to_dict(const lcp::SolutionSet& s) {
  pyb::dict d;
  const auto numpy = [](const Vec& v) { return to_numpy(v); };
  d["solutions"] = list_of(s.solutions, [](const auto& e) {
    pyb::dict sd;
    sd["z"] = to_numpy(e.z);
    sd["w"] = to_numpy(e.w);
    sd["basis"] = e.basis;
    return sd;
  });
  d["pieces"] = list_of(s.pieces, [&](const auto& pc) {
    pyb::dict pd;
    pd["support"] = pc.support;
    pd["vertices"] = pc.vertices;
    pd["rays"] = list_of(pc.rays, numpy);
    return pd;
  });
  d["directions"] = list_of(s.directions, numpy);
  d["complete"] = s.complete;
  d["infinite"] = s.infinite;
  d["ambiguous"] = s.ambiguous;
  d["unrepresentable"] = s.unrepresentable;
  d["nodes"] = s.nodes;
  d["leaves"] = s.leaves;
  d["structured"] = s.structured;
  d["seconds"] = s.seconds;
  d["message"] = s.message;
  return d;
}

lcp::EnumerationOptions enumeration_options(int max_size, double time_limit) {
  lcp::EnumerationOptions o;
  o.max_size = max_size;
  o.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "enumeration options");
  return o;
}

pyb::dict enumerate_problem(const LcpProblem& p, int max_size, double time_limit) {
  throw_if_invalid(p.validate(), "LCP");
  const auto o = enumeration_options(max_size, time_limit);
  lcp::SolutionSet s = without_gil([&] { return lcp::enumerate_all(p, o); });
  return set_to_dict(s);
}

pyb::dict cross_verify_problem(const LcpProblem& p, const std::vector<std::string>& skip,
                               int max_size, double time_limit) {
  throw_if_invalid(p.validate(), "LCP");
  lcp::CrossVerifyOptions o;
  o.enumeration = enumeration_options(max_size, time_limit);
  for (const auto& name : skip) find_solver(name, ProblemKind::kLcp);  // names must exist
  o.skip = skip;
  throw_if_invalid(o.validate(), "cross_verify options");
  lcp::CrossVerifyReport rep = without_gil([&] { return lcp::cross_verify(p, o); });
  pyb::dict d;
  d["set"] = set_to_dict(rep.set);
  d["checks"] = list_of(rep.checks, [](const auto& c) {
    pyb::dict cd;
    cd["solver"] = c.solver;
    cd["status"] = std::string(to_string(c.status));
    cd["residual"] = c.residual;
    cd["data_residual"] = c.data_residual;
    cd["in_set"] = c.in_set;
    cd["solution_index"] = c.solution_index;
    cd["verdict"] = std::string(lcp::to_string(c.verdict));
    cd["seconds"] = c.seconds;
    cd["message"] = c.message;
    return cd;
  });
  d["disagreements"] = rep.disagreements;
  d["consistent"] = rep.consistent();
  return d;
}

}  // namespace

void bind_lcp(pyb::module_& m) {
  // The one default of `cpkit lcp solve` and cpkit.solve (cpkit/lcp/lcp_request.hpp).
  m.attr("DEFAULT_SOLVER") = lcp::kDefaultSolver;
  m.def("solvers", [](const std::string& kind) {
        if (kind == "lcp") return lcp::solvers().names(ProblemKind::kLcp);
        if (kind == "mcp") return lcp::solvers().names(ProblemKind::kMcp);
        throw InputError("kind must be 'lcp' or 'mcp', got '" + kind + "'");
      }, pyb::arg("kind") = "lcp");
  m.def("solve_dense",
        [](const Mat& M, const Vec& q, const std::string& solver, double tol,
           double tol_acceptable, int max_iterations, double time_limit) {
          return solve_problem(dense_problem(M, q), solver,
                               common_options(tol, tol_acceptable, max_iterations, time_limit));
        });
  if (PyModule_AddFunctions(m.ptr(), kFastMethods) != 0) throw pyb::error_already_set();
  m.def("_set_result_classes", &set_result_classes);
  m.def("solve_sparse",
        [](const pyb::handle& M, const Vec& q, const std::string& solver, double tol,
           double tol_acceptable, int max_iterations, double time_limit) {
          return solve_problem(sparse_problem(M, q), solver,
                               common_options(tol, tol_acceptable, max_iterations, time_limit));
        });
  m.def("enumerate_dense", [](const Mat& M, const Vec& q, int max_size, double time_limit) {
    return enumerate_problem(dense_problem(M, q), max_size, time_limit);
  });
  m.def("enumerate_sparse", [](const pyb::handle& M, const Vec& q, int max_size, double time_limit) {
    return enumerate_problem(sparse_problem(M, q), max_size, time_limit);
  });
  m.def("cross_verify_dense", [](const Mat& M, const Vec& q, const std::vector<std::string>& skip,
                                 int max_size, double time_limit) {
    return cross_verify_problem(dense_problem(M, q), skip, max_size, time_limit);
  });
  m.def("cross_verify_sparse", [](const pyb::handle& M, const Vec& q,
                                  const std::vector<std::string>& skip, int max_size,
                                  double time_limit) {
    return cross_verify_problem(sparse_problem(M, q), skip, max_size, time_limit);
  });
}

}  // namespace cpkit::py
