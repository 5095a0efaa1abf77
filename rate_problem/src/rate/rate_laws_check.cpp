// The N-point rate laws checked from the data (rate_laws_check.hpp).
#include "rate_laws_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cpkit::rate::detail {
namespace {

/// |v| relative to s (0 when both are 0; inf for a non-finite v).
double rel0(double v, double s) {
  if (!std::isfinite(v)) return std::numeric_limits<double>::infinity();
  return v == 0 ? 0.0 : std::abs(v) / std::max(s, std::numeric_limits<double>::min());
}
/// Violation of v >= 0 relative to s.
double neg(double v, double s) { return v >= 0 ? 0.0 : rel0(v, s); }

}  // namespace

double rate_laws_violation(const ContactSystem& S, const Eigen::VectorXd& dF,
                           const Eigen::VectorXd& x, const std::vector<SolutionType>& types,
                           double sF, double sW) {
  const int N = S.n_points();
  if (x.size() != 6 * N || dF.size() != 2 * N || static_cast<int>(types.size()) != N ||
      !x.allFinite())
    return std::numeric_limits<double>::infinity();
  auto dPT = [&](int i) { return x(i); };
  auto dPN = [&](int i) { return x(N + i); };
  auto dwT = [&](int i) { return x(2 * N + i); };
  auto dwN = [&](int i) { return x(3 * N + i); };
  auto dwTi = [&](int i) { return x(4 * N + i); };
  auto dww = [&](int i) { return x(5 * N + i); };
  Eigen::VectorXd dP(2 * N), dw(2 * N);
  for (int i = 0; i < N; ++i) {
    dP(2 * i) = dPT(i);
    dP(2 * i + 1) = dPN(i);
    dw(2 * i) = dwT(i);
    dw(2 * i + 1) = dwN(i);
  }
  double v = 0;
  // Equilibrium, each row relative to its terms; a floor of 1e-6 of the scales keeps rows
  // whose terms are all rounding noise from judging that noise against itself.
  const Eigen::VectorXd res = dF - dP - S.A * dw;
  const Eigen::VectorXd terms = dF.cwiseAbs() + dP.cwiseAbs() + S.A.cwiseAbs() * dw.cwiseAbs();
  const Eigen::VectorXd rowA = S.A.cwiseAbs().rowwise().sum();
  for (int r = 0; r < 2 * N; ++r)
    v = std::max(v, rel0(res(r), terms(r) + 1e-6 * (sF + rowA(r) * sW)));
  for (int i = 0; i < N; ++i) {
    const SystemPoint& P = S.points[static_cast<std::size_t>(i)];
    const ContactParameters par = S.point_parameters(i);
    // kinematics (27): dw_T = C_T dP_T + dw_Ti
    v = std::max(v, rel0(dwT(i) - P.C_T * dPT(i) - dwTi(i),
                         std::abs(dwT(i)) + P.C_T * std::abs(dPT(i)) + std::abs(dwTi(i)) + 1e-6 * sW));
    const SolutionType t = types[static_cast<std::size_t>(i)];
    const double fsum = std::max(sF, std::abs(dPT(i)) + P.mu * std::abs(dPN(i)));
    const bool slip = t == SolutionType::kSlipPlus || t == SolutionType::kSlipMinus;
    const double s = t == SolutionType::kSlipPlus ? 1.0 : -1.0;
    switch (P.state.label) {
      case StateLabel::kA:
        if (t != SolutionType::kOpen) return std::numeric_limits<double>::infinity();
        v = std::max({v, rel0(dPT(i), sF), rel0(dPN(i), sF), rel0(dwTi(i) - dwT(i), sW),
                      rel0(dww(i), sW)});
        break;
      case StateLabel::kB:
        v = std::max(v, rel0(dww(i), sW));
        if (t == SolutionType::kSeparation) {
          v = std::max({v, rel0(dPT(i), sF), rel0(dPN(i), sF), neg(-dwN(i), sW)});
        } else if (t == SolutionType::kStick) {
          v = std::max({v, rel0(dwN(i), sW), rel0(dwTi(i), sW), neg(dPN(i), sF),
                        neg(P.mu * dPN(i) - std::abs(dPT(i)), fsum)});
        } else if (slip) {
          v = std::max({v, rel0(dwN(i), sW), neg(dPN(i), sF), rel0(s * dPT(i) - P.mu * dPN(i), fsum),
                        neg(s * dwTi(i), sW)});
        } else {
          return std::numeric_limits<double>::infinity();
        }
        break;
      case StateLabel::kC:
        if (t != SolutionType::kStick) return std::numeric_limits<double>::infinity();
        v = std::max({v, rel0(dwN(i), sW), rel0(dwTi(i), sW), rel0(dww(i), sW)});
        break;
      case StateLabel::kD: {
        const double sg = P.state.sgn_PT;
        const double kappa = par.kappa(P.state.P_N);
        const double mu_eff = S.criterion == Criterion::kSoftening ? P.mu - 2.0 * kappa : P.mu;
        const double fs = std::max(sF, std::abs(dPT(i)) + std::abs(mu_eff) * std::abs(dPN(i)));
        if (t == SolutionType::kStick) {
          v = std::max({v, rel0(dwN(i), sW), rel0(dwTi(i), sW), rel0(dww(i), sW),
                        neg(mu_eff * dPN(i) - sg * dPT(i), fs)});
        } else if (slip && s == sg) {
          const double lambda = sg * dwTi(i);
          v = std::max({v, neg(lambda, sW), rel0(dwN(i) - kappa * lambda, std::abs(dwN(i)) + kappa * std::abs(lambda) + 1e-6 * sW),
                        rel0(dww(i) - kappa * lambda, std::abs(dww(i)) + kappa * std::abs(lambda) + 1e-6 * sW),
                        rel0(mu_eff * dPN(i) - sg * dPT(i), fs)});
        } else {
          return std::numeric_limits<double>::infinity();
        }
        break;
      }
    }
  }
  return v;
}

}  // namespace cpkit::rate::detail
