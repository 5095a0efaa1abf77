#pragma once
// The one-contact routes of the C API's friction solves: one contact with solver "auto" or
// "nsgs".
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"
#include "friction_input.hpp"

namespace cpkit::capi {

/// True for one contact and the solvers whose answer on a contact with exactly one solution is
/// that solution, and otherwise the local solve's from r = 0 ("auto" and "nsgs": both start with
/// nsgs's first sweep from r = 0).
bool one_contact_route(int contacts, const SolverEntry& entry);

/// The per-call path (no allocation, nothing built) for one_contact_route(): a solution of the
/// contact from
///   - the decoupled isotropic contact, W = [[a, 0, 0], [0, c, 0], [0, 0, c]] with a, c > 0
///     (a sphere's contact: its Delassus block in the contact frame is of this form): the normal
///     row alone gives r_N = max(0, -q_N / a) (Signorini), and r_T is the stick force -q_T / c
///     projected onto the disc |r_T| <= mu r_N. With r_N fixed the tangential law is Tresca's
///     friction with the strongly monotone operator c r_T + q_T, whose solution is unique;
///   - otherwise the cheap local solve from r = 0 (lcp::friction::one_contact_newton: separation,
///     stick, then Newton's method on the slip direction), the one nsgs's first sweep takes
///     from r = 0, so that "auto" and "nsgs" give the same answer on either route;
///   - when that finds nothing the verdict accepts, every solution in closed form
///     (lcp::friction::one_contact_solutions), when there is exactly one.
/// Where the contact has several solutions, the answer is one of them (as any solver's), not a
/// proof of uniqueness. When the candidate's unit-free verdict (one_contact_unit_free: the
/// number the friction finalize() decides by) is at most tol, writes r, u = W r + q and the
/// verdict and returns true: finalize() would call it solved. Otherwise false with nothing
/// decided: the caller takes solve_one_contact_unique() / the registered solver, which decide
/// as always.
bool solve_one_contact_fast(const OneContact& contact, const Vec3& q, double mu, double tol,
                            Vec3& r, Vec3& u, double& unit_free);

/// The same route through the library's types: every solution of the contact in closed form;
/// when there is exactly one, it is THE answer any solver that returns one must give; it is
/// decided by the friction finalize() (the verdict) into `r` (0 iterations) and true is
/// returned when the verdict accepts it. Otherwise the caller runs the registered solver.
bool solve_one_contact_unique(const FrictionContactProblem& p, const SolverEntry& entry,
                              const CommonOptions& o, SolveResult& r);

}  // namespace cpkit::capi
