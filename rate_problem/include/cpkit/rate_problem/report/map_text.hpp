#pragma once
/// \file map_text.hpp
/// The text `cpkit map` prints (docs/maps.md, docs/contact_3d.md): the summary of every map kind
/// in words (without --json), the "wrote ..." line, the list of presets and the progress lines
/// on stderr, written once here for the program, Python and tests. Angles in radians; values in
/// the model's (or system file's) units. Each summary is built in one stream, as the program
/// printed it: a precision set for one line carries over to the next.
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"
#include "cpkit/rate_problem/maps/map_request.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

namespace cpkit::rate {

/// "stick, slip+" of a type mask.
std::string map_types_text(unsigned mask);
/// "no solution", "1 solution", "3 solutions", "a continuum of solutions" (count -1).
std::string map_count_text(int count);

/// The one-point model in one line; the quantities that vary along a map axis are "(axis)".
std::string map_model_text(const ContactParameters& p, const ContactState& s,
                           const std::vector<MapParameterRef>& axes = {});

/// "NAME (KIND): DESCRIPTION" per preset (`cpkit map --list-presets`).
std::string map_presets_text();

/// The one-point direction map: the model line, sectors, critical directions, summary lines.
std::string direction_map_text(const DirectionMap& m, const MapSetup& s);
/// The one-point grid maps from their JSON summary (`summary`: "axis", "cells", "seconds",
/// "classes", ...); `theta_range`: --theta-from/--theta-to given.
std::string param_direction_map_text(const nlohmann::json& summary, const MapSetup& s,
                                     bool theta_range);
std::string param_param_map_text(const nlohmann::json& summary, const MapSetup& s);

/// The N-point maps (`r.path` names the system).
std::string system_direction_map_text(const SystemDirectionMap& m, int n_points,
                                      const std::string& path);
std::string system_param_direction_map_text(const SystemParamDirectionMap& m, int n_points,
                                            const SystemMapRequest& r,
                                            const SystemMapAxis& axis);
std::string system_param_param_map_text(const SystemParamParamMap& m, int n_points,
                                        const SystemMapRequest& r, const SystemMapAxis& a1,
                                        const SystemMapAxis& a2);

/// A 3-D map (sphere, param-direction, param-param).
std::string map_3d_text(const Map3dRequest& r, const Map3dPlan& p, const Map3d& m);

/// "wrote DIR/F1 DIR/F2 ...\n": the files of `files`, next to PREFIX.
std::string map_files_text(const std::string& prefix, const nlohmann::json& files);

/// A progress printer on `err`: "\rcpkit map: cells 40% (1.2 s)" for every phase once the run
/// has lasted more than a second (the clock starts now), the phase's final line at 100 % (at a
/// negative fraction, a phase stopped early: " stopped" ends the line).
MapProgress map_progress_printer(std::ostream& err);

}  // namespace cpkit::rate
