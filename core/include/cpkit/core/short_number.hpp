#pragma once
/// \file short_number.hpp
/// A number with 3 significant digits, for messages ("residual 1.2e-09 > tol 1e-09"): enough to
/// read a size or compare with a tolerance, short enough for one line.
#include <cstdio>
#include <string>

namespace cpkit {

/// printf's "%.3g" (what an ostream at precision 3 prints, without building a stream and its
/// locale: a one-contact solve formats a few of these, and the stream was a fifth of its cost).
inline std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace cpkit
