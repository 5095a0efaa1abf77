#pragma once
/// \file system_grid_map.hpp
/// The parameter x direction map of an N-point system (docs/maps.md, "N points"): rows are the
/// values of one parameter of the system, columns the load directions
/// dF(theta) = cos(theta) e1 + sin(theta) e2 (the system's patterns, system_map_patterns), and
/// every cell holds the solution count of the N-point rate problem and its point-type pattern
/// (the set of type tuples present), by complete enumeration (summarize_rate_problem).
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

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/system_rate.hpp"

namespace cpkit::rate {

/// A quantity of a system that a map axis varies.
struct SystemMapParameter {
  enum class Kind { kMu, kCT, kKa, kPN, kCoupling };
  Kind kind = Kind::kMu;
  int point = 0;  ///< 0: every point; i >= 1: point i only (not for coupling)
  std::string name() const;  ///< "mu", "mu@2", "coupling", ...
};
/// Parses "mu", "C_T", "k_a", "P_N", "coupling" or "<name>@i" (1 <= i <= n_points). Throws
/// InputError naming the accepted names.
SystemMapParameter parse_system_map_parameter(std::string_view s, int n_points);

/// The system with the parameter set to `value`, validated: throws InputError naming the
/// parameter and the value when the result is not a valid system (e.g. A(c) not positive
/// definite, mu <= 0).
ContactSystem apply_system_map_parameter(const ContactSystem& base, const SystemMapParameter& p,
                                         double value);

struct SystemParamDirectionMap {
  SystemMapParameter param;
  double from = 0, to = 1;
  int n = 0, theta_n = 0;
  std::vector<double> theta;        ///< cell centres (j + 1/2) 2 pi / theta_n
  std::vector<int8_t> count;        ///< [i * theta_n + j]; -1: a continuum
  std::vector<uint16_t> pattern;    ///< [i * theta_n + j]: index into `patterns`
  /// Distinct point-type patterns, numbered in order of first appearance (row-major), each the
  /// sorted list of type tuples present in the cell (empty: no solution).
  std::vector<std::vector<TypeTuple>> patterns;
  std::vector<int64_t> pattern_cells;  ///< cells per pattern
  std::vector<GridClassBox> classes;   ///< per count (-1 first), bounding boxes (x, theta)
  int64_t unreliable = 0;  ///< cells the enumeration flagged as not decided (complete: false)
  int m_max = 0;           ///< largest rate LCP over the rows
  int threads = 1;
  double seconds = 0;
  double value(int i) const noexcept {
    return n <= 1 ? from : from + (to - from) * static_cast<double>(i) / (n - 1);
  }
  int64_t cells() const noexcept { return static_cast<int64_t>(n) * theta_n; }
};

/// Largest number of cells of one map (the cells are kept in memory: 3 bytes each).
inline constexpr int64_t kMaxSystemMapCells = int64_t{1} << 26;

/// Computes the map on `threads` workers (0: all cores); the result does not depend on the
/// thread count. Throws InputError for an invalid axis (as MapAxis::validate), theta_n outside
/// [1, 1000000], too many cells, or a row that is not a valid system.
SystemParamDirectionMap compute_system_param_direction_map(
    const ContactSystem& system, const SystemMapParameter& param, double from, double to, int n,
    int theta_n, int threads = 0, const MapProgress& progress = {});

}  // namespace cpkit::rate
