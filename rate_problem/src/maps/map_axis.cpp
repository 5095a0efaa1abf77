// The checks of a map axis (map_axis.hpp), in the words each map kind has always used.
#include "cpkit/rate_problem/maps/map_axis.hpp"

#include <cmath>

namespace cpkit::rate {

template <>
std::string MapAxis::validate() const {
  if (n < 1) return "n must be >= 1, got " + std::to_string(n);
  if (n > 100000) return "n must be <= 100000, got " + std::to_string(n);
  if (!std::isfinite(from) || !std::isfinite(to)) return "axis range must be finite";
  if (n > 1 && !(from < to)) return "axis range needs from < to";
  return {};
}

template <>
std::string Map3dAxis::validate() const {
  if (n < 1 || n > 1000000) return "n must be in [1, 1000000]";
  if (!std::isfinite(from)) return "from must be finite";
  if (!std::isfinite(to)) return "to must be finite";
  if (n > 1 && !(from < to)) return "from must be < to";
  return {};
}

}  // namespace cpkit::rate
