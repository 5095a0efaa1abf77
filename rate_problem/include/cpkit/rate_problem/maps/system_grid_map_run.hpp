#pragma once
// An N-point grid map run in chunks (map_run.hpp; GridRunOptions of grid_map_run.hpp):
// resumable, spread over the processes of a job when a transport is given. Each chunk numbers
// its point-type patterns on its own; rank 0 renumbers them in order of first appearance over
// the whole map, so the map is the one compute_system_param_direction_map /
// compute_system_param_param_map give in one pass.
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

#include <string>

namespace cpkit::rate {

/// map: rank 0 (table, classes, counters; cells only without a sink).
using SystemParamDirectionRun = GridMapRun<SystemParamDirectionMap>;
using SystemParamParamRun = GridMapRun<SystemParamParamMap>;

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

/// FNV-1a (64 bit, lower-case hex) of a system's data as read: A (rows, cols, then the
/// column-major entries), per point mu, C_T, k_a, P_s, state.P_N, P_T, P_N, g and the ints
/// (state label, sgn_PT, values_given), the criterion, then dF, pattern1, pattern2 (each its
/// length as int64, -1 when absent, then its entries); every number in its native bytes. A
/// resumed map must read the same system (it is in the checkpoint's manifest); taken from the
/// parsed system, not the file (a --system <(...) pipe can be read once only).
std::string system_data_fingerprint(const ContactSystem& system);

}  // namespace cpkit::rate
