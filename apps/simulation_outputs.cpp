#include "simulation_outputs.hpp"

#include <filesystem>
#include <iostream>
#include <system_error>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "data_files.hpp"
#include "run_program.hpp"

namespace cpkit::cli {
namespace {

bool draw_simulation_figures(const std::string& script_name, const std::string& csv,
                             const std::string& summary, const std::string& plot,
                             const std::vector<std::string>& figures,
                             std::vector<std::string>& written) {
  std::string searched;
  const std::string script = find_data_file(script_name, &searched);
  if (script.empty()) {
    std::cerr << "cpkit simulate: plot script " << script_name << " not found (looked in "
              << searched << "); no figures\n";
    return false;
  }
  // Outputs create their folders (the figures may go elsewhere than --csv/--summary).
  const auto plot_dir = std::filesystem::path(plot).parent_path();
  std::error_code ec;
  if (!plot_dir.empty()) std::filesystem::create_directories(plot_dir, ec);
  if (ec) throw InputError("cannot create the folder of --plot '" + plot + "': " + ec.message());
  // An argument vector, never a shell: the paths come from the user or a config file.
  const std::vector<std::string> argv = {plot_python(), script, "--csv", csv,
                                         "--summary", summary, "--out", plot};
  const ProgramRun pr = run_program(argv, true, kPlotTimeLimit);
  if (!pr.started || pr.exit_code != 0) {
    std::cerr << "cpkit simulate: the plot script failed ("
              << (pr.error.empty() ? "exit " + std::to_string(pr.exit_code) : pr.error)
              << "): " << command_text(argv) << "\n";
    return false;
  }
  for (const auto& fig : figures)
    for (const char* ext : {".png", ".svg"}) written.push_back(plot + fig + ext);
  return true;
}

}  // namespace

std::vector<NamedPath> simulation_output_files(const std::string& csv, const std::string& summary,
                                               const std::string& plot) {
  std::vector<NamedPath> out;
  out.push_back({"--csv", csv.empty() && !plot.empty() ? plot + ".csv" : csv});
  out.push_back({"--summary", summary.empty() && !plot.empty() ? plot + ".json" : summary});
  if (!plot.empty())
    for (const char* fig : {"_loop", "_wear", "_state", "_orbit"})
      for (const char* ext : {".png", ".svg"})
        out.push_back({"--plot " + plot + ": PLOT" + fig + ext, plot + fig + ext});
  return out;
}

bool draw_and_name_outputs(const std::string& script_name, const std::string& csv,
                           const std::string& summary, const std::string& plot,
                           const std::vector<std::string>& figures) {
  std::vector<std::string> written;  // named at the end: the user sees what the run produced
  if (!csv.empty()) written.push_back(csv);
  if (!summary.empty()) written.push_back(summary);
  const bool plot_failed =
      !plot.empty() && !draw_simulation_figures(script_name, csv, summary, plot, figures, written);
  for (const auto& w : written) std::cerr << "cpkit simulate: wrote " << w << '\n';
  return !plot_failed;
}

}  // namespace cpkit::cli
