#include "cpkit/core/residuals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cpkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();

// gamma_k = k u / (1 - k u), u = eps / 2: the relative error bound of a k-term dot product
// [Higham 2002, Lemma 3.1]; w_i = sum_j M_ij z_j + q_i has n + 1 terms.
double gamma_bound(Eigen::Index n) {
  const double ku = static_cast<double>(n + 1) * kEps / 2;
  return ku < 0.5 ? ku / (1 - ku) : kInf;
}

// a / s in the extended sense: s = 0 gives 0 for a = 0 and +-inf otherwise.
double ratio(double a, double s) {
  if (s > 0) return a / s;
  if (a == 0) return 0.0;
  return a > 0 ? kInf : -kInf;
}

// row_violation()'s formula, inlinable (the public function is not, in position-independent
// code, and the per-call path of the C API calls it for every row).
inline double row_violation_of(double wn, double dlo, double dhi) noexcept {
  const double feas = std::max({0.0, -dlo, -dhi});
  const double lo = std::max(dlo, 0.0), hi = std::max(dhi, 0.0);
  const double at_lower = std::max(lo, std::max(0.0, -wn));   // z at l, w >= 0
  const double at_upper = std::max(hi, std::max(0.0, wn));    // z at u, w <= 0
  const double inside = std::abs(wn);                         // w = 0
  return std::max(feas, std::min({at_lower, at_upper, inside}));
}

Vec row_abs_sums(const LcpProblem& p) {
  if (!p.is_sparse()) return p.M.cwiseAbs().rowwise().sum();
  Vec r = Vec::Zero(p.size());
  for (Eigen::Index k = 0; k < p.M_sparse.outerSize(); ++k)
    for (SparseMat::InnerIterator it(p.M_sparse, k); it; ++it) r[it.row()] += std::abs(it.value());
  return r;
}

}  // namespace

DataSizes data_sizes(const LcpProblem& p) {
  DataSizes d;
  d.q_norm = p.q.size() ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  d.m_max = p.max_abs_entry();
  d.row_sums = row_abs_sums(p);
  return d;
}

namespace {
// z_unit()'s formula, inlinable (the public function is not, in position-independent code).
inline double z_unit_of(double q_norm, double m_max, double z_norm) {
  if (q_norm > 0 && m_max > 0) {
    const double z_ref = q_norm / m_max;  // may overflow to inf: then nothing is small
    return std::max(z_norm, z_ref);
  }
  return z_norm;
}
}  // namespace

double z_unit(const DataSizes& d, double z_norm) { return z_unit_of(d.q_norm, d.m_max, z_norm); }

void w_units(const DataSizes& d, const Vec& q, double z_norm, Vec& s) {
  s.resize(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    // ||M_i||_1 min(||z||, z_ref); the cap is written as a ratio <= n times ||q|| so that it
    // cannot overflow. With q = 0 the data have no size of z: no cap.
    double row = d.row_sums[i] * z_norm;
    if (d.m_max > 0 && d.q_norm > 0) row = std::min(row, (d.row_sums[i] / d.m_max) * d.q_norm);
    s[i] = std::abs(q[i]) + row;
  }
}

namespace {

struct RowValues {
  double zn, wn, to_lower, to_upper;
};

// Row i in the units of the test (residuals.hpp): the one place the formula is written.
inline RowValues row_values(double z, double w, double R, double s, double l, double h, double Z,
                            double g) {
  RowValues v;
  v.zn = ratio(z, Z);
  // The rounding allowance is deducted in w's own units first: |w_i| <= gamma R_i is zero.
  const double excess = std::max(0.0, std::abs(w) - g * R);
  v.wn = excess > 0 ? std::copysign(ratio(excess, s), w) : 0.0;
  v.to_lower = std::isinf(l) ? kInf : ratio(z - l, Z);
  v.to_upper = std::isinf(h) ? kInf : ratio(h - z, Z);
  return v;
}

// The units of one candidate: Z, s and R = |M||z| + |q| (header comment).
struct CandidateUnits {
  double Z = 0;
  Vec s, R;
};

CandidateUnits candidate_units(const LcpProblem& p, const Vec& z) {
  CandidateUnits c;
  const DataSizes d = data_sizes(p);
  const double z_norm = z.size() ? z.lpNorm<Eigen::Infinity>() : 0.0;
  c.R = abs_product(p, z) + p.q.cwiseAbs();
  w_units(d, p.q, z_norm, c.s);
  c.Z = z_unit(d, z_norm);
  return c;
}

// The candidate projected onto its bounds (the point whose w is judged; residuals.hpp).
Vec projected(const Vec& z, const Vec* lower, const Vec* upper) {
  Vec zp = z;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double l = lower ? (*lower)[i] : 0.0, h = upper ? (*upper)[i] : kInf;
    zp[i] = std::min(std::max(z[i], l), h);
  }
  return zp;
}

// z: the candidate; wp: w at its projection onto the bounds (units c taken there too).
UnitFreePoint make_point(const Vec& z, const Vec& wp, const CandidateUnits& c, const Vec* lower,
                         const Vec* upper) {
  const Eigen::Index n = z.size();
  UnitFreePoint u;
  u.z.resize(n);
  u.w.resize(n);
  u.to_lower.resize(n);
  u.to_upper.resize(n);
  const double g = gamma_bound(n);
  u.finite = z.allFinite() && wp.allFinite() && c.R.allFinite() && c.s.allFinite();
  for (Eigen::Index i = 0; i < n; ++i) {
    const RowValues v = row_values(z[i], wp[i], c.R[i], c.s[i], lower ? (*lower)[i] : 0.0,
                                   upper ? (*upper)[i] : kInf, c.Z, g);
    u.z[i] = v.zn;
    u.w[i] = v.wn;
    u.to_lower[i] = v.to_lower;  // from z itself: negative when z is outside its bounds
    u.to_upper[i] = v.to_upper;
  }
  return u;
}

}  // namespace

Vec abs_product(const LcpProblem& p, const Vec& z) {
  const Vec az = z.cwiseAbs();
  return p.is_sparse() ? Vec(p.M_sparse.cwiseAbs() * az) : Vec(p.M.cwiseAbs() * az);
}

double unit_free_residual(const Vec& z, const Vec& w, const Vec& R, const Vec& s, double Z,
                          const Vec* lower, const Vec* upper, Eigen::Index* worst) {
  const Eigen::Index n = z.size();
  const double g = gamma_bound(n);
  double worst_value = 0;
  if (worst) *worst = n ? 0 : -1;
  for (Eigen::Index i = 0; i < n; ++i) {
    const RowValues v = row_values(z[i], w[i], R[i], s[i], lower ? (*lower)[i] : 0.0,
                                   upper ? (*upper)[i] : kInf, Z, g);
    double r = row_violation(v.wn, v.to_lower, v.to_upper);
    if (!std::isfinite(z[i]) || !std::isfinite(w[i]) || !std::isfinite(R[i]) ||
        !std::isfinite(s[i]) || std::isnan(r))
      r = kInf;
    if (r > worst_value) {
      worst_value = r;
      if (worst) *worst = i;
    }
  }
  return worst_value;
}

double bound_violation(const Vec& z, double Z, const Vec* lower, const Vec* upper,
                       Eigen::Index* worst) {
  double m = 0;
  if (worst) *worst = -1;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double l = lower ? (*lower)[i] : 0.0, h = upper ? (*upper)[i] : kInf;
    double v = std::max({0.0, ratio(l - z[i], Z), ratio(z[i] - h, Z)});
    if (std::isnan(v)) v = kInf;
    if (v > m) {
      m = v;
      if (worst) *worst = i;
    }
  }
  return m;
}

namespace {

// zp, wp: the projected candidate and its w; z the candidate itself (bound violations).
void fill_common(Residuals& r, const Vec& z, const Vec& zp, const Vec& wp, const CandidateUnits& c,
                 const Vec* lower, const Vec* upper) {
  const Eigen::Index n = z.size();
  r.finite = z.allFinite() && wp.allFinite() && c.R.allFinite() && c.s.allFinite();
  r.z_scale = c.Z;
  r.scale = n ? c.s.maxCoeff() : 0.0;
  r.natural = unit_free_residual(zp, wp, c.R, c.s, c.Z, lower, upper, &r.worst_index);
  Eigen::Index bi = -1;
  const double b = bound_violation(z, c.Z, lower, upper, &bi);
  if (b > r.natural) {
    r.natural = b;
    r.worst_index = bi;
  }
  if (!r.finite) r.natural = kInf;
  const double g = gamma_bound(n);
  for (Eigen::Index i = 0; i < n; ++i) r.rounding = std::max(r.rounding, ratio(g * c.R[i], c.s[i]));
  r.min_z = n ? z.minCoeff() : 0.0;
}

// min over i of the distance of x_i inside [l_i, u_i] (negative when outside).
double box_margin(const Vec& x, const Vec& l, const Vec& u) {
  double m = kInf;
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

// Natural map of a box problem: x - mid(l, u, x - F) (information: natural_abs).
double box_natural_abs(const Vec& x, const Vec& F, const Vec& l, const Vec& u) {
  double m = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double v = std::abs(x[i] - std::min(std::max(x[i] - F[i], l[i]), u[i]));
    if (!(v <= m)) m = v;
  }
  return m;
}

double box_complementarity(const Vec& z, const Vec& w, const Vec& l, const Vec& u) {
  double comp = 0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double lo = std::isfinite(l[i]) ? std::abs(z[i] - l[i]) : kInf;
    const double hi = std::isfinite(u[i]) ? std::abs(u[i] - z[i]) : kInf;
    comp = std::max(comp, std::min({lo * std::max(w[i], 0.0), hi * std::max(-w[i], 0.0),
                                    (std::isinf(lo) && std::isinf(hi)) ? std::abs(w[i]) : kInf}));
  }
  return comp;
}

}  // namespace

double row_violation(double wn, double dlo, double dhi) noexcept {
  return row_violation_of(wn, dlo, dhi);
}

namespace {

/// small_lcp_natural() for a size known at compile time (its loops unrolled; the same
/// operations in the same order as for any n).
template <int n>
double small_natural(const double* M, const double* q, const double* z, double* w) {
  // Every step as lcp_residuals() takes it for a dense problem (the sums in column order, as
  // Eigen's products and row sums of these sizes add them), on the stack.
  auto m = [&](int i, int j) { return M[i + n * j]; };
  double zp[n], wp[n], R[n], s[n];
  bool moved = false;
  double q_norm = 0, m_max = 0, z_norm = 0;
  for (int i = 0; i < n; ++i) {
    zp[i] = std::min(std::max(z[i], 0.0), kInf);
    moved = moved || !(zp[i] == z[i]);
    q_norm = std::max(q_norm, std::abs(q[i]));
    z_norm = std::max(z_norm, std::abs(zp[i]));
    for (int j = 0; j < n; ++j) m_max = std::max(m_max, std::abs(m(i, j)));
  }
  for (int i = 0; i < n; ++i) {
    double mz = 0, mzp = 0, abs_mz = 0, row_sum = 0;
    for (int j = 0; j < n; ++j) {
      mz += m(i, j) * z[j];
      mzp += m(i, j) * zp[j];
      abs_mz += std::abs(m(i, j)) * std::abs(zp[j]);
      row_sum += std::abs(m(i, j));
    }
    w[i] = mz + q[i];
    wp[i] = moved ? mzp + q[i] : w[i];
    R[i] = abs_mz + std::abs(q[i]);
    double row = row_sum * z_norm;  // w_units()
    if (m_max > 0 && q_norm > 0) row = std::min(row, (row_sum / m_max) * q_norm);
    s[i] = std::abs(q[i]) + row;
  }
  const double Z = z_unit_of(q_norm, m_max, z_norm);
  const double g = gamma_bound(n);
  bool finite = true;
  double natural = 0, bound = 0;
  for (int i = 0; i < n; ++i) {  // unit_free_residual() and bound_violation() of fill_common()
    finite = finite && std::isfinite(z[i]) && std::isfinite(wp[i]) && std::isfinite(R[i]) &&
             std::isfinite(s[i]);
    const RowValues v = row_values(zp[i], wp[i], R[i], s[i], 0.0, kInf, Z, g);
    double r = row_violation_of(v.wn, v.to_lower, v.to_upper);
    if (!std::isfinite(zp[i]) || !std::isfinite(wp[i]) || !std::isfinite(R[i]) ||
        !std::isfinite(s[i]) || std::isnan(r))
      r = kInf;
    natural = std::max(natural, r);
    double b = std::max(0.0, ratio(-z[i], Z));  // z_i below its bound 0
    if (std::isnan(b)) b = kInf;
    bound = std::max(bound, b);
  }
  natural = std::max(natural, bound);
  return finite ? natural : kInf;
}

}  // namespace

double small_lcp_natural(int n, const double* M, const double* q, const double* z, double* w) {
  switch (n) {
    case 1: return small_natural<1>(M, q, z, w);
    case 2: return small_natural<2>(M, q, z, w);
    case 3: return small_natural<3>(M, q, z, w);
    case 4: return small_natural<4>(M, q, z, w);
    default: return kInf;
  }
}

UnitFreePoint unit_free_point(const LcpProblem& p, const Vec& z, Vec& w) {
  w = p.w(z);
  const Vec zp = projected(z, nullptr, nullptr);
  const Vec wp = zp == z ? w : p.w(zp);
  return make_point(z, wp, candidate_units(p, zp), nullptr, nullptr);
}

UnitFreePoint unit_free_point(const BoxLcpProblem& p, const Vec& z, Vec& w) {
  w = p.lcp.w(z);
  const Vec zp = projected(z, &p.lower, &p.upper);
  const Vec wp = zp == z ? w : p.lcp.w(zp);
  return make_point(z, wp, candidate_units(p.lcp, zp), &p.lower, &p.upper);
}

Residuals lcp_residuals(const LcpProblem& p, const Vec& z, Vec& w) {
  w = p.w(z);
  const Vec zp = projected(z, nullptr, nullptr);
  const Vec wp = zp == z ? w : p.w(zp);
  Residuals r;
  fill_common(r, z, zp, wp, candidate_units(p, zp), nullptr, nullptr);
  r.min_w = w.size() ? w.minCoeff() : 0.0;
  const Eigen::Index n = z.size();
  r.natural_abs = n ? z.cwiseMin(w).cwiseAbs().maxCoeff() : 0.0;
  if (n && z.cwiseMin(w).hasNaN()) r.natural_abs = std::numeric_limits<double>::quiet_NaN();
  r.complementarity = n ? z.cwiseProduct(w).cwiseAbs().maxCoeff() : 0.0;
  return r;
}

Residuals box_lcp_residuals(const BoxLcpProblem& p, const Vec& z, Vec& w) {
  w = p.lcp.w(z);
  const Vec zp = projected(z, &p.lower, &p.upper);
  const Vec wp = zp == z ? w : p.lcp.w(zp);
  Residuals r;
  fill_common(r, z, zp, wp, candidate_units(p.lcp, zp), &p.lower, &p.upper);
  r.natural_abs = box_natural_abs(z, w, p.lower, p.upper);
  r.complementarity = box_complementarity(z, w, p.lower, p.upper);
  r.min_z = box_margin(z, p.lower, p.upper);
  r.min_w = box_sign_error(z, w, p.lower, p.upper);
  return r;
}

namespace {

// The MCP's Jacobian at x: the callback, else forward differences. False when unavailable.
bool mcp_jacobian(const McpProblem& p, const Vec& x, const Vec& F, LcpProblem& lin) {
  const Eigen::Index n = p.size();
  if (p.sparse_jacobian) {
    SparseMat J;
    if (!p.sparse_jacobian(x, J) || J.rows() != n || J.cols() != n) return false;
    lin.M_sparse = J;
    return true;
  }
  Mat J(n, n);
  if (p.jacobian) {
    if (!p.jacobian(x, J) || J.rows() != n || J.cols() != n) return false;
    lin.M = J;
    return true;
  }
  // Forward differences with steps relative to x's own size.
  const double xn = n ? x.lpNorm<Eigen::Infinity>() : 0.0;
  Vec xp = x, Fp(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double ref = x[j] != 0 ? std::abs(x[j]) : (xn > 0 ? xn : 1.0);
    const double h = std::sqrt(kEps) * ref;
    xp[j] = x[j] + h;
    if (!p.F(xp, Fp) || Fp.size() != n || !Fp.allFinite()) return false;
    J.col(j) = (Fp - F) / (xp[j] - x[j]);
    xp[j] = x[j];
  }
  lin.M = J;
  return true;
}

}  // namespace

Residuals mcp_residuals(const McpProblem& p, const Vec& x, const Vec& F) {
  const Eigen::Index n = x.size();
  // Judge F at the projection of x onto its box (F evaluated again there when x is outside).
  const Vec xp = projected(x, &p.lower, &p.upper);
  Vec Fp = F;
  bool have_Fp = true;
  if (!(xp == x)) have_Fp = p.F(xp, Fp) && Fp.size() == n && Fp.allFinite();
  if (!have_Fp) Fp = Vec::Constant(n, kInf);
  LcpProblem lin;
  CandidateUnits c;
  if (have_Fp && mcp_jacobian(p, xp, Fp, lin) && (lin.is_sparse() || lin.M.allFinite())) {
    lin.q = Fp - (lin.is_sparse() ? Vec(lin.M_sparse * xp) : Vec(lin.M * xp));
    c = candidate_units(lin, xp);
  } else {
    // No usable Jacobian: F's own size, row by row and as a whole, and x's own size.
    c.R = Fp.cwiseAbs();
    c.s = Fp.cwiseAbs().array() + (n ? Fp.lpNorm<Eigen::Infinity>() : 0.0);
    c.Z = n ? xp.lpNorm<Eigen::Infinity>() : 0.0;
  }
  Residuals r;
  fill_common(r, x, xp, Fp, c, &p.lower, &p.upper);
  r.natural_abs = box_natural_abs(x, F, p.lower, p.upper);
  r.complementarity = box_complementarity(x, F, p.lower, p.upper);
  r.min_z = box_margin(x, p.lower, p.upper);
  r.min_w = box_sign_error(x, F, p.lower, p.upper);
  return r;
}

}  // namespace cpkit
