#pragma once
/// \file system_grid_map.hpp
/// Grid maps of an N-point system (docs/maps.md, "N points"):
///  - parameter x direction: rows are the values of one parameter of the system, columns the
///    load directions dF(theta) = cos(theta) e1 + sin(theta) e2 (the system's patterns,
///    system_map_patterns); every cell holds the solution count of the N-point rate problem and
///    its point-type pattern (the set of type tuples present), by complete enumeration
///    (summarize_rate_problem);
///  - parameter x parameter: every cell is classified from its exact direction map
///    (system_direction_map.hpp) as for one point (UniquenessClass), with the union of the type
///    tuples met over all directions as its pattern.
/// Rows are computed on threads in blocks; pattern ids are assigned in row order after each
/// block, so every output is identical for any thread count. With a sink, memory is one block.
///
/// Parameters: `mu`, `C_T`, `k_a`, `P_N` (of every point in state c or d; a d point keeps
/// |P_T| = mu P_N with its sign), `coupling` c (A(c) = D + c (A - D), D the block diagonal of
/// the points' 2x2 blocks: c = 1 the file's A, c = 0 uncoupled points), and per point `mu@i`,
/// `C_T@i`, `k_a@i`, `P_N@i` (i = 1..N as in the file).
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/maps/grid_estimate.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::rate {

/// A quantity of a system that a map axis varies: a row of the map parameter table and the
/// point (0: every point; i >= 1: point i only, not for coupling).
using SystemMapParameter = MapParameterRef;
/// Parses "mu", "C_T", "k_a", "P_s", "P_N", "coupling" or "<name>@i" (1 <= i <= n_points),
/// checked against the map parameter table (map_parameter_table.hpp): InputError naming the
/// parameter and the accepted names.
SystemMapParameter parse_system_map_parameter(std::string_view s, int n_points);

/// The system with the parameter set to `value`, validated: throws InputError naming the
/// parameter and the value when the result is not a valid system (e.g. A(c) not positive
/// definite, mu <= 0).
ContactSystem apply_system_map_parameter(const ContactSystem& base, const SystemMapParameter& p,
                                         double value);

/// Rows of an N-point parameter x direction map: count and pattern (grid_map.hpp).
using SystemParamDirectionRows = ParamDirectionRows;
using SystemParamDirectionSink = ParamDirectionSink;

/// An N-point parameter x direction map: count, pattern, table, classes, unreliable, m_max.
using SystemParamDirectionMap = ParamDirectionMap;

/// Largest map kept in memory (without a sink): 3 bytes a cell. With a sink any size is
/// streamed; memory is one block of rows.
inline constexpr int64_t kMaxSystemMapCells = int64_t{1} << 26;

/// Computes the map: each cell by complete enumeration (summarize_rate_problem) of the row's
/// system at dF(theta) = cos(theta) e1 + sin(theta) e2. options: threads (0: all cores) and the
/// sampled range theta_from..theta_to; method must be kEnumerate. Without a sink the cells are
/// kept in count/pattern; with one they are handed over block by block, in row order, and not
/// kept. The result does not depend on the thread count. Throws InputError for an invalid axis
/// (as MapAxis::validate), theta_n outside [1, 1000000], too many cells to keep, an LCP larger
/// than kMaxSystemMapLcp, or a row that is not a valid system (naming the value).
SystemParamDirectionMap compute_system_param_direction_map(
    const ContactSystem& system, const SystemMapAxis& axis, int theta_n,
    const MapOptions& options = {}, const MapProgress& progress = {},
    const SystemParamDirectionSink& sink = {}, const RowRange& rows = {});

/// Rows of an N-point parameter x parameter map: cls, min_count, max_count and pattern
/// (grid_map.hpp).
using SystemParamParamRows = ParamParamRows;
using SystemParamParamSink = ParamParamSink;

/// An N-point parameter x parameter map: cls, min_count, max_count, pattern, table, classes,
/// unreliable, inconsistent_sectors, m_max.
using SystemParamParamMap = ParamParamMap;

/// Computes a parameter x parameter map, each cell classified from its exact direction map
/// (compute_system_direction_map): unique for every direction, non-unique for some, no solution
/// for some, or both. Sink, threads, determinism and errors as for the parameter x direction
/// map; the two axes must name different parameters.
SystemParamParamMap compute_system_param_param_map(const ContactSystem& system,
                                                   const SystemMapAxis& axis1,
                                                   const SystemMapAxis& axis2,
                                                   const MapOptions& options = {},
                                                   const MapProgress& progress = {},
                                                   const SystemParamParamSink& sink = {},
                                                   const RowRange& rows = {});

/// Up-front cost of a map: the cell phase's time extrapolated from a timed sample of the same
/// map's cells (spread over the grid, one thread, stopped after about a second of sampling).
/// Cells of one map can differ in cost by orders of magnitude: an estimate, not a bound.
/// Filled: cells, seconds (on `threads` workers), threads, sampled (grid_estimate.hpp).
using SystemMapEstimate = GridEstimate;
SystemMapEstimate estimate_system_param_direction_map(const ContactSystem& system,
                                                      const SystemMapAxis& axis, int theta_n,
                                                      const MapOptions& options = {});
SystemMapEstimate estimate_system_param_param_map(const ContactSystem& system,
                                                  const SystemMapAxis& axis1,
                                                  const SystemMapAxis& axis2,
                                                  const MapOptions& options = {});

}  // namespace cpkit::rate
