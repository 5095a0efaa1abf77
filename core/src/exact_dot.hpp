#pragma once
/// \file exact_dot.hpp
/// The exact sign of a dot product of doubles, for certificates that magnitudes cannot fool.
///
/// Each product a_i b_i is split exactly into p + e (p = fl(a b), e = fma(a, b, -p)) and all
/// parts are summed into a non-overlapping expansion with error-free transformations
/// [Shewchuk 1997, Discrete Comput. Geom. 18]. The result is the exact sum except where a product
/// underflows (|a b| below 2^-969, where e may be rounded): each such product adds 2^-1074 to
/// an error bound. The sign is decided only when the exact value exceeds that bound and no
/// product or partial sum overflowed.
#include <cstddef>

namespace cpkit::detail {

/// +1, -1 or 0 when the sign is proven; `unknown` is set when it could not be decided
/// (overflow, or a value within the underflow error bound).
class ExactDot {
 public:
  void add_product(double a, double b);
  /// Sign of the sum so far; sets `decided` to false when it cannot be proven.
  int sign(bool& decided) const;
  /// The sum rounded to double (information only).
  double value() const;
  void clear();

 private:
  void grow(double b);
  static constexpr std::size_t kMax = 64;  // non-overlapping doubles span < 40 components
  double parts_[kMax];
  std::size_t count_ = 0;
  double underflow_bound_ = 0;
  bool overflow_ = false;
};

}  // namespace cpkit::detail
