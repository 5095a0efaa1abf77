// Parameter x direction and parameter x parameter maps (docs/maps.md).
#include "cpkit/rate_problem/maps/grid_map.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <sstream>
#include <thread>
#include <tuple>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "grid_cells.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

/// Values of the uniqueness criteria (as uniqueness_criteria, without names or allocation).
int criterion_values(const ContactParameters& p, const ContactState& state, double out[2]) {
  if (state.label == StateLabel::kB) {
    out[0] = p.a11 - p.mu * p.a12;
    out[1] = p.a11 + p.mu * p.a12;
    return 2;
  }
  if (state.label == StateLabel::kD) {
    const double s = state.sgn_PT >= 0 ? 1.0 : -1.0;
    const double kappa = p.kappa(state.P_N);
    // eqn (51): Lambda = a11 - m s a12 + kappa (s a12 - m a22) - m kappa C_T detA with m = mu
    // for criterion (38) and m = mu_eff = mu - 2 kappa for the softening criterion (35)
    // (docs/model.md; the same m as the rate problem's slip equations).
    const double m = p.criterion == Criterion::kSoftening ? p.mu - 2.0 * kappa : p.mu;
    out[0] = p.a11 - m * s * p.a12 + kappa * (s * p.a12 - m * p.a22) -
             m * kappa * p.C_T * p.detA();
    return 1;
  }
  return 0;
}

/// (params, state) with the axis parameter set to `x`; validated (message names the value).
void set_and_validate(const MapAxis& axis, double x, ContactParameters& p, ContactState& st) {
  apply_map_parameter(axis.param, x, p, st);
  auto where = [&] { return axis.param.name() + " = " + std::to_string(x); };
  if (std::string e = p.validate(); !e.empty())
    throw_if_invalid(e, "map axis " + where() + ": parameters");
  if (std::string e = st.validate(p); !e.empty())
    throw_if_invalid(e, "map axis " + where() + ": contact state");
}

/// Validates the model of every cell of rows [row0, row1) of a parameter x parameter grid
/// (the message names both values).
void validate_cells(const ContactParameters& params, const ContactState& state,
                    const MapAxis& axis1, const MapAxis& axis2, int row0, int row1) {
  for (int i = row0; i < row1; ++i)
    for (int j = 0; j < axis2.n; ++j) {
      ContactParameters p = params;
      ContactState st = state;
      apply_map_parameter(axis1.param, axis1.value(i), p, st);
      try {
        set_and_validate(axis2, axis2.value(j), p, st);
      } catch (const InputError& e) {
        throw InputError("map cell " + axis1.param.name() + " = " +
                         std::to_string(axis1.value(i)) + ", " + e.what());
      }
    }
}

/// Zeros of the uniqueness criteria along one axis (the other quantities fixed), located by a
/// sign scan of the closed forms on a fine grid and bisection to machine precision.
std::vector<std::pair<std::string, double>> criterion_zeros(const ContactParameters& base,
                                                           const ContactState& base_state,
                                                           const MapAxis& axis) {
  std::vector<std::pair<std::string, double>> zeros;
  if (axis.n <= 1) return zeros;
  const auto names = uniqueness_criteria(base, base_state);
  const int scan = std::max(64, 8 * axis.n);
  if (axis.param.row->name == std::string_view("kappa") && !(base_state.P_N > 0))
    return zeros;  // no kappa
  auto model = [&](double x, ContactParameters& p, ContactState& st) {
    p = base;
    st = base_state;
    apply_map_parameter(axis.param, x, p, st);
  };
  // The scan evaluates the closed forms only; a model is validated (the costly part) only where
  // a zero is bracketed: both ends of a bracket and every bisection point must be valid models.
  auto value = [&](std::size_t k, double x) {
    ContactParameters p;
    ContactState st;
    model(x, p, st);
    double v[2] = {0, 0};
    criterion_values(p, st, v);
    return v[k];
  };
  auto valid = [&](double x) {
    ContactParameters p;
    ContactState st;
    model(x, p, st);
    return p.validate().empty() && st.validate(p).empty();
  };
  for (std::size_t k = 0; k < names.size(); ++k) {
    double x0 = axis.from;
    double f0 = value(k, x0);
    if (f0 == 0 && valid(x0)) zeros.emplace_back(names[k].name + "=0", x0);
    for (int i = 1; i <= scan; ++i) {
      const double x1 = axis.from + (axis.to - axis.from) * static_cast<double>(i) / scan;
      const double f1 = value(k, x1);
      if (f1 == 0) {
        if (valid(x0) && valid(x1)) zeros.emplace_back(names[k].name + "=0", x1);
      } else if (f0 != 0 && (f0 < 0) != (f1 < 0) && valid(x0) && valid(x1)) {
        double a = x0, b = x1, fa = f0;
        for (int it = 0; it < 200; ++it) {
          const double c = 0.5 * (a + b);
          if (c <= std::min(a, b) || c >= std::max(a, b)) break;
          const bool okc = valid(c);
          const double fc = value(k, c);
          if (!okc || fc == 0) {
            a = b = c;
            break;
          }
          if ((fc < 0) == (fa < 0)) {
            a = c;
            fa = fc;
          } else {
            b = c;
          }
        }
        zeros.emplace_back(names[k].name + "=0", 0.5 * (a + b));
      }
      x0 = x1;
      f0 = f1;
    }
  }
  return zeros;
}

std::string join_conditions(const std::vector<std::string>& c) {
  std::string s;
  for (const auto& x : c) s += (s.empty() ? "" : "|") + x;
  return s;
}
}  // namespace

std::vector<UniquenessCriterion> uniqueness_criteria(const ContactParameters& p,
                                                     const ContactState& state) {
  double v[2] = {0, 0};
  const int k = criterion_values(p, state, v);
  if (k == 2) return {{"D+", v[0]}, {"D-", v[1]}};
  if (k == 1) return {{"Lambda", v[0]}};
  return {};
}

void GridClassBox::add(double x, double y) noexcept {
  if (cells == 0) {
    x_min = x_max = x;
    y_min = y_max = y;
  } else {
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  }
  ++cells;
}

std::vector<double> map_theta_values(int theta_n, double theta_from, double theta_to) {
  std::vector<double> theta(static_cast<std::size_t>(std::max(0, theta_n)));
  const double span = theta_to - theta_from;
  for (int j = 0; j < theta_n; ++j) theta[j] = theta_from + (j + 0.5) * span / theta_n;
  return theta;
}

int grid_block_rows(int64_t columns) noexcept {
  constexpr int64_t kBlockCells = int64_t{1} << 20;
  return static_cast<int>(std::max<int64_t>(1, kBlockCells / std::max<int64_t>(1, columns)));
}

void validate_map_grid(const ContactParameters& params, const ContactState& state,
                       const MapAxis& axis1, const MapAxis* axis2) {
  throw_if_invalid(axis1.validate(), "map axis " + axis1.param.name());
  if (axis2) throw_if_invalid(axis2->validate(), "map axis " + axis2->param.name());
  if (axis2) return validate_cells(params, state, axis1, *axis2, 0, axis1.n);
  for (int i = 0; i < axis1.n; ++i) {
    ContactParameters p = params;
    ContactState st = state;
    set_and_validate(axis1, axis1.value(i), p, st);
  }
}

ParamDirectionMap compute_param_direction_map(const ContactParameters& params,
                                              const ContactState& state, const MapAxis& axis,
                                              int theta_n, const MapOptions& options,
                                              const MapProgress& progress,
                                              const ParamDirectionSink& sink,
                                              const RowRange& range) {
  throw_if_invalid(options.validate(), "map options");
  throw_if_invalid(axis.validate(), "map axis " + axis.param.name());
  check_theta_n(theta_n);
  const Stopwatch clock;

  // Per-row model data of the range's rows (index i - row0), validated once.
  const auto [row0, row1] = checked_range(range, axis.n);
  const std::size_t range_rows = static_cast<std::size_t>(row1 - row0);
  std::vector<ContactParameters> row_params(range_rows, params);
  std::vector<ContactState> row_state(range_rows, state);
  for (int i = row0; i < row1; ++i)
    set_and_validate(axis, axis.value(i), row_params[i - row0], row_state[i - row0]);

  ParamDirectionMap map;
  map.axis = axis;
  map.theta_n = theta_n;
  map.cross_checked = options.method != RateMethod::kEnumerate;
  map.theta_from = options.theta_from;
  map.theta_to = options.theta_to;
  map.theta = map_theta_values(theta_n, options.theta_from, options.theta_to);
  std::vector<LoadRate> loads(static_cast<std::size_t>(theta_n));
  for (int j = 0; j < theta_n; ++j) loads[j] = LoadRate{std::cos(map.theta[j]), std::sin(map.theta[j])};
  // Without a sink the whole grid is kept; with one, a buffer of one block of rows.
  map.threads = resolve_threads(options.threads, row1 - row0);
  const int block_rows = block_rows_for(static_cast<bool>(sink), row1 - row0, theta_n, map.threads);
  const std::size_t buffer_cells =
      static_cast<std::size_t>(block_rows) * static_cast<std::size_t>(theta_n);
  std::vector<int8_t> count(buffer_cells, 0);
  std::vector<uint8_t> types(buffer_cells, 0);
  std::vector<uint8_t> disagree(map.cross_checked ? buffer_cells : 0, 0);
  std::vector<std::vector<CriticalDirectionPoint>> row_crit(range_rows);

  const RateMethod method = options.method;
  const bool cross = map.cross_checked;
  int block_begin = 0;
  std::vector<Segment> segs;
  auto segment = [&](Segment& g) {
    const int i = g.row;
    const ContactParameters& p = row_params[i - row0];
    const ContactState& st = row_state[i - row0];
    // Once per segment (the row's model is fixed): the state's LCP as a linear function of the
    // load.
    const RatePrecomputed pre = precompute_rate_problem(p, st);
    const std::size_t base =
        static_cast<std::size_t>(i - block_begin) * static_cast<std::size_t>(theta_n);
    int8_t* cnt = count.data() + base;
    uint8_t* typ = types.data() + base;
    const LoadRate* load = loads.data();
    // The cell loop: allocation-free (summarize_rate_problem is).
    if (!cross) {
      for (int j = g.c0; j < g.c1; ++j) {
        const RateSummary s = summarize_rate_problem(pre, load[j], method);
        cnt[j] = static_cast<int8_t>(s.count);
        typ[j] = static_cast<uint8_t>(s.types);
        g.unreliable += !s.reliable;
      }
    } else {
      uint8_t* dis = disagree.data() + base;
      for (int j = g.c0; j < g.c1; ++j) {
        const RateSummary s = summarize_rate_problem(pre, load[j], method);
        const RateSummary e = summarize_rate_problem(pre, load[j], RateMethod::kEnumerate);
        cnt[j] = static_cast<int8_t>(s.count);
        typ[j] = static_cast<uint8_t>(s.types);
        dis[j] = same_solution_set(s, e) ? 0 : 1;
        g.disagreements += dis[j];
        g.unreliable += !s.reliable || !e.reliable;
      }
    }
    if (g.c0 > 0) return;  // the row's critical directions: by its first segment
    // The exact critical directions of this row (curves theta_c(x) over the map).
    MapOptions dopt;
    dopt.method = method;
    const DirectionMap dm = compute_direction_map(p, st, dopt);
    for (const auto& c : dm.critical) {
      // Into the sampled range (directions are angles mod 2 pi); outside it: not drawn.
      double t = options.theta_from + std::fmod(c.theta - options.theta_from, kTwoPi);
      if (t < options.theta_from) t += kTwoPi;
      if (t <= options.theta_to)
        row_crit[i - row0].push_back({axis.value(i), t, join_conditions(c.conditions), c.summary});
    }
  };

  std::array<GridClassBox, 128> boxes{};  // per count + 1 (-1: a continuum)
  run_grid_blocks(row0, row1, block_rows, theta_n, map.threads, block_begin, segs, progress,
                  segment, [&](int b0, int b1) {
                    for (const Segment& g : segs) {
                      map.disagreements += g.disagreements;
                      map.unreliable += g.unreliable;
                    }
                    add_count_boxes(boxes, count.data(), types.data(), map.type_cells, b0, b1,
                                    axis, map.theta);
                    if (sink)
                      sink(ParamDirectionRows{b0, b1, count.data(), types.data(),
                                              cross ? disagree.data() : nullptr});
                  });
  if (!sink)
    std::tie(map.count, map.types, map.disagree) =
        std::forward_as_tuple(std::move(count), std::move(types), std::move(disagree));
  map.classes = present_classes(boxes, -1);
  for (auto& row : row_crit)
    for (auto& c : row) map.critical_directions.push_back(std::move(c));
  for (const auto& z : criterion_zeros(params, state, axis))
    map.critical_values.push_back({z.first, z.second, 0});
  map.seconds = clock.seconds();
  return map;
}

std::string_view to_string(UniquenessClass c) noexcept {
  switch (c) {
    case UniquenessClass::kUniqueAll: return "unique";
    case UniquenessClass::kNonUniqueSome: return "non-unique";
    case UniquenessClass::kNoSolutionSome: return "no-solution";
    case UniquenessClass::kNoneAndSeveral: return "none-and-several";
  }
  return "?";
}

ParamParamMap compute_param_param_map(const ContactParameters& params, const ContactState& state,
                                      const MapAxis& axis1, const MapAxis& axis2,
                                      const MapOptions& options, const MapProgress& progress,
                                      const ParamParamSink& sink, const RowRange& range) {
  throw_if_invalid(options.validate(), "map options");
  throw_if_invalid(axis1.validate(), "map axis " + axis1.param.name());
  throw_if_invalid(axis2.validate(), "map axis " + axis2.param.name());
  check_distinct_axes(axis1, axis2);
  const Stopwatch clock;
  const int n1 = axis1.n, n2 = axis2.n;
  const auto [row0, row1] = checked_range(range, n1);
  validate_cells(params, state, axis1, axis2, row0, row1);  // before any work

  ParamParamMap map;
  map.axis1 = axis1;
  map.axis2 = axis2;
  map.cross_checked = options.method != RateMethod::kEnumerate;
  map.threads = resolve_threads(options.threads, row1 - row0);
  const int block_rows = block_rows_for(static_cast<bool>(sink), row1 - row0, n2, map.threads);
  const std::size_t buffer_cells = static_cast<std::size_t>(block_rows) * static_cast<std::size_t>(n2);
  std::vector<uint8_t> cls(buffer_cells, 0), types(buffer_cells, 0);
  std::vector<int8_t> min_count(buffer_cells, 0), max_count(buffer_cells, 0);
  std::vector<uint8_t> disagree(map.cross_checked ? buffer_cells : 0, 0);
  MapOptions cell_options = options;
  cell_options.threads = 1;

  int block_begin = 0;
  std::vector<Segment> segs;
  auto segment = [&](Segment& g) {
    const int i = g.row;
    for (int j = g.c0; j < g.c1; ++j) {
      ContactParameters p = params;
      ContactState st = state;
      apply_map_parameter(axis1.param, axis1.value(i), p, st);
      apply_map_parameter(axis2.param, axis2.value(j), p, st);
      const DirectionMap dm = compute_direction_map(p, st, cell_options);
      unsigned type_mask = 0;
      const CellClass c = classify_cell(dm, [&](const RateSummary& s) { type_mask |= s.types; });
      const std::size_t k =
          static_cast<std::size_t>(i - block_begin) * static_cast<std::size_t>(n2) + j;
      cls[k] = c.cls;
      min_count[k] = c.lo;
      max_count[k] = c.hi;
      types[k] = static_cast<uint8_t>(type_mask);
      if (map.cross_checked) {
        disagree[k] = dm.disagreements > 0 ? 1 : 0;
        g.disagreements += disagree[k];
      }
      g.inconsistent += dm.inconsistent_sectors;
      g.unreliable += dm.unreliable;
    }
  };
  std::array<GridClassBox, 4> boxes{};  // one per UniquenessClass
  run_grid_blocks(row0, row1, block_rows, n2, map.threads, block_begin, segs, progress, segment,
                  [&](int b0, int b1) {
                    for (const Segment& g : segs) {
                      map.disagreements += g.disagreements;
                      map.inconsistent_sectors += g.inconsistent;
                      map.unreliable += g.unreliable;
                    }
                    add_class_boxes(boxes, cls.data(), b0, b1, axis1, axis2);
                    if (sink)
                      sink(ParamParamRows{b0, b1, cls.data(), min_count.data(), max_count.data(),
                                          types.data(),
                                          map.cross_checked ? disagree.data() : nullptr});
                  });
  if (!sink)
    std::tie(map.cls, map.min_count, map.max_count, map.types, map.disagree) =
        std::forward_as_tuple(std::move(cls), std::move(min_count), std::move(max_count),
                              std::move(types), std::move(disagree));
  map.classes = present_classes(boxes, 0);

  // Critical curve: zeros of the criteria along every row (x fixed) and every column (y fixed),
  // one work item per row and per column; stored by item, so the order is thread-independent.
  std::vector<std::vector<CriticalValue>> item_curve(static_cast<std::size_t>(n1 + n2));
  auto curve_item = [&](int k) {
    ContactParameters p = params;
    ContactState st = state;
    if (k < n1) {
      apply_map_parameter(axis1.param, axis1.value(k), p, st);
      for (const auto& z : criterion_zeros(p, st, axis2))
        item_curve[k].push_back({z.first, axis1.value(k), z.second});
    } else {
      const int j = k - n1;
      apply_map_parameter(axis2.param, axis2.value(j), p, st);
      for (const auto& z : criterion_zeros(p, st, axis1))
        item_curve[k].push_back({z.first, z.second, axis2.value(j)});
    }
  };
  // Items: the range's rows, then every column when the range ends at the last row (so that
  // the parts of a split map, in row order, list the curve as the whole map does).
  std::vector<int> items;
  for (int i = row0; i < row1; ++i) items.push_back(i);
  if (row1 == n1)
    for (int j = 0; j < n2; ++j) items.push_back(n1 + j);
  const int n_items = static_cast<int>(items.size());
  run_items(0, n_items, resolve_threads(options.threads, n_items),
            [&](int k) { curve_item(items[static_cast<std::size_t>(k)]); }, [&](int done) {
              if (progress) progress("critical curves", static_cast<double>(done) / n_items);
            });
  if (progress) progress("critical curves", 1.0);
  for (int k : items)
    for (auto& c : item_curve[static_cast<std::size_t>(k)]) map.critical_curve.push_back(std::move(c));
  map.seconds = clock.seconds();
  return map;
}

}  // namespace cpkit::rate
