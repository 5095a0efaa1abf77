#pragma once
// What the parts of `cpkit map` share (map_command.cpp: options and dispatch; map_one_point.cpp:
// the maps of one contact point).
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"

namespace cpkit::cli {

/// The options of `cpkit map` as given.
struct MapArgs {
  std::string preset, kind, state, method = "enumerate", out, param, param2, criterion;
  std::string system;  // --system FILE: the N-point direction map (map_system.cpp)
  std::string format = "npy";
  double time_limit = 600;  // seconds of cells the estimate may reach (--time-limit)
  // The defaults shown by --help are the values used (a test compares them with the run echo);
  // options whose default depends on the map (--n, --theta-to, ...) show none.
  double a11 = 0, a12 = 0, a22 = 0, mu = 0, C_T = 0, k_a = 0, P_s = 1, P_N = 0;
  int sgnPT = 1;
  double from = 0, to = 0, from2 = 0, to2 = 0, theta_from = 0, theta_to = 0;
  int n = 0, n2 = 0, theta_n = 360, threads = 0;
  std::string max_output = "4G";  // --max-output SIZE (byte_size.hpp)
  bool plot = false, json = false, list_presets = false, resume = false;
  // 3-D systems only (map_system_3d.cpp): --facets K, --point i, --others zero|file, --gamma G
  int facets = 0, point = 1;
  std::string others;  // --others: zero or file (default: file when the file has dF)
  double gamma = 0;
  // Which options were given (CLI11 Option pointers).
  std::map<std::string, CLI::Option*> opt;
  bool given(const std::string& name) const {
    auto it = opt.find(name);
    return it != opt.end() && it->second->count() > 0;
  }
};

/// The model, kind and axes from the preset (if any) and the explicit options.
struct MapSetup {
  rate::ContactParameters params;
  rate::ContactState state;
  rate::MapKind kind = rate::MapKind::kDirection;
  rate::MapAxis axis, axis2;
  bool have_axis = false, have_axis2 = false;
  int theta_n = 360;
};

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
