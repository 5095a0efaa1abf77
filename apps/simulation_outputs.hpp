#pragma once
// The output files of a simulation (one point, N points, 3-D): the paths the output guard
// checks, and the figures (a program concern: the installed plotting scripts).
#include <string>
#include <vector>

#include "cpkit/rate_problem/report/simulation_csv.hpp"
#include "output_guard.hpp"

namespace cpkit::cli {

using rate::open_output;  // the files of `cpkit fc --bench` too

/// Every file a simulation writes: the series `csv` (default PLOT.csv with --plot), the
/// `summary` (default PLOT.json) and the figures PLOT<suffix>.png/.svg of every plotting script.
std::vector<NamedPath> simulation_output_files(const std::string& csv, const std::string& summary,
                                               const std::string& plot);

/// The end of every simulation: when `plot` is given, runs the installed plotting script
/// `script_name` (found by find_data_file) on `csv` and `summary`, writing PLOT<figure>.png/.svg
/// for every suffix in `figures` (the folder of `plot` is created; a missing script or a failed
/// run is reported on stderr); then names on stderr every file written (`csv` and `summary`
/// when not empty, the figures). False when figures were asked for and are missing (exit 4).
bool draw_and_name_outputs(const std::string& script_name, const std::string& csv,
                           const std::string& summary, const std::string& plot,
                           const std::vector<std::string>& figures);

}  // namespace cpkit::cli
