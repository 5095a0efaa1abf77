#pragma once
/// \file branch_rule.hpp
/// What a simulation does where a step has several solutions (a branch point): one rule for
/// the 2-D point, N points and 3-D fretting (docs/simulation.md).
#include <optional>
#include <string_view>

namespace cpkit::rate {

enum class BranchRule {
  kClosest,  ///< take the solution closest to the previous state and record the branch point
  kStop,     ///< stop the run at the first branch point
};

/// "closest" / "stop"
inline std::string_view to_string(BranchRule r) noexcept {
  switch (r) {
    case BranchRule::kClosest:
      return "closest";
    case BranchRule::kStop:
      return "stop";
  }
  return "unknown";
}

inline std::optional<BranchRule> branch_rule_from_string(std::string_view s) noexcept {
  if (s == "closest") return BranchRule::kClosest;
  if (s == "stop") return BranchRule::kStop;
  return std::nullopt;
}

}  // namespace cpkit::rate
