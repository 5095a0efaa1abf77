#include "cpkit/core/friction_problem.hpp"

#include <cmath>
#include <string>

namespace cpkit {
namespace {

std::string size_text(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

// First non-finite stored entry as "name(i, j)"; empty if all finite.
std::string first_nonfinite(const Eigen::SparseMatrix<double>& m, const char* name) {
  for (Eigen::Index k = 0; k < m.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, k); it; ++it)
      if (!std::isfinite(it.value()))
        return std::string(name) + "(" + std::to_string(it.row()) + ", " +
               std::to_string(it.col()) + ") is not finite";
  return {};
}
std::string first_nonfinite(const Eigen::VectorXd& v, const char* name) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      return std::string(name) + "[" + std::to_string(i) + "] is not finite";
  return {};
}
std::string check_mu(const Eigen::VectorXd& mu) {
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    if (!(mu[i] >= 0) || !std::isfinite(mu[i]))
      return "mu[" + std::to_string(i) + "] = " + std::to_string(mu[i]) +
             " must be finite and >= 0";
  return {};
}

}  // namespace

std::string FrictionContactProblem::validate() const {
  const Eigen::Index n = 3 * mu.size();
  if (mu.size() == 0) return "the problem has no contact";
  if (W.rows() != n || W.cols() != n)
    return "W is " + size_text(W.rows(), W.cols()) + ", expected " + size_text(n, n) + " for " +
           std::to_string(mu.size()) + " contacts";
  if (q.size() != n)
    return "q has " + std::to_string(q.size()) + " entries, expected " + std::to_string(n);
  for (const std::string& e : {first_nonfinite(W, "W"), first_nonfinite(q, "q"), check_mu(mu)})
    if (!e.empty()) return e;
  return {};
}

std::string GlobalFrictionContactProblem::validate() const {
  const Eigen::Index n = 3 * mu.size();
  const Eigen::Index m = f.size();
  if (mu.size() == 0) return "the problem has no contact";
  if (m == 0) return "the problem has no degree of freedom";
  if (M.rows() != m || M.cols() != m)
    return "M is " + size_text(M.rows(), M.cols()) + ", expected " + size_text(m, m);
  if (H.rows() != m || H.cols() != n)
    return "H is " + size_text(H.rows(), H.cols()) + ", expected " + size_text(m, n);
  if (w.size() != n)
    return "w has " + std::to_string(w.size()) + " entries, expected " + std::to_string(n);
  for (const std::string& e : {first_nonfinite(M, "M"), first_nonfinite(H, "H"),
                               first_nonfinite(f, "f"), first_nonfinite(w, "w"), check_mu(mu)})
    if (!e.empty()) return e;
  return {};
}

}  // namespace cpkit
