// One implicit step of a 3-D point (docs/contact_3d.md): every solution, the solver chain,
// multistart and faceted, and the fretting simulation under an elliptic load orbit (the time
// series as numpy arrays); the 2-D step and simulation are bind_step.cpp. Results are plain
// dicts; the GIL is released while C++ computes.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "point3d_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/step/multistart_cap.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::py {
namespace {

// ---- step solvers ----------------------------------------------------------------------------

pyb::dict enumerate_step_3d(const pyb::object& point, const pyb::object& P_T0, double P_N0,
                            double g0, const pyb::object& DF, const std::string& wear_law,
                            double k_M) {
  const rate::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  rate::Step3dSolutionSet set = without_gil([&] { return rate::enumerate_step_3d(p); });
  return step_set_dict(set);
}

pyb::dict solve_step_3d(const pyb::object& point, const pyb::object& P_T0, double P_N0, double g0,
                        const pyb::object& DF, const std::string& wear_law, double k_M,
                        const std::vector<std::string>& chain, int max_iterations, double tol,
                        double time_limit) {
  const rate::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  rate::Step3dChainOptions o;
  if (!chain.empty()) o.chain = chain;
  o.solver.max_iterations = max_iterations;
  o.solver.tol = tol;
  o.solver.tol_acceptable = tol;  // "solved" means step_3d_residual <= tol, nothing looser
  o.solver.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "solver options");
  rate::Step3dChainResult r = without_gil([&] { return rate::solve_step_3d(p, o); });
  pyb::list attempts = list_of(r.attempts, [](const Attempt& a) {
    pyb::dict ad;
    ad["solver"] = a.solver;
    ad["solved"] = a.status == Status::kSolved;
    ad["residual"] = a.residual;
    ad["iterations"] = a.iterations;
    ad["seconds"] = a.seconds;
    ad["message"] = a.message;
    return ad;
  });
  pyb::dict d;
  const bool verified = r.status == Status::kSolved;
  d["solved"] = verified;
  d["solver"] = r.solver;
  d["solution"] = verified ? pyb::object(step_solution_dict(r.solution)) : pyb::object(pyb::none());
  d["attempts"] = attempts;
  d["message"] = r.message;
  return d;
}

pyb::dict multistart_step_3d(const pyb::object& point, const pyb::object& P_T0, double P_N0,
                             double g0, const pyb::object& DF, const std::string& wear_law,
                             double k_M, int n_starts, std::uint64_t seed) {
  const rate::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  if (n_starts < 0) throw InputError("n_starts must be >= 0, got " + std::to_string(n_starts));
  rate::check_multistart_cap(n_starts, "n_starts");
  rate::Step3dSolutionSet set =
      without_gil([&] { return rate::multistart_step_3d(p, n_starts, seed); });
  return step_set_dict(set);
}

pyb::dict solve_step_3d_faceted(const pyb::object& point, const pyb::object& P_T0, double P_N0,
                                double g0, const pyb::object& DF, const std::string& wear_law,
                                double k_M, int facets, int n_starts, std::uint64_t seed) {
  const rate::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  if (n_starts < 1) throw InputError("n_starts must be >= 1, got " + std::to_string(n_starts));
  rate::check_multistart_cap(n_starts, "n_starts");
  rate::FacetedStep3dResult r =
      without_gil([&] { return rate::solve_step_3d_faceted(p, facets, n_starts, seed); });
  pyb::dict d = step_set_dict(r.set);
  d["facets"] = r.facets;
  d["size"] = r.size;
  d["lcp"] = r.lcp;
  d["nodes"] = r.nodes;
  d["seconds"] = r.seconds;
  return d;
}

// ---- fretting --------------------------------------------------------------------------------

using Sample = rate::Fretting3dSample;

template <class F>
pyb::array_t<double> column2(const std::vector<Sample>& s, F get) {
  pyb::array_t<double> a({static_cast<pyb::ssize_t>(s.size()), static_cast<pyb::ssize_t>(2)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector2d v = get(s[i]);
    m(static_cast<pyb::ssize_t>(i), 0) = v(0);
    m(static_cast<pyb::ssize_t>(i), 1) = v(1);
  }
  return a;
}

pyb::dict series_dict(const std::vector<Sample>& s) {
  pyb::dict d;
  d["step"] = column(s, [](const Sample& x) { return static_cast<double>(x.step); });
  d["t"] = column(s, [](const Sample& x) { return x.t; });
  d["F_T"] = column2(s, [](const Sample& x) { return x.F_T; });
  d["F_N"] = column(s, [](const Sample& x) { return x.F_N; });
  d["P_T"] = column2(s, [](const Sample& x) { return x.P_T; });
  d["P_N"] = column(s, [](const Sample& x) { return x.P_N; });
  d["g"] = column(s, [](const Sample& x) { return x.g; });
  d["w_T"] = column2(s, [](const Sample& x) { return x.w_T; });
  d["w_N"] = column(s, [](const Sample& x) { return x.w_N; });
  d["w_Ti"] = column2(s, [](const Sample& x) { return x.w_Ti; });
  d["Dw_Ti"] = column2(s, [](const Sample& x) { return x.Dw_Ti; });
  d["lambda"] = column(s, [](const Sample& x) { return x.lambda; });
  d["Dw_w"] = column(s, [](const Sample& x) { return x.Dw_w; });
  d["w_w"] = column(s, [](const Sample& x) { return x.w_w; });
  d["count"] = column(s, [](const Sample& x) { return static_cast<double>(x.count); });
  d["complete"] = column(s, [](const Sample& x) { return x.complete ? 1.0 : 0.0; });
  d["dissipation"] = column(s, [](const Sample& x) { return x.dissipation; });
  d["cycle"] = column(s, [](const Sample& x) { return static_cast<double>(x.cycle); });
  d["type"] = list_of(s, [](const Sample& x) { return std::string(rate::to_string(x.type)); });
  return d;
}

pyb::dict sample_dict(const Sample& x) {
  pyb::dict d;
  d["step"] = x.step;
  d["t"] = x.t;
  put_tn(d, "F", x.F_T, x.F_N);
  put_tn(d, "P", x.P_T, x.P_N);
  d["g"] = x.g;
  put_wear(d, "w", x.w_T, x.w_N, x.w_Ti, x.w_w);
  d["type"] = std::string(rate::to_string(x.type));
  d["cycle"] = x.cycle;
  return d;
}

pyb::dict simulate_fretting_3d(const pyb::object& point, double F_N, double a_X, double a_Y,
                               double angle, double period, int cycles, int steps_per_cycle,
                               int ramp_steps, int lead_steps, const std::string& wear_law,
                               double k_M, const std::string& branch_rule, int record_every,
                               bool local_fallback) {
  rate::EllipticOrbit orbit;
  orbit.F_N = F_N;
  orbit.a_X = a_X;
  orbit.a_Y = a_Y;
  orbit.angle = angle;
  orbit.period = period;
  orbit.cycles = cycles;
  orbit.steps_per_cycle = steps_per_cycle;
  orbit.ramp_steps = ramp_steps;
  orbit.lead_steps = lead_steps;
  throw_if_invalid(orbit.validate(), "orbit");
  rate::Fretting3dOptions o;
  o.params = params_from(point);
  o.wear = wear_from(wear_law, k_M);
  const auto br = rate::branch_rule_from_string(branch_rule);
  if (!br) throw InputError("branch_rule must be 'closest' or 'stop', got '" + branch_rule + "'");
  o.branch_rule = *br;
  if (record_every < 0) throw InputError("record_every must be >= 0, got " + std::to_string(record_every));
  o.record_every = record_every;
  o.local_fallback = local_fallback;
  throw_if_invalid(o.validate(), "fretting");
  const double steps = static_cast<double>(orbit.size());
  const double kept = record_every > 0 ? steps / record_every + 2 : 2;
  // The C++ series, its numpy columns (25 doubles a row) and the per-cycle sums (4 a cycle).
  check_memory(kept * (sizeof(Sample) + 25 * sizeof(double)) + 2.0 * 4 * cycles * sizeof(double),
               "a fretting run of " + std::to_string(orbit.size()) + " steps (record_every " +
                   std::to_string(record_every) + ")");
  rate::Fretting3dResult r = without_gil([&] { return rate::simulate_fretting_3d(orbit, o); });
  auto arr = [](const std::vector<double>& v) { return to_numpy(v); };
  pyb::dict d;
  d["series"] = series_dict(r.series);
  d["final_state"] = sample_dict(r.final_state);
  d["outcome"] = std::string(rate::to_string(r.outcome));
  d["message"] = r.message;
  d["steps"] = r.steps;
  d["branch_steps"] = r.branch_steps;
  d["incomplete_steps"] = r.incomplete_steps;
  d["local_steps"] = r.local_steps;
  d["enumeration_missed"] = r.enumeration_missed;
  d["wear_depth"] = r.wear_depth;
  d["wear_integral"] = r.wear_integral;
  d["total_slip"] = r.total_slip;
  d["total_lambda"] = r.total_lambda;
  d["slip_per_cycle"] = arr(r.slip_per_cycle);
  d["wear_per_cycle"] = arr(r.wear_per_cycle);
  d["wear_X_per_cycle"] = arr(r.wear_X_per_cycle);
  d["wear_Y_per_cycle"] = arr(r.wear_Y_per_cycle);
  d["dissipation"] = r.dissipation;
  d["min_step_dissipation"] = r.min_step_dissipation;
  d["max_residual"] = r.max_residual;
  d["period"] = orbit.period;
  d["cycle_start"] = orbit.cycle_start();
  d["lead_steps"] = orbit.lead();
  return d;
}

}  // namespace

void bind_step_3d(pyb::module_& m) {
  m.def("enumerate_step_3d", &enumerate_step_3d, pyb::arg("point"), pyb::arg("P_T0"),
        pyb::arg("P_N0"), pyb::arg("g0"), pyb::arg("DF"), pyb::arg("wear_law"), pyb::arg("k_M"));
  m.def("solve_step_3d", &solve_step_3d, pyb::arg("point"), pyb::arg("P_T0"), pyb::arg("P_N0"),
        pyb::arg("g0"), pyb::arg("DF"), pyb::arg("wear_law"), pyb::arg("k_M"), pyb::arg("chain"),
        pyb::arg("max_iterations"), pyb::arg("tol"), pyb::arg("time_limit"));
  m.def("multistart_step_3d", &multistart_step_3d, pyb::arg("point"), pyb::arg("P_T0"),
        pyb::arg("P_N0"), pyb::arg("g0"), pyb::arg("DF"), pyb::arg("wear_law"), pyb::arg("k_M"),
        pyb::arg("n_starts"), pyb::arg("seed"));
  m.def("solve_step_3d_faceted", &solve_step_3d_faceted, pyb::arg("point"), pyb::arg("P_T0"),
        pyb::arg("P_N0"), pyb::arg("g0"), pyb::arg("DF"), pyb::arg("wear_law"), pyb::arg("k_M"),
        pyb::arg("facets"), pyb::arg("n_starts"), pyb::arg("seed"));
  m.def("simulate_fretting_3d", &simulate_fretting_3d, pyb::arg("point"), pyb::arg("F_N"),
        pyb::arg("a_X"), pyb::arg("a_Y"), pyb::arg("angle"), pyb::arg("period"),
        pyb::arg("cycles"), pyb::arg("steps_per_cycle"), pyb::arg("ramp_steps"),
        pyb::arg("lead_steps"), pyb::arg("wear_law"), pyb::arg("k_M"), pyb::arg("branch_rule"),
        pyb::arg("record_every"), pyb::arg("local_fallback"));
}

}  // namespace cpkit::py
