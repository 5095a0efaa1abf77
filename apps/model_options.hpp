#pragma once
// The contact-model options shared by `cpkit rate` and `cpkit step` (same names, same help).
#include <CLI/CLI.hpp>
#include <string>

#include "cpkit/rate_problem/model/parameters.hpp"

namespace cpkit::cli {

struct ModelArgs {
  double a11 = 0, a12 = 0, a22 = 0, mu = 0;
  double C_T = 0, k_a = 0, P_s = 1;
  std::string criterion = "38";
};

/// --a11 --a12 --a22 --mu (required), --C_T --k_a --P_s --criterion.
void add_model_options(CLI::App& cmd, ModelArgs& m);

/// The parameters; throws InputError naming the bad option or parameter (A not SPD, mu <= 0, ...).
rate::ContactParameters model_parameters(const ModelArgs& m);

}  // namespace cpkit::cli
