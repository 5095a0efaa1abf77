#pragma once
// An N-point grid map run in chunks (map_run.hpp; GridRunOptions of grid_map_run.hpp):
// resumable, spread over the processes of a job when a transport is given. Each chunk numbers
// its point-type patterns on its own; rank 0 renumbers them in order of first appearance over
// the whole map, so the map is the one compute_system_param_direction_map /
// compute_system_param_param_map give in one pass.
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

namespace cpkit::rate {

struct SystemParamDirectionRun {
  SystemParamDirectionMap map;  ///< rank 0: table, classes, counters; cells only without a sink
  ChunkRunStats stats;
};
struct SystemParamParamRun {
  SystemParamParamMap map;
  ChunkRunStats stats;
};

/// The rows go to `sink` on rank 0 in row order with the map's final pattern ids (without a
/// sink: into map.count/pattern). Ranks other than 0 return an empty map.
SystemParamDirectionRun run_system_param_direction_map(const ContactSystem& system,
                                                       const SystemMapAxis& axis, int theta_n,
                                                       const MapOptions& options,
                                                       const GridRunOptions& run,
                                                       const SystemParamDirectionSink& sink = {});
SystemParamParamRun run_system_param_param_map(const ContactSystem& system,
                                               const SystemMapAxis& axis1,
                                               const SystemMapAxis& axis2,
                                               const MapOptions& options,
                                               const GridRunOptions& run,
                                               const SystemParamParamSink& sink = {});

}  // namespace cpkit::rate
