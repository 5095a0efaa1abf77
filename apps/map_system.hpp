#pragma once
// `cpkit map --system FILE` (map_system.cpp): the maps of N contact points.
#include <string>

namespace cpkit::cli {

/// What `cpkit map --system` was asked (filled by map_command.cpp from the options).
struct SystemMapRequest {
  std::string path, kind, out, param;  ///< --system, --kind, --out, --param
  bool json = false;
  double from = 0, to = 0;                  ///< --from, --to (param-direction)
  int n = 100, theta_n = 360, threads = 0;  ///< --n, --theta-n, --threads (param-direction)
};

/// Runs the map; returns the exit code (0, or 5 when not proved complete).
int run_map_system(const SystemMapRequest& r);

}  // namespace cpkit::cli
