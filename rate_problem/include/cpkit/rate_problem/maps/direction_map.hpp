#pragma once
/// \file direction_map.hpp
/// The direction map of the rate problem [Stromberg et al. 1996, Sec. 4.3, Fig. 5]: for one
/// contact state and parameter set, the solution count and types for every load direction
/// theta in [0, 2 pi), (dF_T, dF_N) = (cos theta, sin theta).
///
/// Method: the candidate critical directions (critical_directions.hpp) are exact; the rate
/// problem is solved at every candidate direction itself and at the midpoint of every arc
/// between consecutive candidates (plus the quarter points as a consistency check). A candidate
/// is reported as critical only when its own solution set (count + types) differs from that of
/// an adjacent arc; non-critical candidates are dropped and their arcs merged. The rate problem
/// is positively homogeneous in the load, so each evaluation uses an unnormalised load on which
/// the vanishing form is exactly zero in floating point.
#include <vector>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"

namespace cpkit::rate {

/// Options of the maps (direction and grid maps).
struct MapOptions {
  /// Route for the cells: kEnumerate (default) or kAnalytic. With any method other than
  /// kEnumerate the enumeration route is run as well on every cell and disagreements are counted.
  RateMethod method = RateMethod::kEnumerate;
  int threads = 0;  ///< grid maps: worker threads, 0 = std::thread::hardware_concurrency()
  /// Parameter x direction maps: the directions sampled, [theta_from, theta_to] in rad
  /// (0 < theta_to - theta_from <= 2 pi; default the whole circle). Zooms on a thin sector.
  double theta_from = 0;
  double theta_to = 6.283185307179586476925286766559;
  std::string validate() const;  ///< empty when usable
};

/// Same count and same types (the `reliable` flag is not compared).
inline bool same_solution_set(const RateSummary& a, const RateSummary& b) noexcept {
  return a.count == b.count && a.types == b.types;
}

/// An open sector of directions: the counter-clockwise arc from theta_from to theta_to.
/// theta_from is in [0, 2 pi) and theta_to in (theta_from, theta_from + 2 pi], so theta_to > 2 pi
/// marks the sector that contains theta = 0; a map with no critical direction has the single
/// sector (0, 2 pi] (covering the whole circle). Summary: the point kind's (RateSummary for one
/// point, SystemRateSummary for N points, system_direction_map.hpp).
template <class Summary>
struct DirectionSectorOf {
  double theta_from = 0, theta_to = 0;
  Summary summary;         ///< at the midpoint, by options.method
  Summary check;           ///< one point: by the enumeration route when cross-checking (else = summary)
  bool consistent = true;  ///< the quarter points gave the same summary as the midpoint
};
using DirectionSector = DirectionSectorOf<RateSummary>;

/// A critical direction (the solution set there differs from an adjacent sector); Load: the
/// point kind's load rate (LoadRate; N points: dF(theta), Eigen::VectorXd).
template <class Summary, class Load>
struct CriticalDirectionOf {
  double theta = 0;
  Load load;  ///< the exact load used (one point: a form is exactly 0 on it)
  std::vector<std::string> conditions;  ///< one point: which forms vanish: "N=0", "L+=0", ...
  Summary summary;
  Summary check;  ///< one point: by the enumeration route when cross-checking (else = summary)
};
using CriticalDirectionResult = CriticalDirectionOf<RateSummary, LoadRate>;

/// A direction map of one point or of N points (system_direction_map.hpp): the loads
/// dF(theta) = cos(theta) e1 + sin(theta) e2 (one point: e1 = dF_T, e2 = dF_N).
template <class Summary, class Load>
struct DirectionMapOf {
  Load e1, e2;  ///< N points: the patterns used (one point: unused)
  std::vector<DirectionSectorOf<Summary>> sectors;         ///< sorted by theta_from
  std::vector<CriticalDirectionOf<Summary, Load>> critical;  ///< sorted by theta
  int candidates = 0;        ///< N points: distinct zeros of the linear forms
  int evaluations = 0;       ///< rate problems solved (per route)
  int disagreements = 0;     ///< one point: evaluations where the two routes disagree (cross-check)
  int inconsistent_sectors = 0;  ///< sectors whose quarter points disagree with the midpoint
  int unreliable = 0;  ///< evaluations the enumeration flagged as too close to call
  bool cross_checked = false;  ///< one point: the enumeration route run as well
};
using DirectionMap = DirectionMapOf<RateSummary, LoadRate>;

/// Computes the direction map. Throws InputError for invalid parameters, state or options.
DirectionMap compute_direction_map(const ContactParameters& params, const ContactState& state,
                                   const MapOptions& options = {});

}  // namespace cpkit::rate
