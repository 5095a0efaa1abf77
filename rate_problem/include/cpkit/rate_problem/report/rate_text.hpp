#pragma once
/// \file rate_text.hpp
/// The text `cpkit rate` prints (without --json) for a RateOutcome, one point, N points or a 3-D
/// system: the heading, the count (or "solutions found ... INCOMPLETE", or a single solver's "a
/// solution ... not a count"), one line per solution (rates with 10 significant digits, in the
/// input's units), the note. Its JSON: rate_outcome_json (report/json.hpp).
#include <string>

#include "cpkit/rate_problem/report/rate_outcome.hpp"

namespace cpkit::rate {

/// The text of `outcome`, exactly as `cpkit rate` prints it on stdout (ends with a newline).
std::string rate_outcome_text(const RateOutcome& outcome);

}  // namespace cpkit::rate
