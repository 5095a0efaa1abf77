#pragma once
// `cpkit step --system FILE` with a "dim": 3 file: one implicit step of one 3-D contact point
// (step_3d.hpp, step_solvers_3d.hpp; docs/contact_3d.md, "Solvers of the 3-D step").
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::cli {

struct Step3dCliArgs {
  std::string system;       ///< the "dim": 3 file (one point)
  std::vector<double> DF;   ///< 3 numbers: DF_TX DF_TY DF_N
  std::string wear_law = "archard";
  double k_M = 0;
  double g0 = 0;            ///< --g0: the open gap of a state-a point (< 0)
  bool all = false;
  bool json = false;
  std::string chain;        ///< --chain (empty: the default exact,fb-soc,ipopt)
  int facets = 0;           ///< --facets K
  int multistart = 0;       ///< --multistart N
  rate::SystemFile file;    ///< the file, read once (its dim is 3)
};

/// Runs the 3-D step; `cmd` tells which options were given (options without effect are
/// refused with InputError). Returns the exit code.
int run_step_3d(const Step3dCliArgs& args, const CLI::App& cmd);

}  // namespace cpkit::cli
