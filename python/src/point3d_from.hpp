#pragma once
// Reading a 3-D point (cpkit.Point3d), small vectors and one-point step problems from Python
// objects, and 3-D quantities and step solutions back as dicts, shared by bind_rate_3d.cpp and
// bind_step_3d.cpp. Errors are InputError (ValueError in Python) naming the field.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"

namespace cpkit::py {

/// Exactly n numbers from a Python sequence; InputError "<what> must hold n numbers, got m".
inline std::vector<double> numbers_of(const pyb::handle& o, std::size_t n, const char* what) {
  auto v = o.cast<std::vector<double>>();
  if (v.size() != n)
    throw InputError(std::string(what) + " must hold " + std::to_string(n) + " numbers, got " +
                     std::to_string(v.size()));
  return v;
}

inline Eigen::Vector2d vec2(const pyb::handle& o, const char* what) {
  const auto v = numbers_of(o, 2, what);
  return {v[0], v[1]};
}

inline Eigen::Vector3d vec3(const pyb::handle& o, const char* what) {
  const auto v = numbers_of(o, 3, what);
  return {v[0], v[1], v[2]};
}

/// ContactParameters3d from an object with A (3x3), mu, C_T, k_a, P_s, alpha (cpkit.Point3d).
inline rate::ContactParameters3d params_from(const pyb::handle& o) {
  rate::ContactParameters3d p;
  const auto A = o.attr("A").cast<std::vector<std::vector<double>>>();
  if (A.size() != 3) throw InputError("A must be 3 x 3 (DOFs T_X, T_Y, N)");
  for (int i = 0; i < 3; ++i) {
    if (A[i].size() != 3) throw InputError("A must be 3 x 3 (DOFs T_X, T_Y, N)");
    for (int j = 0; j < 3; ++j) p.A(i, j) = A[i][j];
  }
  p.mu = finite_number(o.attr("mu"), "mu");
  p.C_T = finite_number(o.attr("C_T"), "C_T");
  p.k_a = finite_number(o.attr("k_a"), "k_a");
  p.P_s = finite_number(o.attr("P_s"), "P_s");
  p.alpha = vec2(o.attr("alpha"), "alpha");
  throw_if_invalid(p.validate(), "point");
  return p;
}

inline pyb::array_t<double> np2(const Eigen::Vector2d& v) { return to_numpy(Vec(v)); }

/// A 3-D quantity X as d["X_T"] (tangential 2-vector, numpy) and d["X_N"] (normal scalar).
inline void put_tn(pyb::dict& d, const std::string& X, const Eigen::Vector2d& T, double N) {
  d[pyb::str(X + "_T")] = np2(T);
  d[pyb::str(X + "_N")] = N;
}

/// A 3-D wear quadruple (w_T, w_N, w_Ti, w_w, or its rate or increment named by X = "dw", "Dw")
/// as d["X_T"], d["X_N"], d["X_Ti"], d["X_w"].
inline void put_wear(pyb::dict& d, const std::string& X, const Eigen::Vector2d& T, double N,
                     const Eigen::Vector2d& Ti, double w) {
  put_tn(d, X, T, N);
  d[pyb::str(X + "_Ti")] = np2(Ti);
  d[pyb::str(X + "_w")] = w;
}

inline rate::Step3dProblem step_problem(const pyb::object& point, const pyb::object& P_T0,
                                   double P_N0, double g0, const pyb::object& DF,
                                   const std::string& wear_law, double k_M) {
  rate::Step3dProblem p;
  p.params = params_from(point);
  p.wear = wear_from(wear_law, k_M);
  p.state.P_T0 = vec2(P_T0, "P_T0");
  p.state.P_N0 = P_N0;
  p.state.g0 = g0;
  p.DF = vec3(DF, "DF");
  throw_if_invalid(p.validate(), "step");
  return p;
}

/// d["slip_direction"] (unit 2-vector) and d["slip_angle"] (radians) of a slip solution; None
/// for the other types.
inline void put_slip(pyb::dict& d, rate::SolutionType type, const Eigen::Vector2d& direction,
                     double angle) {
  const bool slip = type == rate::SolutionType::kSlip;
  d["slip_direction"] = slip ? pyb::object(np2(direction)) : pyb::object(pyb::none());
  d["slip_angle"] = slip ? pyb::object(pyb::float_(angle)) : pyb::object(pyb::none());
}

/// A step solution as a dict with the keys of enumerate_step_3d's solutions.
inline pyb::dict step_solution_dict(const rate::Step3dSolution& s) {
  const rate::Step3dValues& v = s.values;
  pyb::dict values;
  values["P_T1"] = np2(v.P_T1);
  values["P_N1"] = v.P_N1;
  put_tn(values, "DP", v.DP_T, v.DP_N);
  put_wear(values, "Dw", v.Dw_T, v.Dw_N, v.Dw_Ti, v.Dw_w);
  values["g1"] = v.g1;
  values["lambda"] = v.lambda;
  pyb::dict d;
  d["type"] = std::string(rate::to_string(s.type));
  d["values"] = values;
  put_slip(d, s.type, s.slip_direction, s.slip_angle);
  d["residual"] = s.residual;
  return d;
}

inline pyb::dict step_set_dict(const rate::Step3dSolutionSet& set) {
  pyb::list sols;
  for (const auto& s : set.solutions) sols.append(step_solution_dict(s));
  pyb::dict d;
  d["solutions"] = sols;
  d["complete"] = set.complete;
  d["message"] = set.message;
  return d;
}

}  // namespace cpkit::py
