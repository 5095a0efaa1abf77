#include "model_options.hpp"

#include "cpkit/core/errors.hpp"

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

rate::ContactParameters model_parameters(const ModelArgs& m) {
  rate::ContactParameters p;
  p.a11 = m.a11;
  p.a12 = m.a12;
  p.a22 = m.a22;
  p.mu = m.mu;
  p.C_T = m.C_T;
  p.k_a = m.k_a;
  p.P_s = m.P_s;
  const auto crit = rate::criterion_from_string(m.criterion);
  if (!crit) throw InputError("--criterion must be 38 or 35, got '" + m.criterion + "'");
  p.criterion = *crit;
  throw_if_invalid(p.validate(), "contact parameters");
  return p;
}

}  // namespace cpkit::cli
