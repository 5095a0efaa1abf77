#pragma once
// Distributed and resumable grid maps (docs/cluster.md). A map's rows are cut into chunks that
// depend on the map alone (never on the ranks or threads); the chunks are computed by the
// processes of an MPI job, handed out one at a time by rank 0 as ranks finish (cells of one map
// differ in cost by orders of magnitude), or by one process; each finished chunk is kept in a
// checkpoint folder PREFIX.parts/ (written atomically), and rank 0 consumes the chunks in row
// order, so every output is the one a single process writes. A run stopped part-way (Ctrl-C, a
// killed job) is resumed from the finished chunks with --resume.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::cli {

/// One computed chunk: rows [row_begin, row_end), its cell arrays (raw bytes, in the order the
/// map kind defines) and the summary of its rows (the kind's JSON).
struct MapChunk {
  int index = -1, row_begin = 0, row_end = 0;
  int rank = 0;  ///< the process that computed it
  nlohmann::json summary;
  std::vector<std::string> arrays;
};
/// Bytes of a chunk (for MPI messages and checkpoint files) and back; parse_chunk throws
/// InputError when the bytes are not a chunk (a truncated or foreign file).
std::string serialize_chunk(const MapChunk& c);
MapChunk parse_chunk(const std::string& bytes);
/// The checkpoint manifest PREFIX.parts/manifest.json (what the map is), parsed with the limits
/// of every JSON reader (core/json_read.hpp: nesting, numbers, duplicate keys). InputError
/// "--resume: 'origin' is not a checkpoint manifest: ..." for anything but a JSON object.
nlohmann::json parse_checkpoint_manifest(const std::string& text, const std::string& origin);

/// The cut of a map with `rows` rows of `columns` cells: about 64 chunks (one row each for
/// small maps), at most about 2^20 cells a chunk.
struct ChunkPlan {
  int rows = 0, chunk_rows = 1, chunks = 0;
  int64_t columns = 0;
  int begin(int k) const noexcept { return k * chunk_rows; }
  int end(int k) const noexcept { return std::min(rows, (k + 1) * chunk_rows); }
};
ChunkPlan plan_chunks(int rows, int64_t columns);

struct ChunkRun {
  ChunkPlan plan;
  std::function<MapChunk(int k)> compute;          ///< on any rank
  std::function<void(const MapChunk&)> consume;    ///< on rank 0, in chunk order
  std::string checkpoint;  ///< folder for finished chunks ("" for none)
  nlohmann::json manifest; ///< what the map is: a resumed run must have exactly the same
  bool resume = false;     ///< reuse the finished chunks of the checkpoint
  rate::MapProgress progress;
};

struct ChunkRunStats {
  int ranks = 1;
  std::vector<int64_t> rank_cells;  ///< cells each rank computed in this run
  int64_t resumed_cells = 0;        ///< cells taken from the checkpoint
  int resumed_chunks = 0;
};

/// Runs the map's chunks (every rank calls it). Errors during the distributed phase end the
/// whole job (a message naming the rank, then MPI_Abort): no rank waits for a dead one. Throws
/// InputError (before any work) when --resume meets a checkpoint of a different map.
ChunkRunStats run_chunks(const ChunkRun& run);

/// Removes the checkpoint folder (after the outputs are complete).
void remove_checkpoint(const std::string& folder);

/// A grid map's chunks with the checkpoint PREFIX.parts when `out_prefix` is set (manifest:
/// what the map is); `progress` is called on rank 0 only. Returns the run's figures.
ChunkRunStats run_map_chunks(const std::string& out_prefix, bool resume,
                             const nlohmann::json& manifest, const ChunkPlan& plan,
                             const std::function<MapChunk(int)>& compute,
                             const std::function<void(const MapChunk&)>& consume,
                             const rate::MapProgress& progress);

/// The run figures of a map's JSON: "ranks", "rank_cells", and "resumed_cells" after --resume.
void add_run_figures(nlohmann::json& j, const ChunkRunStats& st);

/// Class boxes of a part of a map, as JSON ([code, cells, x_min, x_max, y_min, y_max] each), and
/// their merge into the boxes of the whole map (by code; min/max and sums: what one pass over
/// all cells gives).
nlohmann::json boxes_to_json(const std::vector<rate::GridClassBox>& boxes);
void merge_boxes(std::map<int, rate::GridClassBox>& into, const nlohmann::json& boxes);

}  // namespace cpkit::cli
