#pragma once
/// \file map_output.hpp
/// CSV and JSON forms of the maps (docs/maps.md describes every column and field): one point,
/// and the grid maps of N points.
/// Counts are integers, "inf" for a continuum of solutions; types are joined with '|'
/// ("separation|stick|slip+"), "none" when there is no solution.
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

namespace cpkit::rate {

std::string count_to_string(int count);        ///< "inf" for -1
nlohmann::json count_to_json(int count);       ///< number, or "inf" for -1
std::string types_to_string(unsigned mask);    ///< "stick|slip+", "none" for 0
nlohmann::json types_to_json(unsigned mask);   ///< ["stick", "slip+"]

nlohmann::json model_to_json(const ContactParameters& params, const ContactState& state);

/// {"param", "from", "to", "n"} of a grid map's axis (map_axis.hpp), as the summaries and the
/// checkpoint manifests hold it.
template <AxisSpacing Spacing>
nlohmann::json axis_json(const GridAxis<Spacing>& a) {
  return {{"param", a.param.name()}, {"from", a.from}, {"to", a.to}, {"n", a.n}};
}

/// {"sectors": [{theta_from, theta_to, count, types}], "critical": [{theta, count, types,
///  conditions, dF_T, dF_N}], "evaluations", "disagreements", "inconsistent_sectors"}.
nlohmann::json to_json(const DirectionMap& map);
/// CSV: kind,theta_from,theta_to,count,types,conditions (sectors and critical directions).
void write_csv(const DirectionMap& map, std::ostream& out);

/// Summary (no per-cell data): axes, cells, counts per class, critical curves, seconds, ...
nlohmann::json to_json(const ParamDirectionMap& map);
/// CSV: <param>,theta,count,types[,disagree] (one row per cell).
void write_csv(const ParamDirectionMap& map, std::ostream& out);
/// The same CSV streamed: the header line, then the rows of each block as it is computed.
void write_csv_header(const MapAxis& axis, bool cross_checked, std::ostream& out);
void write_csv_rows(const MapAxis& axis, const std::vector<double>& theta,
                    const ParamDirectionRows& rows, std::ostream& out);
/// CSV: curve,x,theta,conditions,count,types (critical-direction points; critical values with
/// theta empty).
void write_critical_csv(const ParamDirectionMap& map, std::ostream& out);

nlohmann::json to_json(const ParamParamMap& map);
/// CSV: <param1>,<param2>,class,min_count,max_count,types[,disagree].
void write_csv(const ParamParamMap& map, std::ostream& out);
/// The same CSV streamed: the header line, then the rows of each block as it is computed.
void write_csv_header(const MapAxis& axis1, const MapAxis& axis2, bool cross_checked,
                      std::ostream& out);
void write_csv_rows(const MapAxis& axis1, const MapAxis& axis2, const ParamParamRows& rows,
                    std::ostream& out);
/// CSV: curve,x,y.
void write_critical_csv(const ParamParamMap& map, std::ostream& out);

/// The CSV header and rows of the N-point grid maps (17 digits; the CSV of --format csv):
/// <param>,theta,count,pattern and <param1>,<param2>,class,min_count,max_count,pattern.
void write_system_csv_header(const SystemMapAxis& axis, std::ostream& out);
void write_system_csv_rows(const SystemMapAxis& axis, const std::vector<double>& theta,
                           const SystemParamDirectionRows& rows, std::ostream& out);
void write_system_csv_header(const SystemMapAxis& axis1, const SystemMapAxis& axis2,
                             std::ostream& out);
void write_system_csv_rows(const SystemMapAxis& axis1, const SystemMapAxis& axis2,
                           const SystemParamParamRows& rows, std::ostream& out);

}  // namespace cpkit::rate
