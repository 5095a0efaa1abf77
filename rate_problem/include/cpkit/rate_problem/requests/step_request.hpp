#pragma once
/// \file step_request.hpp
/// What `cpkit step` was asked (docs/simulation.md, docs/contact_3d.md), as given, and its run:
/// the checks of every route with the program's messages, the solve and the exit code, so that
/// Python and tests run a request without the program. Four routes:
///   - one 2-D point from the model options (--a11 ... --P_T0 --P_N0 --g0 --dF DFT DFN): every
///     solution (--all, enumerate_step) or one by the solver chain (--chain, solve_step);
///   - N 2-D points (--system FILE of dim 2, 2N --dF values, --all): enumerate_system_step;
///   - one 3-D point (--system FILE of dim 3 with one point, --dF DFX DFY DFN): every solution
///     (--all), the faceted step (--facets K), --multistart N, or the chain (--chain);
///   - N coupled 3-D points: FB-SOC Newton (--chain fb-soc, the default) or --multistart N.
/// Values in the model's units (forces as DF, gaps as lengths); signs as docs/model.md. The
/// outcome: report/step_outcome.hpp.
#include <optional>
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/model_options.hpp"
#include "cpkit/rate_problem/report/step_outcome.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// The solver chain of one 2-D point when --chain is not given.
inline constexpr const char* kDefaultStepChain = "active-set,lemke,fb-newton,ipopt";

/// The options of `cpkit step` as given: an empty optional was not given (the checks that
/// depend on it: options without effect, required options). Defaults are those `cpkit step
/// --help` shows.
struct StepRequest {
  ModelOptions model;  ///< --a11 --a12 --a22 --mu (one 2-D point: required) --C_T --k_a --P_s --criterion
  std::optional<std::string> wear_law;  ///< --wear-law archard|mroz (absent: archard)
  std::optional<double> k_M;            ///< --k_M (Mroz-Stupkiewicz)
  std::optional<double> P_T0, P_N0, g0;  ///< --P_T0 --P_N0 --g0 (start state; --g0 also 3-D)
  std::vector<double> DF;             ///< --dF: 2, 2N, 3 or 3N numbers
  bool all = false;                   ///< --all
  std::optional<std::string> chain;   ///< --chain (comma-separated; absent: kDefaultStepChain
                                      ///< for one 2-D point, the 3-D routes' own chains)
  std::string system;                 ///< --system FILE (empty: one 2-D point)
  /// The --system file, read once (a pipe can be read only once): by the caller, or, when
  /// absent, by run_step_request from `system` after the checks that come first.
  std::optional<SystemFile> file;
  std::optional<int> facets;          ///< --facets K (3-D files)
  std::optional<int> multistart;      ///< --multistart N (3-D files)
};

/// Checks the request (InputError with the program's messages: options that would have no
/// effect, missing options, wrong --dF counts, invalid model or state), runs its route and
/// decides the exit code.
StepOutcome run_step_request(const StepRequest& request);

}  // namespace cpkit::rate
