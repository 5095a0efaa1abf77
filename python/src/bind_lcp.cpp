// LCP bindings: solve (any registered solver, "auto" included), enumerate, cross_verify.
// Dense M arrives as an Eigen matrix, sparse M (scipy.sparse, converted to CSC by the Python
// layer) as an Eigen sparse matrix; the C++ validators name every bad input (ValueError).
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/cross_verify.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

CommonOptions common_options(double tol, double tol_acceptable, int max_iterations,
                             double time_limit) {
  CommonOptions o;
  o.tol = tol;
  o.tol_acceptable = tol_acceptable < tol ? tol : tol_acceptable;
  o.max_iterations = max_iterations;
  o.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "options");
  return o;
}

std::string solver_list(ProblemKind kind) {
  std::string out;
  for (const auto& n : lcp::solvers().names(kind)) out += (out.empty() ? "" : ", ") + n;
  return out;
}

const SolverEntry& find_solver(const std::string& name, ProblemKind kind) {
  const SolverEntry* e = lcp::solvers().find(name);
  if (e == nullptr || !e->accepts(kind))
    throw InputError("solver: unknown solver '" + name + "' (valid: " + solver_list(kind) + ")");
  return *e;
}

pyb::dict solve_problem(const LcpProblem& p, const std::string& solver, const CommonOptions& o) {
  throw_if_invalid(p.validate(), "LCP");
  const SolverEntry& e = find_solver(solver, ProblemKind::kLcp);
  if (!e.accepts(p))
    throw InputError("solver '" + solver + "' does not accept " +
                     std::string(p.is_sparse() ? "sparse" : "dense") + " LCPs");
  SolveResult r;
  {
    pyb::gil_scoped_release release;
    r = e.solve_lcp(p, o);
  }
  if (r.solver.empty()) r.solver = e.info.name;
  return to_dict(r);
}

LcpProblem dense_problem(const Mat& M, const Vec& q) { return LcpProblem(M, q); }
LcpProblem sparse_problem(const SparseMat& M, const Vec& q) {
  LcpProblem p;
  p.M_sparse = M;
  p.q = q;
  return p;
}

pyb::dict set_to_dict(const lcp::SolutionSet& s) {
  pyb::dict d;
  pyb::list sols;
  for (const auto& e : s.solutions) {
    pyb::dict sd;
    sd["z"] = to_numpy(e.z);
    sd["w"] = to_numpy(e.w);
    sd["basis"] = e.basis;
    sols.append(sd);
  }
  d["solutions"] = sols;
  pyb::list pieces;
  for (const auto& pc : s.pieces) {
    pyb::dict pd;
    pd["support"] = pc.support;
    pd["vertices"] = pc.vertices;
    pyb::list rays;
    for (const auto& r : pc.rays) rays.append(to_numpy(r));
    pd["rays"] = rays;
    pieces.append(pd);
  }
  d["pieces"] = pieces;
  pyb::list dirs;
  for (const auto& v : s.directions) dirs.append(to_numpy(v));
  d["directions"] = dirs;
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
  lcp::SolutionSet s;
  {
    pyb::gil_scoped_release release;
    s = lcp::enumerate_all(p, o);
  }
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
  lcp::CrossVerifyReport rep;
  {
    pyb::gil_scoped_release release;
    rep = lcp::cross_verify(p, o);
  }
  pyb::dict d;
  d["set"] = set_to_dict(rep.set);
  pyb::list checks;
  for (const auto& c : rep.checks) {
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
    checks.append(cd);
  }
  d["checks"] = checks;
  d["disagreements"] = rep.disagreements;
  d["consistent"] = rep.consistent();
  return d;
}

}  // namespace

void bind_lcp(pyb::module_& m) {
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
  m.def("solve_sparse",
        [](const SparseMat& M, const Vec& q, const std::string& solver, double tol,
           double tol_acceptable, int max_iterations, double time_limit) {
          return solve_problem(sparse_problem(M, q), solver,
                               common_options(tol, tol_acceptable, max_iterations, time_limit));
        });
  m.def("enumerate_dense", [](const Mat& M, const Vec& q, int max_size, double time_limit) {
    return enumerate_problem(dense_problem(M, q), max_size, time_limit);
  });
  m.def("enumerate_sparse", [](const SparseMat& M, const Vec& q, int max_size, double time_limit) {
    return enumerate_problem(sparse_problem(M, q), max_size, time_limit);
  });
  m.def("cross_verify_dense", [](const Mat& M, const Vec& q, const std::vector<std::string>& skip,
                                 int max_size, double time_limit) {
    return cross_verify_problem(dense_problem(M, q), skip, max_size, time_limit);
  });
  m.def("cross_verify_sparse", [](const SparseMat& M, const Vec& q,
                                  const std::vector<std::string>& skip, int max_size,
                                  double time_limit) {
    return cross_verify_problem(sparse_problem(M, q), skip, max_size, time_limit);
  });
}

}  // namespace cpkit::py
