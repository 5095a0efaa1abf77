#include "cpkit/rate_problem/model/rates.hpp"

#include "cpkit/core/enum_names.hpp"

namespace cpkit::rate {
namespace {

constexpr EnumName<SolutionType> kSolutionTypeNames[] = {
    {SolutionType::kOpen, "open"},
    {SolutionType::kSeparation, "separation"},
    {SolutionType::kStick, "stick"},
    {SolutionType::kSlipPlus, "slip+"},
    {SolutionType::kSlipMinus, "slip-"},
    {SolutionType::kSlip, "slip"},
};
constexpr EnumName<RateSolution::Kind> kKindNames[] = {
    {RateSolution::Kind::kPoint, "point"},
    {RateSolution::Kind::kSegment, "segment"},
    {RateSolution::Kind::kRay, "ray"},
};

}  // namespace

std::string_view to_string(SolutionType t) noexcept { return name_of(kSolutionTypeNames, t); }

std::optional<SolutionType> solution_type_from_string(std::string_view s) noexcept {
  return value_of(kSolutionTypeNames, s);
}

std::string_view to_string(RateSolution::Kind k) noexcept { return name_of(kKindNames, k); }

}  // namespace cpkit::rate
