#pragma once
// A one-point grid map run in chunks (map_run.hpp): resumable from a checkpoint, spread over the
// processes of a job when a transport is given; the map is the one compute_param_direction_map /
// compute_param_param_map give in one pass (cells, counters, class boxes, critical curves).
#include <string>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_run.hpp"

namespace cpkit::rate {

/// How a grid map is run.
struct GridRunOptions {
  std::string checkpoint_prefix;  ///< the checkpoint is PREFIX.parts ("": none, no resume)
  bool resume = false;            ///< reuse the finished chunks of PREFIX.parts
  /// What the map is, beyond the grid (the caller's inputs and options: version, model,
  /// method, format ...); the axes and the plan are added. A resume must match it exactly.
  nlohmann::json manifest = nlohmann::json::object();
  /// Adds the axes (and directions) to the manifest; off when the caller's manifest already
  /// holds them (cpkit's N-point maps echo them in "input").
  bool describe_grid = true;
  MapTransport* transport = nullptr;  ///< null: one process
  MapProgress progress;               ///< rank 0; phase "chunks"
  int chunk_limit = -1;  ///< one process: stop after this many new chunks (complete = false)
  /// Asked before each chunk (ChunkRun::stop): true ends the run there (complete = false,
  /// stopped = true; the finished chunks stay in the checkpoint). `cpkit map`'s time limit.
  std::function<bool()> stop;
};

/// map: rank 0 (summary always; cells only without a sink).
using ParamDirectionRun = GridMapRun<ParamDirectionMap>;
using ParamParamRun = GridMapRun<ParamParamMap>;

/// The map's rows go to `sink` on rank 0 in row order (without a sink: into map.count/types/
/// disagree). Ranks other than 0 return an empty map. map.seconds is the run's wall time.
/// Validate the grid first (validate_map_grid) to name the first invalid value of the map.
ParamDirectionRun run_param_direction_map(const ContactParameters& params,
                                          const ContactState& state, const MapAxis& axis,
                                          int theta_n, const MapOptions& options,
                                          const GridRunOptions& run,
                                          const ParamDirectionSink& sink = {});
ParamParamRun run_param_param_map(const ContactParameters& params, const ContactState& state,
                                  const MapAxis& axis1, const MapAxis& axis2,
                                  const MapOptions& options, const GridRunOptions& run,
                                  const ParamParamSink& sink = {});

/// The chunks of a grid map under `run` (the kinds' common part): `grid` describes the grid
/// (added to run.manifest when run.describe_grid).
ChunkRunStats run_grid_chunks(const GridRunOptions& run, nlohmann::json grid,
                              const ChunkPlan& plan, const std::function<MapChunk(int)>& compute,
                              const std::function<void(const MapChunk&)>& consume);

/// Threads a map uses: `requested` (0: all cores), at most one per row.
int map_worker_threads(int requested, int rows);

}  // namespace cpkit::rate
