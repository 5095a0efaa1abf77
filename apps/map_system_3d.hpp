#pragma once
// `cpkit map --system FILE` with a "dim": 3 file (map_system_3d.cpp): the sphere map of load
// directions and the parameter maps of 3-D points (docs/contact_3d.md, "Maps over the sphere
// of load directions").
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"

namespace cpkit::cli {

/// What `cpkit map --system FILE` (dim 3) was asked (filled by map_command.cpp).
using rate::Map3dRequest;

/// Runs the map; returns the exit code (0; 5 when some cell is not proved complete; 4 when a
/// requested picture could not be drawn). Throws InputError for bad input (exit 2).
int run_map_system_3d(const Map3dRequest& r);

}  // namespace cpkit::cli
