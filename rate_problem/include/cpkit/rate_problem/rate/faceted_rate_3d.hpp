#pragma once
/// \file faceted_rate_3d.hpp
/// The state-b rate problem of one 3-D point with the friction ellipse replaced by an inscribed
/// polygon of k vertices D (cos theta_i, sin theta_i), theta_i = 2 pi i / k: separation
/// (dP = 0) directly, contact as an LCP of size k in the facets' slip multipliers (docs/contact_3d.md, "The faceted problem") solved by complete enumeration
/// (cpkit::lcp::enumerate_all) and mapped to physical rates. An approximation of the elliptic
/// law whose counts settle as k grows (tests compare them with solve_rate_3d); it is the route
/// that carries over to N points, where the exact slip directions of several grazing points are
/// coupled.
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"

namespace cpkit::rate {

/// Largest k accepted (the enumeration's supports are 64-bit masks).
inline constexpr int kMaxFacets = 64;

/// Every solution of the faceted state-b problem for the load rate dF: physical solutions,
/// deduplicated, complete as the enumeration (an LCP of size k), with facets = k and the
/// enumeration's search nodes. Throws InputError for
/// invalid input, a state other than b (the faceted route is for the grazing state; a, c, d are
/// linear: solve_rate_3d), or k outside [3, kMaxFacets].
RateSolutionSet3d solve_rate_3d_faceted(const ContactParameters3d& params,
                                        const Eigen::Vector3d& dF, int facets,
                                        double time_limit_s = 60);

}  // namespace cpkit::rate
