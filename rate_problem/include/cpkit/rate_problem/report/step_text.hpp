#pragma once
/// \file step_text.hpp
/// The text `cpkit step` prints (without --json) for the answer of a request
/// (report/step_outcome.hpp), written once here for the program, Python and tests: one 2-D point
/// (every solution, or the chain's answer), N 2-D points, one 3-D point, N coupled 3-D points.
/// Numbers with 10 significant digits (residuals and slip angles 6); units as the input's.
#include <string>

#include "cpkit/rate_problem/report/step_outcome.hpp"

namespace cpkit::rate {

/// The lines printed to stdout, each ending in '\n'.
std::string step_text(const StepOutcome& outcome);

}  // namespace cpkit::rate
