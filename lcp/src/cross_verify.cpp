#include "cpkit/lcp/cross_verify.hpp"

#include <algorithm>
#include <exception>
#include <limits>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp {

std::string CrossVerifyOptions::validate() const {
  std::string m = enumeration.validate();
  if (!m.empty()) return m;
  m = solve.validate();
  if (!m.empty()) return m;
  if (!(membership_tol > 0 && membership_tol < 1))
    return "CrossVerifyOptions::membership_tol must lie in (0, 1), got " +
           std::to_string(membership_tol);
  return {};
}

std::string_view to_string(Verdict v) noexcept {
  switch (v) {
    case Verdict::kConsistent: return "consistent";
    case Verdict::kNoAnswer: return "no_answer";
    case Verdict::kNotASolution: return "not_a_solution";
    case Verdict::kInfeasibleButSolvable: return "infeasible_but_solvable";
    case Verdict::kProvesIncomplete: return "proves_enumeration_incomplete";
    case Verdict::kUnchecked: return "unchecked";
    case Verdict::kError: return "error";
  }
  return "unknown";
}

bool is_disagreement(Verdict v) noexcept {
  return v == Verdict::kNotASolution || v == Verdict::kInfeasibleButSolvable ||
         v == Verdict::kProvesIncomplete || v == Verdict::kError;
}

CrossVerifyReport cross_verify(const LcpProblem& problem, const CrossVerifyOptions& options) {
  return cross_verify(problem, options, solvers());
}

CrossVerifyReport cross_verify(const LcpProblem& problem, const CrossVerifyOptions& options,
                               const SolverRegistry& registry) {
  throw_if_invalid(problem.validate(), "cross_verify");
  throw_if_invalid(options.validate(), "cross_verify");
  CrossVerifyReport rep;
  rep.set = enumerate_all(problem, options.enumeration);
  const SolutionSet& set = rep.set;
  for (const SolverEntry& entry : registry.entries()) {
    if (!entry.solve_lcp || !entry.accepts(problem)) continue;
    if (std::find(options.skip.begin(), options.skip.end(), entry.info.name) != options.skip.end())
      continue;
    SolverCheck c;
    c.solver = entry.info.name;
    Stopwatch clock;
    SolveResult r;
    try {
      r = entry.solve_lcp(problem, options.solve);
    } catch (const std::exception& e) {
      c.seconds = clock.seconds();
      c.verdict = Verdict::kError;
      c.message = e.what();
      rep.disagreements.push_back(c.solver + ": threw on an accepted problem: " + c.message);
      rep.checks.push_back(std::move(c));
      continue;
    }
    c.seconds = clock.seconds();
    c.status = r.status;
    c.message = r.message;
    if (r.z.size() == problem.size() && r.z.allFinite()) {
      Vec w;
      const Residuals res = lcp_residuals(problem, r.z, w);
      c.residual = res.finite ? res.natural : std::numeric_limits<double>::infinity();
      c.data_residual = res.natural_abs;
    } else {
      c.residual = c.data_residual = std::numeric_limits<double>::infinity();
    }
    if (is_solution(r.status)) {
      // finalize()'s own number and band (residuals.hpp): one definition of "within tolerance".
      if (!(c.residual <= options.solve.tol_acceptable)) {
        c.verdict = Verdict::kNotASolution;
        std::ostringstream m;
        m << c.solver << ": status " << to_string(r.status) << " but the unit-free residual is "
          << c.residual << " > tol_acceptable " << options.solve.tol_acceptable
          << " (||min(z, w)||_inf = " << c.data_residual << " at ||z||_inf = "
          << r.z.cwiseAbs().maxCoeff() << ")";
        rep.disagreements.push_back(m.str());
      } else {
        // The membership tolerance is at least the answer's own residual: a point finalize()
        // accepted can never be "missing" from the set by tolerance alone.
        const double mtol = std::max(options.membership_tol, c.residual);
        c.in_set = set.contains(r.z, mtol);
        const double zn = r.z.cwiseAbs().maxCoeff();
        for (size_t k = 0; k < set.solutions.size(); ++k)
          if ((set.solutions[k].z - r.z).cwiseAbs().maxCoeff() <=
              mtol * std::max(zn, set.solutions[k].z.cwiseAbs().maxCoeff())) {
            c.solution_index = static_cast<int>(k);
            break;
          }
        if (c.in_set) {
          c.verdict = Verdict::kConsistent;
        } else if (set.complete) {
          c.verdict = Verdict::kProvesIncomplete;
          rep.disagreements.push_back(c.solver +
                                      ": a verified solution (residual " +
                                      std::to_string(c.residual) +
                                      ") is not in the enumerated solution set");
        } else {
          c.verdict = Verdict::kUnchecked;
        }
      }
    } else if (r.status == Status::kInfeasible) {
      if (!set.solutions.empty()) {
        c.verdict = Verdict::kInfeasibleButSolvable;
        rep.disagreements.push_back(c.solver + ": reports infeasible, but the enumeration found " +
                                    std::to_string(set.solutions.size()) + " solution(s)");
      } else {
        c.verdict = set.complete ? Verdict::kConsistent : Verdict::kUnchecked;
      }
    } else {
      c.verdict = Verdict::kNoAnswer;
    }
    rep.checks.push_back(std::move(c));
  }
  return rep;
}

}  // namespace cpkit::lcp
