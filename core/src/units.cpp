#include "cpkit/core/units.hpp"

#include <cmath>

namespace cpkit {
namespace {

// Exponent e with |x| in [2^e, 2^(e+1)), 0 for x = 0.
int exponent_of(double x) { return x > 0 && std::isfinite(x) ? std::ilogb(x) : 0; }

}  // namespace

LcpUnits natural_units(const LcpProblem& p) {
  const double qn = p.q.size() ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  const double mn = p.max_abs_entry();
  LcpUnits u;
  if (qn > 0) {
    u.w_exponent = exponent_of(qn);
    u.z_exponent = mn > 0 ? exponent_of(qn) - exponent_of(mn) : 0;
  } else {
    u.w_exponent = exponent_of(mn);
    u.z_exponent = 0;
  }
  return u;
}

namespace {

int column_exponent(const LcpUnits& u, Eigen::Index j) {
  return u.z_exponent + (u.z_columns.size() ? u.z_columns[j] : 0);
}
int row_exponent(const LcpUnits& u, Eigen::Index i) {
  return u.w_exponent + (u.w_rows.size() ? u.w_rows[i] : 0);
}

}  // namespace

LcpUnits equilibrated_units(const LcpProblem& p) {
  LcpUnits u = natural_units(p);
  const Eigen::Index n = p.size();
  u.z_columns = Eigen::VectorXi::Zero(n);
  u.w_rows = Eigen::VectorXi::Zero(n);
  // Visits every stored entry (i, j, M_ij) without densifying sparse storage.
  auto for_each_entry = [&p](auto&& f) {
    if (p.is_sparse()) {
      for (Eigen::Index k = 0; k < p.M_sparse.outerSize(); ++k)
        for (SparseMat::InnerIterator it(p.M_sparse, k); it; ++it) f(it.row(), it.col(), it.value());
    } else {
      for (Eigen::Index j = 0; j < p.M.cols(); ++j)
        for (Eigen::Index i = 0; i < p.M.rows(); ++i) f(i, j, p.M(i, j));
    }
  };
  // Columns of M 2^(z - w): largest entry brought to [1, 2).
  Vec col_max = Vec::Zero(n);
  for_each_entry([&](Eigen::Index, Eigen::Index j, double v) { col_max[j] = std::max(col_max[j], std::abs(v)); });
  for (Eigen::Index j = 0; j < n; ++j)
    if (col_max[j] > 0 && std::isfinite(col_max[j]))
      u.z_columns[j] = -(exponent_of(col_max[j]) + u.z_exponent - u.w_exponent);
  // Rows of [M~ q~] with the new columns: largest entry brought to [1, 2).
  Vec row_max(n);
  for (Eigen::Index i = 0; i < n; ++i) row_max[i] = std::ldexp(std::abs(p.q[i]), -u.w_exponent);
  for_each_entry([&](Eigen::Index i, Eigen::Index j, double v) {
    row_max[i] = std::max(row_max[i], std::ldexp(std::abs(v), column_exponent(u, j) - u.w_exponent));
  });
  for (Eigen::Index i = 0; i < n; ++i)
    if (row_max[i] > 0 && std::isfinite(row_max[i])) u.w_rows[i] = exponent_of(row_max[i]);
  return u;
}

LcpProblem to_units(const LcpProblem& p, const LcpUnits& u) {
  LcpProblem s;
  // M~_ij = M_ij 2^(zc_j - wr_i); q~_i = q_i 2^-wr_i (exact: powers of two).
  if (p.is_sparse()) {
    s.M_sparse = p.M_sparse;
    for (Eigen::Index k = 0; k < s.M_sparse.outerSize(); ++k)
      for (SparseMat::InnerIterator it(s.M_sparse, k); it; ++it)
        it.valueRef() = std::ldexp(it.value(), column_exponent(u, it.col()) - row_exponent(u, it.row()));
  } else {
    s.M = p.M;
    for (Eigen::Index j = 0; j < p.M.cols(); ++j)
      for (Eigen::Index i = 0; i < p.M.rows(); ++i)
        s.M(i, j) = std::ldexp(p.M(i, j), column_exponent(u, j) - row_exponent(u, i));
  }
  s.q.resize(p.q.size());
  for (Eigen::Index i = 0; i < p.q.size(); ++i) s.q[i] = std::ldexp(p.q[i], -row_exponent(u, i));
  s.name = p.name;
  s.note = p.note;
  return s;
}

BoxLcpProblem to_units(const BoxLcpProblem& p, const LcpUnits& u) {
  BoxLcpProblem s;
  s.lcp = to_units(p.lcp, u);
  s.lower = z_to_units(p.lower, u);
  s.upper = z_to_units(p.upper, u);
  return s;
}

Vec z_from_units(const Vec& z_scaled, const LcpUnits& u) {
  Vec z(z_scaled.size());
  for (Eigen::Index j = 0; j < z.size(); ++j) z[j] = std::ldexp(z_scaled[j], column_exponent(u, j));
  return z;
}
Vec z_to_units(const Vec& z, const LcpUnits& u) {
  Vec s(z.size());
  for (Eigen::Index j = 0; j < z.size(); ++j) s[j] = std::ldexp(z[j], -column_exponent(u, j));
  return s;
}

}  // namespace cpkit
