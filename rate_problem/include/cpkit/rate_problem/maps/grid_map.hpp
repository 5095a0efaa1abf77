#pragma once
/// \file grid_map.hpp
/// Grid maps of the rate problem [Stromberg et al. 1996, Sec. 4.3]:
///  - parameter x direction: one parameter on one axis, the load direction theta on the other;
///    every cell holds the solution count and types of the rate problem at
///    (dF_T, dF_N) = (cos theta, sin theta), plus the analytic critical curves
///    (state b: D_s = a11 - s mu a12 = 0, i.e. a11 = mu |a12|; state d: Lambda = 0, eqn (51))
///    and, per parameter row, the exact critical directions (direction_map.hpp);
///  - parameter x parameter: every cell is classified from its exact direction map as unique for
///    every direction, non-unique for some (but solvable for all), or without solution for some.
/// Cells are computed on several threads in blocks of consecutive rows; results are stored by
/// cell index, so the output is identical for any thread count. With a sink, each block is handed
/// over (in row order) as soon as it is done and the cells are not kept: memory is bounded by one
/// block, whatever the grid size.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/map_axis.hpp"

namespace cpkit::rate {

/// A zero of an analytic criterion along a parameter (state b: D_+ / D_-, state d: Lambda).
struct CriticalValue {
  std::string name;  ///< "D+=0" (a11 = mu a12), "D-=0" (a11 = -mu a12), "Lambda=0"
  double x = 0;      ///< value of the first axis parameter
  double y = 0;      ///< param-param maps: value of the second axis parameter (else 0)
};

/// A point of a critical-direction curve theta_c(parameter) of a parameter x direction map.
struct CriticalDirectionPoint {
  double x = 0, theta = 0;
  std::string conditions;  ///< "N=0", "L+=0|S=0", ...
  RateSummary summary;     ///< solution set on the critical direction itself
};

/// Progress callback: the phase ("cells", "critical curves") and the fraction of it done in
/// [0, 1]; called from the calling thread only, about every 0.1 s and once with 1 at the end.
using MapProgress = std::function<void(std::string_view phase, double fraction)>;

/// Cells of one class of a grid map and the bounding box of their axis values (y: theta for a
/// parameter x direction map, the second parameter for a parameter x parameter map).
struct GridClassBox {
  int code = 0;  ///< the count (-1: infinitely many) or the UniquenessClass
  int64_t cells = 0;
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  void add(double x, double y) noexcept;
};

/// The directions of a parameter x direction map: cell centres
/// theta_from + (j + 1/2) (theta_to - theta_from) / theta_n (default: the whole circle).
std::vector<double> map_theta_values(int theta_n, double theta_from = 0,
                                     double theta_to = 6.283185307179586);

/// Rows per block of a streamed grid map with `columns` cells per row (about 2^20 cells).
int grid_block_rows(int64_t columns) noexcept;

/// The rows a call computes: [begin, end) of the first axis (end < 0: to the last row). A map
/// split into row ranges (the chunks of a distributed or resumable run, maps/map_run.hpp)
/// has, in each part, the cells, counters, class boxes and per-row curves of its rows; the
/// whole map is their merge in row order (for N-point maps the pattern tables are renumbered).
/// Only the rows in the range are validated: validate the whole grid first
/// (validate_map_grid) to report the first invalid value of the map.
struct RowRange {
  int begin = 0, end = -1;
};

/// Throws InputError for the first grid value (row by row) that is not a valid model: a map's
/// rows (axis2 == nullptr) or cells.
void validate_map_grid(const ContactParameters& params, const ContactState& state,
                       const MapAxis& axis1, const MapAxis* axis2 = nullptr);

/// Distinct point-type patterns of an N-point map, numbered in order of first appearance
/// (row-major). A pattern is a sorted list of type tuples (TypeTuple, rate/system_rate.hpp;
/// empty: no solution).
struct SystemPatternTable {
  std::vector<std::vector<std::uint64_t>> patterns;
  std::vector<int64_t> cells;  ///< cells per pattern
};

/// Rows [row_begin, row_end) of a parameter x direction map of one point or of N points
/// (system_grid_map.hpp); arrays are row-major with theta_n columns, null where the kind has
/// none (disagree: one point, cross-checked only; pattern: N points).
struct ParamDirectionRows {
  int row_begin = 0, row_end = 0;
  const int8_t* count = nullptr;
  const uint8_t* types = nullptr;     ///< one point: the type mask
  const uint8_t* disagree = nullptr;
  const uint16_t* pattern = nullptr;  ///< N points: ids into the map's pattern table (final)
};
using ParamDirectionSink = std::function<void(const ParamDirectionRows&)>;

/// A parameter x direction map of one point or of N points (system_grid_map.hpp); the fields
/// of the other kind stay empty. Cells are row-major from the first row computed (the whole map
/// without a row range), empty with a sink.
struct ParamDirectionMap {
  MapAxis axis;
  int theta_n = 0;
  double theta_from = 0, theta_to = 0;  ///< the sampled range (MapOptions)
  /// cell centres theta_from + (j + 1/2) (theta_to - theta_from) / theta_n
  std::vector<double> theta;
  std::vector<int8_t> count;     ///< [i * theta_n + j], -1 = infinitely many (a continuum)
  std::vector<uint8_t> types;    ///< one point: type mask (bit = SolutionType)
  std::vector<uint8_t> disagree; ///< one point: 1 where the routes disagree (cross-check only)
  std::vector<uint16_t> pattern; ///< N points: index into `table`
  SystemPatternTable table;      ///< N points: the point-type patterns
  int64_t disagreements = 0;
  int64_t unreliable = 0;  ///< cells the enumeration flagged as too close to call
  bool cross_checked = false;
  std::vector<CriticalValue> critical_values;            ///< one point: analytic curves x = const
  std::vector<CriticalDirectionPoint> critical_directions;  ///< one point: curves theta_c(x)
  std::vector<GridClassBox> classes;       ///< per count, sorted by count (-1 first)
  std::array<int64_t, 32> type_cells{};    ///< one point: cells per type mask
  int m_max = 0;  ///< N points: largest rate LCP over the rows
  double seconds = 0;
  int threads = 1;
  int64_t cells() const noexcept { return static_cast<int64_t>(axis.n) * theta_n; }
};

/// Computes a parameter x direction map (rows: axis values; columns: theta_n directions).
/// Without a sink the cells are kept in count/types/disagree; with a sink they are handed to it
/// block by block and count/types/disagree stay empty (the summary fields are always filled).
/// Throws InputError for invalid options/axis or a parameter row that is not a valid model.
ParamDirectionMap compute_param_direction_map(const ContactParameters& params,
                                              const ContactState& state, const MapAxis& axis,
                                              int theta_n, const MapOptions& options = {},
                                              const MapProgress& progress = {},
                                              const ParamDirectionSink& sink = {},
                                              const RowRange& rows = {});

/// Classes of a parameter x parameter cell.
enum class UniquenessClass : uint8_t {
  kUniqueAll = 0,      ///< exactly one solution for every direction
  kNonUniqueSome = 1,  ///< a solution for every direction, several (or a continuum) for some
  kNoSolutionSome = 2, ///< some directions have no solution, every other direction exactly one
  kNoneAndSeveral = 3, ///< some directions have no solution, others several (or a continuum)
};
/// "unique", "non-unique", "no-solution", "none-and-several"
std::string_view to_string(UniquenessClass c) noexcept;

/// Rows [row_begin, row_end) of a parameter x parameter map of one point or of N points,
/// row-major with axis2.n columns, null where the kind has none (as ParamDirectionRows).
struct ParamParamRows {
  int row_begin = 0, row_end = 0;
  const uint8_t* cls = nullptr;  ///< UniquenessClass
  const int8_t* min_count = nullptr;
  const int8_t* max_count = nullptr;
  const uint8_t* types = nullptr;     ///< one point: the union of the type masks
  const uint8_t* disagree = nullptr;  ///< one point: nullptr unless cross-checked
  const uint16_t* pattern = nullptr;  ///< N points: the union of the type tuples, as an id
};
using ParamParamSink = std::function<void(const ParamParamRows&)>;

/// A parameter x parameter map of one point or of N points (system_grid_map.hpp); the fields
/// of the other kind stay empty. Cells as ParamDirectionMap's.
struct ParamParamMap {
  MapAxis axis1, axis2;
  std::vector<uint8_t> cls;       ///< [i * axis2.n + j]
  std::vector<int8_t> min_count;  ///< over all directions (-1: infinite)
  std::vector<int8_t> max_count;  ///< over all directions (-1: infinite)
  std::vector<uint8_t> types;     ///< one point: union of the type masks over all directions
  std::vector<uint8_t> disagree;  ///< one point: cross-check (empty otherwise)
  std::vector<uint16_t> pattern;  ///< N points: union of the type tuples, index into `table`
  SystemPatternTable table;       ///< N points: the point-type patterns
  int64_t disagreements = 0;
  int64_t inconsistent_sectors = 0;
  int64_t unreliable = 0;  ///< direction-map evaluations flagged as too close to call
  bool cross_checked = false;
  std::vector<CriticalValue> critical_curve;  ///< one point: points (x, y) where a criterion is 0
  std::vector<GridClassBox> classes;          ///< per UniquenessClass present, by code
  int m_max = 0;  ///< N points: largest rate LCP over the rows
  double seconds = 0;
  int threads = 1;
  int64_t cells() const noexcept { return static_cast<int64_t>(axis1.n) * axis2.n; }
};

/// Computes a parameter x parameter map, each cell from its exact direction map; then the
/// critical curves (threaded too; with a row range: the zeros along its rows, and along the
/// columns in the part that ends at the last row). Sink: as for compute_param_direction_map.
ParamParamMap compute_param_param_map(const ContactParameters& params, const ContactState& state,
                                      const MapAxis& axis1, const MapAxis& axis2,
                                      const MapOptions& options = {},
                                      const MapProgress& progress = {},
                                      const ParamParamSink& sink = {},
                                      const RowRange& rows = {});

}  // namespace cpkit::rate
