// The measure that decides "solved" for a frictional contact answer (friction_measure.hpp).
#include "cpkit/core/friction_measure.hpp"

#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/short_number.hpp"
#include "cpkit/core/status.hpp"
#include "finalize_decide.hpp"

namespace cpkit {

const char* to_string(FrictionMeasure m) noexcept {
  switch (m) {
    case FrictionMeasure::kUnitFree: return "unit_free";
    case FrictionMeasure::kRelativeQ: return "relative_q";
    case FrictionMeasure::kRelativeMax: return "relative_max";
  }
  return "?";
}

std::optional<FrictionMeasure> friction_measure_from_string(std::string_view name) noexcept {
  for (FrictionMeasure m : {FrictionMeasure::kUnitFree, FrictionMeasure::kRelativeQ,
                            FrictionMeasure::kRelativeMax})
    if (name == to_string(m)) return m;
  return std::nullopt;
}

std::string friction_measure_names() { return "unit_free, relative_q, relative_max"; }

FrictionMeasure parse_friction_measure(const std::string& name, const std::string& option) {
  if (auto m = friction_measure_from_string(name)) return *m;
  throw InputError("unknown measure '" + name + "' for " + option + " (valid: " +
                   friction_measure_names() + ")");
}

double measured(const FrictionErrors& e, FrictionMeasure m) noexcept {
  switch (m) {
    case FrictionMeasure::kUnitFree: return e.unit_free;
    case FrictionMeasure::kRelativeQ: return e.relative_q;
    case FrictionMeasure::kRelativeMax: return e.relative_max;
  }
  return e.unit_free;
}

void decide_in_measure(const FrictionContactProblem& p, SolveResult& r, const CommonOptions& o,
                       FrictionMeasure m) {
  if (m == FrictionMeasure::kUnitFree || r.z.size() == 0 || r.z.size() != p.q.size() ||
      !r.z.allFinite())
    return;
  // The trust check: what the verdict refutes or cannot verify is never a solution (finalize()
  // called it no solution; for a global problem the global verdict did).
  if (!is_solution(r.status)) return;
  // finalize() stored z's errors with its verdict; a result decided elsewhere is judged here.
  decide_in_measure(p, r, o, m, r.friction_errors ? *r.friction_errors : friction_errors(p, r.z));
}

void decide_in_measure(const FrictionContactProblem& p, SolveResult& r, const CommonOptions& o,
                       FrictionMeasure m, const FrictionErrors& e) {
  if (m == FrictionMeasure::kUnitFree || r.z.size() == 0 || r.z.size() != p.q.size() ||
      !r.z.allFinite() || !is_solution(r.status))
    return;
  if (!(e.unit_free <= o.tol_acceptable)) return;
  const double v = measured(e, m);
  // The reason, appended piece by piece (a small solve's hot path: no temporaries).
  std::string text;
  text.reserve(96);
  const char* name = to_string(m);
  if (v <= o.tol) {
    r.status = Status::kSolved;
    text.append(name).append(" ").append(short_number(v)).append(" <= tol ");
    text.append(short_number(o.tol)).append(" (unit-free ").append(short_number(e.unit_free));
    text.append(")");
  } else if (v <= o.tol_acceptable) {
    r.status = Status::kSolvedInaccurate;
    text.append(name).append(" ").append(short_number(v)).append(" above tol ");
    text.append(short_number(o.tol));
  } else {
    r.status = Status::kNumericalFailure;
    text.append("not a solution in ").append(name).append(": ").append(short_number(v));
    text.append(" > tol_acceptable ").append(short_number(o.tol_acceptable));
    text.append(" (unit-free ").append(short_number(e.unit_free)).append(")");
  }
  detail::append(r.message, text);
}

}  // namespace cpkit
