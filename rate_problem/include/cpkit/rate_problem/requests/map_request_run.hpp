#pragma once
/// \file map_request_run.hpp
/// A whole `cpkit map` request run by the library (docs/maps.md, docs/contact_3d.md "Maps over
/// the sphere of load directions"): the checks of the options, the up-front refusals (time,
/// memory, output size), the map (one point, N points or a 3-D system, the grid maps in
/// resumable chunks), its files under --out PREFIX, the JSON and the text summary, and the exit
/// code. What only the program has is injected (MapEnvironment): the MPI transport, stderr, the
/// lock of the output prefix, the plotting script, the machine's free memory and disk.
/// Bad input: InputError whose message names the option (--n, --format, ...), as the program
/// prints it (exit 2). Values in the model's (or system file's) units; angles in radians.
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/rate_problem/maps/grid_estimate.hpp"
#include "cpkit/rate_problem/maps/map_request.hpp"
#include "cpkit/rate_problem/maps/map_transport.hpp"

namespace cpkit::rate {

/// What the program gives a map run. Every member may be left empty (one process, no notes,
/// no lock, no picture, memory and disk unknown): what tests and Python use.
struct MapEnvironment {
  MapTransport* transport = nullptr;  ///< the job's processes; null: one process (rank 0 of 1)
  std::ostream* err = nullptr;        ///< notes, warnings and progress (the program: stderr)
  bool progress = false;              ///< progress lines on *err during the long phases
  std::string version;                ///< "cpkit_version" of the JSON and checkpoint manifests
  nlohmann::json run_echo;            ///< the "run" object of the JSON (the command line)
  /// Takes --out PREFIX before anything is written: refuses outputs over the inputs (pairs of
  /// what, path), creates the folder, locks the prefix; the result is held until the map is
  /// written.
  std::function<std::shared_ptr<void>(const std::string& prefix,
                                      const std::vector<std::pair<std::string, std::string>>&)>
      claim_prefix;
  /// Draws PREFIX.png/.svg from PREFIX.json (adds "png", "svg" to files); false: not drawn.
  std::function<bool(const std::string& prefix, nlohmann::json& files)> plot;
  std::function<double()> available_memory;                ///< bytes; -1 or empty: unknown
  std::function<double(const std::string& dir)> free_disk;  ///< bytes; -1 or empty: unknown
  int rank() const { return transport ? transport->rank() : 0; }
  int size() const { return transport ? transport->size() : 1; }
};

/// What a map request gave: the summary and the exit code (0 computed; 3 the analytic and the
/// enumeration routes disagree; 4 a requested picture not drawn; 5 not proved complete).
struct MapOutcome {
  ExitCode exit_code = kExitOk;
  bool printing = true;  ///< false on ranks other than 0 of a job (rank 0 writes and prints)
  nlohmann::json json;   ///< what --json prints (null for --list-presets)
  std::string text;      ///< what is printed without --json (with the "wrote ..." line)
};

/// Runs `cpkit map` as requested: --list-presets; a 3-D system (request.file.dim == 3); N
/// points (--system given); else one point. `request.file` is the --system file read once.
MapOutcome run_map_request(const MapRequest& request, const MapEnvironment& env = {});

/// The three routes of run_map_request.
MapOutcome run_one_point_map(const MapRequest& request, const MapEnvironment& env = {});
MapOutcome run_system_map(const SystemMapRequest& request, const MapEnvironment& env = {});
MapOutcome run_map_3d(const MapRequest& request, const MapEnvironment& env = {});

/// The one-point map of the request (make_map_setup) with the axes' and --theta-n ranges
/// checked, the messages in options (--n, --from2, ...).
MapSetup checked_map_setup(const MapRequest& request, const MapEnvironment& env = {});

/// Up-front cost of a one-point grid map of `s` (grid_estimate.hpp).
GridEstimate estimate_grid(const MapSetup& s, const MapOptions& options, bool csv, bool writing);

/// Refuses (InputError) a map whose estimated `output` bytes exceed `max_output` or 95 % of the
/// free disk in `dir` ("the map has CELLS and its output would take about ..."; `fewer` says
/// what to reduce, the hints are appended to the two messages; `gb`: the disk message in GB).
void check_output_fits(const std::string& cells, const std::string& fewer, double output,
                       double max_output, const std::string& dir, const std::string& limit_hint,
                       const std::string& disk_hint, const MapEnvironment& env, bool gb = false);

/// Refuses (InputError) a one-point grid map whose estimate exceeds `time_limit` seconds, the
/// memory (1 GiB, or 80 % of the available memory), or the output's limits (check_output_fits).
void check_grid_fits(const MapSetup& s, const GridEstimate& e, const std::string& out_dir,
                     bool csv, double time_limit, double max_output, const MapEnvironment& env);

}  // namespace cpkit::rate
