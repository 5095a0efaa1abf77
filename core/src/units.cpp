#include "cpkit/core/units.hpp"

#include <cmath>

namespace cpkit {
namespace {

// Exponent e with |x| in [2^e, 2^(e+1)), 0 for x = 0.
int exponent_of(double x) { return x > 0 && std::isfinite(x) ? std::ilogb(x) : 0; }

double max_abs_entry(const LcpProblem& p) {
  if (!p.is_sparse()) return p.M.size() ? p.M.cwiseAbs().maxCoeff() : 0.0;
  double m = 0;
  for (Eigen::Index k = 0; k < p.M_sparse.outerSize(); ++k)
    for (SparseMat::InnerIterator it(p.M_sparse, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

Vec scaled(const Vec& v, int e) {
  Vec r(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) r[i] = std::ldexp(v[i], e);
  return r;
}

}  // namespace

LcpUnits natural_units(const LcpProblem& p) {
  const double qn = p.q.size() ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  const double mn = max_abs_entry(p);
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

LcpProblem to_units(const LcpProblem& p, const LcpUnits& u) {
  LcpProblem s;
  const int em = u.z_exponent - u.w_exponent;  // M~ = M 2^(z - w): near 1 in magnitude
  if (p.is_sparse()) {
    s.M_sparse = p.M_sparse;
    for (Eigen::Index k = 0; k < s.M_sparse.outerSize(); ++k)
      for (SparseMat::InnerIterator it(s.M_sparse, k); it; ++it)
        it.valueRef() = std::ldexp(it.value(), em);
  } else {
    s.M = p.M.unaryExpr([em](double v) { return std::ldexp(v, em); });
  }
  s.q = scaled(p.q, -u.w_exponent);
  s.name = p.name;
  s.note = p.note;
  return s;
}

BoxLcpProblem to_units(const BoxLcpProblem& p, const LcpUnits& u) {
  BoxLcpProblem s;
  s.lcp = to_units(p.lcp, u);
  s.lower = scaled(p.lower, -u.z_exponent);
  s.upper = scaled(p.upper, -u.z_exponent);
  return s;
}

Vec z_from_units(const Vec& z_scaled, const LcpUnits& u) { return scaled(z_scaled, u.z_exponent); }
Vec z_to_units(const Vec& z, const LcpUnits& u) { return scaled(z, -u.z_exponent); }

}  // namespace cpkit
