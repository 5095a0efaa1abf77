#pragma once
/// \file branch_rule.hpp
/// What a simulation does where a step has several solutions (a branch point): one rule for
/// the 2-D point, N points and 3-D fretting (docs/simulation.md).
#include <optional>
#include <string_view>

#include "cpkit/core/enum_names.hpp"

namespace cpkit::rate {

enum class BranchRule {
  kClosest,  ///< take the solution closest to the previous state and record the branch point
  kStop,     ///< stop the run at the first branch point
};

/// The names of the rules ("closest", "stop"), for to_string and branch_rule_from_string.
inline constexpr EnumName<BranchRule> kBranchRuleNames[] = {
    {BranchRule::kClosest, "closest"},
    {BranchRule::kStop, "stop"},
};

/// "closest" / "stop"
inline std::string_view to_string(BranchRule r) noexcept { return name_of(kBranchRuleNames, r); }

inline std::optional<BranchRule> branch_rule_from_string(std::string_view s) noexcept {
  return value_of(kBranchRuleNames, s);
}

}  // namespace cpkit::rate
