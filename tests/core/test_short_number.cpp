// short_number (short_number.hpp) against printf's "%.3g" itself, the definition it reproduces:
// hand-picked edges (decades, ties, the %f / %e switch, the fast path's range ends, signs,
// zeros, non-finite) and random doubles over the whole exponent range.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "../test_budget.hpp"
#include "cpkit/core/short_number.hpp"

namespace {

std::string printf_g3(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

TEST_CASE("short_number is printf's %.3g: edges", "[short_number]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double edges[] = {0.0, -0.0, 1.0, -1.0, 1e-8, 1e-9, 1e-10, 1e-6, 1e-15, 2.2e-16,
                          0.0001, 0.00001, 9.995e-5, 9.9949e-5, 9.9951e-5, 0.001, 0.01, 0.1,
                          0.25, 0.125, 1.5, 2.5, 1.005, 1.015, 1.235, 99.95, 99.949, 100,
                          999.4, 999.5, 999.6, 1000, 1234.5, 12345, 1e5, 1e6, 1.2e21, 9.999e21,
                          1e22, 1e-20, 9.999e-21, 1e-21, 1e300, 5e-324, 1e-310, inf, -inf,
                          std::nan(""), 3.3e-7, 6.7e-17, -4.6e-9, 123, 120, 100.5, 0.1005};
  for (double v : edges) {
    CAPTURE(v);
    CHECK(cpkit::short_number(v) == printf_g3(v));
  }
}

TEST_CASE("short_number is printf's %.3g: random doubles", "[short_number]") {
  std::mt19937_64 rng(58);
  std::uniform_real_distribution<double> mantissa(1, 10);
  std::uniform_int_distribution<int> exponent(-25, 25);
  std::uniform_int_distribution<unsigned long long> bits;
  const int n = cpkit::test::family_size(200000, 20000);
  int fast = 0;
  for (int k = 0; k < n; ++k) {
    double v;
    if (k % 4 == 3) {  // any bit pattern (NaN, subnormal, huge)
      const unsigned long long b = bits(rng);
      std::memcpy(&v, &b, sizeof v);
    } else {
      v = (k % 2 ? -1 : 1) * mantissa(rng) * std::pow(10.0, exponent(rng));
    }
    char buf[32];
    fast += cpkit::detail::short_number_fast(v, buf);
    CAPTURE(v);
    REQUIRE(cpkit::short_number(v) == printf_g3(v));
  }
  CHECK(fast >= n / 2);  // the integer route decides most of them
}
