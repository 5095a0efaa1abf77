#pragma once
// The C API's checks of raw input arrays, before anything is copied or solved, in the words of
// the messages of cpkit.h's callers (argument names as declared there).
#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"

namespace cpkit::capi {

/// InputError "<what> has a non-finite entry (NaN or Inf) at index i" for the first bad entry
/// of a[0..size).
inline void check_finite(const double* a, long long size, const std::string& what) {
  for (long long i = 0; i < size; ++i)
    if (!std::isfinite(a[i]))
      throw InputError(what + " has a non-finite entry (NaN or Inf) at index " +
                       std::to_string(i));
}

/// True when a[0..size) is all finite (the batched calls' check: no message built per problem).
inline bool all_finite(const double* a, long long size) {
  for (long long i = 0; i < size; ++i)
    if (!std::isfinite(a[i])) return false;
  return true;
}

/// InputError unless value >= 1 ("<what> must be >= 1, got value").
inline void check_positive(int value, const char* what) {
  if (value < 1) throw InputError(std::string(what) + " must be >= 1, got " + std::to_string(value));
}

}  // namespace cpkit::capi
