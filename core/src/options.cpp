#include "cpkit/core/options.hpp"

#include <cmath>
#include <sstream>

namespace cpkit {

std::string CommonOptions::validate() const {
  // Runs on every solve: the stream is made only when there is something to say.
  const bool bad = !(tol > 0) || !std::isfinite(tol) || !(tol_acceptable >= tol) ||
                   !std::isfinite(tol_acceptable) || max_iterations < 0 || !(time_limit_s > 0) ||
                   verbosity < 0 || verbosity > 3;
  if (!bad) return {};
  std::ostringstream msg;
  if (!(tol > 0) || !std::isfinite(tol)) {
    msg << "tol must be a positive finite number (got " << tol << ")";
  } else if (!(tol_acceptable >= tol) || !std::isfinite(tol_acceptable)) {
    msg << "tol_acceptable must be finite and >= tol (got " << tol_acceptable << ", tol " << tol
        << ")";
  } else if (max_iterations < 0) {
    msg << "max_iterations must be >= 0 (got " << max_iterations << "; 0 = solver default)";
  } else if (!(time_limit_s > 0)) {
    msg << "time_limit_s must be > 0 (got " << time_limit_s << ")";
  } else if (verbosity < 0 || verbosity > 3) {
    msg << "verbosity must be in 0..3 (got " << verbosity << ")";
  }
  return msg.str();
}

}  // namespace cpkit
