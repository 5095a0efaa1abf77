#pragma once
// Up-front cost of a one-point grid map: time of the cell phase extrapolated from timed
// sub-grids of the same map (rows spread over the axis, directions over the circle, on the map's
// threads, in wall clock, each long enough, 0.05-0.15 s, that a loaded machine shows in it; for
// a param-direction map the rows' set-up and the cells timed apart, grid_estimate.cpp), the
// memory it keeps, the size of what it writes (csv: --format csv; writing: --out given; the
// checkpoint's chunks included). The program refuses what cannot fit before any cell is
// computed; issue 37 measured the old single-thread 1 ms sample 7x below the time of a map on
// a loaded machine, and a later sample 30x below it under AddressSanitizer.
#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::rate {

struct GridEstimate {
  double cells = 0;
  double seconds = 0;  ///< wall time on `threads` workers of one process; -1: a sampled row is
                       ///< invalid
  double sample_seconds = 0;  ///< wall time the timed samples took
  double memory = 0;   ///< bytes
  double output = 0;   ///< bytes written (0 without writing)
  int threads = 1;
  int sampled = 0;     ///< cells timed (N-point maps)
};

GridEstimate estimate_param_direction_map(const ContactParameters& params,
                                          const ContactState& state, const MapAxis& axis,
                                          int theta_n, const MapOptions& options, bool csv,
                                          bool writing);
GridEstimate estimate_param_param_map(const ContactParameters& params, const ContactState& state,
                                      const MapAxis& axis1, const MapAxis& axis2,
                                      const MapOptions& options, bool csv, bool writing);

}  // namespace cpkit::rate
