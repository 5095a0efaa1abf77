#pragma once
// `cpkit fc bench FILE... [--solvers a,b] [--tol T] [--time-limit S] --out PREFIX`: every solver
// on every file (the table: cpkit/lcp/friction/fc_bench.hpp), PREFIX.csv (one row per file and
// solver) and PREFIX.png, the Dolan-More performance profile drawn by
// scripts/cpkit_plot_fc_profile.py.
#include <string>

#include "cpkit/lcp/friction/fc_bench.hpp"

namespace cpkit::cli {

struct FcBenchArgs : lcp::friction::FcBenchRequest {
  std::string out;  ///< PREFIX of PREFIX.csv and PREFIX.png
  bool no_plot = false;
};

/// Exit code: 0 (the table and the picture written, whatever the statuses), 4 when the picture
/// could not be drawn (the CSV is kept). InputError (exit 2) before anything is written: bad
/// files, solver names or options, an output that is an input (PREFIX.csv, .png or .lock one of
/// the FILEs), an output that exists and is not a regular file (a link to /dev/full), a PREFIX
/// another run holds (PREFIX.lock). PREFIX.csv is written as
/// PREFIX.csv.partial, each row flushed, and renamed when complete: a run that stops part-way
/// leaves the previous PREFIX.csv as it was and its finished rows in the .partial file; a write
/// error (full disk) is an InputError naming the file.
int run_fc_bench(const FcBenchArgs& a);

}  // namespace cpkit::cli
