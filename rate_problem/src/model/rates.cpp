#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

std::string_view to_string(SolutionType t) noexcept {
  switch (t) {
    case SolutionType::kOpen:
      return "open";
    case SolutionType::kSeparation:
      return "separation";
    case SolutionType::kStick:
      return "stick";
    case SolutionType::kSlipPlus:
      return "slip+";
    case SolutionType::kSlipMinus:
      return "slip-";
    case SolutionType::kSlip:
      return "slip";
  }
  return "unknown";
}

std::optional<SolutionType> solution_type_from_string(std::string_view s) noexcept {
  if (s == "open") return SolutionType::kOpen;
  if (s == "separation") return SolutionType::kSeparation;
  if (s == "stick") return SolutionType::kStick;
  if (s == "slip+") return SolutionType::kSlipPlus;
  if (s == "slip-") return SolutionType::kSlipMinus;
  if (s == "slip") return SolutionType::kSlip;
  return std::nullopt;
}

std::string_view to_string(RateSolution::Kind k) noexcept {
  switch (k) {
    case RateSolution::Kind::kPoint:
      return "point";
    case RateSolution::Kind::kSegment:
      return "segment";
    case RateSolution::Kind::kRay:
      return "ray";
  }
  return "unknown";
}

}  // namespace cpkit::rate
