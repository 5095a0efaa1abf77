#pragma once
/// \file fc_bench.hpp
/// What `cpkit fc bench FILE... [--solvers a,b] [--tol T] [--time-limit S]` was asked and its
/// table: every solver on every file, one CSV row per file and solver (docs/friction_contact.md,
/// "Command line"). The files, the --out prefix, its lock and the picture are the program's
/// (apps/fc_bench.cpp); the table is written to any stream, each row flushed as it is computed,
/// so a run that stops part-way leaves its finished rows in the stream's file.
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"

namespace cpkit::lcp::friction {

/// The options of `cpkit fc bench` as given (the --out files aside).
struct FcBenchRequest {
  std::vector<std::string> files;
  std::vector<std::string> solvers;  ///< empty: every registered friction solver
  double tol = 1e-10;                ///< in the measure below, in (0, 1e-3]
  /// The measure that decides "solved" (core/friction_measure.hpp): relative_q by default, so
  /// that the profile compares with published ones (FCLIB: Acary, Bremond, Huber, INRIA
  /// RR-9118); unit_free or relative_max on request.
  std::string measure = "relative_q";
  double time_limit_s = 60;          ///< per solve, seconds
};

/// A checked request: every file read, every solver found, the options validated.
struct FcBench {
  std::vector<std::string> files;
  std::vector<FrictionContactProblem> problems;  ///< problems[i] is read from files[i]
  std::vector<std::string> names;                ///< the solvers, in the order run
  std::vector<const SolverEntry*> entries;       ///< entries[k] runs names[k]
  CommonOptions options;
  FrictionMeasure measure = FrictionMeasure::kRelativeQ;
};

/// Reads every file and checks every option and solver name: InputError (exit 2) in the user's
/// words, before any solve runs and before the program writes anything.
FcBench prepare_fc_bench(const FcBenchRequest& request);

/// The CSV header and one row per file and solver (file, problem, contacts, solver, status,
/// iterations, seconds of wall clock, the three errors of friction_verdict.hpp, NaN where a
/// solver returned no r, and the measure that decided the status: measure_solve.hpp, whose
/// re-solves at lower unit-free tolerances are in the row's seconds and iterations), each row flushed when written. `progress`, if given, gets one line per
/// solve. Throws InputError "error writing 'TABLE_NAME' (disk full or not writable?)" as soon as
/// `csv` fails, not after the remaining solves.
void write_fc_bench_table(const FcBench& bench, std::ostream& csv, const std::string& table_name,
                          std::ostream* progress = nullptr);

}  // namespace cpkit::lcp::friction
