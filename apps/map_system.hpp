#pragma once
// `cpkit map --system FILE` (map_system.cpp): the maps of N contact points.
#include <string>

#include "cpkit/rate_problem/maps/map_request.hpp"

namespace cpkit::cli {

using rate::SystemMapRequest;

/// Runs the map; returns the exit code (0; 5 when not proved complete; 4 when a requested
/// picture could not be drawn).
int run_map_system(const SystemMapRequest& r);

}  // namespace cpkit::cli
