#pragma once
// The contact-model options shared by `cpkit rate` and `cpkit step` (same names, same help).
#include <CLI/CLI.hpp>
#include <string>

#include "cpkit/rate_problem/model/model_options.hpp"

namespace cpkit::cli {

/// The values as given; their conversion (model_parameters, criterion_option, wear_law_option,
/// branch_rule_option: InputError naming the option) is library code.
using ModelArgs = rate::ModelOptions;
using rate::branch_rule_option;
using rate::criterion_option;
using rate::model_parameters;
using rate::wear_law_option;

/// --a11 --a12 --a22 --mu (required), --C_T --k_a --P_s --criterion.
void add_model_options(CLI::App& cmd, ModelArgs& m);

}  // namespace cpkit::cli
