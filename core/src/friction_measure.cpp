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
  decide_in_measure(p, r, o, m, friction_errors(p, r.z));
}

void decide_in_measure(const FrictionContactProblem& p, SolveResult& r, const CommonOptions& o,
                       FrictionMeasure m, const FrictionErrors& e) {
  if (m == FrictionMeasure::kUnitFree || r.z.size() == 0 || r.z.size() != p.q.size() ||
      !r.z.allFinite() || !is_solution(r.status))
    return;
  if (!(e.unit_free <= o.tol_acceptable)) return;
  const double v = measured(e, m);
  const std::string name = to_string(m);
  if (v <= o.tol) {
    r.status = Status::kSolved;
    detail::append(r.message, name + " " + short_number(v) + " <= tol " + short_number(o.tol) +
                                  " (unit-free " + short_number(e.unit_free) + ")");
  } else if (v <= o.tol_acceptable) {
    r.status = Status::kSolvedInaccurate;
    detail::append(r.message, name + " " + short_number(v) + " above tol " + short_number(o.tol));
  } else {
    r.status = Status::kNumericalFailure;
    detail::append(r.message, "not a solution in " + name + ": " + short_number(v) +
                                  " > tol_acceptable " + short_number(o.tol_acceptable) +
                                  " (unit-free " + short_number(e.unit_free) + ")");
  }
}

}  // namespace cpkit
