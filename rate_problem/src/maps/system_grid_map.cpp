// Parameter x direction maps of N-point systems (docs/maps.md, "N points").
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "grid_cells.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {
/// A cell's point-type pattern: its sorted type tuples (what the pattern table numbers).
std::vector<TypeTuple> tuples_of(const SystemRateSummary& s) {
  const int k = std::min(s.n_tuples, SystemRateSummary::kCap);
  return {s.tuples.begin(), s.tuples.begin() + k};
}
}  // namespace

SystemMapParameter parse_system_map_parameter(std::string_view s, int n_points) {
  return check_map_parameter(s, kMapNPoints, n_points);
}

ContactSystem apply_system_map_parameter(const ContactSystem& base, const SystemMapParameter& p,
                                         double value) {
  ContactSystem sys = base;
  const int N = sys.n_points();
  auto where = [&] {
    std::ostringstream s;
    s << "map parameter " << p.name() << " = " << value;
    return s.str();
  };
  if (!std::isfinite(value)) throw InputError(where() + ": not a finite number");
  if (!p.row->set_point) {
    // coupling: A(c) = D + c (A - D): the points' own 2x2 blocks stay, the coupling between
    // them scales.
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (i != j) sys.A.block(2 * i, 2 * j, 2, 2) *= value;
  } else {
    bool any = false;  // a point took the value
    for (int i = 0; i < N; ++i) {
      if (p.point > 0 && i != p.point - 1) continue;
      SystemPoint& pt = sys.points[static_cast<std::size_t>(i)];
      if (!p.row->set_point(pt, value)) {  // P_N of a point in state a or b
        if (p.point > 0)
          throw InputError(where() + ": point " + std::to_string(i + 1) + " is in state " +
                           std::string(to_string(pt.state.label)) + " (" + p.row->name +
                           " applies to points in state c or d)");
        continue;
      }
      any = true;
      // A sliding point stays on its friction limit: |P_T| = mu P_N (criterion (38)) or
      // mu P_N - k P_N^2 (35), with its sign.
      if (pt.state.label == StateLabel::kD) {
        const double k = pt.k_a / (3.0 * pt.P_s);
        double limit = pt.mu * pt.P_N;
        if (sys.criterion == Criterion::kSoftening) limit -= k * pt.P_N * pt.P_N;
        pt.P_T = pt.state.sgn_PT * limit;
      }
    }
    if (!any)
      throw InputError("map parameter " + std::string(p.row->name) +
                       ": no point of the system is in state c or d");
  }
  if (std::string e = sys.validate(); !e.empty()) throw InputError(where() + ": " + e);
  return sys;
}

namespace {

/// The global table, filled in row order: ids do not depend on which thread ran which row.
class PatternNumbering {
 public:
  explicit PatternNumbering(SystemPatternTable& table) : table_(table) {}
  /// Merges a block's segments in order: their ids in `pattern` (the block's cells row-major
  /// from row b0, `columns` a row) replaced by global ids, their counters added.
  void merge_segments(const std::vector<Segment>& segs, int b0, int columns, uint16_t* pattern,
                      int64_t& unreliable, int64_t& inconsistent) {
    for (const Segment& g : segs) {
      merge_row(g.table, pattern + static_cast<std::size_t>(g.row - b0) * columns + g.c0,
                g.c1 - g.c0);
      unreliable += g.unreliable;
      inconsistent += g.inconsistent;
    }
  }

 private:
  /// Replaces the row-local ids in ids[0..cells) by global ids and counts the cells.
  void merge_row(const RowPatterns& row, uint16_t* ids, int cells) {
    std::vector<uint16_t> to_global(row.list.size());
    for (std::size_t k = 0; k < row.list.size(); ++k) {
      auto [it, added] = index_.emplace(row.list[k], static_cast<int>(table_.patterns.size()));
      if (added) {
        if (table_.patterns.size() >= 65535)
          throw InputError("the map has more than 65535 distinct point-type patterns");
        table_.patterns.push_back(row.list[k]);
        table_.cells.push_back(0);
      }
      to_global[k] = static_cast<uint16_t>(it->second);
    }
    for (int j = 0; j < cells; ++j) {
      ids[j] = to_global[ids[j]];
      ++table_.cells[ids[j]];
    }
  }

  SystemPatternTable& table_;
  std::map<std::vector<TypeTuple>, int> index_;
};

void validate_axis(const SystemMapAxis& a) {
  throw_if_invalid(a.validate(), "map axis " + a.param.name());
}

/// Size of the rate LCP (the same in every row and cell: parameters do not change states).
int checked_lcp_size(const ContactSystem& system) {
  check_system_map_lcp_size(system, "a map of its cells");
  return system_map_lcp_size(system);
}

void check_common(const ContactSystem& system, const MapOptions& options) {
  check_system_map_lcp_size(system, "a map of its cells");  // O(N): before validate's O(N^3)
  throw_if_invalid(system.validate(), "system");
  throw_if_invalid(options.validate(), "map options");
  if (options.method != RateMethod::kEnumerate)
    throw InputError("map options: the N-point maps use the enumeration route only");
}

ContactSystem cell_system(const ContactSystem& base, const SystemMapAxis& a1, double x,
                          const SystemMapAxis& a2, double y) {
  return apply_system_map_parameter(apply_system_map_parameter(base, a1.param, x), a2.param, y);
}

}  // namespace

SystemParamDirectionMap compute_system_param_direction_map(const ContactSystem& system,
                                                           const SystemMapAxis& axis, int theta_n,
                                                           const MapOptions& options,
                                                           const MapProgress& progress,
                                                           const SystemParamDirectionSink& sink,
                                                           const RowRange& range) {
  check_common(system, options);
  validate_axis(axis);
  check_theta_n(theta_n);
  const int n = axis.n;
  if (!sink && static_cast<int64_t>(n) * theta_n > kMaxSystemMapCells)
    throw InputError("the map has " + std::to_string(static_cast<int64_t>(n) * theta_n) +
                     " cells; a map kept in memory accepts at most " +
                     std::to_string(kMaxSystemMapCells) + " (stream it to files, or lower --n or "
                     "--theta-n)");
  const Stopwatch clock;
  SystemParamDirectionMap map;
  map.axis = axis;
  map.theta_n = theta_n;
  map.theta_from = options.theta_from;
  map.theta_to = options.theta_to;
  map.theta = map_theta_values(theta_n, options.theta_from, options.theta_to);
  map.m_max = checked_lcp_size(system);
  // Every row's system is validated before any cell is computed (the message names the value).
  for (int i = 0; i < n; ++i) (void)apply_system_map_parameter(system, axis.param, axis.value(i));
  Eigen::VectorXd e1, e2;
  system_map_patterns(system, e1, e2);
  std::vector<Eigen::VectorXd> loads(static_cast<std::size_t>(theta_n));
  for (int j = 0; j < theta_n; ++j)
    loads[static_cast<std::size_t>(j)] = std::cos(map.theta[j]) * e1 + std::sin(map.theta[j]) * e2;

  const auto [row0, row1] = checked_range(range, n);
  map.threads = resolve_threads(options.threads, static_cast<int64_t>(row1 - row0) * theta_n);
  const int block_rows =
      block_rows_for(static_cast<bool>(sink), row1 - row0, theta_n, map.threads);
  const std::size_t buffer =
      static_cast<std::size_t>(block_rows) * static_cast<std::size_t>(theta_n);
  std::vector<int8_t> count(buffer, 0);
  std::vector<uint16_t> pattern(buffer, 0);
  std::vector<Segment> segs;
  PatternNumbering numbering(map.table);
  std::array<GridClassBox, 128> boxes{};
  int block_begin = 0;
  auto segment = [&](Segment& g) {
    const SystemRatePrecomputed pre = precompute_system_rate(
        apply_system_map_parameter(system, axis.param, axis.value(g.row)));
    const std::size_t base =
        static_cast<std::size_t>(g.row - block_begin) * static_cast<std::size_t>(theta_n);
    for (int j = g.c0; j < g.c1; ++j) {
      const SystemRateSummary s = summarize_rate_problem(pre, loads[static_cast<std::size_t>(j)]);
      count[base + j] = static_cast<int8_t>(s.count);
      pattern[base + j] = g.table.id(tuples_of(s));
      g.unreliable += !s.reliable;
    }
  };
  run_grid_blocks(row0, row1, block_rows, theta_n, map.threads, block_begin, segs, progress,
                  segment, [&](int b0, int b1) {
                    int64_t no_sectors = 0;  // a parameter x direction map has no sectors
                    numbering.merge_segments(segs, b0, theta_n, pattern.data(), map.unreliable,
                                             no_sectors);
                    add_count_boxes(boxes, count.data(), nullptr, map.type_cells, b0, b1, axis,
                                    map.theta);
                    if (sink)
                      sink(ParamDirectionRows{b0, b1, count.data(), nullptr, nullptr,
                                              pattern.data()});
                  });
  if (!sink) {
    map.count = std::move(count);
    map.pattern = std::move(pattern);
  }
  map.classes = present_classes(boxes, -1);  // by count, -1 (a continuum) first
  map.seconds = clock.seconds();
  return map;
}

SystemParamParamMap compute_system_param_param_map(const ContactSystem& system,
                                                   const SystemMapAxis& axis1,
                                                   const SystemMapAxis& axis2,
                                                   const MapOptions& options,
                                                   const MapProgress& progress,
                                                   const SystemParamParamSink& sink,
                                                   const RowRange& range) {
  check_common(system, options);
  validate_axis(axis1);
  validate_axis(axis2);
  check_distinct_axes(axis1, axis2);
  const int n1 = axis1.n, n2 = axis2.n;
  if (!sink && static_cast<int64_t>(n1) * n2 > kMaxSystemMapCells)
    throw InputError("the map has " + std::to_string(static_cast<int64_t>(n1) * n2) +
                     " cells; a map kept in memory accepts at most " +
                     std::to_string(kMaxSystemMapCells));
  const Stopwatch clock;
  SystemParamParamMap map;
  map.axis1 = axis1;
  map.axis2 = axis2;
  map.m_max = checked_lcp_size(system);
  Eigen::VectorXd e1, e2;
  system_map_patterns(system, e1, e2);  // throws unless the patterns are independent
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n2; ++j) (void)cell_system(system, axis1, axis1.value(i), axis2, axis2.value(j));

  const auto [row0, row1] = checked_range(range, n1);
  map.threads = resolve_threads(options.threads, static_cast<int64_t>(row1 - row0) * n2);
  const int block_rows = block_rows_for(static_cast<bool>(sink), row1 - row0, n2, map.threads);
  const std::size_t buffer = static_cast<std::size_t>(block_rows) * static_cast<std::size_t>(n2);
  std::vector<uint8_t> cls(buffer, 0);
  std::vector<int8_t> lo(buffer, 0), hi(buffer, 0);
  std::vector<uint16_t> pattern(buffer, 0);
  std::vector<Segment> segs;
  PatternNumbering numbering(map.table);
  std::array<GridClassBox, 4> boxes{};  // one per UniquenessClass
  MapOptions cell_options;
  cell_options.threads = 1;
  int block_begin = 0;
  auto segment = [&](Segment& g) {
    for (int j = g.c0; j < g.c1; ++j) {
      const SystemDirectionMap dm = compute_system_direction_map(
          cell_system(system, axis1, axis1.value(g.row), axis2, axis2.value(j)), cell_options);
      std::vector<TypeTuple> tuples;  // the union of the type tuples over all directions
      const CellClass c = classify_cell(dm, [&](const SystemRateSummary& s) {
        for (int t = 0; t < std::min(s.n_tuples, SystemRateSummary::kCap); ++t)
          tuples.push_back(s.tuples[static_cast<std::size_t>(t)]);
      });
      std::sort(tuples.begin(), tuples.end());
      tuples.erase(std::unique(tuples.begin(), tuples.end()), tuples.end());
      const std::size_t at = static_cast<std::size_t>(g.row - block_begin) *
                                 static_cast<std::size_t>(n2) + static_cast<std::size_t>(j);
      cls[at] = c.cls;
      lo[at] = c.lo;
      hi[at] = c.hi;
      pattern[at] = g.table.id(std::move(tuples));
      g.unreliable += dm.unreliable;
      g.inconsistent += dm.inconsistent_sectors;
    }
  };
  run_grid_blocks(row0, row1, block_rows, n2, map.threads, block_begin, segs, progress, segment,
                  [&](int b0, int b1) {
                    numbering.merge_segments(segs, b0, n2, pattern.data(), map.unreliable,
                                             map.inconsistent_sectors);
                    add_class_boxes(boxes, cls.data(), b0, b1, axis1, axis2);
                    if (sink)
                      sink(ParamParamRows{b0, b1, cls.data(), lo.data(), hi.data(), nullptr,
                                          nullptr, pattern.data()});
                  });
  if (!sink) {
    map.cls = std::move(cls);
    map.min_count = std::move(lo);
    map.max_count = std::move(hi);
    map.pattern = std::move(pattern);
  }
  map.classes = present_classes(boxes, 0);
  map.seconds = clock.seconds();
  return map;
}

namespace {
/// Sample positions spread over [0, n): the ends, the middle, then quarters, eighths, ...
std::vector<int> spread(int n, int max_count) {
  std::vector<int> out;
  auto add = [&](int i) {
    if (static_cast<int>(out.size()) < max_count &&
        std::find(out.begin(), out.end(), i) == out.end())
      out.push_back(i);
  };
  add(0);
  add(n - 1);
  for (int parts = 2; parts <= 64 && static_cast<int>(out.size()) < std::min(n, max_count);
       parts *= 2)
    for (int k = 1; k < parts; k += 2) add(static_cast<int>(static_cast<int64_t>(n - 1) * k / parts));
  return out;
}
constexpr double kSampleSeconds = 1.0;  // sampling stops once it has taken this long
}  // namespace

SystemMapEstimate estimate_system_param_direction_map(const ContactSystem& system,
                                                      const SystemMapAxis& axis, int theta_n,
                                                      const MapOptions& options) {
  check_common(system, options);
  validate_axis(axis);
  check_theta_n(theta_n);
  checked_lcp_size(system);
  SystemMapEstimate e;
  e.cells = static_cast<double>(axis.n) * theta_n;
  e.threads = resolve_threads(options.threads, axis.n);
  Eigen::VectorXd e1, e2;
  system_map_patterns(system, e1, e2);
  const std::vector<double> theta = map_theta_values(theta_n, options.theta_from, options.theta_to);
  const std::vector<int> cols = spread(theta_n, 64);
  const Stopwatch clock;
  for (int i : spread(axis.n, 8)) {
    const SystemRatePrecomputed pre =
        precompute_system_rate(apply_system_map_parameter(system, axis.param, axis.value(i)));
    for (int j : cols) {
      const Eigen::VectorXd dF = std::cos(theta[j]) * e1 + std::sin(theta[j]) * e2;
      (void)summarize_rate_problem(pre, dF);
      ++e.sampled;
    }
    if (clock.seconds() > kSampleSeconds) break;
  }
  e.seconds = clock.seconds() / e.sampled * e.cells / e.threads;
  return e;
}

SystemMapEstimate estimate_system_param_param_map(const ContactSystem& system,
                                                  const SystemMapAxis& axis1,
                                                  const SystemMapAxis& axis2,
                                                  const MapOptions& options) {
  check_common(system, options);
  validate_axis(axis1);
  validate_axis(axis2);
  checked_lcp_size(system);
  SystemMapEstimate e;
  e.cells = static_cast<double>(axis1.n) * axis2.n;
  e.threads = resolve_threads(options.threads, axis1.n);
  MapOptions one;
  one.threads = 1;
  const std::vector<int> rows = spread(axis1.n, 3), cols = spread(axis2.n, 3);
  const Stopwatch clock;
  for (int i : rows) {
    for (int j : cols) {
      (void)compute_system_direction_map(
          cell_system(system, axis1, axis1.value(i), axis2, axis2.value(j)), one);
      ++e.sampled;
      if (clock.seconds() > kSampleSeconds) break;
    }
    if (clock.seconds() > kSampleSeconds) break;
  }
  e.seconds = clock.seconds() / e.sampled * e.cells / e.threads;
  return e;
}

}  // namespace cpkit::rate
