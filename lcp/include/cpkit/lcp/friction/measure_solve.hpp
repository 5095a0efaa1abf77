#pragma once
/// \file measure_solve.hpp
/// A solve judged in a chosen measure (core/friction_measure.hpp). cpkit's solvers stop on the
/// unit-free number; the field's relative measures can be larger than it by orders of magnitude
/// (LMGC_100_PR_PerioBox: unit-free 1e-8 is |F_nat| / |q| = 1.2e-4) or far smaller (on most
/// real files the solvers' answers are within tol in the relative measures well before the
/// unit-free number is). So the first solve aims at the unit-free tolerance
///   t_0 = min(tol_acceptable, kFirstTolFactor tol)   (at least tol),
/// and while an answer the unit-free verdict accepts is above tol in the chosen measure, the
/// problem is solved again with the unit-free tolerance lowered by what was missed:
///   t_next = t * min(0.1, 0.5 tol / measured)   (never below kMinUnitFreeTol),
/// at most kMaxTightenings times, all within the caller's time limit. The best answer in the
/// measure among those the unit-free verdict accepts is kept, and its status decided by
/// decide_in_measure(): "solved" never means above tol in the measure, nor an answer the
/// unit-free verdict refutes.
#include <optional>

#include "cpkit/core/friction_measure.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"

namespace cpkit::lcp::friction {

/// The lowest unit-free tolerance a tightening asks for: a few units of double rounding.
constexpr double kMinUnitFreeTol = 1e-15;
/// Re-solves after the first, at most.
constexpr int kMaxTightenings = 4;
/// How much looser than tol (and never looser than tol_acceptable) the first solve's unit-free
/// tolerance is in a relative measure. Measured at tol 1e-8 in relative_q on the 12 local
/// files of tests/data/fclib, PerioBox and Capsules-i100-889 written by Siconos' sparse writer:
/// starting at tol itself took 56 s on the last (its unit-free number stalls near 1e-7 while
/// relative_q is 5e-10), starting at 100 tol 7.8 s; the others within a few hundredths of a
/// second either way (docs/friction_contact.md, "The field's measure").
constexpr double kFirstTolFactor = 100;

/// The unit-free tolerance of the first solve in measure m: tol for kUnitFree, t_0 otherwise.
double first_unit_free_tol(const CommonOptions& options, FrictionMeasure m);

/// The unit-free tolerance of the next solve after one at `unit_free_tol` gave `measured` (> tol)
/// in the measure; nullopt when it would not be lower than the current one (the floor reached).
std::optional<double> next_unit_free_tol(double unit_free_tol, double measured, double tol);

/// True when b is a better answer than a in measure m: accepted by the unit-free verdict
/// (unit_free <= tol_acceptable) before not, then the smaller error in m.
bool better_in_measure(const FrictionContactProblem& problem, const SolveResult& b,
                       const SolveResult& a, const CommonOptions& options, FrictionMeasure m);

/// `entry.solve_fc` judged in measure m (header comment). m = kUnitFree: one solve, as
/// entry.solve_fc(problem, options). Each re-solve starts from the best answer so far when the
/// solver that found it takes a warm start (nsgs, prox, fb-soc; for auto, the one in its chain
/// that found it), else from the start. iterations and seconds add up over the solves; the
/// message says how far the unit-free tolerance was lowered.
SolveResult solve_in_measure(const FrictionContactProblem& problem, const SolverEntry& entry,
                             const CommonOptions& options, FrictionMeasure m);

/// A verified answer (one of friction_solutions') brought within tol in measure m: polished from
/// its own r (polish_on_true_cone, faceted.hpp) at lowered unit-free tolerances as above, kept
/// when better, and its status decided by decide_in_measure(). m = kUnitFree: unchanged.
SolveResult refine_in_measure(const FrictionContactProblem& problem, SolveResult answer,
                              const CommonOptions& options, FrictionMeasure m);

}  // namespace cpkit::lcp::friction
