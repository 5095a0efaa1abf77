// `cpkit map --system FILE` with a "dim": 3 system (docs/contact_3d.md, "Maps over the sphere of
// load directions"): --kind sphere (the load direction of one point over the sphere, two angles),
// param-direction (a parameter x directions in a meridian plane) and param-param (two
// parameters at the file's dF). Every cell: the number of solutions, the mask of solution types
// of the loaded point, and whether the solution set is proved complete. Files: PREFIX_count.npy
// (|i1), PREFIX_types.npy (|u1), PREFIX_complete.npy (|u1), PREFIX_x.npy, PREFIX_y.npy (axis
// values), PREFIX.json; --plot draws PREFIX.png/.svg (scripts/cpkit_plot.py).
// Exit codes: 0 map computed, every cell proved complete; 2 bad input; 4 a requested picture
// not drawn; 5 some cells not proved complete (counted in the JSON, flagged in the files).
#include "map_system_3d.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "map_args.hpp"
#include "map_files.hpp"
#include "memory_limit.hpp"
#include "platform/mpi_session.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"
#include "cpkit/rate_problem/report/map_json.hpp"

namespace cpkit::cli {

namespace {

namespace fs = std::filesystem;
using namespace cpkit::rate;

std::string count_text(int count) {
  if (count < 0) return "infinitely many solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}

/// The summary in words (without --json).
void print_text_3d(const Map3dRequest& r, const Map3dPlan& p, const Map3d& m,
                   const nlohmann::json& files) {
  const Map3dOptions& o = p.options;
  const int N = p.sys.n_points();
  const std::string &xname = p.xname, &yname = p.yname;
  std::cout << r.kind << " map of " << N << (N == 1 ? " 3-D point" : " 3-D points") << " ("
            << r.system << "), ";
  if (r.kind != "param-param") std::cout << "load at point " << r.point << ", ";
  std::cout << (o.facets ? "faceted with " + std::to_string(o.facets) + " facets" : std::string("exact"))
            << ": " << m.cells() << " cells\n";
  if (r.kind == "sphere")
    std::cout << "  dF = (sin b cos g, sin b sin g, cos b): b in [" << fmt(p.grid.beta_from)
              << ", " << fmt(p.grid.beta_to) << "] (" << m.rows << " values) x g in (-pi, pi] ("
              << m.cols << " values)\n";
  else if (r.kind == "param-direction")
    std::cout << "  " << xname << " in [" << fmt(r.from) << ", " << fmt(r.to) << "] ("
              << m.rows << " values) x theta in [" << fmt(p.theta_from) << ", "
              << fmt(p.theta_to) << "] (" << m.cols << " values) at g = " << fmt(p.gamma) << '\n';
  else
    std::cout << "  " << xname << " in [" << fmt(r.from) << ", " << fmt(r.to) << "] x " << yname
              << " in [" << fmt(r.from2) << ", " << fmt(r.to2) << "]\n";
  std::cout << "counts:\n";
  for (const auto& [c, n] : m.count_cells) std::cout << "  " << count_text(c) << ": " << n << " cells\n";
  std::cout << "types:\n";
  for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
    if (m.type_cells[mask] > 0)
      std::cout << "  " << type_mask_string(mask) << ": " << m.type_cells[mask] << " cells\n";
  std::cout << "not proved complete: " << m.incomplete_cells << " cells\n";
  if (m.timed_out_cells > 0)
    std::cout << "time limit reached: " << m.timed_out_cells << " cells cut short or not "
              << "computed\n";
  if (!r.out.empty()) print_written(r.out, files);
}

}  // namespace

int run_map_system_3d(const Map3dRequest& r) {
  const double max_output = parse_byte_size(r.max_output, "--max-output");
  check_map_3d_request(r, mpi::size());
  std::unique_ptr<PrefixLock> lock;  // held until the map is written
  if (!r.out.empty()) lock = claim_map_prefix(r.out, {{"--system", r.system}});
  const Stopwatch clock;
  Map3dPlan p = make_map_3d_plan(r);
  Map3dOptions& o = p.options;
  if (p.cells > kMaxMap3dCells)
    throw InputError("the map has " + p.cells_text + ", more than the " +
                     std::to_string(kMaxMap3dCells) + " cells a 3-D map holds: " + p.fewer);
  if (!r.out.empty())  // before any cell is computed
    check_output_fits(p.cells_text, p.fewer, map_3d_output_bytes(p), max_output,
                      fs::path(r.out).parent_path().string(), "", "");
  // Up-front cost from a timed sample (which also reports invalid input before the long run).
  const int threads = map_worker_threads(r.threads, p.rows());
  int64_t sampled = 0;
  const double seconds = estimate_map_3d_seconds(p, threads, sampled, clock, r.time_limit);
  if (seconds > r.time_limit)
    throw InputError("the map has " + p.cells_text + " and would need about " + fmt(seconds, 3) +
                     " s on " + std::to_string(threads) + " threads (estimated from " +
                     std::to_string(sampled) + " timed cells), more than --time-limit " +
                     fmt(r.time_limit) + ": " + p.fewer +
                     (o.facets ? ", fewer --facets" : "") + ", or raise --time-limit");
  if (seconds > 1.0)
    std::cerr << "cpkit map: " << p.cells_text << ": about " << fmt(seconds, 3) << " s on "
              << threads << " threads (estimate)\n";
  // One deadline for the whole command (issue 24, item 11): the estimate was within it; the
  // cells get what is left, and the ones it does not cover are flagged, never dropped.
  o.time_limit_s = std::max(1e-3, r.time_limit - clock.seconds());
  const Map3d m = compute_map_3d(p, o, [prog = make_map_progress()](double f) { prog("cells", f); });

  nlohmann::json j = map_3d_json(m, r.kind, p.input, p.xname, p.yname);
  j["cpkit_version"] = CPKIT_VERSION;
  const bool complete = m.incomplete_cells == 0;
  j["estimate"] = {{"seconds", seconds >= 0 ? nlohmann::json(seconds) : nlohmann::json()},
                   {"sampled_cells", sampled}};
  j["seconds"] = clock.seconds();

  bool plot_failed = false;
  nlohmann::json files = nlohmann::json::object();
  if (!r.out.empty()) {
    GridFiles out(r.out, files);
    try {
      out.add_npy("count", "|i1", m.rows, m.cols);
      out.add_npy("types", "|u1", m.rows, m.cols);
      out.add_npy("complete", "|u1", m.rows, m.cols);
      out.write_vector("x", m.x);
      out.write_vector("y", m.y);
      out.append({m.count.data(), m.types.data(), m.complete.data()}, m.cells());
      out.finish();
    } catch (...) {
      out.discard();
      throw;
    }
    j["run"] = run_echo();
    plot_failed = !write_map_json(r.out, r.plot, j, files);
  }
  if (m.timed_out_cells > 0)
    std::cerr << "cpkit map: time limit reached (--time-limit " << fmt(r.time_limit) << " s): "
              << m.timed_out_cells << " cells cut short (their count is what was found) or "
              << "not computed (count 0), flagged 0 in 'complete'\n";
  if (!complete)
    std::cerr << "cpkit map: " << m.incomplete_cells
              << " cells not proved complete (a merging pair of slip directions, an "
                 "undecided enumeration, or the time limit): flagged 0 in 'complete'\n";
  if (r.json)
    print_json(j);
  else
    print_text_3d(r, p, m, files);
  if (!complete) return kExitInconclusive;
  return plot_failed ? kExitInternal : kExitOk;
}

}  // namespace cpkit::cli
