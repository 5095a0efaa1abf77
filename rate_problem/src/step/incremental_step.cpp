#include "cpkit/rate_problem/step/incremental_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

double StepProblem::wear_coefficient() const noexcept {
  return wear.law == WearLaw::kArchard ? params.k() : wear.k_M * params.mu;
}

double StepProblem::softening() const noexcept {
  return params.criterion == Criterion::kSoftening ? params.k() : 0.0;
}

std::string StepProblem::validate() const {
  std::string m = params.validate();
  if (!m.empty()) return m;
  std::ostringstream msg;
  if (!std::isfinite(wear.k_M) || wear.k_M < 0) {
    msg << "k_M = " << wear.k_M << ": the Mroz-Stupkiewicz wear constant must be finite and >= 0";
    return msg.str();
  }
  if (wear.law == WearLaw::kMrozStupkiewicz && params.criterion == Criterion::kSoftening) {
    return "the Mroz-Stupkiewicz wear law (41) is supported only with the Coulomb criterion "
           "(38); the softening criterion (35) derives its own (Archard) wear law";
  }
  const double vals[] = {state.P_T0, state.P_N0, state.g0, load.dF_T, load.dF_N};
  const char* names[] = {"P_T0", "P_N0", "g0", "dF_T", "dF_N"};
  for (int i = 0; i < 5; ++i) {
    if (!std::isfinite(vals[i])) {
      msg << names[i] << " = " << vals[i] << " is not finite";
      return msg.str();
    }
  }
  const double fscale =
      std::max({std::abs(state.P_T0), std::abs(state.P_N0), std::abs(load.dF_T),
                std::abs(load.dF_N), 1e-300});
  const double tol = 1e-10;
  if (state.P_N0 < -tol * fscale) {
    msg << "P_N0 = " << state.P_N0 << " < 0: the normal contact force must be >= 0";
    return msg.str();
  }
  const double gscale = std::abs(state.g0) + fscale * (params.a11 + params.a22) / params.detA();
  if (state.g0 > tol * gscale) {
    msg << "g0 = " << state.g0 << " > 0: the gap function w_N - w^w must be <= 0 (no penetration)";
    return msg.str();
  }
  if (state.g0 < -tol * gscale && state.P_N0 > tol * fscale) {
    msg << "P_N0 = " << state.P_N0 << " > 0 with an open gap g0 = " << state.g0
        << ": the state violates P_N0 g0 = 0 (Signorini)";
    return msg.str();
  }
  const double Y = yield(std::max(state.P_N0, 0.0));
  if (std::abs(state.P_T0) > Y + tol * fscale) {
    msg << "|P_T0| = " << std::abs(state.P_T0) << " exceeds the yield limit "
        << (params.criterion == Criterion::kSoftening ? "mu P_N0 - k P_N0^2 (35)"
                                                       : "mu P_N0 (38)")
        << " = " << Y << ": the start state is not admissible";
    if (params.criterion == Criterion::kSoftening && state.P_N0 * params.k() > params.mu)
      msg << " (condition (46) P_N0 <= 3 P_s mu / k_a fails)";
    return msg.str();
  }
  return {};
}

Eigen::Vector3d StepNcp::F(const Eigen::Vector3d& z) const noexcept {
  Eigen::Vector3d f = M * z + q;
  f[0] += c * z[0] * (z[1] + z[2]);
  const double s = d * z[0] * z[0];
  f[1] -= s;
  f[2] -= s;
  return f;
}

Eigen::Matrix3d StepNcp::jacobian(const Eigen::Vector3d& z) const noexcept {
  Eigen::Matrix3d J = M;
  J(0, 0) += c * (z[1] + z[2]);
  J(0, 1) += c * z[0];
  J(0, 2) += c * z[0];
  J(1, 0) -= 2 * d * z[0];
  J(2, 0) -= 2 * d * z[0];
  return J;
}

double StepNcp::residual(const Eigen::Vector3d& z) const noexcept {
  const Eigen::Vector3d f = F(z);
  Eigen::Vector3d terms = M.cwiseAbs() * z.cwiseAbs();
  terms[0] += std::abs(c * z[0] * (z[1] + z[2]));
  terms[1] += std::abs(d * z[0] * z[0]);
  terms[2] += std::abs(d * z[0] * z[0]);
  const double scale = 1.0 + std::max(q.cwiseAbs().maxCoeff(), terms.maxCoeff());
  double nat = 0;
  for (int i = 0; i < 3; ++i) nat = std::max(nat, std::abs(std::min(z[i], f[i])));
  if (!std::isfinite(nat)) return INFINITY;
  return nat / scale;
}

StepNcp build_step_ncp_unchecked(const StepProblem& p) noexcept {
  const ContactParameters& a = p.params;
  const double detA = a.detA(), D0 = a.D0(), e = 1 + a.a11 * a.C_T;
  StepNcp n;
  n.M << e, a.a12, -a.a12,                 //
      a.mu * D0 - a.a12, detA, -detA,      //
      a.mu * D0 + a.a12, -detA, detA;
  const double r1 = -D0 * p.state.P_T0 + a.a12 * p.state.P_N0 - a.a22 * p.load.dF_T +
                    a.a12 * p.load.dF_N;
  n.q << -D0 * p.state.g0 - e * (p.state.P_N0 + p.load.dF_N) + a.a12 * a.C_T * p.load.dF_T, r1,
      -r1;
  n.c = D0 * p.wear_coefficient();
  n.d = D0 * p.softening();
  return n;
}

StepNcp build_step_ncp(const StepProblem& p) {
  throw_if_invalid(p.validate(), "step");
  return build_step_ncp_unchecked(p);
}

McpProblem step_as_mcp(const StepProblem& p) {
  const StepNcp ncp = build_step_ncp(p);
  auto F = [ncp](const Vec& x, Vec& f) {
    if (x.size() != 3) return false;
    const Eigen::Vector3d z(x[0], x[1], x[2]);
    f = ncp.F(z);
    return f.allFinite();
  };
  auto J = [ncp](const Vec& x, Mat& j) {
    if (x.size() != 3) return false;
    const Eigen::Vector3d z(x[0], x[1], x[2]);
    j = ncp.jacobian(z);
    return j.allFinite();
  };
  McpProblem m = make_ncp(3, F, J, "incremental step");
  // Start from the state: P_N1 = P_N0, no slip.
  m.x0 = Vec::Zero(3);
  m.x0[0] = p.state.P_N0;
  return m;
}

LcpProblem step_as_lcp(const StepProblem& p) {
  const StepNcp ncp = build_step_ncp(p);
  if (!ncp.is_lcp())
    throw InputError(
        "step_as_lcp: the step is an LCP only without wear (k_a = 0 / k_M = 0) and without the "
        "softening term (criterion (38) or k_a = 0)");
  return LcpProblem(Mat(ncp.M), Vec(ncp.q), "incremental step (LCP)");
}

StepValues step_values(const StepProblem& p, double DP_N, double xi) noexcept {
  const ContactParameters& a = p.params;
  const double detA = a.detA(), D0 = a.D0(), e = 1 + a.a11 * a.C_T;
  const double S = e * p.load.dF_N - a.a12 * a.C_T * p.load.dF_T;
  StepValues v;
  v.DP_N = DP_N;
  v.DP_T = (a.a22 * p.load.dF_T - a.a12 * p.load.dF_N + a.a12 * DP_N - detA * xi) / D0;
  v.Dw_T = a.C_T * v.DP_T + xi;
  v.Dw_N = (S - e * DP_N - a.a12 * xi) / D0;
  v.Dw_Ti = xi;
  v.P_N1 = p.state.P_N0 + DP_N;
  v.P_T1 = p.state.P_T0 + v.DP_T;
  v.Dw_w = p.wear_coefficient() * std::max(v.P_N1, 0.0) * std::abs(xi);
  v.g1 = p.state.g0 + v.Dw_N - v.Dw_w;
  return v;
}

Eigen::Vector3d step_unknowns(const StepValues& v) noexcept {
  return Eigen::Vector3d(v.P_N1, std::max(v.Dw_Ti, 0.0), std::max(-v.Dw_Ti, 0.0));
}

bool step_started_open(const StepProblem& p) noexcept {
  const ContactParameters& a = p.params;
  const double fscale = std::max({std::abs(p.state.P_T0), std::abs(p.state.P_N0),
                                  std::abs(p.load.dF_T), std::abs(p.load.dF_N),
                                  std::numeric_limits<double>::min()});
  const double comp = (a.a11 + a.a22) / a.detA() + a.C_T;
  return p.state.g0 < -1e-9 * (std::abs(p.state.g0) + fscale * comp);
}

SolutionType classify_step(const StepProblem& p, const StepValues& v) noexcept {
  // Every test compares a quantity with the magnitudes of the terms it is made of (unit-free:
  // the same verdict in any units, whatever the conditioning of A).
  const ContactParameters& a = p.params;
  const double tol = 1e-9;
  const bool started_open = step_started_open(p);
  // Displacements of this solution, or what its forces move the stiffest direction by.
  const double forces = std::abs(v.DP_T) + std::abs(v.DP_N) + std::abs(p.load.dF_T) +
                        std::abs(p.load.dF_N);
  const double dscale = std::max({std::abs(v.Dw_T), std::abs(v.Dw_N), std::abs(v.Dw_Ti),
                                  std::abs(p.state.g0), std::abs(a.C_T * v.DP_T),
                                  forces / (a.a11 + a.a22)});
  const double Pt = std::abs(p.state.P_N0) + std::abs(v.DP_N);
  if (v.P_N1 <= tol * Pt) {
    if (started_open) return SolutionType::kOpen;
    if (v.g1 < -tol * (std::abs(p.state.g0) + std::abs(v.Dw_N) + std::abs(v.Dw_w)))
      return SolutionType::kSeparation;
  }
  if (std::abs(v.Dw_Ti) <= tol * dscale) return SolutionType::kStick;
  return v.Dw_Ti > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
}

}  // namespace cpkit::rate
