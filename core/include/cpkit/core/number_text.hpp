#pragma once
/// \file number_text.hpp
/// Strict decimal numbers, as every cpkit text reader reads them (problem files, load CSVs;
/// docs/file_formats.md, "Numbers"): an optional sign, digits, an optional fraction and
/// exponent, nothing else (no hexadecimal `0x1p3`, no `nan`/`inf`, no surrounding spaces), and
/// a literal that does not fit a double is refused rather than rounded to 0 or infinity.
#include <string>
#include <string_view>

namespace cpkit {

/// Outcome of parsing one number.
enum class NumberText { kOk, kNotANumber, kNotFinite, kOverflow, kUnderflow };

/// Parses the whole token as a decimal double (locale-free). kNotFinite for nan/inf; kOverflow
/// when |x| exceeds the largest double (`1e400`); kUnderflow when a non-zero literal is below the
/// smallest subnormal (`1e-400`: it would silently become 0). Subnormal values (`1e-320`) are
/// accepted (they are doubles, with reduced precision). `value` is set only on kOk.
NumberText parse_decimal(std::string_view token, double& value);

/// What is wrong with a token parse_decimal refused, e.g. "expected a number, got '0x10'" or
/// "'1e400' is outside the range of double (|x| > 1.8e308)"; empty for kOk.
std::string describe_number(NumberText outcome, std::string_view token);

/// A number as messages show it: the stream's default format (printf's %g), 6 significant
/// digits unless asked for more ("0.25", "1e+300"; std::to_string would print 300 digits, or
/// 0.000000 for 1e-9).
std::string num_text(double v, int significant_digits = 6);

}  // namespace cpkit
