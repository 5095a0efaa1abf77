#pragma once
/// \file model_options.hpp
/// The contact-model options of the commands (`cpkit rate`, `cpkit step`, `cpkit simulate`:
/// --a11 --a12 --a22 --mu --C_T --k_a --P_s --criterion, --wear-law, --branch-rule) as given,
/// and their conversion to the model's types. Kept here, not in the program, so that a command's
/// request (step/step_request.hpp) is checked by the library with the program's messages. Units
/// as ContactParameters (parameters.hpp).
#include <string>

#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/wear.hpp"

namespace cpkit::rate {

/// The one-point model options as given (defaults: those `--help` shows).
struct ModelOptions {
  double a11 = 0, a12 = 0, a22 = 0, mu = 0;
  double C_T = 0, k_a = 0, P_s = 1;
  std::string criterion = "38";
};

/// The parameters; throws InputError naming the bad option or parameter (A not SPD, mu <= 0, ...).
ContactParameters model_parameters(const ModelOptions& m);

/// The values of --criterion, --wear-law and --branch-rule; each throws InputError
/// "--X must be ..., got '...'" for a name it does not know.
Criterion criterion_option(const std::string& name);
WearLaw wear_law_option(const std::string& name);
BranchRule branch_rule_option(const std::string& name);

}  // namespace cpkit::rate
