#pragma once
/// \file map_json.hpp
/// The JSON (and CSV) of the maps of N points and of 3-D systems (docs/maps.md "N points",
/// docs/contact_3d.md "Maps over the sphere of load directions"), as `cpkit map --system FILE`
/// prints and writes them, written once here for the program, Python and tests. Angles in
/// radians; parameter values in the system file's units. The program adds what only it knows
/// ("cpkit_version", the run's figures, "estimate", "seconds", "files", "run", "format").
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// "stick,slip+" style names of type tuples (one per tuple) of an N-point system.
std::vector<std::string> type_tuple_names(const std::vector<TypeTuple>& tuples, int n_points);
/// The names of the tuples kept in a summary (at most SystemRateSummary::kCap).
std::vector<std::string> type_tuple_names(const SystemRateSummary& s, int n_points);

/// [{"id", "types", "cells"}] of a grid map's pattern table.
nlohmann::json pattern_table_json(const SystemPatternTable& t, int n_points);

/// The direction map of an N-point system: {"kind": "direction", "input"
/// ({"system": `path`, "name", "n_points", "patterns": [e1, e2]}), "sectors", "critical",
/// "counts" (count -> {"radians": total open arc}), "candidates", "evaluations", "unreliable",
/// "inconsistent_sectors", "complete"}. complete is true only when no evaluation was too close
/// to call and every sector is uniform.
nlohmann::json system_direction_map_json(const SystemDirectionMap& m, const ContactSystem& sys,
                                         const std::string& path);
/// The direction map as CSV: kind,theta_from,theta_to,count,types (a critical direction has
/// theta_from = theta_to; types joined by '|'), 17 digits.
void write_system_direction_csv(const SystemDirectionMap& m, int n_points, std::ostream& out);

/// A parameter x direction map of N points: {"kind", "input" (`input` as given),
/// "cells", "counts" ([{"count", "cells", "param_min", "param_max", "theta_min", "theta_max"}]),
/// "patterns", "lcp_size_max", "unreliable", "complete"}; complete: no cell too close to call.
nlohmann::json system_param_direction_json(const SystemParamDirectionMap& m, int n_points,
                                           const nlohmann::json& input);
/// A parameter x parameter map of N points: {"kind", "input", "cells",
/// "classes" ([{"class", "code", "cells", "x_min", "x_max", "y_min", "y_max"}]), "class_codes",
/// "patterns", "lcp_size_max", "unreliable", "inconsistent_sectors", "complete"}.
nlohmann::json system_param_param_json(const SystemParamParamMap& m, int n_points,
                                       const nlohmann::json& input);

/// The CSV of the N-point grid maps: maps/map_output.hpp.

/// A 3-D map (sphere, param-direction or param-param, `kind`): {"kind", "dim": 3,
/// "input", "axes" ({"x": xname, "y": yname}), "cells", "counts" ([{"count" (or "infinite"),
/// "cells"}]), "types" ([{"mask", "types", "cells"}]), "type_bits", "incomplete_cells",
/// "timed_out_cells", "time_limit_reached", "complete", "threads"}; complete: every cell proved
/// complete.
nlohmann::json map_3d_json(const Map3d& m, const std::string& kind, const nlohmann::json& input,
                           const std::string& xname, const std::string& yname);

}  // namespace cpkit::rate
