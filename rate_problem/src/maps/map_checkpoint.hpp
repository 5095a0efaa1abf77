#pragma once
// The checkpoint folder of a map run (map_checkpoint.cpp), private to maps/.
#include <cstdint>
#include <string>
#include <vector>

#include "cpkit/rate_problem/maps/map_run.hpp"

namespace cpkit::rate {

/// FNV-1a hash of the bytes (the map identity written into every chunk).
uint64_t fnv1a(const std::string& bytes);
/// FOLDER/chunk_<k>.bin
std::string chunk_path(const std::string& folder, int k);
/// Chunk k read back from `path`, checked against the map (a regular file of bounded size,
/// this map's id, the plan's rows); InputError otherwise.
MapChunk read_chunk(const ChunkRun& run, const std::string& path, int k);
/// Written under a temporary name and renamed: the file is complete or absent.
void write_file_atomic(const std::string& path, const std::string& bytes);
/// The chunks already finished in the checkpoint (rank 0; 1 = present): on resume with the same
/// manifest (stats count them); otherwise the folder is started afresh.
std::vector<char> open_checkpoint(const ChunkRun& run, ChunkRunStats& stats);

}  // namespace cpkit::rate
