#pragma once
// Internal to the direction maps (direction_map.cpp, system_direction_map.cpp): the sectors of a
// direction map from its arcs, written once for one point and N points.
#include <cstddef>
#include <vector>

namespace cpkit::rate {

/// Merges the arcs between consecutive candidate directions into the map's sectors: arc i runs
/// from candidate i to candidate i + 1 (one full-circle arc when there is no candidate); the
/// critical candidates `crit` (indices, ascending) bound the sectors, the others are dropped and
/// their arcs merged (they have the same solution set). Each sector takes the solution set of
/// its first arc (`from_arc(sector, arc)`) and the consistency of all its arcs; each critical
/// candidate goes to `critical`, in order.
template <class Arc, class Candidate, class Sector, class FromArc>
void sectors_from_arcs(const std::vector<Arc>& arcs, const std::vector<Candidate>& candidates,
                       const std::vector<std::size_t>& crit, std::vector<Sector>& sectors,
                       std::vector<Candidate>& critical, FromArc&& from_arc) {
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  if (crit.empty()) {
    Sector s;
    s.theta_from = 0;
    s.theta_to = kTwoPi;
    from_arc(s, arcs[0]);
    for (const Arc& a : arcs) s.consistent = s.consistent && a.consistent;
    sectors.push_back(s);
    return;
  }
  const std::size_t m = candidates.size();
  for (std::size_t k = 0; k < crit.size(); ++k) {
    const std::size_t i0 = crit[k], i1 = crit[(k + 1) % crit.size()];
    Sector s;
    s.theta_from = candidates[i0].theta;
    s.theta_to = candidates[i1].theta;
    if (s.theta_to <= s.theta_from) s.theta_to += kTwoPi;
    from_arc(s, arcs[i0]);
    for (std::size_t i = i0;; i = (i + 1) % m) {  // the arcs merged into this sector
      s.consistent = s.consistent && arcs[i].consistent;
      if ((i + 1) % m == i1) break;
    }
    sectors.push_back(s);
    critical.push_back(candidates[i0]);
  }
}

}  // namespace cpkit::rate
