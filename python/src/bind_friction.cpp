// 3-D frictional contact problems (issue 26): the FCLIB / Siconos readers and the registered
// friction solvers. W crosses as an Eigen sparse matrix (scipy.sparse CSC on the Python side,
// converted by pybind11/eigen.h).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

namespace pyb = pybind11;

pyb::dict read_fclib(const std::string& path) {
  const FrictionContactProblem p = read_friction_problem(path);
  pyb::dict d;
  d["W"] = p.W;
  d["q"] = p.q;
  d["mu"] = p.mu;
  d["name"] = p.name;
  d["note"] = p.note;
  return d;
}

pyb::dict solve_friction(const Eigen::SparseMatrix<double>& W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& mu, const std::string& solver, double tol,
                         double time_limit) {
  FrictionContactProblem p;
  p.W = W;
  p.q = q;
  p.mu = mu;
  throw_if_invalid(p.validate(), "solve_friction");
  const SolverEntry* entry = cpkit::lcp::solvers().find(solver);
  if (entry == nullptr || !entry->accepts(ProblemKind::kFrictionContact)) {
    std::string names;
    for (const auto& n : cpkit::lcp::solvers().names(ProblemKind::kFrictionContact))
      names += (names.empty() ? "" : ", ") + n;
    throw InputError("solver: unknown friction solver '" + solver + "' (valid: " + names + ")");
  }
  CommonOptions o;
  o.tol = tol;
  if (o.tol_acceptable < o.tol) o.tol_acceptable = o.tol;
  o.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "solve_friction");
  SolveResult r;
  {
    pyb::gil_scoped_release release;
    r = entry->solve_fc(p, o);
  }
  if (r.solver.empty()) r.solver = entry->info.name;
  pyb::dict d;
  d["status"] = std::string(to_string(r.status));
  d["solved"] = is_solution(r.status);
  d["solver"] = r.solver;
  d["r"] = r.z;
  d["u"] = r.w;
  if (r.z.size() == p.W.rows()) {
    const FrictionErrors e = friction_errors(p, r.z);
    d["errors"] = pyb::dict(pyb::arg("unit_free") = e.unit_free,
                            pyb::arg("relative_q") = e.relative_q,
                            pyb::arg("relative_max") = e.relative_max);
  }
  d["iterations"] = r.iterations;
  d["seconds"] = r.seconds;
  d["message"] = r.message;
  return d;
}

}  // namespace

void bind_friction(pyb::module_& m) {
  m.def("read_fclib", &read_fclib, pyb::arg("path"));
  m.def("solve_friction", &solve_friction, pyb::arg("W"), pyb::arg("q"), pyb::arg("mu"),
        pyb::arg("solver"), pyb::arg("tol"), pyb::arg("time_limit"));
}

}  // namespace cpkit::py
