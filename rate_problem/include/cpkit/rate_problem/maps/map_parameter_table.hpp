#pragma once
// The one table of map parameters (docs/maps.md): every quantity a map axis (`--param`,
// `--param2`) can vary, for which kind of map (one point, N points of a 2-D system, 3-D
// systems), whether one point's value can be chosen (NAME@i, i = 1..N), how a value is applied
// and how it is validated. The three map kinds and Python check a name against it, so that an
// unknown or inapplicable name is refused the same way (InputError naming it: exit 2). The rows
// apply themselves to the model of a one-point map (set_one_point) and to a point of a system
// (set_point, set_point_3d).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"

namespace cpkit::rate {

struct SystemPoint;
struct SystemPoint3d;

/// The map kinds a parameter applies to (bits).
enum MapDimension : unsigned {
  kMapOnePoint = 1,  ///< cpkit map --preset / model options (grid_map.hpp)
  kMapNPoints = 2,   ///< cpkit map --system FILE, "dim": 2 (system_grid_map.hpp)
  kMap3d = 4,        ///< cpkit map --system FILE, "dim": 3 (sphere_map_3d.hpp)
};
std::string_view to_string(MapDimension d) noexcept;  ///< "one-point", "N-point", "3-D"

struct MapParameterRow {
  const char* name;       ///< as written on the command line: "mu", "P_s", "a12/a11"
  unsigned dimensions;    ///< MapDimension bits
  bool per_point;         ///< NAME@i accepted (maps of systems: N points, 3-D)
  const char* applied;    ///< what a value sets
  const char* validated;  ///< what is checked, and when
  /// Sets the value in the model of a one-point map (null: not a one-point parameter). Throws
  /// InputError when impossible (kappa with P_N = 0).
  void (*set_one_point)(ContactParameters& params, ContactState& state, double value) = nullptr;
  /// Sets the value in one point of an N-point system; false when the point does not take it
  /// (P_N: a point in state a or b). Null: not a quantity of the points of N-point maps
  /// (coupling scales the system's A).
  bool (*set_point)(SystemPoint& point, double value) = nullptr;
  /// Sets the value in one point of a 3-D system (null: not a parameter of 3-D maps).
  void (*set_point_3d)(SystemPoint3d& point, double value) = nullptr;
};
/// Every map parameter, in the order of the docs.
const std::vector<MapParameterRow>& map_parameter_table();

/// A row of the table and the point it applies to: what a map axis varies (one point: point 0;
/// N points: SystemMapParameter, 3-D: Map3dParameter).
struct MapParameterRef {
  const MapParameterRow* row = &map_parameter_table().front();  ///< default: mu
  int point = 0;              ///< 0: every point; i >= 1: point i only
  std::string name() const;  ///< "mu", "mu@2", "coupling", ...
};
inline bool operator==(const MapParameterRef& a, const MapParameterRef& b) noexcept {
  return a.row == b.row && a.point == b.point;
}
inline bool operator!=(const MapParameterRef& a, const MapParameterRef& b) noexcept {
  return !(a == b);
}
/// NAME or NAME@i checked against the table for a map of `dimension` with `n_points` points:
/// the row and the point (0: every point). Throws InputError naming the parameter when it is
/// unknown (with the accepted names of this kind), applies to other kinds of map only (naming
/// them), does not take @i, or its i is not in 1..n_points. A non-empty `context` starts the
/// message ("--param: ...").
MapParameterRef check_map_parameter(std::string_view text, MapDimension dimension, int n_points,
                                    const std::string& context = "");

/// The row named `name`, of every point ("mu", "kappa"; no check of the map kind): for code that
/// names a parameter itself. Throws InputError for a name not in the table.
MapParameterRef map_parameter(std::string_view name);

/// A one-point map's parameter: a one-point row's name or one of its older spellings ("ratio",
/// "a12_a11", "CT", "C_t", "ka", "Ps", "PN"); empty for anything else.
std::optional<MapParameterRef> map_parameter_from_string(std::string_view name);

/// Sets `p` (a one-point row) to `value` in (params, state). Throws InputError when impossible
/// (kappa with P_N = 0) or when the row is not a one-point parameter.
void apply_map_parameter(const MapParameterRef& p, double value, ContactParameters& params,
                         ContactState& state);

/// The accepted names of one kind of map, comma-separated ("mu, a11, ..."; with NAME@i for
/// systems), for messages and --help.
std::string map_parameter_names(MapDimension dimension, int n_points = 0);

}  // namespace cpkit::rate
