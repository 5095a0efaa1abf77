#pragma once
/// \file multistart_cap.hpp
/// The cap on the number of starts of the 3-D multistarts (multistart_step_3d,
/// multistart_system_step_3d, the starts of solve_step_3d_faceted; `cpkit step --multistart N`,
/// Python `multistart_step_3d(n_starts=...)`). Each start is a full FB-SOC Newton solve and the
/// starts run one after the other, so a count such as 10^9 would run for days with no answer:
/// it is refused up front (docs/contact_3d.md, "Solvers of the 3-D step").
#include <string>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate3d {

/// Largest number of starts accepted: about 2 minutes for one point (FB-SOC and Ipopt, about
/// 12 ms a start) and about a second for two coupled points (FB-SOC, 0.1 ms a start).
inline constexpr int kMaxMultistartStarts = 10'000;

/// InputError naming `what` (e.g. "--multistart", "n_starts") and the cap when n_starts exceeds
/// kMaxMultistartStarts.
inline void check_multistart_cap(long long n_starts, const std::string& what) {
  if (n_starts > kMaxMultistartStarts)
    throw InputError(what + " = " + std::to_string(n_starts) + " starts exceeds the cap of " +
                     std::to_string(kMaxMultistartStarts) +
                     " (kMaxMultistartStarts: each start is a full Newton solve)");
}

}  // namespace cpkit::rate3d
