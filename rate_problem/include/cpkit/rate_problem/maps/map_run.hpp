#pragma once
// The run of a grid map (docs/cluster.md): its rows cut into chunks that depend on the map alone
// (never on the ranks or threads), computed by one process or by the processes of a job (handed
// out one at a time by rank 0 as ranks finish: cells of one map differ in cost by orders of
// magnitude), each finished chunk kept in a checkpoint folder PREFIX.parts/ (written
// atomically), consumed by rank 0 in row order, so that every output is the one a single process
// writes. A run stopped part-way (Ctrl-C, a killed job, ChunkRun::chunk_limit) is resumed from
// the finished chunks.
//
// The library knows no MPI: the program injects the transport (MapTransport; cpkit's is
// apps/platform/mpi_session.hpp). Without one the run is one process, rank 0 of 1, so that
// Python and the tests call it directly.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_transport.hpp"

namespace cpkit::rate {

/// One computed chunk: rows [row_begin, row_end), its cell arrays (raw bytes, in the order the
/// map kind defines) and the summary of its rows (the kind's JSON).
struct MapChunk {
  uint64_t map_id = 0;  ///< the map it belongs to (ChunkRun::map_id; set by rank 0 when stored)
  int index = -1, row_begin = 0, row_end = 0;
  int rank = 0;  ///< the process that computed it
  nlohmann::json summary;
  std::vector<std::string> arrays;
};
/// Bytes of a chunk (for messages and checkpoint files) and back; parse_chunk throws InputError
/// when the bytes are not a chunk (a truncated or foreign file, a summary nested too deep).
std::string serialize_chunk(const MapChunk& c);
MapChunk parse_chunk(const std::string& bytes);
/// JSON of a checkpoint file (a manifest, a chunk's summary), parsed with the bounded parser of
/// every cpkit input: invalid or too deep text is an InputError naming `what`.
nlohmann::json parse_checkpoint_json(const std::string& text, const std::string& what);

/// The cut of a map with `rows` rows of `columns` cells: about 64 chunks (one row each for
/// small maps), at most about 2^20 cells a chunk.
struct ChunkPlan {
  int rows = 0, chunk_rows = 1, chunks = 0;
  int64_t columns = 0;
  int begin(int k) const noexcept { return k * chunk_rows; }
  int end(int k) const noexcept { return std::min(rows, (k + 1) * chunk_rows); }
};
ChunkPlan plan_chunks(int rows, int64_t columns);
/// Chunk k of the plan, its rows set, to be filled by the map kind.
inline MapChunk chunk_of(const ChunkPlan& plan, int k) {
  MapChunk c;
  c.index = k;
  c.row_begin = plan.begin(k);
  c.row_end = plan.end(k);
  return c;
}

struct ChunkRun {
  ChunkPlan plan;
  std::function<MapChunk(int k)> compute;          ///< on any rank
  std::function<void(const MapChunk&)> consume;    ///< on rank 0, in chunk order
  std::string checkpoint;  ///< folder for finished chunks ("" for none)
  nlohmann::json manifest; ///< what the map is: a resumed run must have exactly the same
  /// Hash of the manifest, written into every chunk: a chunk of another map (another run on
  /// the same prefix) is refused on resume.
  uint64_t map_id = 0;
  bool resume = false;     ///< reuse the finished chunks of the checkpoint
  MapProgress progress;
  MapTransport* transport = nullptr;  ///< null: one process
  /// At most this many chunks computed in this run (one process; -1: all). A run stopped by it
  /// returns complete = false with the finished chunks in the checkpoint, to be resumed.
  int chunk_limit = -1;
  /// Asked (on rank 0) before each chunk is begun or handed out: true stops the run there (the
  /// time limit of `cpkit map`). The chunks already running are finished and kept; the run
  /// returns complete = false and stopped = true, to be resumed; `progress` then gets the
  /// fraction -1 (the phase ended early). Empty: never.
  std::function<bool()> stop;
};

struct ChunkRunStats {
  int ranks = 1;
  std::vector<int64_t> rank_cells;  ///< cells each rank computed in this run
  int64_t resumed_cells = 0;        ///< cells taken from the checkpoint
  int resumed_chunks = 0;
  bool complete = false;  ///< every chunk consumed (rank 0; other ranks: their part done)
  bool stopped = false;   ///< ChunkRun::stop ended the run (rank 0)
  int rows_done = 0;      ///< rows consumed, from the first on (rank 0): all of them when complete
};

/// A grid map run in chunks (grid_map_run.hpp, system_grid_map_run.hpp): the map (rank 0) and
/// what the run did.
template <class Map>
struct GridMapRun {
  Map map;
  ChunkRunStats stats;
};

/// Runs the map's chunks (every rank calls it). Errors during the distributed phase end the
/// whole job (MapTransport::abort naming the rank). Throws InputError (before any work) when a
/// resume meets a checkpoint of a different map, or a file there cpkit did not write.
ChunkRunStats run_chunks(const ChunkRun& run);

/// Removes the checkpoint folder (after the outputs are complete).
void remove_checkpoint(const std::string& folder);

/// A grid map's chunks with the checkpoint PREFIX.parts when `out_prefix` is set (manifest:
/// what the map is; the plan is added to it); `progress` is called on rank 0 only.
ChunkRunStats run_map_chunks(const std::string& out_prefix, bool resume,
                             const nlohmann::json& manifest, const ChunkPlan& plan,
                             const std::function<MapChunk(int)>& compute,
                             const std::function<void(const MapChunk&)>& consume,
                             const MapProgress& progress, MapTransport* transport = nullptr,
                             int chunk_limit = -1, const std::function<bool()>& stop = {});

/// The run figures of a map's JSON: "ranks", "rank_cells", and "resumed_cells" after a resume.
void add_run_figures(nlohmann::json& j, const ChunkRunStats& st);

/// Class boxes of a part of a map, as JSON ([code, cells, x_min, x_max, y_min, y_max] each), and
/// their merge into the boxes of the whole map (by code; min/max and sums: what one pass over
/// all cells gives).
nlohmann::json boxes_to_json(const std::vector<GridClassBox>& boxes);
void merge_boxes(std::map<int, GridClassBox>& into, const nlohmann::json& boxes);

}  // namespace cpkit::rate
