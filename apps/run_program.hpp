#pragma once
// Runs a helper program (the plotting scripts) with an argument vector: no shell is involved,
// so file names from the command line or a config file are passed as data, never as code.
#include <string>
#include <vector>

namespace cpkit::cli {

/// Seconds a plotting script may take (a first matplotlib run builds its font cache in ~20 s;
/// the scripts subsample big maps): beyond, it is stopped and the data files are kept.
inline constexpr double kPlotTimeLimit = 300;

struct ProgramRun {
  bool started = false;  ///< false when the program could not be started (`error` says why)
  int exit_code = -1;    ///< the program's exit code; -1 when it was killed by a signal
  std::string error;
};

/// Runs argv[0] (looked up in PATH when it has no '/') with arguments argv[1..] and waits for
/// it. With `stdout_to_stderr` its standard output goes to our standard error (keeps our
/// stdout machine-readable). With time_limit_s > 0 a program still running after that many
/// seconds is killed (exit_code -1, `error` says so): a hung plotting script never hangs cpkit.
ProgramRun run_program(const std::vector<std::string>& argv, bool stdout_to_stderr,
                       double time_limit_s = 0);

/// The command for messages ("run this yourself"), each argument shell-quoted.
std::string command_text(const std::vector<std::string>& argv);

}  // namespace cpkit::cli
