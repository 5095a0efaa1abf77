// SOCCP data check and verdict (soc_problem.hpp).
#include "cpkit/core/soc_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"
#include "finalize_decide.hpp"

namespace cpkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();

// a / s in the extended sense: s = 0 gives 0 for a = 0 and +-inf otherwise.
double ratio(double a, double s) {
  if (s > 0) return a / s;
  if (a == 0) return 0.0;
  return a > 0 ? kInf : -kInf;
}

// Projection onto the Lorentz cone in R^3 (spectral form).
Eigen::Vector3d project_cone(const Eigen::Vector3d& v) {
  const double t = v.tail<2>().norm();
  if (t <= v[0]) return v;
  if (t <= -v[0]) return Eigen::Vector3d::Zero();
  const double a = 0.5 * (v[0] + t);
  Eigen::Vector3d p;
  p[0] = a;
  p.tail<2>() = (a / t) * v.tail<2>();
  return p;
}

}  // namespace

std::string SocProblem::validate() const {
  const Eigen::Index n = q.size();
  if (M.rows() != n || M.cols() != n)
    return "M is " + std::to_string(M.rows()) + " x " + std::to_string(M.cols()) +
           ", expected " + std::to_string(n) + " x " + std::to_string(n) + " (size of q)";
  Eigen::Index sum = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (blocks[b] != 1 && blocks[b] != 3)
      return "block " + std::to_string(b) + " has size " + std::to_string(blocks[b]) +
             " (supported: 1 = half-line, 3 = Lorentz cone)";
    sum += blocks[b];
  }
  if (sum != n)
    return "block sizes sum to " + std::to_string(sum) + ", expected " + std::to_string(n);
  if (!M.allFinite()) return "M has non-finite entries";
  if (!q.allFinite()) return "q has non-finite entries";
  return {};
}

Eigen::Vector3d soc_natural_map(const Eigen::Vector3d& z, const Eigen::Vector3d& w, int size) {
  if (size == 1) return Eigen::Vector3d(z[0] - std::max(z[0] - w[0], 0.0), 0, 0);
  return z - project_cone(z - w);
}

Residuals soc_residuals(const SocProblem& p, const Eigen::VectorXd& z, const Eigen::VectorXd& w) {
  const Eigen::Index n = p.size();
  Residuals res;
  res.finite = z.allFinite() && w.allFinite();
  const double z_inf = n ? z.lpNorm<Eigen::Infinity>() : 0.0;
  const double q_inf = n ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  const double m_max = n ? p.M.cwiseAbs().maxCoeff() : 0.0;
  const bool has_ref = q_inf > 0 && m_max > 0;
  const double Z = has_ref ? std::max(z_inf, q_inf / m_max) : z_inf;
  const double gamma = (n + 1) * kEps / 2 / (1 - (n + 1) * kEps / 2);  // [Higham 2002, 3.1]
  const Eigen::VectorXd Mz_abs = p.M.cwiseAbs() * z.cwiseAbs();
  res.z_scale = Z;
  res.worst_index = n ? 0 : -1;
  res.min_z = res.min_w = n ? kInf : 0.0;
  Eigen::Index k0 = 0;
  for (const int size : p.blocks) {
    Eigen::Vector3d zb = Eigen::Vector3d::Zero(), wb = zb, a = zb;
    double c_max = 0;
    for (int j = 0; j < size; ++j) {
      const Eigen::Index k = k0 + j;
      const double row = p.M.row(k).cwiseAbs().sum();
      double c = row * z_inf;
      if (has_ref) c = std::min(c, (row / m_max) * q_inf);  // the cap, as a ratio (no overflow)
      c_max = std::max(c_max, c);
      zb[j] = z[k];
      wb[j] = w[k];
      a[j] = gamma * (Mz_abs[k] + std::abs(p.q[k]));
    }
    const double S = p.q.segment(k0, size).norm() + c_max;
    res.scale = std::max(res.scale, S);
    Eigen::Vector3d zn, wn;
    for (int j = 0; j < 3; ++j) {
      zn[j] = ratio(zb[j], Z);
      wn[j] = ratio(wb[j], S);
    }
    const double allowance = ratio(a.norm(), S);
    double v = std::max(0.0, soc_natural_map(zn, wn, size).norm() - allowance);
    if (std::isnan(v) || !zb.allFinite() || !wb.allFinite() || !std::isfinite(S)) v = kInf;
    if (v > res.natural) {
      res.natural = v;
      res.worst_index = k0;
    }
    res.rounding = std::max(res.rounding, allowance);
    res.natural_abs = std::max(res.natural_abs, soc_natural_map(zb, wb, size).norm());
    res.complementarity = std::max(res.complementarity, std::abs(zb.dot(wb)));
    res.min_z = std::min(res.min_z, zb[0]);
    res.min_w = std::min(res.min_w, wb[0]);
    k0 += size;
  }
  if (!res.finite) res.natural = kInf;
  return res;
}

SolveResult finalize(const SocProblem& p, SolveResult claim, const CommonOptions& options) {
  throw_if_invalid(p.validate(), "cone problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
  const bool claimed_solution = is_solution(claim.status);
  if (detail::refuse_infeasibility(claim, "a cone problem") ||
      !detail::usable_point(claim, p.size(), claimed_solution))
    return claim;
  claim.w = p.M * claim.z + p.q;
  claim.residuals = soc_residuals(p, claim.z, claim.w);
  detail::decide(claim, claimed_solution, options);
  return claim;
}

}  // namespace cpkit
