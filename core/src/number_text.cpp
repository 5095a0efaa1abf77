// Strict decimal numbers and numbers in messages (number_text.hpp).
#include "cpkit/core/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <system_error>

#include "io_text.hpp"

namespace cpkit {

NumberText parse_decimal(std::string_view token, double& value) {
  using Number = NumberText;
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // as fscanf("%le") and strtod accept
  if (token.size() != t.size() && (t.empty() || t.front() == '-')) return Number::kNotANumber;
  double v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ptr != t.data() + t.size() || ec == std::errc::invalid_argument) return Number::kNotANumber;
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves v unset; strtod tells which side of the range the literal is on (cpkit
    // never changes the C locale, so strtod reads '.' as from_chars does).
    const double side = std::strtod(std::string(t).c_str(), nullptr);
    return std::fabs(side) > 1 ? Number::kOverflow : Number::kUnderflow;
  }
  if (!std::isfinite(v)) return Number::kNotFinite;
  value = v;
  return Number::kOk;
}

std::string describe_number(NumberText outcome, std::string_view token) {
  using Number = NumberText;
  const std::string q = "'" + io_text::quoted(token) + "'";
  switch (outcome) {
    case Number::kOk:
      return {};
    case Number::kNotANumber:
      return "expected a number, got " + q;
    case Number::kNotFinite:
      return q + " is not a finite number";
    case Number::kOverflow:
      return q + " is outside the range of double (|x| > 1.8e308)";
    case Number::kUnderflow:
      return q + " is below the smallest double (4.9e-324) and would be read as 0";
  }
  return "bad number " + q;
}

std::string num_text(double v, int significant_digits) {
  std::ostringstream o;
  o.precision(significant_digits);
  o << v;
  return o.str();
}

}  // namespace cpkit
