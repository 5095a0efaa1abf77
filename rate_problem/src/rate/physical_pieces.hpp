#pragma once
// Internal: from the LCP solution set to physical pieces of the N-point rate problem.
#include <vector>

#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::rate::detail {

/// q = Q dF with rounding noise (relative to the terms) snapped to zero.
Eigen::VectorXd system_q(const SystemRatePrecomputed& pre, const Eigen::VectorXd& dF);
/// 6N stacked rates (dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w; N each) -> SystemRates.
SystemRates to_rates(const SystemRatePrecomputed& pre, const Eigen::VectorXd& x);
/// Type of every point for the physical rates r, judged relative to the scales.
std::vector<SolutionType> classify_system_rates(const SystemRatePrecomputed& pre,
                                                const SystemRates& r, double force_scale,
                                                double disp_scale);
/// Complete enumeration of the LCP and the physical pieces split by type tuple. on_critical: dF
/// is a computed critical direction (summarize_rate_problem): a point's inequality within its
/// rounding is taken to hold with equality instead of making the set incomplete.
SystemRateSolutionSet enumerate_system(const SystemRatePrecomputed& pre, const Eigen::VectorXd& dF,
                                       bool on_critical = false);

}  // namespace cpkit::rate::detail
