// check_certificate(): a Farkas proof y >= 0, M^T y <= 0, q^T y < 0 re-checked from the data,
// exactly where double precision allows it (finalize.hpp has the contract).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "cpkit/core/finalize.hpp"
#include "exact_dot.hpp"

namespace cpkit {
namespace {

struct Evaluation {
  bool exact = false;     // every sign proven
  bool rounding = false;  // holds within componentwise rounding
  double q_dot_y = 0;
  double max_MTy = 0;
};

double gamma_bound(Eigen::Index n) {
  const double ku = static_cast<double>(n + 1) * std::numeric_limits<double>::epsilon() / 2;
  return ku < 0.5 ? ku / (1 - ku) : std::numeric_limits<double>::infinity();
}

Evaluation evaluate(const LcpProblem& p, const Vec& y) {
  const Eigen::Index n = p.size();
  const double g = gamma_bound(n);
  Evaluation e;
  detail::ExactDot acc;
  bool decided = false;
  double a = 0;  // |q|^T y
  for (Eigen::Index i = 0; i < n; ++i) {
    acc.add_product(p.q[i], y[i]);
    a += std::abs(p.q[i]) * y[i];
  }
  e.q_dot_y = acc.value();
  const int qs = acc.sign(decided);
  bool exact = decided && qs < 0;
  bool rounding = decided && qs < 0 && e.q_dot_y < -g * a;
  e.max_MTy = -std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < n; ++j) {
    acc.clear();
    a = 0;
    if (p.is_sparse()) {
      for (SparseMat::InnerIterator it(p.M_sparse, j); it; ++it) {
        acc.add_product(it.value(), y[it.row()]);
        a += std::abs(it.value()) * y[it.row()];
      }
    } else {
      for (Eigen::Index i = 0; i < n; ++i) {
        acc.add_product(p.M(i, j), y[i]);
        a += std::abs(p.M(i, j)) * y[i];
      }
    }
    const int s = acc.sign(decided);
    const double v = acc.value();
    e.max_MTy = std::max(e.max_MTy, v);
    if (!decided || s > 0) exact = false;
    if (!std::isfinite(a) || !std::isfinite(v) || !(v <= g * a)) rounding = false;
  }
  e.exact = exact;
  e.rounding = rounding;
  return e;
}

// Scales y by a power of two (exactly) so that ||y||_inf lies in [1, 2).
Vec power_of_two_normalised(const Vec& y) {
  const int e = std::ilogb(y.maxCoeff());
  return y.unaryExpr([e](double v) { return std::ldexp(v, -e); });
}

// Best rational approximation p / q of x in [0, 1] with q <= max_den (continued fractions);
// false when none is within rel_tol.
bool rational(double x, std::int64_t max_den, double rel_tol, std::int64_t& num, std::int64_t& den) {
  std::int64_t p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double r = x;
  for (int k = 0; k < 64; ++k) {
    const double a = std::floor(r);
    if (a > 1e15) break;
    const auto ai = static_cast<std::int64_t>(a);
    const std::int64_t p2 = ai * p1 + p0, q2 = ai * q1 + q0;
    if (q2 > max_den) break;
    p0 = p1; q0 = q1; p1 = p2; q1 = q2;
    if (std::abs(x - static_cast<double>(p1) / static_cast<double>(q1)) <= rel_tol) {
      num = p1;
      den = q1;
      return true;
    }
    const double frac = r - a;
    if (frac <= 0) break;
    r = 1 / frac;
  }
  return false;
}

// y (normalised to max 1) snapped to integers with a common denominator; false when the
// entries are not all close to rationals of small denominators.
bool snapped(const Vec& y_normalised, Vec& out) {
  const Eigen::Index n = y_normalised.size();
  std::vector<std::int64_t> num(static_cast<size_t>(n)), den(static_cast<size_t>(n));
  std::int64_t lcm = 1;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!rational(y_normalised[i], 1 << 20, 1e-9, num[static_cast<size_t>(i)],
                  den[static_cast<size_t>(i)]))
      return false;
    lcm = std::lcm(lcm, den[static_cast<size_t>(i)]);
    if (lcm > (std::int64_t(1) << 40)) return false;
  }
  out.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
    out[i] = static_cast<double>(num[static_cast<size_t>(i)] * (lcm / den[static_cast<size_t>(i)]));
  return out.maxCoeff() > 0;
}

}  // namespace

bool check_certificate(const LcpProblem& p, Certificate& cert) {
  cert.checked = false;
  cert.exact = false;
  const Eigen::Index n = p.size();
  if (cert.y.size() != n || !cert.y.allFinite()) return false;
  const Vec y_plus = cert.y.cwiseMax(0.0);
  if (!(y_plus.maxCoeff() > 0)) return false;
  const Vec y = power_of_two_normalised(y_plus);
  Evaluation e = evaluate(p, y);
  cert.y = y;
  if (!e.exact) {
    Vec ys;
    if (snapped(y / y.maxCoeff(), ys)) {
      const Evaluation es = evaluate(p, ys);
      if (es.exact) {
        e = es;
        cert.y = power_of_two_normalised(ys);
      }
    }
  }
  cert.q_dot_y = e.q_dot_y;
  cert.max_MTy = e.max_MTy;
  cert.exact = e.exact;
  cert.checked = e.exact || e.rounding;
  return cert.checked;
}

}  // namespace cpkit
