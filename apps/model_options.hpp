#pragma once
// The contact-model options shared by `cpkit rate` and `cpkit step` (same names, same help).
#include <CLI/CLI.hpp>
#include <string>

#include "cpkit/rate_problem/model/model_options.hpp"

namespace cpkit::cli {

/// The values the options are bound to (defaults: those --help shows); the request gets the
/// ones given (given_model_options). Their conversion (model_parameters, criterion_option,
/// wear_law_option, branch_rule_option: InputError naming the option) is library code.
struct ModelArgs {
  double a11 = 0, a12 = 0, a22 = 0, mu = 0;
  double C_T = 0, k_a = 0, P_s = 1;
  std::string criterion = "38";
};
using rate::branch_rule_option;
using rate::criterion_option;
using rate::model_parameters;
using rate::wear_law_option;

/// --a11 --a12 --a22 --mu (required), --C_T --k_a --P_s --criterion.
void add_model_options(CLI::App& cmd, ModelArgs& m);

/// The model options the user gave on `cmd` (after parsing), for the request.
rate::ModelOptions given_model_options(const CLI::App& cmd, const ModelArgs& m);

}  // namespace cpkit::cli
