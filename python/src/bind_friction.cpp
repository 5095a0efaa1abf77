// 3-D frictional contact bindings (issue 26): read_fclib, solve_friction, friction_solutions,
// friction_errors, and the global problem's read_fclib_global, solve_friction_global. W (and the
// global M, H) arrive as scipy.sparse matrices, read by sparse_from, which checks every index
// before Eigen sees it (sparse_from.hpp).
// Invalid problems, unknown solvers and unreadable files raise ValueError (InputError) with the
// C++ message; every solve runs without the GIL.
#include <limits>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "sparse_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/friction/global.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/friction/solutions.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {
namespace {

FrictionContactProblem make_problem(const pyb::handle& W, const Vec& q, const Vec& mu) {
  FrictionContactProblem p;
  p.W = sparse_from(W, "W");
  p.q = q;
  p.mu = mu;
  throw_if_invalid(p.validate(), "friction problem");
  return p;
}

CommonOptions fc_options(double tol, double tol_acceptable, int max_iterations,
                         double time_limit) {
  // The command line's bound (apps/fc_command.cpp): a larger tolerance would call almost any r
  // solved.
  if (!(tol > 0 && tol <= 1e-3))
    throw InputError("tol must be in (0, 1e-3] (the unit-free residual), got " +
                     std::to_string(tol));
  return common_options(tol, tol_acceptable, max_iterations, time_limit);
}

pyb::dict errors_dict(const FrictionErrors& e) {
  pyb::dict d;
  d["unit_free"] = e.unit_free;
  d["relative_q"] = e.relative_q;
  d["relative_max"] = e.relative_max;
  return d;
}

/// A result as `cpkit fc solve --json` prints it (r, u, errors recomputed from the data), plus
/// the residuals and attempts of SolveResult.
pyb::dict fc_result_dict(const SolveResult& r, const FrictionContactProblem& p) {
  pyb::dict full = to_dict(r);
  pyb::dict d;
  d["status"] = full["status"];
  d["solver"] = r.solver;
  d["r"] = full["z"];
  d["u"] = full["w"];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Not sized: no answer, or a global problem whose M could not be condensed (p is empty).
  const bool sized = p.W.rows() > 0 && r.z.size() == p.W.rows();
  const double inf = std::numeric_limits<double>::infinity();
  const FrictionErrors e = sized ? friction_errors(p, r.z) : FrictionErrors{inf, nan, nan};
  d["errors"] = errors_dict(e);
  pyb::list per;  // as `fc solve --json`'s per_contact (friction_verdict.hpp)
  if (sized)
    for (const ContactReport& c : friction_contacts(p, r.z)) {
      pyb::dict one;
      one["state"] = to_string(c.state);
      one["error"] = c.error;
      per.append(one);
    }
  d["per_contact"] = per;
  d["residuals"] = full["residuals"];
  d["iterations"] = r.iterations;
  d["seconds"] = r.seconds;
  d["attempts"] = full["attempts"];
  d["message"] = r.message;
  return d;
}

pyb::dict read_fclib(const std::string& path) {
  FrictionContactProblem p = without_gil([&] { return read_friction_problem(path); });
  pyb::dict d;
  d["W"] = p.W;  // scipy.sparse.csc_matrix (pybind11's Eigen caster)
  d["q"] = to_numpy(p.q);
  d["mu"] = to_numpy(p.mu);
  d["name"] = p.name;
  d["note"] = p.note;
  return d;
}

pyb::dict read_fclib_global(const std::string& path) {
  GlobalFrictionContactProblem p = without_gil([&] { return read_global_friction_problem(path); });
  pyb::dict d;
  d["M"] = p.M;
  d["H"] = p.H;
  d["f"] = to_numpy(p.f);
  d["w"] = to_numpy(p.w);
  d["mu"] = to_numpy(p.mu);
  d["name"] = p.name;
  d["note"] = p.note;
  return d;
}

const SolverEntry& friction_entry(const std::string& solver) {
  return find_solver(solver, ProblemKind::kFrictionContact, "friction solver");
}

/// The condensation route of `cpkit fc solve` on a global file (lcp/friction/global.hpp): the
/// local result's fields (of the condensed problem) plus v, dofs, condensed and global_errors.
pyb::dict solve_friction_global(const pyb::handle& M, const pyb::handle& H, const Vec& f,
                                const Vec& w, const Vec& mu, const std::string& solver,
                                double tol, double tol_acceptable, int max_iterations,
                                double time_limit, bool proximal) {
  const GlobalFrictionContactProblem g{sparse_from(M, "M"), sparse_from(H, "H"), f, w, mu,
                                       /*name=*/"", /*note=*/""};
  throw_if_invalid(g.validate(), "global friction problem");
  const CommonOptions o = fc_options(tol, tol_acceptable, max_iterations, time_limit);
  const SolverEntry& e = friction_entry(solver);
  lcp::friction::GlobalSolveResult out = without_gil([&] {
    return proximal ? lcp::friction::solve_global_proximal(g, e.info.name, o)
                    : lcp::friction::solve_global(g, e.info.name, o);
  });
  if (out.result.solver.empty()) out.result.solver = e.info.name;
  pyb::dict d = fc_result_dict(out.result, out.condensed.local);
  d["v"] = to_numpy(out.v);
  d["dofs"] = g.dofs();
  d["condensed"] = out.condensed.ok;
  // No v computed (M not condensed, no r): nothing was judged; None, never 0 (which reads as
  // perfect), as `cpkit fc solve --json` writes null.
  const bool judged = out.v.size() == g.dofs() && out.result.z.size() == g.H.cols();
  pyb::dict ge;
  ge["balance"] = judged ? pyb::object(pyb::float_(out.errors.balance)) : pyb::none();
  ge["local"] = judged ? pyb::object(pyb::float_(out.errors.local)) : pyb::none();
  d["global_errors"] = ge;
  return d;
}

pyb::dict solve_friction(const pyb::handle& W, const Vec& q, const Vec& mu,
                         const std::string& solver, double tol, double tol_acceptable,
                         int max_iterations, double time_limit, const std::string& measure) {
  const FrictionContactProblem p = make_problem(W, q, mu);
  const CommonOptions o = fc_options(tol, tol_acceptable, max_iterations, time_limit);
  const FrictionMeasure m = parse_friction_measure(measure, "measure");
  const SolverEntry* e = &friction_entry(solver);
  SolveResult r = without_gil([&] { return lcp::friction::solve_in_measure(p, *e, o, m); });
  return fc_result_dict(r, p);
}

pyb::dict friction_solutions(const pyb::handle& W, const Vec& q, const Vec& mu, int starts,
                             unsigned seed, double tol, double time_limit,
                             const std::string& measure) {
  const FrictionContactProblem p = make_problem(W, q, mu);
  const FrictionMeasure m = parse_friction_measure(measure, "measure");
  lcp::friction::FrictionSolutionsOptions o;
  o.common = fc_options(tol, CommonOptions{}.tol_acceptable, 0, time_limit);
  if (starts < 1) throw InputError("starts must be at least 1, got " + std::to_string(starts));
  o.starts = starts;
  o.seed = seed;
  throw_if_invalid(o.validate(), "friction_solutions options");
  lcp::friction::FrictionSolutionSet s =
      without_gil([&] {
        lcp::friction::FrictionSolutionSet set = lcp::friction::friction_solutions(p, o);
        for (auto& r : set.solutions)
          r = lcp::friction::refine_in_measure(p, std::move(r), o.common, m);
        return set;
      });
  pyb::dict d;
  d["solutions"] = list_of(s.solutions, [&](const SolveResult& r) { return fc_result_dict(r, p); });
  d["complete"] = s.complete;
  d["message"] = s.message;
  return d;
}

pyb::dict errors_of(const pyb::handle& W, const Vec& q, const Vec& mu, const Vec& r) {
  const FrictionContactProblem p = make_problem(W, q, mu);
  if (r.size() != p.W.rows())
    throw InputError("r must have 3 n_c = " + std::to_string(p.W.rows()) + " entries, got " +
                     std::to_string(r.size()));
  return errors_dict(friction_errors(p, r));
}

}  // namespace

void bind_friction(pyb::module_& m) {
  m.def("read_fclib", &read_fclib);
  m.def("solve_friction", &solve_friction);
  m.def("read_fclib_global", &read_fclib_global);
  m.def("solve_friction_global", &solve_friction_global);
  m.def("friction_solutions", &friction_solutions);
  m.def("friction_errors", &errors_of);
  m.def("friction_solvers",
        []() { return lcp::solvers().names(ProblemKind::kFrictionContact); });
}

}  // namespace cpkit::py
