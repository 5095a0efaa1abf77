// The verdict on frictional contact candidates (friction_verdict.hpp).
#include "cpkit/core/friction_verdict.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

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
  const Eigen::Index n = p.q.size();
  d.q_inf = n ? p.q.lpNorm<Eigen::Infinity>() : 0.0;
  d.abs_W = p.W.cwiseAbs();
  d.row_sums = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < d.abs_W.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(d.abs_W, k); it; ++it) {
      d.row_sums[it.row()] += it.value();
      count[it.row()] += 1;
      d.w_max = std::max(d.w_max, it.value());
    }
  d.row_gamma.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) d.row_gamma[k] = gamma_bound(count[k] + 1);
  return d;
}

Residuals friction_residuals(const FrictionContactProblem& p, const FrictionUnits& d,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             FrictionErrors* errors, std::vector<ContactReport>* contacts) {
  if (contacts) contacts->assign(static_cast<std::size_t>(p.contacts()), ContactReport{});
  const Eigen::Index nc = p.contacts();
  Residuals res;
  res.finite = r.allFinite() && u.allFinite();
  const double r_inf = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
  const bool has_ref = d.q_inf > 0 && d.w_max > 0;
  // R = max(||r||, r_ref); r_ref may overflow to inf (then nothing is small).
  const double R = has_ref ? std::max(r_inf, d.q_inf / d.w_max) : r_inf;
  const Eigen::VectorXd Wr_abs = d.abs_W * r.cwiseAbs();
  res.z_scale = R;
  res.worst_index = nc ? 0 : -1;
  res.min_z = kInf;
  res.min_w = kInf;
  double abs_sq = 0;
  for (Eigen::Index i = 0; i < nc; ++i) {
    const double mu = p.mu[i];
    const Vec3 ri = r.segment<3>(3 * i), ui = u.segment<3>(3 * i);
    double c_max = 0, s_N = 0;
    Vec3 a;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Index k = 3 * i + j;
      // c_k = ||W_k||_1 min(||r||, r_ref), the cap written as a ratio so it cannot overflow.
      double c = d.row_sums[k] * r_inf;
      if (has_ref) c = std::min(c, (d.row_sums[k] / d.w_max) * d.q_inf);
      c_max = std::max(c_max, c);
      if (j == 0) s_N = std::abs(p.q[k]) + c;
      a[j] = d.row_gamma[k] * (Wr_abs[k] + std::abs(p.q[k]));
    }
    const double S = p.q.segment<3>(3 * i).norm() + c_max;
    res.scale = std::max(res.scale, S);

    // The cone law in unit-free variables, less what rounding of u_i can change in it.
    Vec3 rn, un;
    for (int j = 0; j < 3; ++j) {
      rn[j] = ratio(ri[j], R);
      un[j] = ratio(ui[j], S);
    }
    const double allowance = (1 + mu) * ratio(a.norm(), S);
    const double cone = std::max(0.0, natural_map(rn, un, mu).norm() - allowance);
    // Signorini on the normal row, in that row's own units (the LCP rule).
    const double excess = std::max(0.0, std::abs(ui[0]) - a[0]);
    const double wn = excess > 0 ? std::copysign(ratio(excess, s_N), ui[0]) : 0.0;
    const double normal = std::abs(std::min(rn[0], wn));
    double v = std::max(cone, normal);
    if (std::isnan(v) || !ri.allFinite() || !ui.allFinite() || !std::isfinite(S) ||
        !a.allFinite())
      v = kInf;
    if (contacts) {
      ContactReport& c = (*contacts)[static_cast<std::size_t>(i)];
      c.error = v;
      const double margin = mu * rn[0] - rn.tail<2>().norm();
      c.state = rn[0] < wn ? ContactState::kSeparated
                : margin >= un.tail<2>().norm() ? ContactState::kStick
                                                : ContactState::kSlip;
    }
    if (v > res.natural) {
      res.natural = v;
      res.worst_index = 3 * i;
    }
    res.rounding = std::max(res.rounding, allowance);

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

const char* to_string(ContactState s) noexcept {
  switch (s) {
    case ContactState::kSeparated: return "separated";
    case ContactState::kStick: return "stick";
    case ContactState::kSlip: return "slip";
  }
  return "?";
}

std::vector<ContactReport> friction_contacts(const FrictionContactProblem& p,
                                             const Eigen::VectorXd& r) {
  check_sizes(p, r);
  std::vector<ContactReport> out;
  friction_residuals(p, friction_units(p), r, p.W * r + p.q, nullptr, &out);
  return out;
}

FrictionErrors friction_errors(const FrictionContactProblem& p, const Eigen::VectorXd& r) {
  check_sizes(p, r);
  const Eigen::VectorXd u = p.W * r + p.q;
  FrictionErrors e;
  friction_residuals(p, friction_units(p), r, u, &e);
  return e;
}

SolveResult finalize(const FrictionContactProblem& p, SolveResult claim,
                     const CommonOptions& options) {
  throw_if_invalid(p.validate(), "friction problem" + (p.name.empty() ? "" : " '" + p.name + "'"));
  const bool claimed_solution = is_solution(claim.status);
  if (detail::refuse_infeasibility(claim, "a friction problem") ||
      !detail::usable_point(claim, p.q.size(), claimed_solution))
    return claim;
  claim.w = p.W * claim.z + p.q;
  claim.residuals = friction_residuals(p, friction_units(p), claim.z, claim.w);
  detail::decide(claim, claimed_solution, options);
  return claim;
}

}  // namespace cpkit
