#pragma once
/// \file map_3d_plan.hpp
/// What a 3-D map (`cpkit map --system FILE` with "dim": 3; docs/contact_3d.md, "Maps over the
/// sphere of load directions") computes, from the request as given: the system, the route
/// (exact or faceted) and its limits, the grid or the axes, the echo of the input; the map
/// itself (one call for the three kinds); its up-front time estimate and output size. Angles
/// in radians; parameter values in the system file's units. Bad input: InputError whose message
/// names the option (--n, --facets, ...), as the program prints it (exit 2).
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_request.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// What a 3-D map was asked: the request of `cpkit map` (map_request.hpp); `system` is the file's
/// path (for messages and the echo), `file` the file read once.
using Map3dRequest = MapRequest;

/// The map a request computes, with its echo (`input`) and the words of the messages.
struct Map3dPlan {
  std::string kind;
  ContactSystem3d sys;
  Map3dOptions options;
  SphereGrid grid;          ///< sphere
  Map3dAxis a1, a2;         ///< param-direction: a1; param-param: a1, a2
  int theta_n = 360;        ///< param-direction
  double theta_from = 0, theta_to = 6.283185307179586, gamma = 0;
  nlohmann::json input;     ///< the "input" echo of the result
  int64_t cells = 0;        ///< rows x columns
  std::string cells_text;   ///< "91 x 180 cells (--n x --n2)"
  std::string fewer;        ///< "use a smaller --n or --n2"
  std::string xname, yname; ///< the axes' names ("beta", "gamma", a parameter, "theta")
  int rows() const noexcept { return kind == "sphere" ? grid.n_beta : a1.n; }
  int cols() const noexcept {
    return kind == "sphere" ? grid.n_gamma : kind == "param-direction" ? theta_n : a2.n;
  }
};

/// Checks a 3-D map request before any work: the kind (sphere, param-direction, param-param),
/// the options that apply to it (any other option given is refused: no silent default), the
/// ones it needs, finite values, --time-limit, --format (npy only), --plot/--format with --out,
/// --threads in [0, 1024], --others. `processes`: of the job (3-D maps run in one process).
/// InputError naming the option.
void check_map_3d_request(const MapRequest& r, int processes = 1);

/// The plan of a request checked by check_map_3d_request: parses the
/// system, checks the route's limits (--facets, grazing points, LCP size), --point, --others,
/// the grid or the axes. Throws InputError naming the option or the file.
Map3dPlan make_map_3d_plan(const Map3dRequest& r);

/// The map of the plan with `options` (the plan's, or a variant: threads, time limit).
Map3d compute_map_3d(const Map3dPlan& p, const Map3dOptions& options,
                     const Map3dProgress& progress = {});

/// Seconds of the whole map on `threads`, from a timed sample of at most 4 x 8 cells spread over
/// the same ranges (one thread; the faster of two runs). The sample runs within what is left of
/// `time_limit` (`clock` started with the command): a sample that does not finish in it throws
/// InputError (the map would need more). A map no larger than the sample is not estimated:
/// returns -1 and sampled = 0 (it is computed once, within the deadline).
double estimate_map_3d_seconds(const Map3dPlan& p, int threads, int64_t& sampled,
                               const Stopwatch& clock, double time_limit);

/// Bytes a written map takes: 3 a cell (count, types, complete), 8 per axis value, and the
/// JSON and .npy headers (5 x 4096).
double map_3d_output_bytes(const Map3dPlan& p);

}  // namespace cpkit::rate
