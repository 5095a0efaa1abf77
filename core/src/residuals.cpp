#include "cpkit/core/residuals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cpkit {
namespace {

// Largest |v_i| and its index (first on ties); -1 for an empty vector.
void max_abs(const Vec& v, double& value, Eigen::Index& index) {
  value = 0;
  index = v.size() > 0 ? 0 : -1;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double a = std::abs(v[i]);
    if (a > value || std::isnan(a)) {
      value = a;
      index = i;
      if (std::isnan(a)) return;
    }
  }
}

// scale = 1 + ||q||_inf; rounding = 2 n eps max_i (|M||z| + |q|)_i / scale, the worst-case
// error of the dot products that form w = M z + q [Higham 2002, Sec. 3.1].
void lcp_scale(const LcpProblem& p, const Vec& z, Residuals& r) {
  const Vec az = z.cwiseAbs();
  const Vec terms = (p.is_sparse() ? Vec(p.M_sparse.cwiseAbs() * az) : Vec(p.M.cwiseAbs() * az)) +
                    p.q.cwiseAbs();
  const double n = static_cast<double>(std::max<Eigen::Index>(z.size(), 1));
  r.scale = 1.0 + p.q.lpNorm<Eigen::Infinity>();
  r.rounding = terms.size() ? 2.0 * n * std::numeric_limits<double>::epsilon() *
                                  terms.maxCoeff() / r.scale
                            : 0.0;
}

// Natural residual of a box problem: x - mid(l, u, x - F).
Vec box_natural_map(const Vec& x, const Vec& F, const Vec& l, const Vec& u) {
  return x - (x - F).cwiseMax(l).cwiseMin(u);
}

// min over i of the distance of x_i inside [l_i, u_i] (negative when outside).
double box_margin(const Vec& x, const Vec& l, const Vec& u) {
  double m = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < x.size(); ++i) m = std::min({m, x[i] - l[i], u[i] - x[i]});
  return x.size() ? m : 0.0;
}

// Sign error of F for a box problem: the most negative of F_i at x_i = l_i, -F_i at u_i,
// -|F_i| strictly inside (0 when all sign conditions hold).
double box_sign_error(const Vec& x, const Vec& F, const Vec& l, const Vec& u) {
  double m = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    double s;
    if (x[i] <= l[i]) s = F[i];
    else if (x[i] >= u[i]) s = -F[i];
    else s = -std::abs(F[i]);
    m = std::min(m, s);
  }
  return m;
}

}  // namespace

Residuals lcp_residuals(const LcpProblem& p, const Vec& z, Vec& w) {
  w = p.w(z);
  Residuals r;
  max_abs(z.cwiseMin(w), r.natural_abs, r.worst_index);
  r.complementarity = z.size() ? z.cwiseProduct(w).cwiseAbs().maxCoeff() : 0.0;
  r.min_z = z.size() ? z.minCoeff() : 0.0;
  r.min_w = w.size() ? w.minCoeff() : 0.0;
  lcp_scale(p, z, r);
  r.natural = r.natural_abs / r.scale;
  return r;
}

Residuals box_lcp_residuals(const BoxLcpProblem& p, const Vec& z, Vec& w) {
  w = p.lcp.w(z);
  Residuals r;
  max_abs(box_natural_map(z, w, p.lower, p.upper), r.natural_abs, r.worst_index);
  // |z_i - l_i| w_i^+ and |u_i - z_i| w_i^- are the box analogues of z_i w_i.
  double comp = 0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double lo = std::isfinite(p.lower[i]) ? std::abs(z[i] - p.lower[i]) : INFINITY;
    const double hi = std::isfinite(p.upper[i]) ? std::abs(p.upper[i] - z[i]) : INFINITY;
    comp = std::max(comp, std::min({lo * std::max(w[i], 0.0), hi * std::max(-w[i], 0.0),
                                    (std::isinf(lo) && std::isinf(hi)) ? std::abs(w[i]) : INFINITY}));
  }
  r.complementarity = comp;
  r.min_z = box_margin(z, p.lower, p.upper);
  r.min_w = box_sign_error(z, w, p.lower, p.upper);
  lcp_scale(p.lcp, z, r);
  r.natural = r.natural_abs / r.scale;
  return r;
}

Residuals mcp_residuals(const McpProblem& p, const Vec& x, const Vec& F) {
  Residuals r;
  max_abs(box_natural_map(x, F, p.lower, p.upper), r.natural_abs, r.worst_index);
  double comp = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double lo = std::isfinite(p.lower[i]) ? std::abs(x[i] - p.lower[i]) : INFINITY;
    const double hi = std::isfinite(p.upper[i]) ? std::abs(p.upper[i] - x[i]) : INFINITY;
    comp = std::max(comp, std::min({lo * std::max(F[i], 0.0), hi * std::max(-F[i], 0.0),
                                    (std::isinf(lo) && std::isinf(hi)) ? std::abs(F[i]) : INFINITY}));
  }
  r.complementarity = comp;
  r.min_z = box_margin(x, p.lower, p.upper);
  r.min_w = box_sign_error(x, F, p.lower, p.upper);
  r.scale = 1.0 + F.lpNorm<Eigen::Infinity>();
  r.natural = r.natural_abs / r.scale;
  return r;
}

}  // namespace cpkit
