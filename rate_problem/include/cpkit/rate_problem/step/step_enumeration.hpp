#pragma once
/// \file step_enumeration.hpp
/// All solutions of one incremental step (incremental_step.hpp) by complementary active sets
/// [Stromberg et al. 1996, Sec. 4; docs/model.md Sec. 3; docs/simulation.md].
///
/// A physical solution is determined by (DP_N, xi = Dw_T^i), so the active sets are four pieces:
/// - P_N1 = 0 (separation/open): P_T1 = 0 fixes xi; admissible when g1 <= 0.
/// - stick, P_N1 > 0, xi = 0: g1 = 0 is linear in DP_N.
/// - slip s = +-1, P_N1 > 0, xi = s l, l > 0: the friction row s P_T1 = Y(P_N1) gives
///   l = (b0 + b1 x + b2 x^2) / det A (x = DP_N, written in increments so that no O(state)
///   terms cancel), and substituting it into the bilinear gap row g1 = 0 leaves one scalar
///   polynomial in x: a quadratic for criterion (38) (solved by the cancellation-free
///   q = -(b + sgn(b) sqrt(disc))/2 form) and a cubic for (35) (real roots in [0, mu/k] by
///   monotone bracketing between the critical points).
/// When the reduced polynomial vanishes identically (degenerate data, e.g. a11 = mu |a12| on
/// N = 0) the piece is a segment or a ray, reported as such. Types are partitioned as in the
/// rate problem (rate_problem/src/rate/piece_geometry.hpp): a piece holds the points of its own
/// type only, so an end of another type (the stick end xi = 0 of a slip segment, or an open
/// end P_N1 = 0 of a step that started open) is an open end of the piece and is listed as a
/// point of its own type; point solutions on the closed part of a piece are not listed again.
///
/// Units and verification (unit-free, issue 24 item 3). The pieces are solved in normalised
/// units: forces divided by 2^eF (eF from the largest of |P_T0|, P_N0, |DF_T|, |DF_N|),
/// stiffnesses by 2^eA (eA from max(a11, a22)), lengths by 2^(eF - eA); powers of two keep the
/// scaling exact, so scaling A, or A and the loads, changes nothing but the units of the
/// answer, and loads near 1e308 or subnormal ones are solved like loads of order 1. Every
/// candidate is polished by Newton steps on the model's own equations (equilibrium
/// DF - DP = A Dw, Dw_T = C_T DP_T + Dw_Ti and the two active conditions of its piece, imposed
/// exactly) unless it is already at the rounding level, and then judged by its backward error:
/// the largest violation of those equations, each divided by the magnitudes of its own terms
/// (at least the step's force or displacement scale), and of the piece's sign conditions
/// (P_N1 >= 0 against the normal forces, |P_T1| <= Y(P_N1) against the tangential ones,
/// g1 <= 0 and s Dw_T^i >= 0 against the displacements). A sign condition violated by 25 %
/// rejects a candidate before polishing. Backward error <= 1e-12: accepted; > tol: rejected;
/// in between: neither, and the set says complete = false. A solution whose values overflow in
/// the caller's units is not representable: enumerate_step throws InputError (as the rate
/// problem does), enumerate_step_points counts it in `unrepresentable`. Types come from the
/// piece (separation/open, stick, slip+/-); a slip root whose Dw_T^i is at the rounding level of
/// its own displacements is the stick point. Duplicates (the same physical point found by two
/// pieces) are merged; the first piece in the order above names its type.
///
/// Jumps: a solution is continuous (rate-consistent) when it lies on a branch that starts at the
/// start state as the increment is scaled from 0 to 1: the enumeration is repeated for t DF,
/// t = 0, 1/128, ..., 1, and each solution is linked to its nearest neighbour at the previous t
/// (distance |DP_N| + |DP_T| + (det A / D0)|xi|, links only below 0.1 times the force scale).
/// The other solutions are flagged `jump`. From state d with Lambda < 0 a step can have a jump
/// (e.g. to separation) where the rate problem has none (continuous_count == 0).
#include <array>
#include <string>
#include <vector>

#include "cpkit/rate_problem/step/incremental_step.hpp"
#include "cpkit/rate_problem/step/step_result.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

/// One connected piece of the step's solution set (a point, segment or ray).
struct StepSolution {
  SolutionType type = SolutionType::kStick;
  RateSolution::Kind kind = RateSolution::Kind::kPoint;
  StepValues start;          ///< the point; a segment's first end; a ray's origin
  StepValues end;            ///< segment: second end
  StepValues direction;      ///< ray: direction (unit length in DP_N)
  bool start_closed = true;  ///< segment/ray: `start` belongs to the piece (same type)
  bool end_closed = true;    ///< segment: `end` belongs to the piece (same type)
  double residual = 0;       ///< unit-free backward error at `start` (worst over the ends)
  bool jump = false;         ///< not on a branch from the start state (see the file comment)
};

/// The pieces of one 2-D point's step (step_result.hpp), in the order separation/open, stick,
/// slip+, slip-. `complete` is false when some candidate could be neither accepted nor rejected
/// (backward error between 1e-12 and tol): the listed solutions are verified, but the set may
/// miss some.
struct StepSolutionSet : StepSolutionSetOf<StepSolution> {
  bool infinite = false;                ///< a segment or a ray is present
  int continuous_count = 0;  ///< rate-consistent point solutions (-1 when not determined)
  /// Number of solutions: -1 when infinite.
  int count() const noexcept;
  /// Bit mask of the types present (bit = static_cast<int>(SolutionType)).
  unsigned type_mask() const noexcept;
};

struct StepEnumerationOptions {
  double tol = 1e-9;        ///< rejection threshold of the unit-free backward error (see above)
  bool detect_jumps = true; ///< follow the branches in t (129 enumerations) to flag jumps
};

/// All solutions. Throws InputError for an invalid problem (StepProblem::validate) and when a
/// solution is not representable in double precision.
StepSolutionSet enumerate_step(const StepProblem& problem,
                               const StepEnumerationOptions& options = {});

/// Allocation-free core for hot loops (the simulation, benchmarks): point solutions as
/// (type, DP_N, xi), at most kMaxStepPoints. `infinite` is set when some piece is a continuum
/// (its points are then not listed: call enumerate_step for the pieces). Inputs must be valid.
struct StepPoint {
  SolutionType type = SolutionType::kStick;
  double DP_N = 0;
  double xi = 0;
  StepValues values;  ///< the verified values (polished; step_values() would recompute them)
};
constexpr int kMaxStepPoints = 8;
struct StepPoints {
  std::array<StepPoint, kMaxStepPoints> points;
  int n = 0;
  bool infinite = false;
  int undecided = 0;            ///< candidates neither accepted nor rejected (see above)
  int unrepresentable = 0;      ///< solutions whose values overflow in the caller's units
  bool complete() const noexcept { return undecided == 0 && unrepresentable == 0; }
};
/// `ncp` is not used (the pieces are solved in normalised units); kept for the callers.
void enumerate_step_points(const StepProblem& problem, const StepNcp& ncp, StepPoints& out,
                           double tol = 1e-9) noexcept;

/// Real roots of c2 x^2 + c1 x + c0 without cancellation (q = -(c1 + sgn(c1) sqrt(disc))/2,
/// roots q/c2 and c0/q); degree drops when |c2| <= deg_tol * scale2 (and likewise c1).
/// Returns the number of roots (0-2) or -1 when the polynomial vanishes identically.
/// Exposed for tests.
int stable_quadratic_roots(double c2, double c1, double c0, double scale2, double scale1,
                           double scale0, double deg_tol, double roots[2]) noexcept;

}  // namespace cpkit::rate
