#pragma once
/// \file critical_directions.hpp
/// Exact candidate critical load directions of the rate problem [Stromberg et al. 1996,
/// Sec. 4.3, Fig. 5] (working equations: docs/model.md Sec. 2).
///
/// Every condition that decides which solution types exist is the sign of a linear form
/// c_T dF_T + c_N dF_N of the load rate (model.md notation):
///   state b: N = a11 dF_N - a12 dF_T (separation N < 0; slip dP_N = N / D_s >= 0),
///            S = (1 + a11 C_T) dF_N - a12 C_T dF_T (stick dP_N >= 0),
///            L_+ and L_-, L_s = (s + mu a12 C_T) dF_T - mu (1 + a11 C_T) dF_N
///            (stick L_s <= 0; slip lambda = L_s / D_s > 0);
///   state d: L_s with s = sgn P_T (stick L_s <= 0; slip lambda = L_s / Lambda > 0), mu replaced
///            by mu_eff = mu - 2 kappa for the softening criterion (35);
///   states a and c: none (the solution is unique for every direction).
/// A form vanishes on exactly two opposite directions, here computed in closed form:
/// the load (dF_T, dF_N) = (c_N, -c_T) and its negative, with no sampling. Load directions are
/// angles theta in [0, 2 pi) measured from +dF_T towards +dF_N: (dF_T, dF_N) = (cos, sin).
#include <string>
#include <vector>

#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"

namespace cpkit::rate {

/// A linear form c_T dF_T + c_N dF_N of the load rate, named as in model.md ("N", "S", "L+", "L-").
struct LoadLinearForm {
  std::string name;
  double c_T = 0, c_N = 0;
  double operator()(const LoadRate& l) const noexcept { return c_T * l.dF_T + c_N * l.dF_N; }
};

/// The forms whose signs decide the solution set of `state` (see the file comment).
/// Parameters must be valid (params.validate() empty).
std::vector<LoadLinearForm> critical_linear_forms(const ContactParameters& params,
                                                  const ContactState& state);

/// A direction on which one or more of the forms vanish.
struct CandidateDirection {
  double theta = 0;                    ///< in [0, 2 pi)
  LoadRate load;                       ///< (c_N, -c_T) or its negative: the form is exactly 0
  std::vector<std::string> conditions; ///< e.g. {"N=0"} or {"S=0", "L+=0"} when lines coincide
};

/// All directions where a form of critical_linear_forms() vanishes, sorted by theta; directions
/// closer than 1e-12 rad are merged (their conditions united).
std::vector<CandidateDirection> candidate_critical_directions(const ContactParameters& params,
                                                              const ContactState& state);

/// theta in [0, 2 pi) of a nonzero load rate.
double load_angle(const LoadRate& load) noexcept;

}  // namespace cpkit::rate
