#pragma once
/// \file rate_request.hpp
/// What `cpkit rate` was asked (docs/cli.md), as given, and the one call that answers it: one
/// point (the model options, --state, --dF DFT DFN), an N-point 2-D system file or a 3-D system
/// file (--system FILE, read once here; its "dim" chooses the route). Values in the model's
/// units (forces as dF, stiffnesses as A); the sign of P_T as in docs/contact_model.md.
/// Bad input: InputError whose message names the option (--dF, --method, ...), as the program
/// prints it (exit 2). The outcome: report/rate_outcome.hpp; its text and JSON: report/rate_text.hpp,
/// report/json.hpp.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/model_options.hpp"
#include "cpkit/rate_problem/report/rate_outcome.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::rate {

/// The options of `cpkit rate` as given: an empty optional (an empty dF) was not given.
/// Defaults are those `cpkit rate --help` shows.
struct RateRequest {
  std::optional<std::string> state;  ///< --state a|b|c|d (one point: required)
  ModelOptions model;  ///< --a11 --a12 --a22 --mu (one point: required) --C_T --k_a --P_s --criterion
  double P_N = 0;                ///< --P_N (states c and d)
  std::optional<int> sgn_PT;     ///< --sgnPT (state d only; absent: +1)
  std::vector<double> dF;        ///< --dF: DFT DFN (one point), 2N or 3N numbers (--system)
  std::string method = "enumerate";
  std::string system;                ///< --system FILE: an N-point or 3-D system (empty: one point)
  /// The --system file already read (the C API's JSON text); absent: read from `system`, which
  /// then only names it in messages.
  std::optional<SystemFile> file;
  int facets = 0;                    ///< --facets K: a 3-D system's faceted route (0: exact)
  std::optional<double> time_limit;  ///< --time-limit S: the faceted 3-D solves' budget
};

/// Validates `request` in the order `cpkit rate` always has (options that have no effect in
/// the state, one-point options with --system, the model, the state, dF, the method), solves it
/// by its route (solve_rate_problem_checked, solve_rate_problem for N points,
/// solve_system_rate_3d) and decides the exit code. `note` receives, as they arise, remarks on
/// accepted options (a material parameter that does not enter the state; before anything can be
/// refused) and, when a single solver found no solution, why and the enumerated count.
RateOutcome run_rate_request(const RateRequest& request,
                             const std::function<void(const std::string&)>& note = {});

}  // namespace cpkit::rate
