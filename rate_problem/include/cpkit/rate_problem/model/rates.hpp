#pragma once
/// \file rates.hpp
/// Load rates, solution rates and the solution-set result of the rate problem.
/// Rate vector order everywhere: (dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w) (model.md Sec. 4).
#include <optional>
#include <string_view>
#include <vector>

namespace cpkit::rate {

struct LoadRate {
  double dF_T = 0, dF_N = 0;
};

/// Solution types; they partition the solution set (model.md Sec. 2).
/// The type of a rate (or step) solution. A 2-D point slips forwards or backwards (kSlipPlus,
/// kSlipMinus); a 3-D point slips in a direction of the plane, reported separately (kSlip).
/// kSlip is last so that the 2-D type masks (1 << type) keep their bits.
enum class SolutionType { kOpen, kSeparation, kStick, kSlipPlus, kSlipMinus, kSlip };
/// "open", "separation", "stick", "slip+", "slip-", "slip"
std::string_view to_string(SolutionType t) noexcept;
std::optional<SolutionType> solution_type_from_string(std::string_view s) noexcept;

struct Rates {
  double dP_T = 0, dP_N = 0, dw_T = 0, dw_N = 0, dw_Ti = 0, dw_w = 0;
};

/// One connected piece of the solution set: a point, a segment or a ray (never sampled).
struct RateSolution {
  enum class Kind { kPoint, kSegment, kRay };
  SolutionType type = SolutionType::kStick;
  Kind kind = Kind::kPoint;
  Rates start;                ///< the point; a segment's first end; a ray's origin
  bool start_closed = true;   ///< segment/ray: does the piece contain `start`?
  Rates end;                  ///< segment: second end
  bool end_closed = true;     ///< segment: does the piece contain `end`?
  Rates direction;            ///< ray: direction
};
std::string_view to_string(RateSolution::Kind k) noexcept;  ///< "point", "segment", "ray"

}  // namespace cpkit::rate
