#pragma once
/// \file mpcc.hpp
/// Mathematical programs with complementarity constraints (MPCC) and their solution by a
/// sequence of smooth nonlinear programs (NLPs) [Scholtes 2001, SIAM J. Optim. 11:918-936;
/// Ralph & Wright 2004, Optim. Methods Softw. 19:527-556; Luo, Pang & Ralph 1996].
///
/// Problem (all quantities dimensionless; x in R^n):
///   minimize    f(x)
///   subject to  lower <= x <= upper                     (bounds, entries may be infinite)
///               c_lower <= c(x) <= c_upper              (m general constraints; equality when
///                                                        c_lower_j == c_upper_j)
///               0 <= G(x)  _|_  H(x) >= 0               (p complementarity pairs:
///                                                        G_i >= 0, H_i >= 0, G_i H_i = 0)
/// All derivatives come from callbacks (dense). An optional callback gives the Hessian of the
/// weighted sum of f, c, G and H; without it Ipopt's limited-memory quasi-Newton is used.
///
/// The MPCC violates every standard constraint qualification, so it is solved through a
/// reformulation (MpccReformulation) whose parameter is driven to its limit, followed by an
/// optional "piece" polish: the NLP in which, for each pair, the side identified as zero is
/// fixed to zero (both sides for biactive pairs, released by the sign of their multipliers, a
/// B-stationarity check [Scheel & Scholtes 2000, Math. Oper. Res. 25:1-22]). The result is a
/// local answer (a stationary point), never a proof of global optimality.
///
/// Ipopt is not assumed thread-safe (nor is MUMPS): every Ipopt call in cpkit is serialized by
/// one process-wide mutex, so concurrent callers wait for each other. NLopt calls are not
/// serialized (NLopt objects are per call).
///
/// Iterates with ||x||_inf > 1e10 (1 + ||x_start||_inf) (an unbounded penalty NLP, say) are
/// treated as diverged and never returned as candidates.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/status.hpp"

namespace cpkit::lcp {

/// f(x) into f; false outside the domain.
using ScalarCallback = std::function<bool(const Vec& x, double& f)>;
/// A vector function v(x) (c, G, H or grad f) into v; false outside the domain.
using VectorCallback = std::function<bool(const Vec& x, Vec& v)>;
/// A dense Jacobian (rows x n) into J; false outside the domain.
using MatrixCallback = std::function<bool(const Vec& x, Mat& J)>;
/// Dense symmetric n x n matrix
///   sigma * hess f + sum_j lambda_c[j] hess c_j + sum_i lambda_G[i] hess G_i
///                  + sum_i lambda_H[i] hess H_i
/// into Hs (the full matrix; only its lower triangle is read); false outside the domain.
using HessianCallback = std::function<bool(const Vec& x, double sigma, const Vec& lambda_c,
                                           const Vec& lambda_G, const Vec& lambda_H, Mat& Hs)>;

/// The MPCC above. Empty callbacks mean "absent": no objective (f = 0), m = 0, p = 0.
struct MpccProblem {
  Eigen::Index n = 0;          ///< number of variables
  Vec lower;                   ///< size n (may hold -inf); empty: all -inf
  Vec upper;                   ///< size n (may hold +inf); empty: all +inf
  Vec x0;                      ///< starting point (size n); empty: the projection of 0
  ScalarCallback objective;    ///< f; empty: f = 0
  VectorCallback gradient;     ///< grad f (size n); required when objective is set
  Eigen::Index m = 0;          ///< number of general constraints
  VectorCallback constraints;  ///< c (size m)
  MatrixCallback constraint_jacobian;  ///< dc/dx (m x n)
  Vec c_lower;                 ///< size m (may hold -inf)
  Vec c_upper;                 ///< size m (may hold +inf)
  Eigen::Index p = 0;          ///< number of complementarity pairs
  VectorCallback G;            ///< G (size p)
  MatrixCallback G_jacobian;   ///< dG/dx (p x n)
  VectorCallback H;            ///< H (size p)
  MatrixCallback H_jacobian;   ///< dH/dx (p x n)
  HessianCallback hessian;     ///< optional exact second derivatives (see HessianCallback)
  std::string name;

  /// Empty when usable; otherwise names the bad field (sizes, NaN, lower > upper, missing
  /// callbacks).
  std::string validate() const;
};

/// How the complementarity constraints are made smooth.
enum class MpccReformulation {
  /// Scholtes' relaxation: G >= 0, H >= 0, G_i H_i <= t; t decreases geometrically
  /// (t_initial, t_initial * t_factor, ...) down to t_min [Scholtes 2001].
  kScholtes,
  /// l1 (exact) penalty: minimize f + rho * sum_i G_i H_i s.t. G >= 0, H >= 0; rho grows by
  /// rho_factor while complementarity is violated, up to rho_max [Ralph & Wright 2004].
  kPenalty,
};
/// "scholtes" / "penalty"
std::string_view to_string(MpccReformulation r) noexcept;
/// Also accepts "l1-penalty".
std::optional<MpccReformulation> mpcc_reformulation_from_string(std::string_view s) noexcept;

/// Which NLP solver solves the smooth subproblems.
enum class NlpBackend {
  kIpopt,  ///< Ipopt 3.11 (interior point, MUMPS), calls serialized by a global mutex
  kNlopt,  ///< NLopt SLSQP (sequential quadratic programming, dense), exceptions mapped
};
/// "ipopt" / "nlopt"
std::string_view to_string(NlpBackend b) noexcept;
std::optional<NlpBackend> nlp_backend_from_string(std::string_view s) noexcept;

struct MpccOptions {
  /// max_iterations: per-NLP iteration limit (0: Ipopt 500, NLopt 1000 evaluations);
  /// time_limit_s: for the whole sequence; verbosity >= 3 (with a log sink) forwards the NLP
  /// solver's own output to the sink (Ipopt print level 5); otherwise the NLP solver is silent.
  CommonOptions common;
  MpccReformulation reformulation = MpccReformulation::kScholtes;
  NlpBackend backend = NlpBackend::kIpopt;
  double t_initial = 1.0;     ///< Scholtes: first relaxation parameter (> 0)
  double t_factor = 0.1;      ///< Scholtes: t <- t * t_factor, in (0, 1)
  /// Scholtes: smallest t tried (> 0). Either sequence also ends early when three NLPs in a
  /// row fail or leave max_i |min(G_i, H_i)| above 0.9 x its best value (stagnation).
  double t_min = 1e-14;
  double rho_initial = 1.0;   ///< penalty: first rho (> 0)
  double rho_factor = 10.0;   ///< penalty: rho <- rho * rho_factor on failure (> 1)
  double rho_max = 1e10;      ///< penalty: largest rho tried
  /// Acceptance of the MPCC point: max(bound, constraint violation) <= feasibility_tol * (1 +
  /// scale) and max_i |min(G_i, H_i)| <= complementarity_tol * (1 + scale), scale the largest
  /// |G_i|, |H_i|, |c_j| at the point.
  double feasibility_tol = 1e-8;
  double complementarity_tol = 1e-8;
  double nlp_tol = 1e-10;     ///< NLP solver tolerance (Ipopt "tol", NLopt ftol_rel/xtol_rel)
  bool exact_hessian = true;  ///< use MpccProblem::hessian when present (else limited memory)
  bool polish = true;         ///< run the piece-NLP polish after the relaxation sequence
  int max_subproblems = 60;   ///< cap on NLP solves (relaxation + polish)
  /// Optional caller's test, called with the final point of every converged relaxation/penalty
  /// NLP; when
  /// it returns true the sequence ends there (no piece polish), x is that point and
  /// MpccResult::stopped_early is set. Used by the complementarity solvers, whose own
  /// verification (active-set Newton + finalize) usually succeeds long before t reaches t_min.
  std::function<bool(const Vec& x)> early_stop;
  std::string validate() const;
};

/// One NLP of the sequence.
struct MpccSubproblem {
  std::string kind;            ///< "scholtes", "penalty" or "piece"
  double parameter = 0;        ///< t (scholtes), rho (penalty), 0 (piece)
  std::string nlp_status;      ///< the NLP solver's own verdict, e.g. "Solve_Succeeded"
  bool nlp_converged = false;  ///< the NLP solver reported a (possibly acceptable) optimum
  int iterations = 0;
  double objective = 0;        ///< f at the NLP's final point (without penalty terms)
  double complementarity = 0;  ///< max_i |min(G_i, H_i)| there
  double infeasibility = 0;    ///< max bound/constraint/sign violation there
  double seconds = 0;
};

struct MpccResult {
  /// kSolved: the final point is feasible and complementary to the tolerances of MpccOptions
  /// and the NLP it came from converged (a stationary point; local, not global).
  /// kSolvedInaccurate: feasible and complementary, but its NLP did not report convergence.
  /// kStalled: the sequence ended with complementarity or feasibility violated (x is then the
  /// least violating point seen, not an MPCC-feasible point). kTimeLimit,
  /// kNumericalFailure (callbacks failed, NLP breakdown) as usual.
  Status status = Status::kNotRun;
  Vec x;
  double objective = 0;
  double complementarity = 0;  ///< max_i |min(G_i, H_i)| at x
  double infeasibility = 0;    ///< max bound/constraint/sign violation at x
  int iterations = 0;          ///< NLP iterations summed over subproblems
  double seconds = 0;
  std::vector<MpccSubproblem> subproblems;  ///< every NLP solved, in order
  bool stopped_early = false;  ///< MpccOptions::early_stop ended the sequence
  std::string message;
};

/// Solves the MPCC; throws InputError for an invalid problem or options (before any work).
MpccResult solve_mpcc(const MpccProblem& problem, const MpccOptions& options = {});

}  // namespace cpkit::lcp
