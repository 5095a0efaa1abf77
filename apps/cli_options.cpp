#include "cli_options.hpp"

#include <cerrno>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>

namespace cpkit::cli {
namespace {

std::string not_empty(const std::string& v) {
  return v.empty() ? std::string("an empty value is not allowed") : std::string();
}

/// A finite decimal floating-point number, the whole text (no leading/trailing blanks).
std::string finite_number(const std::string& v) {
  if (v.empty()) return "an empty value is not allowed";
  if (std::isspace(static_cast<unsigned char>(v.front())) ||
      std::isspace(static_cast<unsigned char>(v.back())))
    return "'" + v + "' has surrounding blanks";
  const char* s = v.c_str();
  char* end = nullptr;
  errno = 0;
  const double d = std::strtod(s, &end);
  if (end != s + v.size()) return "'" + v + "' is not a number";
  if (v.find_first_of("xX") != std::string::npos)
    return "'" + v + "' is not a decimal number";  // strtod also reads hexadecimal floats
  if (!std::isfinite(d)) return "'" + v + "' is not a finite number (or beyond the range of double)";
  if (errno == ERANGE && d == 0) return "'" + v + "' underflows to 0 in double precision";
  return {};
}

/// A plain decimal integer (optional sign, digits only) in [lo, hi]; rewritten without leading
/// zeros so that CLI11's base-0 conversion cannot read it as octal.
CLI::Validator decimal_integer(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& v) -> std::string {
        if (v.empty()) return "an empty value is not allowed";
        std::size_t i = (v[0] == '+' || v[0] == '-') ? 1 : 0;
        if (i == v.size()) return "'" + v + "' is not an integer";
        for (std::size_t k = i; k < v.size(); ++k)
          if (v[k] < '0' || v[k] > '9') return "'" + v + "' is not an integer";
        errno = 0;
        const long long x = std::strtoll(v.c_str(), nullptr, 10);
        if (errno == ERANGE || x < lo || x > hi)
          return "'" + v + "' is out of range [" + std::to_string(lo) + ", " +
                 std::to_string(hi) + "]";
        v = std::to_string(x);
        return {};
      },
      "", "decimal integer");
}

void check_options_of(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size_max() == 0) continue;  // a flag
    const std::string type = opt->get_type_name();
    if (type == "FLOAT") {
      opt->check(CLI::Validator(finite_number, "", "finite number"));
    } else if (type == "INT") {
      // The targets are int (counts, signs, sizes): their range.
      opt->transform(decimal_integer(INT_MIN, INT_MAX));
    } else if (type == "UINT") {
      opt->transform(decimal_integer(0, INT_MAX));
    } else {
      opt->check(CLI::Validator(not_empty, "", "not empty"));
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    check_options_of(*sub);
}

}  // namespace

void check_all_option_values(CLI::App& app) { check_options_of(app); }

}  // namespace cpkit::cli
