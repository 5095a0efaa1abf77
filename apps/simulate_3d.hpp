#pragma once
// `cpkit simulate --system FILE` with a "dim": 3 file: fretting of one 3-D point under an
// elliptic tangential load orbit (docs/contact_3d.md, "Fretting with an elliptic load orbit";
// library: cpkit/rate_problem/simulation/fretting_3d.hpp).
//
//   cpkit simulate --system POINT3D.json --orbit aX aY [--orbit-angle RAD] [--lead-steps N]
//                  [--F_N X --period X --cycles N --steps-per-cycle N --ramp-steps N]
//                  [--wear-law archard|mroz --k_M X] [--branch-rule closest|stop]
//                  [--csv OUT.csv] [--summary OUT.json] [--plot PREFIX] [--every N] [--json]
//
// Exit codes: 0 completed, 1 stopped (no solution, a branch point with --branch-rule stop,
// numerical failure), 5 stopped at a step with several solutions whose enumeration is not
// proved complete (ambiguous), 2 bad input (N > 1 points, a start state other than grazing,
// options of the 2-D simulation, bad values), 4 the figures were asked for and are missing.
#include <map>
#include <string>
#include <vector>

#include "cpkit/rate_problem/system/system_file.hpp"

#include "cli_common.hpp"

namespace cpkit::cli {

/// The options only the 3-D run has (registered by add_simulate_3d_options).
struct Simulate3dArgs {
  std::vector<double> orbit;  ///< a_X a_Y
  double orbit_angle = 0;
  bool angle_given = false;
  int lead_steps = -1;
  bool lead_given = false;
  /// The first 3-D option given ("--orbit", ...), or empty.
  std::string first_given() const;
};

/// What the 3-D run takes from the 2-D command's parsed options.
struct Simulate3dCommon {
  std::string system;
  rate::SystemFile file;  ///< the system file, read once (its dim is 3)
  std::map<std::string, double> num;  ///< numeric options given (key without "--")
  std::string wear_law, branch_rule, csv, summary, plot;
  int every = 1;
  bool every_given = false;
  bool json = false;
  /// Options of the 2-D simulation given on the command line (refused with a "dim": 3 file).
  std::vector<std::string> other_given;
};

void add_simulate_3d_options(CLI::App* cmd, Simulate3dArgs& args);

/// Runs the 3-D fretting simulation; returns the exit code. Throws InputError for bad input.
int run_simulate_3d(const Simulate3dArgs& a3, const Simulate3dCommon& c);

}  // namespace cpkit::cli
