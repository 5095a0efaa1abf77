#pragma once
// `cpkit simulate` with an N-point system file (docs/simulation.md, "N points"): the run of
// rate::simulate_system, its CSV streamed row by row, its JSON summary and figures.
#include "cpkit/rate_problem/system/system_file.hpp"
#include "cpkit/rate_problem/simulation/simulate_config.hpp"

namespace cpkit::cli {

/// Runs the settings' system simulation (validate first); returns the exit code.
int run_system_simulation(const rate::SimulateSettings& s, const rate::SystemFile& file,
                          bool print_json_summary);

}  // namespace cpkit::cli
