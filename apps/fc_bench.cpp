#include "fc_bench.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "cli_common.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "data_files.hpp"
#include "run_program.hpp"
#include "simulation_outputs.hpp"

namespace cpkit::cli {
namespace {

/// A CSV field in quotes (file and problem names may hold commas or quotes).
std::string quoted(const std::string& v) {
  std::string out = "\"";
  for (char c : v) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

}  // namespace

int run_fc_bench(const FcBenchArgs& a) {
  if (a.out.empty()) throw InputError("fc bench: --out PREFIX is required");
  if (!(a.tol > 0 && a.tol <= 1e-3))
    throw InputError("--tol must be in (0, 1e-3], got " + num_text(a.tol));
  if (!(a.time_limit_s > 0)) throw InputError("--time-limit must be > 0, got " + num_text(a.time_limit_s));
  // Every file read and every name checked before the first solve: bad input costs nothing.
  std::vector<FrictionContactProblem> problems;
  for (const auto& f : a.files) problems.push_back(read_friction_problem(f));
  std::vector<std::string> names = a.solvers;
  if (names.empty()) names = cpkit::lcp::solvers().names(ProblemKind::kFrictionContact);
  std::vector<const SolverEntry*> entries;
  for (const auto& n : names) {
    const SolverEntry* e = cpkit::lcp::solvers().find(n);
    if (e == nullptr || !e->accepts(ProblemKind::kFrictionContact))
      throw InputError("unknown friction solver '" + n + "' in --solvers");
    entries.push_back(e);
  }
  CommonOptions o;
  o.tol = a.tol;
  if (o.tol_acceptable < o.tol) o.tol_acceptable = o.tol;
  o.time_limit_s = a.time_limit_s;
  throw_if_invalid(o.validate(), "fc bench");

  const std::string csv = a.out + ".csv";
  std::ofstream f = open_output(csv);
  f << "file,problem,contacts,solver,status,iterations,seconds,unit_free,relative_q,relative_max\n"
    << std::setprecision(6);
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const auto& p = problems[i];
    for (std::size_t k = 0; k < entries.size(); ++k) {
      // Wall clock around the one call: what a user waits for (setup and factorisations included).
      const auto t0 = std::chrono::steady_clock::now();
      const SolveResult r = entries[k]->solve_fc(p, o);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double nan = std::nan("");
      const FrictionErrors e = r.z.size() == p.W.rows() ? friction_errors(p, r.z)
                                                        : FrictionErrors{nan, nan, nan};
      f << quoted(a.files[i]) << ',' << quoted(p.name) << ',' << p.contacts() << ',' << names[k] << ','
        << to_string(r.status) << ',' << r.iterations << ',' << s << ',' << e.unit_free << ','
        << e.relative_q << ',' << e.relative_max << '\n';
      std::cerr << p.name << " " << names[k] << ": " << to_string(r.status) << " in " << s
                << " s\n";
    }
  }
  f.close();
  std::cout << csv << '\n';
  if (a.no_plot) return kExitOk;
  std::string searched;
  const std::string script = find_data_file("cpkit_plot_fc_profile.py", &searched);
  const std::vector<std::string> argv = {plot_python(), script, "--csv", csv, "--out",
                                         a.out + ".png"};
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
