#pragma once
// The contact-model options shared by `cpkit rate` and `cpkit step` (same names, same help).
#include <CLI/CLI.hpp>
#include <string>

#include "cpkit/rate_problem/model/branch_rule.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/wear.hpp"

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

/// The values of --criterion, --wear-law and --branch-rule (rate, step, simulate); each throws
/// InputError "--X must be ..., got '...'" for a name it does not know.
rate::Criterion criterion_option(const std::string& name);
rate::WearLaw wear_law_option(const std::string& name);
rate::BranchRule branch_rule_option(const std::string& name);

}  // namespace cpkit::cli
