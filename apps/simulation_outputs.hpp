#pragma once
// The output files of a simulation (one point or N points): its data files and its figures.
#include <fstream>
#include <string>
#include <vector>

#include "output_guard.hpp"

namespace cpkit::cli {

/// Every file a simulation writes: the series `csv` (default PLOT.csv with --plot), the
/// `summary` (default PLOT.json) and the figures PLOT<suffix>.png/.svg of every plotting script.
std::vector<NamedPath> simulation_output_files(const std::string& csv, const std::string& summary,
                                               const std::string& plot);

/// Opens an output file for writing, creating its folder first (configs name paths such as
/// out/fretting.csv). Throws InputError naming the path when it cannot be written.
std::ofstream open_output(const std::string& path);

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
