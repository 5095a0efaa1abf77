// `cpkit fc bench`'s checks and table (fc_bench.hpp): every solver on every file, a row each.
#include "cpkit/lcp/friction/fc_bench.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/option_words.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/friction/fc_request.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::lcp::friction {
namespace {

/// A CSV field in quotes (file and problem names may hold commas or quotes).
std::string quoted(const std::string& v) {
  std::string out = "\"";
  for (char c : v) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

/// Flushes `csv` and throws when it has failed: a full disk stops the run at the row it hit.
void flush_or_throw(std::ostream& csv, const std::string& table_name) {
  csv.flush();
  if (!csv) throw InputError("error writing '" + table_name + "' (disk full or not writable?)");
}

/// " (TITLE)" after a file name in the progress log: an FCLIB file's title, when it says more
/// than the file's own name (a .dat problem is named after its file).
std::string title_beside(const std::string& title, const std::string& file) {
  if (title.empty() || title == std::filesystem::path(file).stem().string()) return {};
  return " (" + title + ")";
}

}  // namespace

FcBench prepare_fc_bench(const FcBenchRequest& a) {
  if (!(a.tol > 0 && a.tol <= 1e-3))
    throw InputError("--tol must be in (0, 1e-3], got " + num_text(a.tol));
  const FrictionMeasure measure = parse_friction_measure(a.measure, "--measure");
  if (!(a.time_limit_s > 0))
    throw InputError("--time-limit must be > 0, got " + num_text(a.time_limit_s));
  FcBench b;
  b.files = a.files;
  for (const auto& f : a.files) b.problems.push_back(read_friction_problem(f));
  b.names = a.solvers;
  if (b.names.empty()) b.names = solvers().names(ProblemKind::kFrictionContact);
  for (const auto& n : b.names) {
    const SolverEntry* e = solvers().find(n);
    if (e == nullptr || !e->accepts(ProblemKind::kFrictionContact))
      throw InputError("unknown friction solver '" + n + "' in --solvers (valid: " +
                       fc_solver_list() + ")");
    b.entries.push_back(e);
  }
  b.measure = measure;
  b.options.tol = a.tol;
  if (b.options.tol_acceptable < b.options.tol) b.options.tol_acceptable = b.options.tol;
  b.options.time_limit_s = a.time_limit_s;
  throw_if_invalid_option(b.options.validate(), {{"tol", "--tol"}, {"time_limit_s", "--time-limit"}});
  return b;
}

void write_fc_bench_table(const FcBench& b, std::ostream& csv, const std::string& table_name,
                          std::ostream* progress) {
  csv << "file,problem,contacts,solver,status,iterations,seconds,unit_free,relative_q,relative_max,measure\n"
      << std::setprecision(6);
  flush_or_throw(csv, table_name);
  for (std::size_t i = 0; i < b.problems.size(); ++i) {
    const auto& p = b.problems[i];
    for (std::size_t k = 0; k < b.entries.size(); ++k) {
      // Wall clock around the one call: what a user waits for (setup and factorisations included).
      const auto t0 = std::chrono::steady_clock::now();
      const SolveResult r = solve_in_measure(p, *b.entries[k], b.options, b.measure);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double nan = std::nan("");
      const FrictionErrors e = r.z.size() == p.W.rows() ? friction_errors(p, r.z)
                                                        : FrictionErrors{nan, nan, nan};
      csv << quoted(b.files[i]) << ',' << quoted(p.name) << ',' << p.contacts() << ','
          << b.names[k] << ',' << to_string(r.status) << ',' << r.iterations << ',' << s << ','
          << e.unit_free << ',' << e.relative_q << ',' << e.relative_max << ','
          << to_string(b.measure) << '\n';
      flush_or_throw(csv, table_name);
      if (progress)  // by file, as the user named it (FCLIB titles repeat across files)
        *progress << b.files[i] << title_beside(p.name, b.files[i]) << " " << b.names[k] << ": "
                  << to_string(r.status) << " in " << s << " s\n";
    }
  }
}

}  // namespace cpkit::lcp::friction
