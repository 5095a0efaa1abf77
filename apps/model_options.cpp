#include "model_options.hpp"

#include "cli_common.hpp"

namespace cpkit::cli {

void add_model_options(CLI::App& cmd, ModelArgs& m) {
  // Required values have no default to show (--help shows only defaults that are used).
  cmd.add_option("--a11", m.a11, "stiffness A11")->required()->default_str("");
  cmd.add_option("--a12", m.a12, "stiffness A12")->required()->default_str("");
  cmd.add_option("--a22", m.a22, "stiffness A22")->required()->default_str("");
  cmd.add_option("--mu", m.mu, "friction coefficient (> 0)")->required()->default_str("");
  cmd.add_option("--C_T", m.C_T, "tangential compliance (>= 0)");
  cmd.add_option("--k_a", m.k_a, "Archard wear coefficient (>= 0)");
  cmd.add_option("--P_s", m.P_s, "hardness (> 0)");
  cmd.add_option("--criterion", m.criterion,
                 "friction-and-wear criterion: 38 (Coulomb) or 35 (softening)");
}

rate::ModelOptions given_model_options(const CLI::App& cmd, const ModelArgs& m) {
  rate::ModelOptions g;
  g.a11 = if_given(cmd, "--a11", m.a11);
  g.a12 = if_given(cmd, "--a12", m.a12);
  g.a22 = if_given(cmd, "--a22", m.a22);
  g.mu = if_given(cmd, "--mu", m.mu);
  g.C_T = if_given(cmd, "--C_T", m.C_T);
  g.k_a = if_given(cmd, "--k_a", m.k_a);
  g.P_s = if_given(cmd, "--P_s", m.P_s);
  g.criterion = if_given(cmd, "--criterion", m.criterion);
  return g;
}

}  // namespace cpkit::cli
