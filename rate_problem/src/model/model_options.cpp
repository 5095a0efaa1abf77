#include "cpkit/rate_problem/model/model_options.hpp"

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

ContactParameters model_parameters(const ModelOptions& m) {
  ContactParameters p;
  p.a11 = m.a11.value_or(0);
  p.a12 = m.a12.value_or(0);
  p.a22 = m.a22.value_or(0);
  p.mu = m.mu.value_or(0);
  p.C_T = m.C_T.value_or(0);
  p.k_a = m.k_a.value_or(0);
  p.P_s = m.P_s.value_or(1);
  p.criterion = criterion_option(m.criterion.value_or("38"));
  throw_if_invalid(p.validate(), "contact parameters");
  return p;
}

Criterion criterion_option(const std::string& name) {
  const auto c = criterion_from_string(name);
  if (!c) throw InputError("--criterion must be 38 or 35, got '" + name + "'");
  return *c;
}

WearLaw wear_law_option(const std::string& name) {
  const auto law = wear_law_from_string(name);
  if (!law) throw InputError("--wear-law must be archard or mroz, got '" + name + "'");
  return *law;
}

BranchRule branch_rule_option(const std::string& name) {
  const auto rule = branch_rule_from_string(name);
  if (!rule) throw InputError("--branch-rule must be closest or stop, got '" + name + "'");
  return *rule;
}

}  // namespace cpkit::rate
