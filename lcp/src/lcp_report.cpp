// The text and JSON of `cpkit lcp solve|verify|enumerate` (docs/cli.md): field names and text are
// what users script against, kept character for character.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cpkit/core/report.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/lcp_request.hpp"

namespace cpkit::lcp {
namespace {

/// The JSON object printed for one result (to_json plus the problem's name when known).
nlohmann::json result_json(const SolveResult& r, const LcpProblem& problem) {
  nlohmann::json j = to_json(r);
  if (!problem.name.empty()) j["problem"] = problem.name;
  return j;
}

/// The text report printed for one result (with the pivot/iteration trace when recorded).
std::string result_text(const SolveResult& r, const LcpProblem& problem) {
  std::ostringstream s;
  if (!problem.name.empty()) s << "problem:    " << problem.name << " (n = " << problem.size()
                               << ")\n";
  s << to_text(r);
  if (!r.trace.empty()) {
    // Pivoting methods number the variables 0..n-1 = z_i, n = z0, n+1+i = w_i.
    const Eigen::Index n = problem.size();
    auto var = [n](int id) {
      if (id < n) return "z" + std::to_string(id + 1);
      if (id == n) return std::string("z0");
      return "w" + std::to_string(id - n);
    };
    s << "trace:\n";
    for (const auto& e : r.trace) {
      s << "  " << e.iteration << ' ' << e.kind;
      if (e.entering >= 0 && e.leaving >= 0)
        s << ": " << var(e.entering) << " enters, " << var(e.leaving) << " leaves";
      s << " (step " << e.step << ", residual " << e.residual << ")\n";
    }
  }
  return s.str();
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

/// consistent (complete and no disagreement), disagreement (any, even against an incomplete
/// enumeration: those verdicts do not depend on completeness), inconclusive (otherwise).
std::string verdict_name(const CrossVerifyReport& rep) {
  if (!rep.consistent()) return "disagreement";
  return rep.set.complete ? "consistent" : "inconclusive";
}

nlohmann::json report_json(const CrossVerifyReport& rep, const LcpProblem& p) {
  nlohmann::json j;
  if (!p.name.empty()) j["problem"] = p.name;
  const SolutionSet& s = rep.set;
  j["enumeration"] = {{"complete", s.complete},
                      {"count", s.infinite ? nlohmann::json("inf") : nlohmann::json(s.count())},
                      {"continuum", s.infinite},
                      {"num_extreme", s.count()},
                      {"ambiguous", s.ambiguous},
                      {"seconds", s.seconds}};
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& c : rep.checks)
    rows.push_back({{"solver", c.solver},
                    {"status", std::string(to_string(c.status))},
                    {"residual", number_or_null(c.residual)},
                    {"data_residual", number_or_null(c.data_residual)},
                    {"in_set", c.in_set},
                    {"solution_index", c.solution_index},
                    {"verdict", std::string(to_string(c.verdict))},
                    {"seconds", c.seconds},
                    {"message", c.message}});
  j["solvers"] = rows;
  j["disagreements"] = rep.disagreements;
  // "consistent" only when the check was conclusive: an incomplete enumeration verifies nothing.
  j["consistent"] = rep.consistent() && s.complete;
  j["verdict"] = verdict_name(rep);
  return j;
}

std::string report_text(const CrossVerifyReport& rep, const LcpProblem& p) {
  std::ostringstream o;
  const SolutionSet& s = rep.set;
  if (!p.name.empty()) o << "problem: " << p.name << " (n = " << p.size() << ")\n";
  o << "enumeration: " << (s.complete ? "complete" : "INCOMPLETE") << ", "
    << (s.infinite ? "infinite (continuum), " : "") << s.count() << " extreme solution(s)";
  if (s.ambiguous) o << ", " << s.ambiguous << " ambiguous sign test(s)";
  o << '\n';
  char line[256];
  std::snprintf(line, sizeof line, "%-12s %-18s %-11s %-11s %-7s %-30s %9s\n", "solver", "status",
                "residual", "data_res", "in_set", "verdict", "seconds");
  o << line;
  for (const auto& c : rep.checks) {
    const std::string in = cpkit::is_solution(c.status)
                               ? (c.in_set ? (c.solution_index >= 0 ? "#" + std::to_string(c.solution_index)
                                                                   : std::string("piece"))
                                           : std::string("NO"))
                               : std::string("-");
    std::snprintf(line, sizeof line, "%-12s %-18s %-11.3g %-11.3g %-7s %-30s %9.4f\n",
                  c.solver.c_str(), std::string(to_string(c.status)).c_str(), c.residual,
                  c.data_residual, in.c_str(), std::string(to_string(c.verdict)).c_str(),
                  c.seconds);
    o << line;
  }
  if (rep.consistent() && s.complete) {
    o << "consistent: every solver agrees with the enumeration\n";
  } else if (rep.consistent()) {
    o << "INCONCLUSIVE: the enumeration is incomplete"
      << (s.message.empty() ? std::string() : " (" + s.message + ")")
      << "; no solver contradicted the solutions found so far, but answers outside them could "
         "not be checked (raise --time-limit)\n";
  } else {
    o << "DISAGREEMENTS (" << rep.disagreements.size() << "):\n";
    for (const auto& d : rep.disagreements) o << "  " << d << '\n';
  }
  return o.str();
}

nlohmann::json set_json(const SolutionSet& s, const LcpProblem& p) {
  nlohmann::json j;
  if (!p.name.empty()) j["problem"] = p.name;
  j["n"] = p.size();
  j["complete"] = s.complete;
  if (s.infinite)
    j["count"] = "inf";
  else
    j["count"] = s.count();
  j["num_extreme"] = s.count();
  j["continuum"] = s.infinite;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& e : s.solutions)
    sols.push_back({{"z", to_json(e.z)}, {"w", to_json(e.w)}, {"basis", e.basis}});
  j["solutions"] = sols;
  if (s.infinite) {
    nlohmann::json dirs = nlohmann::json::array();
    for (const auto& d : s.directions) dirs.push_back(to_json(d));
    j["directions"] = dirs;
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& pc : s.pieces) {
      nlohmann::json rays = nlohmann::json::array();
      for (const auto& r : pc.rays) rays.push_back(to_json(r));
      pieces.push_back({{"support", pc.support}, {"vertices", pc.vertices}, {"rays", rays}});
    }
    j["pieces"] = pieces;
  }
  j["ambiguous"] = s.ambiguous;
  j["nodes"] = s.nodes;
  j["seconds"] = s.seconds;
  j["message"] = s.message;  // always present (documented field; empty when nothing to say)
  return j;
}

std::string vec_text(const Vec& v) {
  std::ostringstream o;
  o << '[';
  for (Eigen::Index i = 0; i < v.size(); ++i) o << (i ? ", " : "") << v(i);
  o << ']';
  return o.str();
}

std::string set_text(const SolutionSet& s, const LcpProblem& p) {
  std::ostringstream o;
  if (!p.name.empty()) o << "problem:    " << p.name << " (n = " << p.size() << ")\n";
  o << "complete:   " << (s.complete ? "yes" : "NO") << '\n';
  if (s.complete)
    o << "count:      " << (s.infinite ? std::string("inf (a continuum)") : std::to_string(s.count()))
      << '\n';
  else
    o << "count:      at least " << (s.infinite ? std::string("a continuum") : std::to_string(s.count()))
      << " (the enumeration is INCOMPLETE: more solutions may exist)\n";
  o << "extreme solutions: " << s.count() << '\n';
  for (size_t k = 0; k < s.solutions.size(); ++k)
    o << "  " << k << ": z = " << vec_text(s.solutions[k].z) << "  w = " << vec_text(s.solutions[k].w)
      << '\n';
  if (s.infinite) {
    o << "pieces of positive dimension: " << s.pieces.size() << '\n';
    for (const auto& pc : s.pieces) {
      o << "  support {";
      for (size_t i = 0; i < pc.support.size(); ++i) o << (i ? ", " : "") << pc.support[i];
      o << "}: vertices {";
      for (size_t i = 0; i < pc.vertices.size(); ++i) o << (i ? ", " : "") << pc.vertices[i];
      o << "}";
      for (const auto& r : pc.rays) o << " ray " << vec_text(r);
      o << '\n';
    }
    o << "directions: " << s.directions.size() << '\n';
    for (const auto& d : s.directions) o << "  " << vec_text(d) << '\n';
  }
  if (s.ambiguous) o << "ambiguous sign tests: " << s.ambiguous << '\n';
  if (!s.message.empty()) o << "message:    " << s.message << '\n';
  o << "time:       " << s.seconds << " s\n";
  return o.str();
}

}  // namespace

nlohmann::json lcp_solve_json(const LcpSolveOutcome& out) {
  const LcpProblem& problem = out.problem;
  if (!out.all_solvers) {
    nlohmann::json j = result_json(out.results.front(), problem);
    if (!out.hint.empty()) j["hint"] = out.hint;
    return j;
  }
  // One object, like every --json output: the problem, then one result per solver.
  nlohmann::json arr = nlohmann::json::array();
  for (std::size_t k = 0; k < out.results.size(); ++k) {
    nlohmann::json j = result_json(out.results[k], problem);
    j["entry"] = out.entries[k];  // the registry entry run ("solver" is who produced z)
    arr.push_back(j);
  }
  nlohmann::json j;
  if (!problem.name.empty()) j["problem"] = problem.name;
  j["n"] = problem.size();
  j["solved_by_any"] = out.exit_code == kExitOk;
  j["results"] = arr;
  if (!out.hint.empty()) j["hint"] = out.hint;
  return j;
}

std::string lcp_solve_text(const LcpSolveOutcome& out) {
  const LcpProblem& problem = out.problem;
  const std::string hint = out.hint.empty() ? std::string() : "hint:       " + out.hint + "\n";
  if (!out.all_solvers) return result_text(out.results.front(), problem) + hint;
  std::ostringstream s;
  if (!problem.name.empty()) s << "problem: " << problem.name << " (n = " << problem.size() << ")\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-12s %-18s %-12s %-10s %-10s %s\n", "solver", "status",
                "residual", "iterations", "seconds", "answered by");
  s << line;
  for (std::size_t k = 0; k < out.results.size(); ++k) {
    const SolveResult& r = out.results[k];
    std::snprintf(line, sizeof line, "%-12s %-18s %-12.3g %-10d %-10.4f %s\n",
                  out.entries[k].c_str(), std::string(to_string(r.status)).c_str(),
                  r.residuals.natural, r.iterations, r.seconds, r.solver.c_str());
    s << line;
  }
  return s.str() + hint;
}

nlohmann::json lcp_verify_json(const LcpVerifyOutcome& out) {
  return report_json(out.result, out.problem);
}

std::string lcp_verify_text(const LcpVerifyOutcome& out) {
  return report_text(out.result, out.problem);
}

nlohmann::json lcp_enumerate_json(const LcpEnumerateOutcome& out) {
  return set_json(out.result, out.problem);
}

std::string lcp_enumerate_text(const LcpEnumerateOutcome& out) {
  return set_text(out.result, out.problem);
}

}  // namespace cpkit::lcp
