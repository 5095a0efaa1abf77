#pragma once
// The output files of a simulation (one point or N points): its data files and its figures.
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "output_guard.hpp"

namespace cpkit::cli {

/// Every file a simulation writes: the series `csv` (default PLOT.csv with --plot), the
/// `summary` (default PLOT.json) and the figures PLOT<suffix>.png/.svg of every plotting script.
std::vector<NamedPath> simulation_output_files(const std::string& csv, const std::string& summary,
                                               const std::string& plot);

/// Opens an output file for writing, creating its folder first (configs name paths such as
/// out/fretting.csv). Throws InputError naming the path when it cannot be written.
std::ofstream open_output(const std::string& path);

/// Flushes an output file and throws InputError naming `path` when it could not be written
/// (disk full, not writable).
void finish_output(std::ofstream& f, const std::string& path);

/// Writes `j` as JSON text (indent 1) and a line end to `path` (open_output, finish_output).
void write_json_file(const std::string& path, const nlohmann::json& j);

/// The end of every simulation: draws the figures when `plot` is given (draw_simulation_figures
/// with `script_name` and `figures`), then names on stderr every file written (`csv` and
/// `summary` when not empty, the figures). False when figures were asked for and are missing.
bool draw_and_name_outputs(const std::string& script_name, const std::string& csv,
                           const std::string& summary, const std::string& plot,
                           const std::vector<std::string>& figures);

/// Runs the installed plotting script `script_name` (found by find_data_file) on the time series
/// `csv` and the summary `summary`, writing PLOT<figure>.png/.svg for every suffix in `figures`
/// (the folder of `plot` is created). On success the figure files are appended to `written`;
/// a missing script or a failed run is reported on stderr and returns false (the caller then
/// exits 4: the figures were asked for and are missing).
bool draw_simulation_figures(const std::string& script_name, const std::string& csv,
                             const std::string& summary, const std::string& plot,
                             const std::vector<std::string>& figures,
                             std::vector<std::string>& written);

}  // namespace cpkit::cli
