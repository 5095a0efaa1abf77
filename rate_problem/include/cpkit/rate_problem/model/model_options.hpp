#pragma once
/// \file model_options.hpp
/// The contact-model options of the commands (`cpkit rate`, `cpkit step`, `cpkit simulate`:
/// --a11 --a12 --a22 --mu --C_T --k_a --P_s --criterion, --wear-law, --branch-rule) as given,
/// and their conversion to the model's types. Kept here, not in the program, so that a command's
/// request (requests/step_request.hpp) is checked by the library with the program's messages. Units
/// as ContactParameters (parameters.hpp).
#include <optional>
#include <string>

#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/wear.hpp"

namespace cpkit::rate {

/// The one-point model options as given: an empty field was not given (a request's checks tell
/// "given" from "not given"); the values used then are the defaults `--help` shows (0, and
/// P_s = 1, criterion 38).
struct ModelOptions {
  std::optional<double> a11, a12, a22, mu;
  std::optional<double> C_T, k_a, P_s;
  std::optional<std::string> criterion;
};

/// The parameters (defaults for the options not given); throws InputError naming the bad
/// option or parameter (A not SPD, mu <= 0, ...).
ContactParameters model_parameters(const ModelOptions& m);

/// The values of --criterion, --wear-law and --branch-rule; each throws InputError
/// "--X must be ..., got '...'" for a name it does not know.
Criterion criterion_option(const std::string& name);
WearLaw wear_law_option(const std::string& name);
BranchRule branch_rule_option(const std::string& name);

}  // namespace cpkit::rate
