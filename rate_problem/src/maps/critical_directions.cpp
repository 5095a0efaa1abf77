// Exact candidate critical directions of the rate problem (docs/model.md Sec. 2).
#include "critical_directions.hpp"

#include <algorithm>
#include <cmath>

namespace cpkit::rate {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kMergeTol = 1e-12;  // rad: directions closer than this are one direction
}  // namespace

double load_angle(const LoadRate& load) noexcept {
  double t = std::atan2(load.dF_N, load.dF_T);
  if (t < 0) t += kTwoPi;
  if (t >= kTwoPi) t -= kTwoPi;
  return t;
}

std::vector<LoadLinearForm> critical_linear_forms(const ContactParameters& p,
                                                  const ContactState& state) {
  std::vector<LoadLinearForm> forms;
  const double g = 1.0 + p.a11 * p.C_T;  // 1 + a11 C_T
  // The friction coefficient of the slip equations: mu for criterion (38); for the softening
  // criterion (35) in state d, mu_eff = mu - 2 kappa (docs/model.md; P_N = 0 in state b, so
  // mu_eff = mu there).
  const double m = state.label == StateLabel::kD && p.criterion == Criterion::kSoftening
                       ? p.mu - 2.0 * p.kappa(state.P_N)
                       : p.mu;
  auto L = [&](int s) {
    // L_s = (s + m a12 C_T) dF_T - m (1 + a11 C_T) dF_N
    return LoadLinearForm{s > 0 ? "L+" : "L-", static_cast<double>(s) + m * p.a12 * p.C_T,
                          -m * g};
  };
  switch (state.label) {
    case StateLabel::kA:
    case StateLabel::kC:
      break;  // unique for every direction: nothing changes
    case StateLabel::kB:
      forms.push_back({"N", -p.a12, p.a11});        // N = a11 dF_N - a12 dF_T
      forms.push_back({"S", -p.a12 * p.C_T, g});    // S = (1 + a11 C_T) dF_N - a12 C_T dF_T
      forms.push_back(L(+1));
      forms.push_back(L(-1));
      break;
    case StateLabel::kD:
      forms.push_back(L(state.sgn_PT >= 0 ? +1 : -1));
      break;
  }
  return forms;
}

std::vector<CandidateDirection> candidate_critical_directions(const ContactParameters& params,
                                                              const ContactState& state) {
  std::vector<CandidateDirection> dirs;
  for (const auto& f : critical_linear_forms(params, state)) {
    if (f.c_T == 0 && f.c_N == 0) continue;  // a form that vanishes identically decides nothing
    // The form vanishes on (dF_T, dF_N) = +-(c_N, -c_T): exactly, c_T c_N - c_N c_T = 0.
    for (const double sign : {1.0, -1.0}) {
      CandidateDirection d;
      d.load = LoadRate{sign * f.c_N, -sign * f.c_T};
      d.theta = load_angle(d.load);
      d.conditions.push_back(f.name + "=0");
      dirs.push_back(std::move(d));
    }
  }
  std::sort(dirs.begin(), dirs.end(),
            [](const CandidateDirection& a, const CandidateDirection& b) {
              return a.theta < b.theta;
            });
  std::vector<CandidateDirection> merged;
  for (auto& d : dirs) {
    if (!merged.empty() && d.theta - merged.back().theta <= kMergeTol) {
      for (auto& c : d.conditions) merged.back().conditions.push_back(std::move(c));
    } else {
      merged.push_back(std::move(d));
    }
  }
  // Wrap-around: a direction just below 2 pi and one at 0 are the same direction.
  if (merged.size() > 1 && merged.front().theta + kTwoPi - merged.back().theta <= kMergeTol) {
    for (auto& c : merged.back().conditions) merged.front().conditions.push_back(std::move(c));
    merged.pop_back();
  }
  for (auto& d : merged) std::sort(d.conditions.begin(), d.conditions.end());
  return merged;
}

}  // namespace cpkit::rate
