#pragma once
/// \file short_number.hpp
/// A number with 3 significant digits, for messages ("residual 1.2e-09 > tol 1e-09"): enough to
/// read a size or compare with a tolerance, short enough for one line.
#include <sstream>
#include <string>

namespace cpkit {

inline std::string short_number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace cpkit
