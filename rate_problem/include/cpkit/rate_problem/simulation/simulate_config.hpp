#pragma once
// The settings of `cpkit simulate` (docs/simulation.md, "Config file"): parsed from a JSON
// config, overridden by the command line, and checked as a whole before anything is allocated.
// Part of the library so that tests (tests/rate_problem/test_simulate_config.cpp), the fuzz
// target (tests/fuzz/fuzz_simulate_config.cpp) and Python can call the parser directly.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cpkit/rate_problem/simulation/load_history.hpp"
#include "cpkit/core/memory_limit.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"

namespace cpkit::rate {

struct SimulateSettings {
  rate::SimulationOptions opt;
  std::string load_type = "fretting";  ///< fretting | ramp | csv
  rate::FrettingCycle fretting;
  rate::LoadRamp ramp;
  std::string load_csv;  ///< csv load history (relative paths resolved against the config)
  double csv_period = 0;
  std::string csv, summary, plot;
  int every = 1;
  bool have[4] = {false, false, false, false};  ///< a11, a12, a22, mu given
  /// N-point system file (config key "system", relative to the config; --system): the points'
  /// parameters come from it, the load is the fretting cycle through its patterns or a csv
  /// with t and 2N forces per row (docs/simulation.md, "N points").
  std::string system;
};

/// Parses a config (JSON text; `origin` names it in messages, `dir` is the folder relative
/// load files are resolved against) into `s`. Throws cpkit::InputError naming the key for
/// invalid JSON, unknown keys, wrong types, non-finite numbers and integers that are not
/// integers or do not fit their field ("load.cycles = 4294967297 is out of range [1, ...]").
void parse_simulate_config(const std::string& text, const std::string& origin,
                           const std::string& dir, SimulateSettings& s);

/// Largest config file and csv load history read (a bound, so that /dev/zero or a huge file
/// is an error, not an unbounded allocation). A csv row is at least 6 bytes ("0,0,0\n").
constexpr std::size_t kMaxConfigBytes = std::size_t{1} << 20;     // 1 MiB
constexpr std::size_t kMaxLoadCsvBytes = std::size_t{64} << 20;   // 64 MiB

/// Most steps a simulation may take (`cpkit simulate`; docs/simulation.md, "Length cap"): the
/// steps run one after the other, so a count such as --ramp-steps 1e9 would run for hours with
/// no answer; it is refused up front, naming the cap. One 2-D point: about 0.4 us a step, so
/// 10^8 steps take under a minute. N points or a 3-D point: 0.1-0.2 ms a step (two points, one
/// 3-D point), so 10^6 steps take a few minutes (more points take longer per step).
constexpr std::int64_t kMaxSimulationSteps = 100'000'000;
constexpr std::int64_t kMaxSystemSimulationSteps = 1'000'000;

/// InputError naming the cap when `steps` exceeds it: kMaxSimulationSteps, or with `system`
/// (N points, a 3-D point) kMaxSystemSimulationSteps. `what` says where the steps come from
/// ("ramp_steps + cycles x steps_per_cycle").
void check_simulation_steps(std::int64_t steps, bool system, const std::string& what);

/// Reads at most `max_bytes` of a file (any kind: regular, pipe, device); InputError naming
/// `what` and the path when it cannot be opened or is larger.
std::string read_bounded(const std::string& path, std::size_t max_bytes, const std::string& what);

/// Reads and parses a config file (parse_simulate_config; the folder of `path` is `dir`).
void read_simulate_config(const std::string& path, SimulateSettings& s);

/// Checks the settings as a whole, before any allocation: the required parameters, the model
/// (SimulationOptions::validate), the load (FrettingCycle/LoadRamp::validate) and the memory the
/// run would keep (a CSV load history, the per-cycle sums; the time series is streamed to its
/// file) against kMemoryLimitBytes. Throws
/// cpkit::InputError; the memory message names the size needed. A csv load is checked by
/// check_history once read.
void validate_simulate_settings(const SimulateSettings& s);

/// The memory check for a history of `steps` points (csv loads: after reading).
void check_history_memory(std::int64_t steps, const SimulateSettings& s);

/// The load history of the settings (validate first).
rate::LoadHistory make_simulate_history(const SimulateSettings& s);
/// The load of the settings as a source (validate first): fretting and ramp loads generated
/// point by point; a CSV load is read into `storage`, which must outlive the source.
rate::LoadSource make_simulate_source(const SimulateSettings& s, rate::LoadHistory& storage);

}  // namespace cpkit::rate
