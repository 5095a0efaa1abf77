#pragma once
// Strict checks of option values shared by every subcommand (docs/conventions.md, "Command
// line"). CLI11 on its own takes an empty value as 0, accepts "nan", "inf" and out-of-range
// floating-point text (strtold gives +-inf), and reads integers with base prefixes ("010" is 8).
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cpkit/core/option_words.hpp"  // in_option_words, throw_if_invalid_option

namespace cpkit::cli {

/// Walks `app` and all its subcommands (call after every option is registered) and checks
/// every value before it is converted: no value may be empty; FLOAT options need a finite
/// decimal number (no nan/inf, nothing beyond the range of double); INT/UINT options need a
/// plain decimal integer that fits the option's type. A violation is a CLI11 ValidationError
/// naming the option (exit 2).
void check_all_option_values(CLI::App& app);

/// Checks the words of a command line (argv without the program name) before CLI11 parses it,
/// so that the first message is about what the user actually got wrong: an unknown subcommand
/// (`cpkit foo`: "unknown subcommand 'foo' for 'cpkit' (valid: lcp, map, ...)") or an unknown
/// long option (`cpkit step --bogus`: "unknown option --bogus for 'cpkit step'", not "--a11 is
/// required"). Empty when fine.
std::string check_command_words(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace cpkit::cli
