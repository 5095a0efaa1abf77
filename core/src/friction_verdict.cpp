// The verdict on frictional contact candidates (friction_verdict.hpp).
#include "cpkit/core/friction_verdict.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_cone.hpp"
#include "finalize_decide.hpp"

namespace cpkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();

// gamma_k = k u / (1 - k u), u = eps / 2 [Higham 2002, Lemma 3.1].
double gamma_bound(double k) {
  const double ku = k * kEps / 2;
  return ku < 0.5 ? ku / (1 - ku) : kInf;
}

// a / s in the extended sense: s = 0 gives 0 for a = 0 and +-inf otherwise.
double ratio(double a, double s) {
  if (s > 0) return a / s;
  if (a == 0) return 0.0;
  return a > 0 ? kInf : -kInf;
}

// Siconos' normalisation: divide only when the norm exceeds DBL_EPSILON.
double siconos_relative(double error, double norm) {
  return std::abs(norm) > DBL_EPSILON ? error / norm : error;
}

void check_sizes(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
  if (r.size() != p.q.size())
    throw InputError("friction candidate r has " + std::to_string(r.size()) +
                     " entries, expected " + std::to_string(p.q.size()) + " (3 per contact)");
}

}  // namespace

FrictionUnits friction_units(const FrictionContactProblem& p) {
  FrictionUnits d;
  const Eigen::Index n = p.q.size(), nc = p.contacts();
  d.q_inf = n ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  d.row_sums = Eigen::VectorXd::Zero(n);
  d.block_max = Eigen::VectorXd::Zero(nc);
  // W read by columns (its own storage: no copy); each row's sum is still formed over its
  // columns in ascending order, as a row-by-row reading forms it.
  Eigen::VectorXd count = Eigen::VectorXd::Zero(n);
  for (Eigen::Index col = 0; col < p.W.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(p.W, col); it; ++it) {
      const Eigen::Index k = it.row();
      const double a = std::abs(it.value());
      d.row_sums[k] += a;
      count[k] += 1;
      d.w_max = std::max(d.w_max, a);
      if (col / 3 == k / 3) d.block_max[k / 3] = std::max(d.block_max[k / 3], a);
    }
  }
  d.row_gamma.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) d.row_gamma[k] = gamma_bound(count[k] + 1);
  const bool has_ref = d.q_inf > 0 && d.w_max > 0;
  const double r_ref = has_ref ? d.q_inf / d.w_max : kInf;
  d.r_cap = Eigen::VectorXd::Constant(nc, r_ref);
  for (Eigen::Index i = 0; i < nc; ++i) {
    if (!(d.block_max[i] > 0)) d.block_max[i] = d.w_max;
    if (has_ref && d.block_max[i] > 0)
      d.r_cap[i] = std::max(r_ref, p.q.segment<3>(3 * i).lpNorm<Eigen::Infinity>() / d.block_max[i]);
  }
  return d;
}

namespace {

// u_k = (W r)_k + q_k in twice the working precision (Dot2, Ogita, Rump & Oishi, SIAM J. Sci.
// Comput. 26(6), 2005, Alg. 5.3): error-free products (fma) and sums, so that its error is
// at most u |u_k| + gamma_{m+1}^2 ((|W||r|)_k + |q_k|) (their Prop. 5.5), not gamma (|W||r|)_k.
// Start with s = q_k, add the row's products in ascending column order, read sum().
struct Dot2 {
  double s = 0, c = 0;
  void add(double value, double x_col) {
    const double x = value * x_col;
    const double e = std::fma(value, x_col, -x);
    const double t = s + x, z = t - s;
    c += ((s - (t - z)) + (x - z)) + e;
    s = t;
  }
  double sum() const { return s + c; }
};

// What the verdict needs of row k of W at r: c_k = (|W| rc)_k (r capped at the data's size) and
// full_k = (|W| |r|)_k, each summed over the row's columns in ascending order.
struct RowSums {
  double c = 0, full = 0;
};

// W's rows as the verdict reads them, for a given r: sums(k), accurate(k) (u_k by Dot2, asked
// only where full_k > c_k), gamma(k) (row k's rounding factor gamma_{m_k+1}), block_max(i). Two
// readers: the general problem (W read by columns, its own storage) and one contact's dense
// 3 x 3 block (one_contact_unit_free); both sum every row in ascending column order, so that
// they give the same numbers bit for bit.
class ColumnReader {
 public:
  ColumnReader(const FrictionContactProblem& p, const FrictionUnits& d, const double* r)
      : d_(d), sums_(static_cast<std::size_t>(p.q.size())) {
    const Eigen::SparseMatrix<double>& W = p.W;
    bool beyond = false;  // some row with full > c
    for (Eigen::Index col = 0; col < W.outerSize(); ++col) {
      const double ar = std::abs(r[col]), rc = std::min(ar, d.r_cap[col / 3]);
      for (Eigen::SparseMatrix<double>::InnerIterator it(W, col); it; ++it) {
        RowSums& rs = sums_[static_cast<std::size_t>(it.row())];
        const double a = std::abs(it.value());
        rs.c += a * rc;
        rs.full += a * ar;
      }
      beyond = beyond || ar > rc;
    }
    if (!beyond) return;
    // The rows whose u_k the verdict forms accurately, all in one more pass over the columns.
    accurate_.resize(sums_.size());
    for (std::size_t k = 0; k < sums_.size(); ++k)
      if (sums_[k].full > sums_[k].c) accurate_[k].s = p.q[static_cast<Eigen::Index>(k)];
    for (Eigen::Index col = 0; col < W.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(W, col); it; ++it) {
        const auto k = static_cast<std::size_t>(it.row());
        if (sums_[k].full > sums_[k].c) accurate_[k].add(it.value(), r[col]);
      }
  }
  const RowSums& sums(Eigen::Index k) const { return sums_[static_cast<std::size_t>(k)]; }
  double accurate(Eigen::Index k) const { return accurate_[static_cast<std::size_t>(k)].sum(); }
  double gamma(Eigen::Index k) const { return d_.row_gamma[k]; }
  double block_max(Eigen::Index i) const { return d_.block_max[i]; }

 private:
  const FrictionUnits& d_;
  std::vector<RowSums> sums_;
  std::vector<Dot2> accurate_;
};

// What the verdict reads of one contact: its units, its velocity after the rounding allowance,
// and whether the allowance stayed within the data's size.
struct ContactReading {
  ContactUnits3 units;
  Vec3 u_reduced = Vec3::Zero();
  double rounding = 0;     // max_k a_k / s_k
  bool verifiable = true;  // false when u cannot be formed within the data's allowance
};

// Contact i of r (3 n_c entries), u = W r + q; q: the problem's q (3 n_c entries).
template <class Rows>
ContactReading read_contact(const Rows& rows, const double* q, Eigen::Index i, const double* r,
                            const double* u) {
  ContactReading cu;
  double c_max = 0;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Index k = 3 * i + j;
    const RowSums sums = rows.sums(k);
    const double c = sums.c, full = sums.full;  // (|W| rc)_k and (|W| |r|)_k
    const double qk = std::abs(q[k]);
    double a = rows.gamma(k) * (c + qk), uk = u[k];
    if (full > c) {  // some |r_j| beyond the data's size: form u_k accurately (header comment)
      uk = rows.accurate(k);
      const double g = rows.gamma(k);
      const double own = 2 * kEps * std::abs(uk) + g * g * (full + qk);
      if (g * g * (full + qk) > a) cu.verifiable = false;
      a += own;
    }
    c_max = std::max(c_max, c);
    const double s = qk + c;
    if (j == 0) cu.units.s_N = s;
    cu.u_reduced[j] = std::copysign(std::max(0.0, std::abs(uk) - a), uk);
    cu.rounding = std::max(cu.rounding, ratio(a, s));
  }
  cu.units.S = Eigen::Map<const Vec3>(q + 3 * i).norm() + c_max;
  // W = 0 (no d_i): r does not move u, and r_i is judged in its own size alone.
  const double r_own = Eigen::Map<const Vec3>(r + 3 * i).lpNorm<Eigen::Infinity>();
  const double d_i = rows.block_max(i);
  cu.units.R = d_i > 0 ? std::max(r_own, cu.units.S / d_i) : r_own;
  return cu;
}

}  // namespace

ContactReport judge_contact(const Vec3& r, const Vec3& u_reduced, const ContactUnits3& units,
                            double mu, double state_tol) {
  // The cone law in unit-free variables at the velocity rounding cannot tell from u.
  Vec3 rn, un;
  for (int j = 0; j < 3; ++j) {
    rn[j] = ratio(r[j], units.R);
    un[j] = ratio(u_reduced[j], units.S);
  }
  const double cone = natural_map(rn, un, mu).norm();
  // Signorini on the normal row, in that row's own units (the LCP rule). r_N counts as a force
  // by what it allows (mu r_N bounds r_T): at a huge mu a tiny r_N carrying a large r_T is a
  // contact, and then u_N must be 0.
  const double normal =
      std::abs(std::min(std::max(1.0, mu) * rn[0], ratio(u_reduced[0], units.s_N)));
  // Coulomb's bound |r_T| <= mu r_N read in r_T's units: the friction force beyond what the
  // normal force allows. For mu <= 1 this is at most sqrt(2) times the distance to the cone;
  // for a huge mu the distance (~|r_T| / mu) would excuse r_T != 0 at r_N = 0 (F4-04).
  const double excess = std::max(0.0, rn.tail<2>().norm() - mu * rn[0]);
  ContactReport c;
  c.error = std::max({cone, normal, excess});
  if (std::isnan(c.error) || !r.allFinite() || !u_reduced.allFinite() ||
      !std::isfinite(units.S) || !std::isfinite(units.R) || !std::isfinite(units.s_N))
    c.error = kInf;
  c.state = rn[0] <= state_tol                 ? ContactState::kSeparated
            : un.tail<2>().norm() <= state_tol ? ContactState::kStick
                                               : ContactState::kSlip;
  return c;
}

Residuals friction_residuals(const FrictionContactProblem& p, const FrictionUnits& d,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             FrictionErrors* errors, std::vector<ContactReport>* contacts,
                             double state_tol) {
  if (contacts) contacts->assign(static_cast<std::size_t>(p.contacts()), ContactReport{});
  const Eigen::Index nc = p.contacts();
  Residuals res;
  res.finite = r.allFinite() && u.allFinite();
  res.worst_index = nc ? 0 : -1;
  res.min_z = kInf;
  res.min_w = kInf;
  double abs_sq = 0;
  const ColumnReader rows(p, d, r.data());  // every row's sums at r, W read by columns
  for (Eigen::Index i = 0; i < nc; ++i) {
    const double mu = p.mu[i];
    const Vec3 ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
    const ContactReading cu = read_contact(rows, p.q.data(), i, r.data(), u.data());
    res.scale = std::max(res.scale, cu.units.S);
    res.z_scale = std::max(res.z_scale, cu.units.R);
    const ContactReport c = judge_contact(ri, cu.u_reduced, cu.units, mu, state_tol);
    const double v = cu.verifiable && ui.allFinite() ? c.error : kInf;
    if (contacts) (*contacts)[static_cast<std::size_t>(i)] = ContactReport{c.state, v};
    if (v > res.natural) {
      res.natural = v;
      res.worst_index = 3 * i;
    }
    res.rounding = std::max(res.rounding, cu.rounding);

    const Vec3 m = natural_map(ri, ui, mu);
    abs_sq += m.squaredNorm();
    res.natural_abs = std::max(res.natural_abs, m.norm());
    res.complementarity = std::max(res.complementarity, std::abs(ri.dot(de_saxce(ui, mu))));
    res.min_z = std::min(res.min_z, ri[0]);
    res.min_w = std::min(res.min_w, ui[0]);
  }
  if (!res.finite) res.natural = kInf;
  if (nc == 0) res.min_z = res.min_w = 0;
  if (errors) {
    const double E = std::sqrt(abs_sq);
    errors->unit_free = res.natural;
    errors->relative_q = siconos_relative(E, p.q.norm());
    errors->relative_max = siconos_relative(E, std::max({p.q.norm(), r.norm(), u.norm()}));
  }
  return res;
}

namespace {

// One contact's dense 3 x 3 W as the verdict reads it (ColumnReader's twin): every column is
// visited, the entries not stored being exact zeros, which change no sum when r is finite.
struct DenseRows {
  const Mat3& W;
  const double* r;
  const double* q;
  double row_gamma[3];
  double r_cap, d;
  RowSums sums(Eigen::Index k) const {
    RowSums rs;
    for (Eigen::Index j = 0; j < 3; ++j) {
      const double a = std::abs(W(k, j)), ar = std::abs(r[j]);
      rs.c += a * std::min(ar, r_cap);
      rs.full += a * ar;
    }
    return rs;
  }
  double accurate(Eigen::Index k) const {
    Dot2 u{q[k], 0};
    for (Eigen::Index j = 0; j < 3; ++j) u.add(W(k, j), r[j]);
    return u.sum();
  }
  double gamma(Eigen::Index k) const { return row_gamma[k]; }
  double block_max(Eigen::Index) const { return d; }
};

}  // namespace

double one_contact_unit_free(const Mat3& W, const int stored[3], const Vec3& q, double mu,
                             const Vec3& r, Vec3& u) {
  // u as finalize() forms W r + q: the row's products summed in column order, then q.
  for (int k = 0; k < 3; ++k) {
    double s = 0;
    for (int j = 0; j < 3; ++j) s += W(k, j) * r[j];
    u[k] = s + q[k];
  }
  if (!r.allFinite() || !u.allFinite()) return kInf;
  // The units of friction_units() for one contact (its block is all of W).
  DenseRows rows{W, r.data(), q.data(), {}, kInf, 0};
  double w_max = 0;
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) w_max = std::max(w_max, std::abs(W(k, j)));
    rows.row_gamma[k] = gamma_bound(static_cast<double>(stored[k]) + 1);
  }
  const double q_inf = q.lpNorm<Eigen::Infinity>();
  rows.d = w_max;
  if (q_inf > 0 && w_max > 0) rows.r_cap = q_inf / w_max;  // cap_0 = max(r_ref, q_inf / d) = r_ref
  const ContactReading cu = read_contact(rows, q.data(), 0, r.data(), u.data());
  const double v = cu.verifiable ? judge_contact(r, cu.u_reduced, cu.units, mu).error : kInf;
  return std::max(0.0, v);
}

const char* to_string(ContactState s) noexcept {
  switch (s) {
    case ContactState::kSeparated: return "separated";
    case ContactState::kStick: return "stick";
    case ContactState::kSlip: return "slip";
  }
  return "?";
}

std::vector<ContactReport> friction_contacts(const FrictionContactProblem& p,
                                             const Eigen::VectorXd& r, double tol) {
  check_sizes(p, r);
  std::vector<ContactReport> out;
  const FrictionUnits units = friction_units(p);
  const Eigen::VectorXd u = p.W * r + p.q;
  if (tol < 0) {  // the answer's own unit-free error (header comment)
    const double own = friction_residuals(p, units, r, u).natural;
    tol = std::isfinite(own) ? own : 0.0;
  }
  friction_residuals(p, units, r, u, nullptr, &out, tol);
  return out;
}

namespace {

FrictionErrors errors_checked(const FrictionContactProblem& p, const FrictionUnits& units,
                              const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = p.W * r + p.q;
  FrictionErrors e;
  friction_residuals(p, units, r, u, &e);
  return e;
}

}  // namespace

FrictionErrors friction_errors(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  check_sizes(p, r);
  return errors_checked(p, friction_units(p), r);
}

FrictionErrors friction_errors(const FrictionContactProblem& p, const FrictionUnits& units,
                               const Eigen::VectorXd& r) {
  check_sizes(p, r);
  return errors_checked(p, units, r);
}

namespace {

// finalize() once the problem is valid; units computed only when a point is judged.
template <class Units>
SolveResult finalize_valid(const FrictionContactProblem& p, Units units, SolveResult claim,
                           const CommonOptions& options) {
  const bool claimed_solution = is_solution(claim.status);
  claim.friction_errors.reset();
  if (detail::refuse_infeasibility(claim, "a friction problem") ||
      !detail::usable_point(claim, p.q.size(), claimed_solution))
    return claim;
  claim.w = p.W * claim.z + p.q;
  FrictionErrors errors;  // friction_errors()'s numbers: the same u, the same sums
  claim.residuals = friction_residuals(p, units(), claim.z, claim.w, &errors);
  claim.friction_errors = errors;
  detail::decide(claim, claimed_solution, options);
  return claim;
}

}  // namespace

SolveResult finalize(const FrictionContactProblem& p, SolveResult claim,
                     const CommonOptions& options) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
  return finalize_valid(p, [&] { return friction_units(p); }, std::move(claim), options);
}

SolveResult finalize(const FrictionContactProblem& p, const FrictionUnits& units,
                     SolveResult claim, const CommonOptions& options) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
  return finalize_valid(p, [&]() -> const FrictionUnits& { return units; }, std::move(claim),
                        options);
}

}  // namespace cpkit
