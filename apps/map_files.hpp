#pragma once
// What every `cpkit map` kind shares (map_command.cpp: one point; map_system.cpp: N points):
// progress on stderr, the files of a grid map written while its cells are computed, the
// plotting script.
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_files.hpp"
#include "output_guard.hpp"
#include "platform/mpi_session.hpp"

namespace cpkit::cli {

/// Prints "\rcpkit map: cells 40% (1.2 s)" on stderr for every phase once the map has run for
/// more than a second, and the phase's final line at 100 %.
rate::MapProgress make_map_progress();

/// Runs the plotting script on PREFIX.json; false when no picture was drawn (the data is
/// written either way; the caller then exits 4: a requested plot that fails is a failure).
/// Adds "png" and "svg" to `files` on success.
bool run_map_plot(const std::string& prefix, nlohmann::json& files);

/// The map's files (maps/map_files.hpp).
using rate::GridFiles;
using rate::write_text_file;
using rate::axis_values;

/// A map kind's chunked library run (`call`, returning the result) with the files discarded if
/// it fails; false on ranks other than 0 (rank 0 writes and prints).
template <class Result, class Call>
bool run_to_files(GridFiles& out, Result& res, Call&& call) {
  try {
    res = call();
    if (mpi::rank() != 0) return false;
    out.finish();
  } catch (...) {
    out.discard();
    throw;
  }
  return true;
}

/// Writes PREFIX.json (files["json"] added, j["files"] = files; under a temporary name, renamed)
/// and, with `plot`, draws the picture (run_map_plot) and writes PREFIX.json again with the
/// picture's files. False when the picture was asked for and not drawn (the caller exits 4).
bool write_map_json(const std::string& prefix, bool plot, nlohmann::json& j,
                    nlohmann::json& files);

/// "wrote DIR/F1 DIR/F2 ..." on stdout: the files of `files`, next to PREFIX.
void print_written(const std::string& prefix, const nlohmann::json& files);

/// Refuses (InputError, exit 2) a map whose estimated `output` bytes exceed --max-output or 95 %
/// of the free disk in `dir` ("the map has CELLS and its output would take about ..."; `fewer`
/// says what to reduce; the hints are appended to the two messages; `gb`: the disk message in
/// GB, as the N-point maps word it).
void check_output_fits(const std::string& cells, const std::string& fewer, double output,
                       double max_output, const std::string& dir, const std::string& limit_hint,
                       const std::string& disk_hint, bool gb = false);

/// Creates PREFIX's folder; throws InputError when --out is not a usable file prefix.
void prepare_out_prefix(const std::string& prefix);

/// Everything a map does with --out PREFIX before it writes: refuses (InputError, exit 2) a
/// PREFIX whose files or checkpoint folder PREFIX.parts would overwrite or remove an input,
/// creates PREFIX's folder, and on rank 0 locks the prefix for the run (PREFIX.lock: a second
/// run on the same prefix is refused). Returns the lock (null on other ranks).
std::unique_ptr<PrefixLock> claim_map_prefix(const std::string& prefix,
                                             const std::vector<NamedPath>& inputs);

}  // namespace cpkit::cli
