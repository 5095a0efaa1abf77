#pragma once
// Internal to the grid maps: what the one-point and N-point grid maps (grid_map.cpp,
// system_grid_map.cpp) share cell by cell, written once for both point kinds; the analytic
// uniqueness criteria of one point (grid_map.cpp; map_output.cpp writes them).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::rate {

/// The analytic criteria whose sign decides uniqueness for every direction: state b
/// {"D+", D_+}, {"D-", D_-}; state d {"Lambda", Lambda(sgn P_T)} of eqn (51), with mu replaced
/// by mu_eff = mu - 2 kappa for the softening criterion (35) (as in the rate problem); else none.
struct UniquenessCriterion {
  std::string name;
  double value = 0;
};
std::vector<UniquenessCriterion> uniqueness_criteria(const ContactParameters& params,
                                                     const ContactState& state);

/// Rows per block: all rows without a sink; else about 2^20 cells, at least 4 rows per worker
/// (or long rows would run on one thread).
inline int block_rows_for(bool streamed, int rows, int64_t columns, int threads) {
  return streamed ? std::min(rows, std::max(grid_block_rows(columns), 4 * threads)) : rows;
}

/// Throws InputError when the two axes of a param-param map vary the same parameter.
inline void check_distinct_axes(const MapAxis& axis1, const MapAxis& axis2) {
  if (axis1.param == axis2.param)
    throw InputError("param-param map: the two axes vary the same parameter '" +
                     axis1.param.name() + "'");
}

/// Class and count range of a param-param cell, from its exact direction map.
struct CellClass {
  uint8_t cls = 0;  ///< UniquenessClass
  int8_t lo = 0, hi = 0;  ///< lowest and highest count over all directions (-1: a continuum)
};

/// Classifies a cell from the summaries of every sector and critical direction of its direction
/// map (DirectionMap or SystemDirectionMap); `types(summary)` gathers the cell's types.
template <class DirectionMapKind, class Types>
CellClass classify_cell(const DirectionMapKind& dm, Types&& types) {
  auto rank = [](int c) { return c < 0 ? 1000 : c; };  // a continuum ranks above all counts
  CellClass out;
  int lo_rank = 1001, hi_rank = -1;
  bool none = false, multiple = false;
  auto visit = [&](const auto& s) {
    const int r = rank(s.count);
    if (r < lo_rank) { lo_rank = r; out.lo = static_cast<int8_t>(s.count); }
    if (r > hi_rank) { hi_rank = r; out.hi = static_cast<int8_t>(s.count); }
    types(s);
    none = none || s.count == 0;
    multiple = multiple || (s.count != 0 && s.count != 1);
  };
  for (const auto& s : dm.sectors) visit(s.summary);
  for (const auto& c : dm.critical) visit(c.summary);
  // "no solution for some directions" must not hide that others have several.
  out.cls = static_cast<uint8_t>(none && multiple ? UniquenessClass::kNoneAndSeveral
                                 : none           ? UniquenessClass::kNoSolutionSome
                                 : multiple       ? UniquenessClass::kNonUniqueSome
                                                  : UniquenessClass::kUniqueAll);
  return out;
}

/// Adds the cells of block rows [b0, b1) of a param-param map (classes `cls`, row-major from
/// row b0) to the boxes of their classes.
inline void add_class_boxes(std::array<GridClassBox, 4>& boxes, const uint8_t* cls, int b0,
                            int b1, const MapAxis& axis1, const MapAxis& axis2) {
  for (int i = b0; i < b1; ++i)
    for (int j = 0; j < axis2.n; ++j)
      boxes[cls[static_cast<std::size_t>(i - b0) * static_cast<std::size_t>(axis2.n) +
                static_cast<std::size_t>(j)]]
          .add(axis1.value(i), axis2.value(j));
}

}  // namespace cpkit::rate
