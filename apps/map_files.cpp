// Shared by every `cpkit map` kind: progress, grid files, the plotting script (map_files.hpp).
#include "map_files.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cli_common.hpp"
#include "data_files.hpp"
#include "machine_resources.hpp"
#include "memory_limit.hpp"
#include "platform/mpi_session.hpp"
#include "run_program.hpp"

namespace cpkit::cli {

namespace fs = std::filesystem;

namespace {
constexpr int kPlotNoMatplotlib = 5;  // exit code of cpkit_plot.py when matplotlib is missing
}  // namespace

rate::MapProgress make_map_progress() {
  struct State {
    Stopwatch clock;
    std::string phase;
    bool printed = false;
    int percent = -1;
    double last = 0;
  };
  auto st = std::make_shared<State>();
  return [st](std::string_view phase, double f) {
    if (phase != st->phase) {
      st->phase = std::string(phase);
      st->printed = false;
      st->percent = -1;
    }
    const double t = st->clock.seconds();
    const int percent = static_cast<int>(100 * f);
    // A new line only when the percentage changed (or every 5 s): short logs when redirected.
    if (f < 1.0 && t > 1.0 && (percent != st->percent || t > st->last + 5.0)) {
      st->percent = percent;
      st->last = t;
      std::cerr << "\rcpkit map: " << phase << ' ' << std::setw(3) << static_cast<int>(100 * f)
                << "% (" << std::fixed << std::setprecision(1) << t << " s)" << std::defaultfloat
                << std::flush;
      st->printed = true;
    } else if (f >= 1.0 && st->printed) {
      std::cerr << "\rcpkit map: " << phase << " 100% (" << std::fixed << std::setprecision(1)
                << t << " s)" << std::defaultfloat << '\n';
      st->printed = false;
    }
  };
}

bool run_map_plot(const std::string& prefix, nlohmann::json& files) {
  std::string searched;
  const std::string script = find_data_file("cpkit_plot.py", &searched);
  if (script.empty()) {
    std::cerr << "cpkit map: plotting script cpkit_plot.py not found (looked in " << searched
              << "); the data is in " << prefix << ".json and the files it lists\n";
    return false;
  }
  const std::vector<std::string> argv = {plot_python(), script, prefix + ".json"};
  const std::string cmd = command_text(argv);
  const ProgramRun pr = run_program(argv, true, kPlotTimeLimit);
  const int code = pr.started ? pr.exit_code : -1;
  if (code == 0) {
    files["png"] = fs::path(prefix + ".png").filename().string();
    files["svg"] = fs::path(prefix + ".svg").filename().string();
    std::cerr << "cpkit map: wrote " << prefix << ".png and " << prefix << ".svg\n";
    return true;
  }
  if (code == kPlotNoMatplotlib) {
    std::cerr << "cpkit map: no picture: matplotlib is not available to " << plot_python()
              << ". The data was written (" << prefix
              << ".json and the files it lists). To get the picture install matplotlib (Debian: "
                 "apt-get install python3-matplotlib) and run:\n  "
              << cmd << '\n';
  } else {
    std::cerr << "cpkit map: the plotting script failed ("
              << (pr.error.empty() ? "exit " + std::to_string(code) : pr.error)
              << "); the data was written. Command:\n  " << cmd << '\n';
  }
  return false;
}

bool write_map_json(const std::string& prefix, bool plot, nlohmann::json& j,
                    nlohmann::json& files) {
  files["json"] = fs::path(prefix).filename().string() + ".json";
  j["files"] = files;
  write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
  if (!plot) return true;
  const bool drawn = run_map_plot(prefix, files);
  j["files"] = files;
  write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
  return drawn;
}

void print_written(const std::string& prefix, const nlohmann::json& files) {
  std::cout << "wrote";
  for (const auto& [k, v] : files.items())
    std::cout << ' ' << (fs::path(prefix).parent_path() / v.get<std::string>()).string();
  std::cout << '\n';
}

void check_output_fits(const std::string& cells, const std::string& fewer, double output,
                       double max_output, const std::string& dir, const std::string& limit_hint,
                       const std::string& disk_hint, bool gb) {
  if (output > max_output)
    throw InputError("the map has " + cells + " and its output would take about " +
                     byte_text(output) + " (estimated), more than --max-output " +
                     byte_text(max_output) + ": " + fewer + limit_hint + ", or raise --max-output");
  if (!(output > 0)) return;
  const double free = free_disk_bytes(dir);
  if (free < 0 || !(output > 0.95 * free)) return;
  std::ostringstream gbs;  // the N-point maps' wording: "1.23 GB but only 0.5 GB"
  gbs << std::setprecision(3) << output / 1e9 << " GB but only " << free / 1e9 << " GB";
  throw InputError("the map has " + cells + " and its output would take about " +
                   (gb ? gbs.str() : byte_text(output) + " but only " + byte_text(free)) +
                   " is free in '" + (dir.empty() ? "." : dir) + "': " + fewer + disk_hint);
}

void prepare_out_prefix(const std::string& prefix) {
  if (fs::path(prefix).filename().empty())
    throw InputError("--out needs a file prefix such as out/map (got '" + prefix + "')");
  const fs::path parent = fs::path(prefix).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) throw InputError("cannot create the output folder '" + parent.string() + "'");
  }
}

std::unique_ptr<PrefixLock> claim_map_prefix(const std::string& prefix,
                                             const std::vector<NamedPath>& inputs) {
  if (fs::path(prefix).filename().empty())
    throw InputError("--out needs a file prefix such as out/map (got '" + prefix + "')");
  refuse_outputs_over_inputs("cpkit map", map_output_files(prefix), inputs);
  for (const auto& i : inputs)
    if (inside_folder(i.path, prefix + ".parts"))
      throw InputError("cpkit map: the input '" + i.path + "' (" + i.what +
                       ") lies in the checkpoint folder '" + prefix +
                       ".parts' of --out " + prefix + ", which a map replaces; move it first");
  prepare_out_prefix(prefix);
  if (mpi::rank() != 0) return nullptr;
  return std::make_unique<PrefixLock>(prefix);
}

}  // namespace cpkit::cli
