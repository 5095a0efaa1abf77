#pragma once
// Shared conventions of the cpkit command line (exit codes, output helpers).
#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/core/number_text.hpp"

namespace cpkit::cli {

// Exit codes (kExitOk, ...): cpkit/core/exit_code.hpp, visible here from namespace cpkit.

/// Each subcommand registers itself and sets `exit_code` from its callback.
/// Errors of the input kind are thrown as cpkit::InputError and mapped to kExitBadInput by main.
struct Context {
  int exit_code = kExitOk;
};

void add_lcp_command(CLI::App& app, Context& ctx);
void add_map_command(CLI::App& app, Context& ctx);  ///< `cpkit map`
void add_rate_command(CLI::App& app, Context& ctx);
void add_step_command(CLI::App& app, Context& ctx);      ///< `cpkit step`
void add_simulate_command(CLI::App& app, Context& ctx);  ///< `cpkit simulate`
void add_fc_command(CLI::App& app, Context& ctx);        ///< `cpkit fc` (friction problems)
// Further subcommands (rate, map, step, simulate) declare their registration functions here.

/// JSON text (indent 1). Strings that are not valid UTF-8 (a file name in another encoding)
/// get U+FFFD in place of the bad bytes instead of making dump() throw.
inline std::string json_text(const nlohmann::json& j) {
  return j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// The "run" object of every JSON result: version, command, options used (run_echo.cpp).
nlohmann::json run_echo();

/// Prints a JSON object to stdout (pretty with indent 1), with the "run" object added
/// (reproducibility: docs/conventions.md).
inline void print_json(nlohmann::json j) {
  if (j.is_object() && !j.contains("run")) j["run"] = run_echo();
  std::cout << json_text(j) << std::endl;
}

/// `value` (the variable option `name` of `cmd` is bound to) when the user gave the option,
/// else nothing: how a request's optional fields are filled, so that the library tells "not
/// given" from a value without knowing the option's spelling.
template <class T>
std::optional<T> if_given(const CLI::App& cmd, const std::string& name, const T& value) {
  return cmd.count(name) > 0 ? std::optional<T>(value) : std::nullopt;
}

/// Prints a library outcome (`to_json` of it with --json, else `to_text`) and returns its
/// exit code (the requests of cpkit/lcp/lcp_request.hpp, friction/fc_request.hpp).
template <class Outcome, class Json, class Text>
int print_outcome(const Outcome& out, bool json, Json to_json, Text to_text) {
  if (json)
    print_json(to_json(out));
  else
    std::cout << to_text(out) << std::flush;
  return out.exit_code;
}

}  // namespace cpkit::cli
