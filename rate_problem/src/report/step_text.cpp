#include "cpkit/rate_problem/report/step_text.hpp"

#include <sstream>

#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "piece_report.hpp"

namespace cpkit::rate {
namespace {

std::string values_text(const StepValues& v) {
  std::ostringstream o;
  o.precision(10);
  o << "DP_T=" << v.DP_T << " DP_N=" << v.DP_N << " Dw_T=" << v.Dw_T << " Dw_N=" << v.Dw_N
    << " Dw_Ti=" << v.Dw_Ti << " Dw_w=" << v.Dw_w << " | P_T1=" << v.P_T1 << " P_N1=" << v.P_N1
    << " g1=" << v.g1;
  return o.str();
}

std::string count_text(int count) {
  return count < 0 ? std::string("infinitely many") : std::to_string(count);
}

/// --all of one 2-D point: the count, each piece (point, segment, ray), the notes.
void point_all_text(std::ostream& out, const StepSolutionSet& s) {
  out << "step: " << count_text(s.count()) << " solution(s)";
  if (s.continuous_count >= 0)
    out << ", " << s.continuous_count << " continuous (rate-consistent)";
  if (!s.complete) out << " (NOT proved complete)";
  out << "\n";
  for (const auto& sol : s.solutions) {
    out << "  " << to_string(sol.type) << " (" << to_string(sol.kind)
        << (sol.jump ? ", jump" : "") << "): ";
    report_detail::piece_text(out, sol, "from ", " ", values_text);
  }
  if (s.continuous_count == 0 && !s.solutions.empty())
    out << "note: every solution is a jump: the rate problem has no solution in this "
           "load direction\n";
  if (!s.complete) out << "note: " << s.message << "\n";
}

/// The chain's answer for one 2-D point, and out of how many solutions an active-set answer
/// was picked.
void point_chain_text(std::ostream& out, const StepOutcome& o) {
  const StepSolveResult& r = o.one;
  out << "status: " << to_string(r.status) << " (solver " << r.solver
      << ", residual " << r.residuals.natural << ")\n";
  if (is_solution(r.status))
    out << "  " << to_string(r.solution.type) << ": " << values_text(r.solution.values) << "\n";
  if (!r.message.empty()) out << "note: " << r.message << "\n";
  if (o.has_enumeration) {
    const StepSolutionSet& all = o.set;
    out << "1 of " << count_text(all.count()) << (all.count() == 1 ? " solution" : " solutions")
        << (all.complete ? "" : " found (the enumeration is NOT proved complete)")
        << (all.count() == 1 ? "" : "; --all lists them") << "\n";
  }
}

void system_text(std::ostream& out, const StepOutcome& o) {
  const SystemStepSolutionSet& s = o.system_set;
  out << "step (" << o.system_problem.system.n_points() << " points): " << s.solutions.size()
      << " solution(s)" << (s.complete ? " (complete)" : " (NOT proved complete)") << "\n";
  for (const auto& sol : s.solutions) {
    out << "  " << types_string(sol.types) << "\n";
    for (std::size_t i = 0; i < sol.values.size(); ++i)
      out << "    point " << i + 1 << ": " << values_text(sol.values[i]) << "\n";
  }
  for (const auto& n : s.notes) out << "note: " << n << "\n";
}

std::string solution_3d_text(const Step3dSolution& s) {
  const Step3dValues& v = s.values;
  std::ostringstream o;
  o.precision(10);
  o << to_string(s.type) << ": P_T1=[" << v.P_T1(0) << ", " << v.P_T1(1) << "] P_N1=" << v.P_N1
    << " DP=[" << v.DP_T(0) << ", " << v.DP_T(1) << ", " << v.DP_N << "] Dw=[" << v.Dw_T(0)
    << ", " << v.Dw_T(1) << ", " << v.Dw_N << "] Dw_Ti=[" << v.Dw_Ti(0) << ", " << v.Dw_Ti(1)
    << "] Dw_w=" << v.Dw_w << " lambda=" << v.lambda;
  o.precision(6);
  if (s.type == SolutionType::kSlip) o << " slip_angle=" << s.slip_angle;
  o << " residual=" << s.residual;
  return o.str();
}

/// One 3-D point or N coupled 3-D points: the mode's header, the solutions, the note.
void step_3d_text(std::ostream& out, const StepOutcome& oc) {
  const Step3dOutcome& o = oc.step_3d;
  const int N = o.n_points();
  const std::string name = o.system.name.empty() ? oc.system : o.system.name;
  const bool found = o.status == Status::kSolved;
  if (N == 1) {
    out << "step, 3-D point " << name << " (state " << o.system.points[0].state.state << "), ";
  } else {
    out << "step, " << N << " coupled 3-D points " << name << " (states ";
    for (const auto& pt : o.system.points) out << pt.state.state;
    out << "), ";
  }
  if (o.mode == "chain" && N == 1) {
    out << "solver chain: " << (found ? "solved by " + o.solver : "no solution found") << "\n";
  } else if (o.mode == "chain") {
    out << "FB-SOC Newton: "
        << (found ? "solved in " + std::to_string(o.iterations) + " iterations"
                   : "no solution found")
        << "\n";
  } else {
    out << (o.mode == "all"      ? "exact"
            : o.mode == "facets" ? "faceted with " + std::to_string(oc.facets) + " facets"
                                 : "multistart")
        << "\n";
    const bool complete = N == 1 && o.set.complete;
    const int count = N == 1 ? o.set.count() : o.system_set.count();
    if (complete) out << "count: " << count << "\n";
    else out << "solutions found: " << count << " (NOT proved complete: not a count)\n";
  }
  if (N == 1) {
    for (const auto& s : o.set.solutions) out << "  " << solution_3d_text(s) << "\n";
  } else {
    int k = 0;
    for (const auto& s : o.system_set.solutions) {
      std::ostringstream r;
      r.precision(6);
      r << s.residual;
      out << "  solution " << ++k << " (residual " << r.str() << "):\n";
      int i = 0;
      for (const auto& x : s.points) out << "    point " << ++i << " " << solution_3d_text(x) << "\n";
    }
  }
  const std::string& message = N == 1 ? o.set.message : o.system_set.message;
  if (!message.empty()) out << "note: " << message << "\n";
}

}  // namespace

std::string step_text(const StepOutcome& outcome) {
  std::ostringstream out;
  switch (outcome.route) {
    case StepRoute::kPointAll:
      point_all_text(out, outcome.set);
      break;
    case StepRoute::kPointChain:
      point_chain_text(out, outcome);
      break;
    case StepRoute::kSystem:
      system_text(out, outcome);
      break;
    case StepRoute::kPoint3d:
    case StepRoute::kSystem3d:
      step_3d_text(out, outcome);
      break;
  }
  return out.str();
}

}  // namespace cpkit::rate
