// Up-front cost of a one-point grid map (grid_estimate.hpp): a small timed sample of the same
// map on one thread, extrapolated.
#include "cpkit/rate_problem/maps/grid_estimate.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"

namespace cpkit::rate {

namespace {

GridEstimate sample_param_direction(const ContactParameters& params, const ContactState& state,
                                    const MapAxis& axis, int theta_n, const MapOptions& options,
                                    bool csv, bool writing) {
  GridEstimate e;
  MapOptions one = options;
  one.threads = 1;
  const double cross_bytes = options.method != RateMethod::kEnumerate ? 1 : 0;
  const double n = axis.n, tn = theta_n;
  e.cells = n * tn;
  e.threads = map_worker_threads(options.threads, axis.n);
  MapAxis sa = axis;
  sa.n = std::min(axis.n, 8);
  const int ts = std::min(theta_n, 1024);
  const std::vector<double> theta = map_theta_values(ts);
  std::ostringstream text;
  // Each sample is timed twice and the faster run kept (a busy machine inflates one run).
  double t1 = 1e300, t0 = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    const Stopwatch c1;
    compute_param_direction_map(params, state, sa, ts, one, {},
                                [&](const ParamDirectionRows& r) {
                                  if (csv && rep == 0) write_csv_rows(sa, theta, r, text);
                                });
    t1 = std::min(t1, c1.seconds());
    // The per-row part (critical directions, set-up): one direction per row.
    const Stopwatch c0;
    compute_param_direction_map(params, state, sa, 1, one, {}, [](const ParamDirectionRows&) {});
    t0 = std::min(t0, c0.seconds());
  }
  const double per_row = t0 / sa.n;
  const double per_cell = std::max(0.0, t1 - t0) / (sa.n * std::max(1, ts - 1));
  e.seconds = (n * per_row + e.cells * per_cell) / e.threads;
  const double block =
      std::min(n, std::max<double>(grid_block_rows(theta_n), 4 * e.threads)) * tn;
  e.memory = block * (3 + (csv ? 60 : 0)) + tn * (8 + 16 + (csv ? 40 : 0)) +
             n * (sizeof(ContactParameters) + sizeof(ContactState) + 100 +
                  8 * (sizeof(CriticalDirectionPoint) + 16));
  if (writing)
    e.output = csv ? e.cells * static_cast<double>(text.str().size()) / (sa.n * ts)
                   : e.cells * (2 + cross_bytes) + 8 * (n + tn) + 5 * 128;
  // The finished chunks stay in PREFIX.parts until the outputs are complete (maps/map_run.hpp).
  if (writing) e.output += e.cells * (2 + cross_bytes);
  return e;
}

GridEstimate sample_param_param(const ContactParameters& params, const ContactState& state,
                                const MapAxis& axis1, const MapAxis& axis2,
                                const MapOptions& options, bool csv, bool writing) {
  GridEstimate e;
  MapOptions one = options;
  one.threads = 1;
  const double cross_bytes = options.method != RateMethod::kEnumerate ? 1 : 0;
  const double n1 = axis1.n, n2 = axis2.n;
  e.cells = n1 * n2;
  e.threads = map_worker_threads(options.threads, axis1.n);
  MapAxis a1 = axis1, a2 = axis2;
  a1.n = std::min(axis1.n, 3);
  a2.n = std::min(axis2.n, 6);
  std::ostringstream text;
  double t = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    const Stopwatch c1;
    compute_param_param_map(params, state, a1, a2, one, {}, [&](const ParamParamRows& r) {
      if (csv && rep == 0) write_csv_rows(a1, a2, r, text);
    });
    t = std::min(t, c1.seconds());
  }
  e.seconds = t / (a1.n * a2.n) * e.cells / e.threads;
  const double block =
      std::min(n1, std::max<double>(grid_block_rows(axis2.n), 4 * e.threads)) * n2;
  e.memory = block * (5 + (csv ? 80 : 0)) + (n1 + n2) * (100 + 4 * sizeof(CriticalValue));
  if (writing)
    e.output = csv ? e.cells * static_cast<double>(text.str().size()) / (a1.n * a2.n)
                   : e.cells * (4 + cross_bytes) + 8 * (n1 + n2) + 7 * 128;
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
