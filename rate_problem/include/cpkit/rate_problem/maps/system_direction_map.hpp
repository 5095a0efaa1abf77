#pragma once
/// \file system_direction_map.hpp
/// The direction map of the N-point rate problem (docs/maps.md, "N points"): for one system
/// (states, parameters, A), the solution count and type tuples for every load direction
/// dF(theta) = cos(theta) e1 + sin(theta) e2, theta in [0, 2 pi), with the system's patterns
/// e1, e2 (2N each; default e1 = (1, 0, 1, 0, ...), e2 = (0, 1, 0, 1, ...): the same tangential
/// or normal load rate on every point).
///
/// Method (exact critical directions): q = Q dF(theta) of the Schur-complement LCP is linear in
/// (cos, sin). For every complementary basis the basic z, the non-basic w and the physical rates
/// (which decide the point types) are linear forms a cos + b sin; a basis with a singular matrix
/// gives the consistency forms u^T q (u in the left null space). A sign or type can change only
/// where such a form vanishes: theta0 and theta0 + pi. All zeros are collected, sorted and
/// deduplicated; the rate problem is summarised (summarize_rate_problem) at every candidate and
/// at the midpoint (and quarter points, as a check) of every arc between candidates. A candidate
/// is critical when its solution set or the sets of the arcs on either side differ; the other
/// candidates are dropped and their arcs merged.
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::rate {

/// Same count and same type tuples (the `reliable` flag is not compared).
bool same_solution_set(const SystemRateSummary& a, const SystemRateSummary& b) noexcept;

/// An open sector (theta_from, theta_to) of directions, conventions as DirectionSector.
using SystemDirectionSector = DirectionSectorOf<SystemRateSummary>;
/// A critical direction: the solution set there differs from an adjacent sector; load: dF =
/// cos(theta) e1 + sin(theta) e2.
using SystemCriticalDirection = CriticalDirectionOf<SystemRateSummary, Eigen::VectorXd>;

/// The N-point direction map: e1, e2 (the patterns used), sectors, critical, candidates,
/// evaluations, inconsistent_sectors, unreliable.
using SystemDirectionMap = DirectionMapOf<SystemRateSummary, Eigen::VectorXd>;

/// The load patterns of a system's maps: the file's e1, e2, or by default e1 = (1, 0, 1, 0, ...),
/// e2 = (0, 1, 0, 1, ...). Throws InputError when they are linearly dependent.
void system_map_patterns(const ContactSystem& system, Eigen::VectorXd& e1, Eigen::VectorXd& e2);

/// Largest Schur-complement LCP (3 per point in state b, 1 per point in state d) whose 2^m
/// complementary bases the map scans.
inline constexpr int kMaxSystemMapLcp = 12;

/// Size of a system's rate LCP from its states alone (3 per point in state b, 1 per point in
/// state d): O(N), nothing allocated in proportion to the work.
int system_map_lcp_size(const ContactSystem& system) noexcept;
/// Throws InputError when the rate LCP is larger than kMaxSystemMapLcp. Called right after a
/// system is read and before anything proportional to N or 2^m is computed (a 1000-point
/// system is refused at once, not after its N^3 precomputation).
void check_system_map_lcp_size(const ContactSystem& system, const std::string& what);

/// Computes the direction map. options.method must be kEnumerate; options.threads workers
/// (0: all cores) scan the bases and evaluate the arcs, with a result that does not depend on
/// their number; theta_from/theta_to are not used (the exact map covers the whole circle). Throws InputError for an invalid system or options, patterns that are
/// linearly dependent (the directions would not sweep a plane), or an LCP larger than
/// kMaxSystemMapLcp.
SystemDirectionMap compute_system_direction_map(const ContactSystem& system,
                                                const MapOptions& options = {});

}  // namespace cpkit::rate
