#pragma once
/// \file simulate_request.hpp
/// What `cpkit simulate` was asked, as given, and its one run (docs/simulation.md; 3-D:
/// docs/contact_3d.md, "Fretting with an elliptic load orbit"): one 2-D point (settings from the
/// options over an optional --config; load fretting, ramp or csv), N points (--system with a
/// "dim": 2 file) and one 3-D point under an elliptic tangential load orbit (--system with a
/// "dim": 3 file). Values in the model's units (forces as F, displacements as w), angles in
/// radians. Bad input: cpkit::InputError with the message the program prints (exit 2).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/core/exit_code.hpp"
#include "cpkit/rate_problem/simulation/simulate_config.hpp"

namespace cpkit::rate {

/// The numeric options of `cpkit simulate` as given (absent: not given; --config or the
/// defaults apply). Counts (cycles, steps, ...) are numbers here too (1e6 is accepted) and must
/// be integers.
struct SimulateNumbers {
  std::optional<double> a11, a12, a22, mu, C_T, k_a, P_s;  ///< the model
  std::optional<double> k_M;                                 ///< Mroz-Stupkiewicz wear
  /// fretting (period also for csv loads)
  std::optional<double> F_N, amplitude, period, cycles, steps_per_cycle, ramp_steps;
  std::optional<double> F_T0, F_N0, F_T1, F_N1, duration, steps;  ///< ramp
  std::optional<double> heat_capacity, T_ref, T_initial;          ///< heat
};

/// The options of `cpkit simulate` as given (empty string, empty vector or no value: not given).
struct SimulateRequest {
  std::string config;  ///< --config FILE (JSON settings, overridden by the options)
  std::string system;  ///< --system FILE: N points ("dim": 2) or one 3-D point ("dim": 3)
  SimulateNumbers numbers;  ///< --a11 ... --T-initial
  std::string criterion, wear_law, load, load_csv, branch_rule;  ///< --criterion ... --branch-rule
  std::string csv, summary, plot;           ///< --csv FILE, --summary FILE, --plot PREFIX
  std::vector<double> T_body, conductance;  ///< --T-body T1 T2, --conductance c1 c2
  bool heat = false;                        ///< --heat
  std::optional<int> every;                 ///< --every n (default 1)
  // A "dim": 3 system only:
  std::vector<double> orbit;           ///< --orbit aX aY (half-axes of the load orbit)
  std::optional<double> orbit_angle;   ///< --orbit-angle (rad, default 0)
  std::optional<int> lead_steps;       ///< --lead-steps (default steps-per-cycle / 4)
  /// Echoed in every summary as today: "run" (the program's command line and options) and
  /// the version ("cpkit_version" of the N-point and 3-D summaries).
  nlohmann::json run;
  std::string version;
};

/// What a run produced, for the program to print.
struct SimulateOutcome {
  nlohmann::json summary;  ///< the JSON summary (report/simulation_json.hpp, plus run/version)
  std::string text;        ///< the text summary (report/simulation_text.hpp)
  /// Files written: the series (default PLOT.csv) and the summary (default PLOT.json); empty:
  /// none. `plot` is the figures' PREFIX (empty: no figures), drawn by the program with the
  /// script `plot_script` as PREFIX<figure>.png/.svg for every suffix in `figures`.
  std::string csv, summary_file, plot, plot_script;
  std::vector<std::string> figures;
  /// kExitOk: the run completed; kExitNoSolution: it stopped (no solution, a continuum, a
  /// branch point with --branch-rule stop, numerical failure); kExitInconclusive: it stopped at
  /// a step whose enumeration is not proved complete (N points, 3-D).
  ExitCode exit_code = kExitOk;
};

/// Validates the request (today's messages, in today's order), runs it and writes its files:
/// the series as it is produced (never held in memory) and the summary. A system file is read
/// once and dispatched on its dimension. `check_outputs` is called with the merged settings
/// (config and options) before anything is written, so that the program can refuse outputs
/// that are inputs. Throws cpkit::InputError for bad input and files that cannot be written.
SimulateOutcome run_simulate_request(
    const SimulateRequest& request,
    const std::function<void(const SimulateSettings&)>& check_outputs = {});

}  // namespace cpkit::rate
