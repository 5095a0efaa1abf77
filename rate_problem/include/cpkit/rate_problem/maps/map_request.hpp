#pragma once
/// \file map_request.hpp
/// What `cpkit map` was asked (docs/maps.md), as given: one request for every map kind (one
/// point, N points, 3-D systems), and the one-point map it describes (make_map_setup: the
/// preset, the model options over it, the kind and the axes). Values in the model's units;
/// angles in radians. Bad input: InputError whose message names the option (--a11, --param,
/// ...), as the program prints it (exit 2).
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// The options of `cpkit map` as given: an empty optional was not given (the program fills
/// the fields, apps/map_command.cpp). Defaults are those `cpkit map --help` shows; options
/// whose default depends on the map (--n, --theta-to, ...) are read only when given.
struct MapRequest {
  std::optional<std::string> preset, kind, state, criterion;
  std::optional<std::string> method;  ///< enumerate (default) | analytic
  std::optional<std::string> out;     ///< --out PREFIX
  std::optional<std::string> param, param2;
  std::optional<std::string> system;  ///< --system FILE (N points or a 3-D system)
  SystemFile file;                    ///< the --system file, read once by the caller (dim known)
  std::optional<std::string> format;      ///< npy (default) | csv
  std::optional<double> time_limit;       ///< seconds the map may take (default 600)
  std::optional<std::string> max_output;  ///< SIZE (core/memory_limit.hpp; default 4G)
  std::optional<double> a11, a12, a22, mu, C_T, k_a, P_s, P_N;
  std::optional<int> sgnPT;  ///< +1 or -1 (state d)
  std::optional<double> from, to, from2, to2, theta_from, theta_to;
  std::optional<int> n, n2, theta_n;
  std::optional<int> threads;  ///< 0 (default): all cores
  std::optional<bool> resume;  ///< N-point and one-point grid maps written with --out
  bool plot = false, json = false, list_presets = false;
  // 3-D systems only: --facets K, --point i (1-based, default 1), --others zero|file, --gamma G
  std::optional<int> facets, point;
  std::optional<std::string> others;
  std::optional<double> gamma;
};

/// The defaults of the options `cpkit map --help` shows with one.
inline constexpr const char* kMapMethodDefault = "enumerate";
inline constexpr const char* kMapFormatDefault = "npy";
inline constexpr const char* kMapMaxOutputDefault = "4G";
inline constexpr double kMapTimeLimitDefault = 600;

/// The names of the options given ("--n"), in the order the program has always named the first
/// one it refuses: alphabetical (byte order: "--C_T" before "--a11").
std::vector<std::string> map_options_given(const MapRequest& a);

/// The one-point map of a request: the model, the kind and the axes.
struct MapSetup {
  ContactParameters params;
  ContactState state;
  MapKind kind = MapKind::kDirection;
  MapAxis axis, axis2;
  bool have_axis = false, have_axis2 = false;
  int theta_n = 360;
};

/// The one-point map of the request: the preset's model, kind and axes (if any), then the
/// options given over them (--kind, --state, --criterion, the model values, --param/--from/
/// --to/--n and the second axis, --theta-n). Refuses options that would have no effect (never a
/// hidden default), a missing model, invalid model values or states, an axis without its range,
/// a kind without its axes. `note` receives remarks on accepted options (a material parameter
/// that does not enter the state). The axes' own checks (MapAxis::validate: n, from, to) and
/// the --theta-n range are left to the caller, which words them in options.
MapSetup make_map_setup(const MapRequest& a,
                        const std::function<void(const std::string&)>& note = {});

/// What `cpkit map --system` was asked (the program fills it from MapRequest; defaults are the N-point maps').
struct SystemMapRequest {
  std::string path, kind, out, param, param2;  ///< --system, --kind, --out, --param, --param2
  SystemFile file;                       ///< the --system file, read once (dim 2)
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

/// The N-point map of a request (--system FILE of dim 2, `file` read once): refuses options that
/// do not apply to the kind (direction by default; the model comes from the file), a missing
/// axis option, --plot/--resume/--format without --out, a direction map over `processes` > 1,
/// bad --format, --time-limit, --threads, --max-output. Defaults: --n and --n2 100, --theta-n
/// 360, theta in [0, 2 pi). InputError naming the option.
SystemMapRequest system_map_request(const MapRequest& a, SystemFile file, int processes = 1);

/// A grid map of N points (--kind param-direction or param-param) as the request describes it.
struct SystemGridPlan {
  ContactSystem sys;
  SystemMapAxis axis, axis2;  ///< axis2: param-param only
  MapOptions options;         ///< threads; param-direction: the sampled theta range
  nlohmann::json input;       ///< the "input" echo of the result (axes and patterns included)
  std::string cells_text;     ///< "100 x 360 cells (--n x --theta-n)"
  std::string fewer;          ///< "use a smaller --n or --theta-n"
};

/// Parses the system (its rate LCP size checked before any work in proportion to N), the axes
/// (names checked against the map parameter table), the options and the load patterns.
/// InputError naming the option or the file.
SystemGridPlan make_system_grid_plan(const SystemMapRequest& r);

}  // namespace cpkit::rate
