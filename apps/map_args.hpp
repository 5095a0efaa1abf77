#pragma once
// What the parts of `cpkit map` share (map_command.cpp: options and dispatch; map_one_point.cpp:
// the maps of one contact point).
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/map_request.hpp"

namespace cpkit::cli {

/// The options of `cpkit map` as given (maps/map_request.hpp), with their CLI11 options.
struct MapArgs : rate::MapRequest {
  std::map<std::string, CLI::Option*> opt;
};

using rate::MapSetup;

/// The model, kind and axes from the preset (if any) and the explicit options (InputError for
/// options that are invalid or would have no effect).
MapSetup build_setup(const MapArgs& a);

/// Number text with `digits` significant digits; "stick, slip+" of a type mask; "3 solutions".
std::string fmt(double x, int digits = 4);
std::string types_text(unsigned mask);
std::string count_text(int count);

/// The map of one contact point (a preset or the model options): exit code.
int run_map_one_point(const MapArgs& a);

}  // namespace cpkit::cli
