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
  p.criterion = criterion_option(m.criterion);
  throw_if_invalid(p.validate(), "contact parameters");
  return p;
}

rate::Criterion criterion_option(const std::string& name) {
  const auto c = rate::criterion_from_string(name);
  if (!c) throw InputError("--criterion must be 38 or 35, got '" + name + "'");
  return *c;
}

rate::WearLaw wear_law_option(const std::string& name) {
  const auto law = rate::wear_law_from_string(name);
  if (!law) throw InputError("--wear-law must be archard or mroz, got '" + name + "'");
  return *law;
}

rate::BranchRule branch_rule_option(const std::string& name) {
  const auto rule = rate::branch_rule_from_string(name);
  if (!rule) throw InputError("--branch-rule must be closest or stop, got '" + name + "'");
  return *rule;
}

}  // namespace cpkit::cli
