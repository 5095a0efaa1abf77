#pragma once
/// \file system_rate.hpp
/// The rate problem of N contact points coupled through A (docs/contact_model.md, "N points"):
/// given the system (states, parameters, A) and a load rate dF (2N, interleaved T_1, N_1, ...),
/// every solution. Each point obeys its own rate laws [Stromberg et al. 1996, Sec. 4.3]
/// (a: dP = 0; b: three complementarity pairs; c: stick; d: stick or slip of sign s), coupled by
/// dF - dP = A dw (the rate of eqn (47)). The free unknowns are eliminated (Schur complement)
/// and the remaining LCP of size 3 n_b + n_d is enumerated completely; every solution is mapped
/// back to physical rates, deduplicated there, and split by type tuple.
///
/// Units: forces and displacement rates as in A (force/length); no absolute tolerances (all
/// tests are relative to the load and to the stiffness, docs/contact_model.md). The problem is
/// solved in its own units (dF / max|dF_i|, A / max|A_ij|) and every listed piece is checked
/// against the rate laws from the data before it is returned (a piece that fails is dropped
/// and complete = false); beyond cond(A) = 1e8 the set is never called complete.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// Rates of all N points, one entry per point in each vector (order of model.md Sec. 4).
struct SystemRates {
  Eigen::VectorXd dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w;
};

/// One connected piece of the solution set with one type tuple: a point, a segment or a ray.
/// As for one point (RateSolution), pieces are never sampled and the types partition the set:
/// an end of a segment/ray with another type tuple is open here and listed as its own piece.
struct SystemRateSolution {
  std::vector<SolutionType> types;  ///< one per point
  RateSolution::Kind kind = RateSolution::Kind::kPoint;
  SystemRates start;          ///< the point; a segment's first end; a ray's origin
  bool start_closed = true;   ///< segment/ray: does the piece contain `start`?
  SystemRates end;            ///< segment: second end
  bool end_closed = true;     ///< segment: does the piece contain `end`?
  SystemRates direction;      ///< ray: direction (unit max-norm in the force components)
};

/// All solutions of one N-point rate problem. `complete` is false for the single-solver
/// methods, and when the enumeration could not decide every case (sign tests too close to call,
/// time limit) or met a piece of dimension >= 2 (a "face" of physical solutions, possible for
/// two or more degenerate points; not listed, message says), when a candidate piece failed the
/// check of the rate laws (not listed), or cond(A) > 1e8.
struct SystemRateSolutionSet : RatePieceSetOf<SystemRateSolution> {
  /// Single solvers: the solver's point is not in the enumerated set (CLI exit 3).
  bool disagreement = false;
  /// Force and displacement-rate scales used by the tolerance tests (relative to the load).
  double force_scale = 1, disp_scale = 1;
};

/// Type tuple encoded base 5 in 64 bits: sum_i type_i 5^i (point 1 is the lowest digit;
/// SolutionType's values 0..4). Up to 27 points fit.
using TypeTuple = std::uint64_t;
inline constexpr int kMaxTupleNPoints = 27;
TypeTuple encode_types(const std::vector<SolutionType>& types) noexcept;
std::vector<SolutionType> decode_types(TypeTuple code, int n_points);
/// "stick/slip+" (the per-point names joined by "/").
std::string types_string(const std::vector<SolutionType>& types);

/// Solves the N-point rate problem for the load rate dF (2N). `method`: kEnumerate (every
/// solution) or kLemke / kFbNewton / kIpopt (one solution by that LCP solver, checked against
/// the enumerated set; complete = false). kAnalytic is for one point only: InputError.
/// Throws InputError for an invalid system (validate()) or dF (size, NaN/Inf), or when a
/// solution's rates are beyond double's range ("not representable").
SystemRateSolutionSet solve_rate_problem(const ContactSystem& system, const Eigen::VectorXd& dF,
                                         RateMethod method = RateMethod::kEnumerate);

/// Is `r` (within rel_tol relative to the set's scales) in the set? (points, segments, rays
/// with their open/closed ends; the type tuple is not compared.)
bool contains(const SystemRateSolutionSet& set, const SystemRates& r, double rel_tol = 1e-7);

/// The fast path for maps: everything that does not depend on dF, computed once per system.
/// Read-only after construction, so one object can serve many threads.
struct SystemRatePrecomputed {
  ContactSystem system;
  int m = 0;                 ///< LCP size 3 n_b + n_d
  Eigen::MatrixXd M;         ///< m x m
  Eigen::MatrixXd Q;         ///< m x 2N: q = Q dF
  Eigen::MatrixXd Pf, Pz;    ///< 6N x 2N, 6N x m: physical rates = Pf dF + Pz z
  Eigen::MatrixXd G;         ///< m x 6N: w = G (physical rates) (the LCP's complementary rows)
  double inv_min_eig = 1;    ///< 1 / smallest eigenvalue of A (largest compliance)
  double inv_max_eig = 1;    ///< 1 / largest eigenvalue of A (the displacement-rate scale's floor)
  double max_C_T = 0;
};
/// Validates the system (InputError) and precomputes.
SystemRatePrecomputed precompute_system_rate(const ContactSystem& system);

/// Count and type tuples of one load: what a map cell needs.
struct SystemRateSummary {
  static constexpr int kCap = 16;   ///< distinct type tuples stored
  int count = 0;                    ///< number of solutions, -1 when infinite
  int n_tuples = 0;                 ///< distinct type tuples present (at most kCap stored)
  std::array<TypeTuple, kCap> tuples{};  ///< sorted ascending
  /// false when the enumeration met sign tests too close to call, a piece of dimension >= 2,
  /// a piece that failed the check of the rate laws, cond(A) > 1e8, or more than kCap tuples:
  /// count/tuples may then be wrong.
  bool reliable = true;
};
/// Same count and tuples as solve_rate_problem(pre.system, dF). Inputs must be valid (dF of
/// size 2N, finite). Thread-safe. on_critical: dF is a computed critical direction (the direction
/// map's candidates), whose exact set is wanted: an inequality that holds only within its
/// rounding holds with equality there, and does not make the summary unreliable.
SystemRateSummary summarize_rate_problem(const SystemRatePrecomputed& pre,
                                         const Eigen::VectorXd& dF,
                                         bool on_critical = false) noexcept;

}  // namespace cpkit::rate
