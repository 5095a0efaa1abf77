#include "cpkit/rate_problem/step/step_solve.hpp"

#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/finalize.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::rate {

std::string StepSolveOptions::validate() const {
  std::string m = common.validate();
  if (!m.empty()) return m;
  if (chain.empty()) return "chain: the solver chain is empty";
  for (const auto& name : chain)
    if (name.empty()) return "chain: a solver name is empty";
  return {};
}

namespace {

void append(std::string& msg, const std::string& s) {
  if (!msg.empty()) msg += "; ";
  msg += s;
}

Attempt attempt_of(const SolveResult& r) {
  Attempt a;
  a.solver = r.solver;
  a.status = r.status;
  a.residual = r.residuals.natural;
  a.seconds = r.seconds;
  a.message = r.message;
  return a;
}

}  // namespace

StepSolveResult solve_step(const StepProblem& problem, const StepSolveOptions& options) {
  throw_if_invalid(problem.validate(), "step");
  throw_if_invalid(options.validate(), "step solve options");
  const StepNcp ncp = build_step_ncp_unchecked(problem);
  const McpProblem mcp = step_as_mcp(problem);
  StepSolveResult out;
  std::string skipped;
  std::vector<Attempt> attempts;
  SolveResult last;
  last.status = Status::kNotRun;
  StepValues active_set_values;  // the verified values and type of the active-set link's point
  SolutionType active_set_type = SolutionType::kStick;
  for (const auto& name : options.chain) {
    SolveResult r;
    if (name == "active-set") {
      Stopwatch sw;
      StepPoints pts;
      enumerate_step_points(problem, ncp, pts, options.common.tol_acceptable);
      if (pts.unrepresentable > 0)  // as enumerate_step and the rate problem: refused
        throw InputError("step: a solution is not representable in double precision (its "
                         "values overflow in these units)");
      r.solver = "active-set";
      if (pts.n == 0) {
        r.status = Status::kStalled;
        r.message = pts.infinite ? "the solutions form a continuum (use enumerate_step)"
                                 : pts.undecided > 0
                                       ? "active-set enumeration: no candidate verified, " +
                                             std::to_string(pts.undecided) +
                                             " neither verified nor rejected (ill-conditioned)"
                                       : "complete active-set enumeration found no solution";
        r.z = Vec::Zero(3);
        r.z[0] = problem.state.P_N0;
      } else {
        int best = 0;
        double bd = INFINITY;
        for (int i = 0; i < pts.n; ++i) {
          const StepValues v = step_values(problem, pts.points[i].DP_N, pts.points[i].xi);
          const double d = std::abs(v.DP_T) + std::abs(v.DP_N);
          if (d < bd) {
            bd = d;
            best = i;
          }
        }
        const StepValues& v = pts.points[best].values;
        active_set_values = v;
        active_set_type = pts.points[best].type;
        r.z = Vec(step_unknowns(v));
        r.status = Status::kSolved;  // a claim: finalize() decides
        r.message = std::to_string(pts.n) + " active-set solution(s); the closest to the start "
                    "state taken";
      }
      r.seconds = sw.seconds();
      r = finalize(mcp, r, options.common);
    } else {
      const SolverEntry* e = lcp::solvers().find(name);
      if (e == nullptr) {
        append(skipped, "solver '" + name + "' is not registered (skipped)");
        continue;
      }
      if (name == "lemke" || (!e->solve_mcp && e->solve_lcp)) {
        if (!ncp.is_lcp()) {
          append(skipped, "solver '" + name + "' skipped: the step is an LCP only without wear");
          continue;
        }
        if (!e->solve_lcp) {
          append(skipped, "solver '" + name + "' does not accept LCPs (skipped)");
          continue;
        }
        const LcpProblem lcp = step_as_lcp(problem);
        r = e->solve_lcp(lcp, options.common);
        r.solver = name;
        r = finalize(mcp, r, options.common);
      } else {
        if (!e->solve_mcp) {
          append(skipped, "solver '" + name + "' does not accept NCPs (skipped)");
          continue;
        }
        r = e->solve_mcp(mcp, options.common);
        r.solver = name;
        r = finalize(mcp, r, options.common);
      }
    }
    attempts.push_back(attempt_of(r));
    last = r;
    if (is_solution(r.status)) break;
  }
  static_cast<SolveResult&>(out) = last;
  out.attempts = attempts;
  if (!skipped.empty()) append(out.message, skipped);
  if (is_solution(last.status) && last.z.size() == 3) {
    // Physical values from z: DP_N = P_N1 - P_N0, xi = l+ - l-.
    StepPoint& pt = out.solution;
    pt.values = last.solver == "active-set"
                    ? active_set_values
                    : step_values(problem, last.z[0] - problem.state.P_N0, last.z[1] - last.z[2]);
    pt.type = last.solver == "active-set" ? active_set_type : classify_step(problem, pt.values);
    pt.DP_N = pt.values.DP_N;
    pt.xi = pt.values.Dw_Ti;
  }
  return out;
}

}  // namespace cpkit::rate
