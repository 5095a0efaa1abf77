#pragma once
// Reproducibility: every JSON result of `cpkit` carries a "run" object that says how it was
// made: {"cpkit_version", "command": the arguments after `cpkit`, "options": every option of the
// subcommand with the value used (given or default)}. With the input files it names, a result
// file alone reproduces the run.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cpkit::cli {

/// Remembers the command line and the parsed program (call once in main, before parse()).
void remember_command_line(const CLI::App& app, const std::vector<std::string>& args);

/// The "run" object for the subcommand being run. Option values are JSON numbers where they
/// are numbers, true/false for flags, arrays for options with several values.
nlohmann::json run_echo();

}  // namespace cpkit::cli
