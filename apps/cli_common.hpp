#pragma once
// Shared conventions of the cpkit command line (exit codes, output helpers).
#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

namespace cpkit::cli {

/// Exit codes users script against (keep exactly).
enum ExitCode : int {
  kExitOk = 0,            ///< solved / at least one solution
  kExitNoSolution = 1,    ///< the solve ran but found no solution
  kExitBadInput = 2,      ///< bad input or usage; message on stderr, nothing on stdout
  kExitDisagreement = 3,  ///< `lcp verify`: a solver disagrees with the enumeration
};

/// Each subcommand registers itself and sets `exit_code` from its callback.
/// Errors of the input kind are thrown as cpkit::InputError and mapped to kExitBadInput by main.
struct Context {
  int exit_code = kExitOk;
};

void add_lcp_command(CLI::App& app, Context& ctx);
void add_map_command(CLI::App& app, Context& ctx);  ///< `cpkit map` (issue 7)
void add_rate_command(CLI::App& app, Context& ctx);
void add_step_command(CLI::App& app, Context& ctx);      ///< `cpkit step` (issue 8)
void add_simulate_command(CLI::App& app, Context& ctx);  ///< `cpkit simulate` (issue 8)
// Further subcommands (rate, map, step, simulate) declare their registration functions here.

/// Prints a JSON object to stdout (one line per object, pretty with indent 1). Text that is not
/// UTF-8 (e.g. from a file name) is printed with U+FFFD instead of failing.
inline void print_json(const nlohmann::json& j) {
  std::cout << j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

}  // namespace cpkit::cli
