#pragma once
// `cpkit map --system FILE` (map_system.cpp): the maps of N contact points.
#include <string>

#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::cli {

/// What `cpkit map --system` was asked (filled by map_command.cpp from the options).
struct SystemMapRequest {
  std::string path, kind, out, param, param2;  ///< --system, --kind, --out, --param, --param2
  rate::SystemFile file;                       ///< the --system file, read once (dim 2)
  std::string format = "npy";                  ///< --format (grid maps written with --out)
  bool json = false, plot = false;
  bool resume = false;  ///< --resume: reuse the finished chunks in PREFIX.parts
  double from = 0, to = 0, from2 = 0, to2 = 0;  ///< --from, --to, --from2, --to2
  int n = 100, n2 = 100, theta_n = 360;         ///< --n, --n2, --theta-n
  int threads = 0;                              ///< --threads (0: all cores)
  bool theta_range = false;                     ///< --theta-from/--theta-to given
  double theta_from = 0, theta_to = 6.283185307179586;
  double time_limit = 600;                      ///< --time-limit (grid maps)
  double max_output = 4.0 * 1024 * 1024 * 1024;  ///< --max-output in bytes (grid maps, --out)
};

/// Runs the map; returns the exit code (0; 5 when not proved complete; 4 when a requested
/// picture could not be drawn).
int run_map_system(const SystemMapRequest& r);

}  // namespace cpkit::cli
