#pragma once
// Internal to the grid maps: what the one-point and N-point grid maps (grid_map.cpp,
// system_grid_map.cpp) share, written once for both point kinds: the grid driver (blocks of
// rows cut into segments run on threads), a param-param cell's class, the class boxes; and the
// analytic uniqueness criteria of one point (grid_map.cpp; map_output.cpp writes them).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"
#include "run_items.hpp"

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

/// N points: a segment's pattern table, ids in order of first appearance in the segment.
struct RowPatterns {
  std::vector<std::vector<TypeTuple>> list;
  uint16_t id(std::vector<TypeTuple>&& tuples) {
    auto it = std::find(list.begin(), list.end(), tuples);
    if (it != list.end()) return static_cast<uint16_t>(it - list.begin());
    if (list.size() >= 65535)
      throw InputError("a map row has more than 65535 distinct point-type patterns");
    list.push_back(std::move(tuples));
    return static_cast<uint16_t>(list.size() - 1);
  }
};

/// A piece of one row, a work item: rows are split when a block has too few rows for the
/// threads (a chunk of a distributed map may be a single row). Its counters are its cells';
/// N points: each segment numbers its patterns itself, and merged in segment order they give
/// the numbering of a row-major scan.
struct Segment {
  int row = 0, c0 = 0, c1 = 0;
  RowPatterns table;
  int64_t unreliable = 0, inconsistent = 0, disagreements = 0;
};

/// The grid driver of every one-point and N-point grid map: rows [row0, row1) with `columns`
/// cells each, in blocks of `block_rows` rows (the cell buffers hold one block, indexed from
/// `block_begin`); each block's segments computed by `segment(Segment&)` on `threads` workers,
/// then `block(b0, b1)` (counters, class boxes, sink, in row order); progress "cells".
template <class SegmentFn, class BlockFn>
void run_grid_blocks(int row0, int row1, int block_rows, int columns, int threads,
                     int& block_begin, std::vector<Segment>& segs, const MapProgress& progress,
                     SegmentFn&& segment, BlockFn&& block) {
  for (block_begin = row0; block_begin < row1; block_begin += block_rows) {
    const int b0 = block_begin, b1 = std::min(row1, block_begin + block_rows);
    segs.clear();
    const int per_row = std::max(1, std::min(columns, (4 * threads + b1 - b0 - 1) / (b1 - b0)));
    for (int i = b0; i < b1; ++i)
      for (int k = 0; k < per_row; ++k) {
        Segment g;
        g.row = i;
        g.c0 = static_cast<int>(int64_t{columns} * k / per_row);
        g.c1 = static_cast<int>(int64_t{columns} * (k + 1) / per_row);
        segs.push_back(std::move(g));
      }
    const int n_segs = static_cast<int>(segs.size());
    run_items(0, n_segs, threads, [&](int k) { segment(segs[static_cast<std::size_t>(k)]); },
              [&](int done) {
                if (progress)
                  progress("cells", (b0 - row0 + static_cast<double>(done) / n_segs * (b1 - b0)) /
                                        (row1 - row0));
              });
    block(b0, b1);
  }
  if (progress) progress("cells", 1.0);
}

/// Adds the cells of block rows [b0, b1) of a param-direction map (counts `count`, row-major
/// from row b0) to the boxes of their counts (index count + 1, -1 = a continuum); one point:
/// the cells of each type mask `types` to `type_cells`.
inline void add_count_boxes(std::array<GridClassBox, 128>& boxes, const int8_t* count,
                            const uint8_t* types, std::array<int64_t, 32>& type_cells, int b0,
                            int b1, const MapAxis& axis, const std::vector<double>& theta) {
  const int n = static_cast<int>(theta.size());
  std::array<int, 128> first{}, last{};
  for (int i = b0; i < b1; ++i) {
    const std::size_t base = static_cast<std::size_t>(i - b0) * static_cast<std::size_t>(n);
    first.fill(-1);
    std::array<int64_t, 128> n_count{};
    for (int j = 0; j < n; ++j) {
      const int c = (count[base + j] + 1) & 127;
      if (first[c] < 0) first[c] = j;
      last[c] = j;
      ++n_count[c];
      if (types) ++type_cells[types[base + j] & 31u];
    }
    for (std::size_t c = 0; c < boxes.size(); ++c)
      if (n_count[c] > 0) {
        // theta increases with j: the first and last cell bound the row's theta range.
        boxes[c].add(axis.value(i), theta[first[c]]);
        boxes[c].add(axis.value(i), theta[last[c]]);
        boxes[c].cells += n_count[c] - 2;
      }
  }
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
