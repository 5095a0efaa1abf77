#include "cli_options.hpp"

#include <cerrno>
#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "nearest_name.hpp"

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

/// A decimal integer in [lo, hi]: plain digits (optional sign), or a decimal number with an
/// integral value such as `1e7` or `10000000.0` (how scripts and Python's json write counts).
/// Rewritten as plain digits without leading zeros so that CLI11's base-0 conversion cannot read
/// it as octal.
CLI::Validator decimal_integer(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& v) -> std::string {
        if (v.empty()) return "an empty value is not allowed";
        const std::string range =
            "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        std::size_t i = (v[0] == '+' || v[0] == '-') ? 1 : 0;
        if (i == v.size()) return "'" + v + "' is not an integer";
        bool digits = true;
        for (std::size_t k = i; k < v.size(); ++k) digits &= v[k] >= '0' && v[k] <= '9';
        if (digits) {
          errno = 0;
          const long long x = std::strtoll(v.c_str(), nullptr, 10);
          if (errno == ERANGE || x < lo || x > hi)
            return "'" + v + "' is out of range " + range;
          v = std::to_string(x);
          return {};
        }
        if (!finite_number(v).empty()) return "'" + v + "' is not an integer";
        const double d = std::strtod(v.c_str(), nullptr);
        if (d != std::floor(d)) return "'" + v + "' is not an integer";
        // Compared as doubles: lo and hi (int limits) are exact in double.
        if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
          return "'" + v + "' is out of range " + range;
        v = std::to_string(static_cast<long long>(d));
        return {};
      },
      "", "decimal integer");
}

void check_options_of(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size_max() == 0) continue;  // a flag
    // An empty list is no default: --help shows none (and the run echo omits the option).
    if (opt->get_default_str() == "[]") opt->default_str("");
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

bool is_long_option(const std::string& t) { return t.size() > 2 && t[0] == '-' && t[1] == '-'; }

std::string subcommand_names(const CLI::App& app) {
  std::string out;
  for (const CLI::App* sub : app.get_subcommands({}))
    out += (out.empty() ? "" : ", ") + sub->get_name();
  return out;
}

/// " (did you mean --theta-n?)" for a mistyped long option: the nearest long option of `app`
/// and of the commands above it (their options are accepted there too); empty when none is near.
std::string option_suggestion(const CLI::App* app, const std::string& typed) {
  std::vector<std::string> names;
  for (const CLI::App* a = app; a != nullptr; a = a->get_parent())
    for (const CLI::Option* o : a->get_options())
      for (const std::string& l : o->get_lnames()) names.push_back(l);
  names.push_back("help");
  const std::string near = nearest_name(typed.substr(2), names);
  return near.empty() ? std::string() : " (did you mean --" + near + "?)";
}

/// " (did you mean map?)" for a mistyped subcommand of `app`; empty when none is near.
std::string subcommand_suggestion(const CLI::App& app, const std::string& typed) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  const std::string near = nearest_name(typed, names);
  return near.empty() ? std::string() : " (did you mean " + near + "?)";
}

std::string command_path(const CLI::App* app) {
  std::string path;
  for (; app->get_parent() != nullptr; app = app->get_parent()) path = " " + app->get_name() + path;
  return "cpkit" + path;
}

}  // namespace

void check_all_option_values(CLI::App& app) { check_options_of(app); }

std::string check_command_words(const CLI::App& app, const std::vector<std::string>& args) {
  const CLI::App* cur = &app;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& t = args[k];
    if (t == "--") break;  // the rest are values
    if (is_long_option(t)) {
      const std::string name = t.substr(0, t.find('='));
      // --DF is the accepted alias of --dF (main.cpp rewrites it before parsing).
      const std::string lookup = name == "--DF" ? std::string("--dF") : name;
      bool known = false;
      for (const CLI::App* a = cur; a != nullptr && !known; a = a->get_parent())
        known = a->get_option_no_throw(lookup) != nullptr || (a == cur && name == "--help");
      if (!known)
        return "unknown option " + name + " for '" + command_path(cur) + "'" +
               option_suggestion(cur, name) + " (see '" + command_path(cur) + " --help')";
      continue;
    }
    if (t.empty() || t[0] == '-') continue;  // a short option or a negative number
    const bool has_subcommands = !cur->get_subcommands({}).empty();
    if (!has_subcommands) continue;  // a value or a positional argument
    const CLI::App* sub = nullptr;
    for (const CLI::App* c : cur->get_subcommands({}))
      if (c->check_name(t)) sub = c;
    if (sub == nullptr) {
      // A value of the previous option (cpkit --version takes none; subcommand-level options
      // come after the subcommand), so a bare word here is a subcommand name.
      if (k > 0 && is_long_option(args[k - 1])) continue;
      return "unknown subcommand '" + t + "' for '" + command_path(cur) + "'" +
             subcommand_suggestion(*cur, t) + " (valid: " + subcommand_names(*cur) + ")";
    }
    cur = sub;
  }
  // `cpkit` or `cpkit lcp` alone: say which subcommands there are (--help/--version excepted).
  bool asks = false;
  for (const auto& t : args) asks |= t == "--help" || t == "-h" || t == "--version";
  if (!asks && !cur->get_subcommands({}).empty())
    return "'" + command_path(cur) + "' needs a subcommand: " + subcommand_names(*cur) +
           " (see '" + command_path(cur) + " --help')";
  return {};
}

}  // namespace cpkit::cli
