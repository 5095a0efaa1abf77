#include "fc_bench.hpp"

#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/rate_problem/maps/map_files.hpp"
#include "data_files.hpp"
#include "output_guard.hpp"
#include "run_program.hpp"

namespace cpkit::cli {

namespace fs = std::filesystem;

int run_fc_bench(const FcBenchArgs& a) {
  if (a.out.empty()) throw InputError("fc bench: --out PREFIX is required");
  if (fs::path(a.out).filename().empty())
    throw InputError("--out needs a file prefix such as out/bench (got '" + a.out + "')");
  // Nothing of --out may be a problem file, before anything is read or written (as `cpkit map`).
  std::vector<NamedPath> inputs;
  for (const auto& f : a.files) inputs.push_back({"FILE", f});
  const std::vector<NamedPath> outputs = prefix_output_files(a.out, {".csv", ".png", ".lock"});
  refuse_outputs_over_inputs("cpkit fc bench", outputs, inputs);
  refuse_special_outputs("cpkit fc bench", outputs);  // e.g. PREFIX.csv -> /dev/full
  const lcp::friction::FcBench bench = lcp::friction::prepare_fc_bench(a);
  const fs::path parent = fs::path(a.out).parent_path();
  std::error_code ec;
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) throw InputError("cannot create the output folder '" + parent.string() + "'");
  const PrefixLock lock(a.out);  // a second run on the same prefix is refused, not interleaved

  const std::string csv = a.out + ".csv";
  rate::write_text_file(csv, [&](std::ostream& f) {
    lcp::friction::write_fc_bench_table(bench, f, csv, &std::cerr);
  });
  std::cout << csv << '\n';
  if (a.no_plot) return kExitOk;
  std::string searched;
  const std::string script = find_data_file("cpkit_plot_fc_profile.py", &searched);
  // The picture says the tolerance and time limit the table was computed with.
  const std::vector<std::string> argv = {
      plot_python(), script, "--csv", csv, "--out", a.out + ".png",
      "--tol", num_text(bench.options.tol), "--time-limit", num_text(bench.options.time_limit_s)};
  if (script.empty()) {
    std::cerr << "cpkit fc bench: cpkit_plot_fc_profile.py not found (looked in " << searched
              << "); the CSV is written, no profile\n";
    return kExitInternal;
  }
  const ProgramRun pr = run_program(argv, true, kPlotTimeLimit);
  if (!pr.started || pr.exit_code != 0) {
    std::cerr << "cpkit fc bench: the profile could not be drawn ("
              << (pr.error.empty() ? "exit " + std::to_string(pr.exit_code) : pr.error)
              << "); the CSV is written. Run: " << command_text(argv) << '\n';
    return kExitInternal;
  }
  std::cout << a.out << ".png\n";
  return kExitOk;
}

}  // namespace cpkit::cli
