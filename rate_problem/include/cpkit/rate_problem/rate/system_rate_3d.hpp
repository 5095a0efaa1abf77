#pragma once
/// \file system_rate_3d.hpp
/// The rate problem of N coupled 3-D contact points (docs/contact_3d.md, "N points"): every
/// grazing point's friction ellipse is replaced by the inscribed polygon of k facets (the
/// one-point faceted problem, faceted_rate_3d.hpp); points in states a, c, d are linear (d: the
/// slip direction is the ellipse's normal at the current traction, exactly). For every subset
/// of the grazing points that separate (2^n_b of them) the rate equations are solved for the
/// rates as affine functions of the slip multipliers, whose complementarity conditions form an
/// LCP of size n_d + k (grazing points in contact), solved by complete enumeration.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// One solution of a 3-D system's rate problem: per point its type and rates; a ray (one
/// point, state b or d) starts at `rates` and runs along `direction`.
struct SystemRateRow3d {
  std::vector<SolutionType> types;
  std::vector<Rates3d> rates;      ///< the point; a ray's origin
  std::vector<Rates3d> direction;  ///< a ray's direction (empty for a point)
  bool ray = false;
  bool origin_included = true;     ///< a ray: is its origin part of it
};
using SystemSolution3d = SystemRateRow3d;

/// Every solution of a 3-D system's rate problem, by either route below.
using SystemRateSet3d = RateSet3dOf<SystemRateRow3d>;
using SystemRateRoute3d = SystemRateSet3d;

/// Largest number of grazing points (2^n_b separation subsets).
inline constexpr int kMaxGrazing3d = 10;

/// Every solution of the faceted N-point problem for the load rate dF (3N). Throws InputError
/// for invalid input, facets outside [3, kMaxFacets], more than kMaxGrazing3d grazing points, an
/// LCP larger than the enumeration's 64 (n_d + k n_b: fewer facets or points), or a time limit
/// that is not positive.
/// `time_limit_s` (wall clock, seconds; may be infinite) bounds the whole solve: it is checked
/// before every separation case and what is left of it bounds each case's enumeration. When it
/// runs out the result has timed_out = true, complete = false and a message saying so; the
/// solutions found so far are listed (never called the whole set).
SystemRateSet3d solve_system_rate_3d_faceted(const ContactSystem3d& system,
                                             const Eigen::VectorXd& dF, int facets,
                                             double time_limit_s = 60);

/// Every solution of a 3-D system's rate problem for dF (3N): one point exactly
/// (solve_rate_3d, facets = 0) or faceted (solve_rate_3d_faceted, state b only); N > 1 points by
/// solve_system_rate_3d_faceted (facets > 0 required). `time_limit_s` bounds the faceted solves.
/// Throws InputError for facets = 0 with N > 1, facets > 0 for one point not in state b, and
/// what the routes refuse.
SystemRateRoute3d solve_system_rate_3d(const ContactSystem3d& system, const Eigen::VectorXd& dF,
                                       int facets, double time_limit_s = 60);

}  // namespace cpkit::rate
