// Up-front cost of a one-point grid map (grid_estimate.hpp): a timed sub-grid of the same map
// on its threads, in wall clock, extrapolated.
#include "cpkit/rate_problem/maps/grid_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"

namespace cpkit::rate {

namespace {

/// Wall time a sample takes before it is trusted: long enough that a loaded machine shows in it
/// (a burst of a few milliseconds runs at full speed on a busy machine, the map would not).
constexpr double kSampleSeconds = 0.15;

/// The growth of a sample that took `t` seconds towards kSampleSeconds: 2 to 16 times.
int growth(double t) {
  const double f = t > 0 ? 1.5 * kSampleSeconds / t : 16;
  return static_cast<int>(std::min(16.0, std::max(2.0, f)));
}

/// Wall seconds of `run` (a sample of the map, on the map's threads).
template <class Run>
double wall_seconds(Run&& run) {
  const Stopwatch c;
  run();
  return c.seconds();
}

GridEstimate sample_param_direction(const ContactParameters& params, const ContactState& state,
                                    const MapAxis& axis, int theta_n, const MapOptions& options,
                                    bool csv, bool writing) {
  const Stopwatch sample;
  GridEstimate e;
  const double cross_bytes = options.method != RateMethod::kEnumerate ? 1 : 0;
  const double n = axis.n, tn = theta_n;
  e.cells = n * tn;
  e.threads = map_worker_threads(options.threads, axis.n);
  // Sub-grids of the same map (rows spread over the whole axis, directions over the circle),
  // on the map's threads, timed in wall clock: what the map will take on this machine as loaded
  // now. A row costs a set-up (the state's LCP as a function of the load, its critical
  // directions) and a part per direction (a cell); builds weigh them differently (under
  // AddressSanitizer the set-up, which allocates, slows far more than the cells, whose cost is
  // arithmetic). Each is timed by a sample long enough that a loaded machine's pauses average
  // out:
  // - the set-up: rows of one direction, grown until kSampleSeconds / 3;
  // - the cells: rows of ts directions, ts grown until the cells take 3/4 of that sample (or
  //   are the map's rows) so that the set-up's share taken off them is small, then rows,
  //   until kSampleSeconds or the whole map.
  // Issue 37: one short sample of 1 and 1024 directions (rows grown first), whose difference
  // was noise, put the 10^10-cell map at 104 s under ASan; it ran at ~3,200 s. Not sampled:
  // the chunked run's record of each row (maps/grid_map_run.cpp): a map of a few directions per
  // row takes up to ~2.5x its estimate (a sample through the chunked run met its per-chunk
  // start-up instead, milliseconds on a loaded VM, and overestimated 3-17x).
  MapAxis sa = axis;
  auto time_of = [&](int directions) {
    return wall_seconds([&] {
      compute_param_direction_map(params, state, sa, directions, options, {},
                                  [](const ParamDirectionRows&) {});
    });
  };
  sa.n = std::min(axis.n, std::max(8, 4 * e.threads));
  double t0 = time_of(1);
  while (t0 < kSampleSeconds / 3 && sa.n < axis.n) {
    sa.n = static_cast<int>(std::min<int64_t>(axis.n, int64_t{sa.n} * growth(3 * t0)));
    t0 = time_of(1);
  }
  const double setup_per_row = t0 / sa.n;
  double cell_time = 0;
  if (theta_n > 1) {
    sa.n = std::min(axis.n, std::max(8, 4 * e.threads));
    int ts = std::min(theta_n, 256);
    double t1 = time_of(ts);
    for (;;) {
      const bool cells_dominate = ts == theta_n || t1 >= 4 * setup_per_row * sa.n;
      if (cells_dominate && (t1 >= kSampleSeconds || (sa.n == axis.n && ts == theta_n))) break;
      if (!cells_dominate || sa.n == axis.n)
        ts = static_cast<int>(
            std::min<int64_t>(theta_n, int64_t{ts} * (cells_dominate ? growth(t1) : 4)));
      else
        sa.n = static_cast<int>(std::min<int64_t>(axis.n, int64_t{sa.n} * growth(t1)));
      t1 = time_of(ts);
    }
    cell_time = std::max(0.0, t1 / sa.n - setup_per_row) / (ts - 1);
  }
  e.seconds = n * (setup_per_row + (tn - 1) * cell_time);
  e.sample_seconds = sample.seconds();
  const double block =
      std::min(n, std::max<double>(grid_block_rows(theta_n), 4 * e.threads)) * tn;
  e.memory = block * (3 + (csv ? 60 : 0)) + tn * (8 + 16 + (csv ? 40 : 0)) +
             n * (sizeof(ContactParameters) + sizeof(ContactState) + 100 +
                  8 * (sizeof(CriticalDirectionPoint) + 16));
  if (writing && csv) {
    // The bytes of a CSV line, from a few rows written out (not timed).
    MapAxis ca = axis;
    ca.n = std::min(axis.n, 8);
    const int cs = std::min(theta_n, 1024);
    const std::vector<double> theta = map_theta_values(cs);
    std::ostringstream text;
    compute_param_direction_map(params, state, ca, cs, options, {},
                                [&](const ParamDirectionRows& r) {
                                  write_csv_rows(ca, theta, r, text);
                                });
    e.output = e.cells * static_cast<double>(text.str().size()) / (ca.n * cs);
  } else if (writing) {
    e.output = e.cells * (2 + cross_bytes) + 8 * (n + tn) + 5 * 128;
  }
  // The finished chunks stay in PREFIX.parts until the outputs are complete (maps/map_run.hpp).
  if (writing) e.output += e.cells * (2 + cross_bytes);
  return e;
}

GridEstimate sample_param_param(const ContactParameters& params, const ContactState& state,
                                const MapAxis& axis1, const MapAxis& axis2,
                                const MapOptions& options, bool csv, bool writing) {
  const Stopwatch sample;
  GridEstimate e;
  const double cross_bytes = options.method != RateMethod::kEnumerate ? 1 : 0;
  const double n1 = axis1.n, n2 = axis2.n;
  e.cells = n1 * n2;
  e.threads = map_worker_threads(options.threads, axis1.n);
  // As for param-direction: a sub-grid run as the map is, on its threads, in wall clock, grown until it
  // takes kSampleSeconds or is the whole map; both axes alike (the axis sampled more thinly
  // grows), since the cost of a cell varies along both (a 6-column sample of a 300 x 300 map,
  // both ends of the axis among them, put it at 3x its time).
  MapAxis a1 = axis1, a2 = axis2;
  a1.n = std::min(axis1.n, std::max(3, 2 * e.threads));
  a2.n = std::min(axis2.n, 6);
  auto time_of = [&] {
    return wall_seconds([&] {
      run_param_param_map(params, state, a1, a2, options, {}, [](const ParamParamRows&) {});
    });
  };
  double t = time_of();
  while (t < kSampleSeconds && (a1.n < axis1.n || a2.n < axis2.n)) {
    // sqrt of the growth on each axis that can grow, or all of it on the only one that can.
    const int g = growth(t), h = std::max(2, static_cast<int>(std::sqrt(double(g)) + 0.5));
    const bool both = a1.n < axis1.n && a2.n < axis2.n;
    if (a1.n < axis1.n)
      a1.n = static_cast<int>(std::min<int64_t>(axis1.n, int64_t{a1.n} * (both ? h : g)));
    if (a2.n < axis2.n)
      a2.n = static_cast<int>(std::min<int64_t>(axis2.n, int64_t{a2.n} * (both ? h : g)));
    t = time_of();
  }
  e.seconds = t / (static_cast<double>(a1.n) * a2.n) * e.cells;
  e.sample_seconds = sample.seconds();
  const double block =
      std::min(n1, std::max<double>(grid_block_rows(axis2.n), 4 * e.threads)) * n2;
  e.memory = block * (5 + (csv ? 80 : 0)) + (n1 + n2) * (100 + 4 * sizeof(CriticalValue));
  if (writing && csv) {
    // The bytes of a CSV line, from a few cells written out (not timed).
    MapAxis c1 = axis1, c2 = axis2;
    c1.n = std::min(axis1.n, 3);
    c2.n = std::min(axis2.n, 6);
    std::ostringstream text;
    compute_param_param_map(params, state, c1, c2, options, {}, [&](const ParamParamRows& r) {
      write_csv_rows(c1, c2, r, text);
    });
    e.output = e.cells * static_cast<double>(text.str().size()) / (c1.n * c2.n);
  } else if (writing) {
    e.output = e.cells * (4 + cross_bytes) + 8 * (n1 + n2) + 7 * 128;
  }
  if (writing) e.output += e.cells * (4 + cross_bytes);  // and the checkpoint's chunks
  return e;
}

}  // namespace

GridEstimate estimate_param_direction_map(const ContactParameters& params,
                                          const ContactState& state, const MapAxis& axis,
                                          int theta_n, const MapOptions& options, bool csv,
                                          bool writing) {
  try {
    return sample_param_direction(params, state, axis, theta_n, options, csv, writing);
  } catch (const InputError&) {
    GridEstimate e;  // a sampled row is not a valid model: the map names the first invalid value
    e.seconds = -1;
    return e;
  }
}

GridEstimate estimate_param_param_map(const ContactParameters& params, const ContactState& state,
                                      const MapAxis& axis1, const MapAxis& axis2,
                                      const MapOptions& options, bool csv, bool writing) {
  try {
    return sample_param_param(params, state, axis1, axis2, options, csv, writing);
  } catch (const InputError&) {
    GridEstimate e;
    e.seconds = -1;
    return e;
  }
}

}  // namespace cpkit::rate
