#pragma once
// Private to lcp/src: what the enumeration's three parts share. enumerate.cpp holds the entry
// point (equilibration, the small fixed-size cases, the final re-check), enumerate_engine.cpp
// the general engine (depth-first search over complementary bases), enumerate_bipartite.cpp the
// structured path for bimatrix games (vertex enumeration of two polytopes).
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/enumerate.hpp"

namespace cpkit::lcp::detail {

using Mask = std::uint64_t;  // supports of the general engine (n <= kMaxEnumerationSize)
inline constexpr double kGray = 1e4;        // gray band of the sign tests (as enumerate_small)
inline constexpr double kHuge = std::numeric_limits<double>::max();

inline bool finite(double x) { return std::abs(x) <= kHuge; }

inline constexpr double kPivotTol = 1e-10;  // tableau pivot threshold, relative to its row/column
// A tableau row proves infeasibility when q'_r < -kPruneTol * |q'_r|-magnitude (the sum of the
// absolute values of the q-terms that make up q'_r, a bound of its round-off scale) and no free
// column can raise it (T(r, c) > tol * max_c |T(r, c)|). The q part and the T part are measured
// separately: they have different units, and a tiny T(r, c) > 0 can raise any q'_r < 0.
inline constexpr double kPruneTol = 1e-9;
// Relative round-off allowed in a tableau coefficient (against its row's largest entry) when
// bounding the round-off of q': kPruneTol * kCoefNoise (1e-15) is above the few-ulp error of a
// coefficient after a few pivots, so noise never proves infeasibility (only costs pruning).
inline constexpr double kCoefNoise = 1e-6;
inline constexpr double kLeafTol = 1e-8;    // leaf pre-filter (the decision is made on a fresh solve)

/// The wall-clock limit shared by every phase (search, pieces, post-processing).
class Deadline {
 public:
  explicit Deadline(double limit_s) : limit_(limit_s) {}
  /// True once the limit has passed (checks the clock every `every` calls).
  bool passed(int every = 1) {
    if (hit_) return true;
    if (++calls_ % every != 0) return false;
    hit_ = clock_.seconds() > limit_;
    return hit_;
  }
  bool hit() const { return hit_; }

 private:
  Stopwatch clock_;
  double limit_;
  long long calls_ = 0;
  bool hit_ = false;
};

inline std::vector<int> basis_of(Mask S, int n) {
  std::vector<int> b(n);
  for (int i = 0; i < n; ++i) b[i] = (S >> i) & 1u ? i : ~i;
  return b;
}

inline std::vector<int> indices_of(Mask S, int n) {
  std::vector<int> idx;
  for (int i = 0; i < n; ++i)
    if ((S >> i) & 1u) idx.push_back(i);
  return idx;
}

/// Why the structured path did not answer: the general engine then decides (kUndecided), or,
/// on a budget, the answer is incomplete and says so.
enum class Structured { kAnswered, kUndecided, kTimeLimit, kMemory };

/// The general engine on the equilibrated problem in `work` (exact: the equilibration was exact).
void run_engine(const EnumerationOptions& opt, SolutionSet& work, Deadline& deadline, bool exact);

/// The structured path; kAnswered when it produced the complete answer in `out`; kUndecided
/// leaves `out` untouched (the general engine must run); on a budget (time, memory) `out`
/// says complete = false and why.
Structured try_bipartite(const EnumerationOptions& opt, SolutionSet& out, Deadline& deadline);

}  // namespace cpkit::lcp::detail
