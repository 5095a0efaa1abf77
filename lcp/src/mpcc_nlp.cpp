// The smooth NLP of one MPCC subproblem (see mpcc_nlp.hpp for the row layout).
#include "mpcc_nlp.hpp"

#include <limits>

namespace cpkit::lcp::detail {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

NlpEvaluator::NlpEvaluator(const MpccProblem& problem, std::vector<PairMode> modes, double t,
                           double rho)
    : problem_(problem), modes_(std::move(modes)), t_(t), rho_(rho) {
  const Eigen::Index n = problem.n, m = problem.m, p = problem.p;
  x_lower_ = problem.lower.size() == n ? problem.lower : Vec::Constant(n, -kInf);
  x_upper_ = problem.upper.size() == n ? problem.upper : Vec::Constant(n, kInf);
  product_row_.assign(static_cast<std::size_t>(p), -1);
  Eigen::Index rows = m + 2 * p;
  for (Eigen::Index i = 0; i < p; ++i)
    if (modes_[static_cast<std::size_t>(i)] == PairMode::kRelaxed)
      product_row_[static_cast<std::size_t>(i)] = rows++;
  rows_ = rows;
  g_lower_.resize(rows_);
  g_upper_.resize(rows_);
  if (m > 0) {
    g_lower_.head(m) = problem.c_lower;
    g_upper_.head(m) = problem.c_upper;
  }
  for (Eigen::Index i = 0; i < p; ++i) {
    const PairMode mode = modes_[static_cast<std::size_t>(i)];
    g_lower_(m + 2 * i) = 0;
    g_upper_(m + 2 * i) = mode == PairMode::kFixG ? 0.0 : kInf;
    g_lower_(m + 2 * i + 1) = 0;
    g_upper_(m + 2 * i + 1) = mode == PairMode::kFixH ? 0.0 : kInf;
    const Eigen::Index r = product_row_[static_cast<std::size_t>(i)];
    if (r >= 0) {
      g_lower_(r) = -kInf;
      g_upper_(r) = t_;
    }
  }
}

bool NlpEvaluator::eval_pairs(const Vec& x, Vec& G, Vec& H) const {
  const Eigen::Index p = problem_.p;
  if (p == 0) {
    G.resize(0);
    H.resize(0);
    return true;
  }
  G.resize(p);
  H.resize(p);
  return problem_.G(x, G) && problem_.H(x, H) && G.size() == p && H.size() == p &&
         G.allFinite() && H.allFinite();
}

bool NlpEvaluator::eval_pair_jacobians(const Vec& x, Mat& JG, Mat& JH) const {
  const Eigen::Index p = problem_.p, n = problem_.n;
  JG.resize(p, n);
  JH.resize(p, n);
  if (p == 0) return true;
  return problem_.G_jacobian(x, JG) && problem_.H_jacobian(x, JH) && JG.rows() == p &&
         JG.cols() == n && JH.rows() == p && JH.cols() == n && JG.allFinite() && JH.allFinite();
}

bool NlpEvaluator::objective(const Vec& x, double& value) const {
  value = 0;
  if (problem_.objective && !problem_.objective(x, value)) return false;
  bool any_penalty = false;
  for (PairMode mode : modes_) any_penalty |= mode == PairMode::kPenalty;
  if (any_penalty) {
    Vec G, H;
    if (!eval_pairs(x, G, H)) return false;
    for (Eigen::Index i = 0; i < problem_.p; ++i)
      if (modes_[static_cast<std::size_t>(i)] == PairMode::kPenalty) value += rho_ * G(i) * H(i);
  }
  return std::isfinite(value);
}

bool NlpEvaluator::gradient(const Vec& x, Vec& grad) const {
  grad = Vec::Zero(problem_.n);
  if (problem_.objective && (!problem_.gradient(x, grad) || grad.size() != problem_.n))
    return false;
  bool any_penalty = false;
  for (PairMode mode : modes_) any_penalty |= mode == PairMode::kPenalty;
  if (any_penalty) {
    Vec G, H;
    Mat JG, JH;
    if (!eval_pairs(x, G, H) || !eval_pair_jacobians(x, JG, JH)) return false;
    for (Eigen::Index i = 0; i < problem_.p; ++i)
      if (modes_[static_cast<std::size_t>(i)] == PairMode::kPenalty)
        grad += rho_ * (H(i) * JG.row(i).transpose() + G(i) * JH.row(i).transpose());
  }
  return grad.allFinite();
}

bool NlpEvaluator::constraints(const Vec& x, Vec& g) const {
  const Eigen::Index m = problem_.m, p = problem_.p;
  g.resize(rows_);
  if (m > 0) {
    Vec c(m);
    if (!problem_.constraints(x, c) || c.size() != m) return false;
    g.head(m) = c;
  }
  Vec G, H;
  if (!eval_pairs(x, G, H)) return false;
  for (Eigen::Index i = 0; i < p; ++i) {
    g(m + 2 * i) = G(i);
    g(m + 2 * i + 1) = H(i);
    const Eigen::Index r = product_row_[static_cast<std::size_t>(i)];
    if (r >= 0) g(r) = G(i) * H(i);
  }
  return g.allFinite();
}

bool NlpEvaluator::jacobian(const Vec& x, Mat& J) const {
  const Eigen::Index m = problem_.m, p = problem_.p, n = problem_.n;
  J.setZero(rows_, n);
  if (m > 0) {
    Mat Jc(m, n);
    if (!problem_.constraint_jacobian(x, Jc) || Jc.rows() != m || Jc.cols() != n) return false;
    J.topRows(m) = Jc;
  }
  if (p > 0) {
    Vec G, H;
    Mat JG, JH;
    if (!eval_pairs(x, G, H) || !eval_pair_jacobians(x, JG, JH)) return false;
    for (Eigen::Index i = 0; i < p; ++i) {
      J.row(m + 2 * i) = JG.row(i);
      J.row(m + 2 * i + 1) = JH.row(i);
      const Eigen::Index r = product_row_[static_cast<std::size_t>(i)];
      if (r >= 0) J.row(r) = H(i) * JG.row(i) + G(i) * JH.row(i);
    }
  }
  return J.allFinite();
}

bool NlpEvaluator::hessian(const Vec& x, double sigma, const Vec& lambda, Mat& Hs) const {
  if (!problem_.hessian) return false;
  const Eigen::Index m = problem_.m, p = problem_.p, n = problem_.n;
  Vec lc = m > 0 ? Vec(lambda.head(m)) : Vec();
  Vec lG = Vec::Zero(p), lH = Vec::Zero(p), cross = Vec::Zero(p);
  Vec G, H;
  Mat JG, JH;
  if (p > 0 && (!eval_pairs(x, G, H) || !eval_pair_jacobians(x, JG, JH))) return false;
  for (Eigen::Index i = 0; i < p; ++i) {
    lG(i) = lambda(m + 2 * i);
    lH(i) = lambda(m + 2 * i + 1);
    const PairMode mode = modes_[static_cast<std::size_t>(i)];
    double k = 0;  // weight of the product G_i H_i in the Lagrangian
    if (mode == PairMode::kPenalty) k = sigma * rho_;
    const Eigen::Index r = product_row_[static_cast<std::size_t>(i)];
    if (r >= 0) k = lambda(r);
    // hess(G H) = H hess G + G hess H + grad G grad H^T + grad H grad G^T
    lG(i) += k * H(i);
    lH(i) += k * G(i);
    cross(i) = k;
  }
  Hs.setZero(n, n);
  if (!problem_.hessian(x, sigma, lc, lG, lH, Hs) || Hs.rows() != n || Hs.cols() != n)
    return false;
  for (Eigen::Index i = 0; i < p; ++i) {
    if (cross(i) == 0) continue;
    Hs.noalias() += cross(i) * (JG.row(i).transpose() * JH.row(i) +
                                JH.row(i).transpose() * JG.row(i));
  }
  return Hs.allFinite();
}

}  // namespace cpkit::lcp::detail
