#pragma once
// Internal (not installed): the smooth NLP solved at each step of the MPCC sequence, shared by
// the Ipopt and NLopt backends. See cpkit/lcp/mpcc.hpp for the problem and the reformulations.
//
// NLP rows, in order (bounds g_lower <= g(x) <= g_upper):
//   c_j(x)                        j < m            [c_lower_j, c_upper_j]
//   G_i(x), H_i(x)                per pair i       [0, 0] when fixed to zero, else [0, inf)
//   G_i(x) H_i(x)                 relaxed pairs    (-inf, t]
// Objective: f(x) + rho * sum over penalty pairs of G_i(x) H_i(x).
#include <string>
#include <vector>

#include "cpkit/lcp/mpcc.hpp"

namespace cpkit::lcp::detail {

enum class PairMode {
  kRelaxed,  ///< G >= 0, H >= 0, G H <= t
  kPenalty,  ///< G >= 0, H >= 0, rho G H added to the objective
  kFixG,     ///< G = 0, H >= 0
  kFixH,     ///< G >= 0, H = 0
};

class NlpEvaluator {
 public:
  NlpEvaluator(const MpccProblem& problem, std::vector<PairMode> modes, double t, double rho);

  Eigen::Index n() const { return problem_.n; }
  Eigen::Index rows() const { return rows_; }
  const Vec& x_lower() const { return x_lower_; }
  const Vec& x_upper() const { return x_upper_; }
  const Vec& g_lower() const { return g_lower_; }
  const Vec& g_upper() const { return g_upper_; }
  bool has_hessian() const { return static_cast<bool>(problem_.hessian); }

  /// Each returns false when a callback fails or returns non-finite values.
  bool objective(const Vec& x, double& value) const;
  bool gradient(const Vec& x, Vec& grad) const;
  bool constraints(const Vec& x, Vec& g) const;
  bool jacobian(const Vec& x, Mat& J) const;  ///< rows() x n
  /// sigma * hess(objective) + sum_r lambda_r hess(g_r) (Ipopt's convention), full n x n.
  bool hessian(const Vec& x, double sigma, const Vec& lambda, Mat& Hs) const;

 private:
  bool eval_pairs(const Vec& x, Vec& G, Vec& H) const;
  bool eval_pair_jacobians(const Vec& x, Mat& JG, Mat& JH) const;

  const MpccProblem& problem_;
  std::vector<PairMode> modes_;
  std::vector<Eigen::Index> product_row_;  // row of G_i H_i for relaxed pairs, else -1
  double t_;
  double rho_;
  Eigen::Index rows_ = 0;
  Vec x_lower_, x_upper_, g_lower_, g_upper_;
};

/// How one NLP solve ended.
struct NlpOutcome {
  Vec x;                   ///< final point (the start when nothing usable came back)
  std::string status;      ///< the backend's own verdict
  bool converged = false;  ///< optimum (or acceptable point) reported
  bool eval_failed = false;
  bool time_limit = false;
  int iterations = 0;
};

/// Ipopt backend (serialized by a process-wide mutex). time_limit_s <= 0: no limit.
NlpOutcome solve_nlp_ipopt(const NlpEvaluator& nlp, const Vec& x0, const MpccOptions& options,
                           double time_limit_s, double bound_relax);
/// NLopt SLSQP backend.
NlpOutcome solve_nlp_nlopt(const NlpEvaluator& nlp, const Vec& x0, const MpccOptions& options,
                           double time_limit_s);

}  // namespace cpkit::lcp::detail
