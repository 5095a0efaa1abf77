#include "exact_dot.hpp"

#include <cmath>

namespace cpkit::detail {
namespace {

// Knuth's TwoSum: s + t == a + b exactly (no overflow assumed; checked by the caller).
inline void two_sum(double a, double b, double& s, double& t) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  t = (a - av) + (b - bv);
}

constexpr double kTinyProduct = 0x1p-969;  // below it fma's error term may be rounded
constexpr double kSmallestSubnormal = 0x1p-1074;

}  // namespace

void ExactDot::clear() {
  count_ = 0;
  underflow_bound_ = 0;
  overflow_ = false;
}

// Shewchuk's GROW-EXPANSION with zero elimination; components stay in increasing magnitude
// and non-overlapping, so their number is bounded by the exponent range / 53.
void ExactDot::grow(double b) {
  if (b == 0 || overflow_) return;
  double q = b;
  std::size_t out = 0;
  for (std::size_t i = 0; i < count_; ++i) {
    double s, t;
    two_sum(q, parts_[i], s, t);
    if (!std::isfinite(s)) {
      overflow_ = true;
      return;
    }
    q = s;
    if (t != 0) parts_[out++] = t;
  }
  if (q != 0) {
    if (out == kMax) {  // cannot happen for non-overlapping doubles; refuse rather than guess
      overflow_ = true;
      return;
    }
    parts_[out++] = q;
  }
  count_ = out;
}

void ExactDot::add_product(double a, double b) {
  if (a == 0 || b == 0) return;
  const double p = a * b;
  if (!std::isfinite(p) || !std::isfinite(a) || !std::isfinite(b)) {
    overflow_ = true;
    return;
  }
  const double e = std::fma(a, b, -p);
  if (std::abs(p) < kTinyProduct) underflow_bound_ += kSmallestSubnormal;
  grow(p);
  grow(e);
}

int ExactDot::sign(bool& decided) const {
  decided = false;
  if (overflow_) return 0;
  if (count_ == 0) {
    decided = underflow_bound_ == 0;
    return 0;
  }
  // The largest component dominates the sum of the others (non-overlapping expansion).
  const double top = parts_[count_ - 1];
  const double v = value();
  if (std::abs(v) <= 2 * underflow_bound_) return 0;
  decided = true;
  return top > 0 ? 1 : -1;
}

double ExactDot::value() const {
  double v = 0;
  for (std::size_t i = 0; i < count_; ++i) v += parts_[i];
  return v;
}

}  // namespace cpkit::detail
