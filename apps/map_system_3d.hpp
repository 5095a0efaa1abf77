#pragma once
// `cpkit map --system FILE` with a "dim": 3 file (map_system_3d.cpp): the sphere map of load
// directions and the parameter maps of 3-D points (docs/contact_3d.md, "Maps over the sphere
// of load directions").
#include <string>
#include <vector>

#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::cli {

/// What `cpkit map --system FILE` (dim 3) was asked (filled by map_command.cpp).
struct Map3dRequest {
  std::string path, kind, out, param, param2, others;
  rate::SystemFile file;  ///< the --system file, read once (its dim is 3)
  bool json = false, plot = false;
  double from = 0, to = 0, from2 = 0, to2 = 0, theta_from = 0, theta_to = 0, gamma = 0;
  double time_limit = 600;
  double max_output = 4.0 * 1024 * 1024 * 1024;  ///< --max-output in bytes (written outputs)
  int n = 0, n2 = 0, theta_n = 0, threads = 0, facets = 0, point = 1;
  std::string format;
  std::vector<std::string> given;  ///< the options given (names as "--n")
  bool has(const std::string& o) const;
};

/// Runs the map; returns the exit code (0; 5 when some cell is not proved complete; 4 when a
/// requested picture could not be drawn). Throws InputError for bad input (exit 2).
int run_map_system_3d(const Map3dRequest& r);

}  // namespace cpkit::cli
