#pragma once
// Internal: the rounding level at which the pivoting codes of lcp/ (Lemke's lexicographic ratio
// test, lemke.cpp; the lexicographic simplex of the polytope traversal, enumerate.cpp) call two
// computed ratios or entries equal. A fixed tolerance (1e-9) used as the tie criterion merged
// real differences: q spanning 0.01 and 1e-10 gave ratios 1.8e-10 apart, 1e5 times their
// rounding, and the "tie" broken on the perturbation columns was not the lexicographic minimum
// (issue 24, item 7: Lemke cycled; the polytope traversal gave up on games whose rows are in
// other units and fell back to a search 100x slower, or to the time limit).
#include <algorithm>
#include <limits>

namespace cpkit::lcp::detail {

/// Window in which a near tie is looked for (relative to the sizes of the numbers compared):
/// decisions outside it are clear at any rounding; inside it, they are made at tie_level().
constexpr double kTieWindow = 1e-9;

/// Relative rounding level of numbers formed from `terms` products (k + 1 for a basis of size
/// k): a few ulps per term (64 eps (terms)), or `backward_error` times a margin of 4 when the
/// factors carry a measured backward error that is larger; never above kTieWindow. Two numbers
/// are tied when they differ by at most this level times the size of their terms.
inline double tie_level(int terms, double backward_error) {
  const double eps = std::numeric_limits<double>::epsilon();
  return std::min(kTieWindow, std::max(64 * eps * std::max(terms, 1), 4 * backward_error));
}

}  // namespace cpkit::lcp::detail
