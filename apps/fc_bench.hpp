#pragma once
// `cpkit fc bench FILE... [--solvers a,b] [--tol T] [--time-limit S] --out PREFIX`: every solver
// on every file, PREFIX.csv (one row per file and solver) and PREFIX.png, the Dolan-More
// performance profile drawn by scripts/cpkit_plot_fc_profile.py.
#include <limits>
#include <string>
#include <vector>

namespace cpkit::cli {

struct FcBenchArgs {
  std::vector<std::string> files;
  std::vector<std::string> solvers;  ///< empty: every registered friction solver
  std::string out;                   ///< PREFIX of PREFIX.csv and PREFIX.png
  double tol = 1e-10;
  double time_limit_s = 60;          ///< per solve
  bool no_plot = false;
};

/// Exit code: 0 (the table and the picture written, whatever the statuses), 4 when the picture
/// could not be drawn (the CSV is kept). Bad files or solver names throw InputError before any
/// solve runs.
int run_fc_bench(const FcBenchArgs& a);

}  // namespace cpkit::cli
