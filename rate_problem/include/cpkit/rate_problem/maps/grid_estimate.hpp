#pragma once
// Up-front cost of a one-point grid map: time of the cell phase extrapolated from a timed
// sub-grid of the same map (rows spread over the axis, on the map's threads, in wall clock, grown
// until it takes 0.15 s or is the whole map: a loaded machine shows in it), the memory it keeps,
// the size of what it writes (csv: --format csv; writing: --out given; the checkpoint's chunks
// included). The program refuses what cannot fit before any cell is computed; issue 37 measured
// the old single-thread 1 ms sample 7x below the time of a map on a loaded machine.
#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::rate {

struct GridEstimate {
  double cells = 0;
  double seconds = 0;  ///< wall time on `threads` workers of one process; -1: a sampled row is
                       ///< invalid
  double memory = 0;   ///< bytes
  double output = 0;   ///< bytes written (0 without writing)
  int threads = 1;
};

GridEstimate estimate_param_direction_map(const ContactParameters& params,
                                          const ContactState& state, const MapAxis& axis,
                                          int theta_n, const MapOptions& options, bool csv,
                                          bool writing);
GridEstimate estimate_param_param_map(const ContactParameters& params, const ContactState& state,
                                      const MapAxis& axis1, const MapAxis& axis2,
                                      const MapOptions& options, bool csv, bool writing);

}  // namespace cpkit::rate
