// A uniform double in [0, 1) from the 53 high bits of a 64-bit draw: the same sequence on every
// platform and standard library (std::uniform_real_distribution's is not specified), so a seeded
// run gives the same starts everywhere.
#pragma once

#include <random>

namespace cpkit::lcp::detail {

inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace cpkit::lcp::detail
