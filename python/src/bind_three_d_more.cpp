// More of the three-dimensional API (docs/contact_3d.md): the maps of a "dim": 3 system over the
// sphere of load directions and over parameters (numpy grids), the solvers of one implicit 3-D
// step (chain, multistart, faceted) and the fretting simulation under an elliptic load orbit
// (the time series as numpy arrays). Results are plain dicts; the GIL is released while C++
// computes.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "point3d_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/step/multistart_cap.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"
#include "cpkit/rate_problem/step/step_3d.hpp"
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::py {
namespace {

// ---- maps ------------------------------------------------------------------------------------

/// Map options of a system: facets (0 exact), point (1-based, as the CLI's --point), the other
/// points' load rates ("auto": the file's dF when N > 1 and the file has one, as the CLI;
/// "zero"; "file").
rate3d::Map3dOptions map_options(const rate3d::ContactSystem3d& sys, int facets, int point,
                                 const std::string& others, int threads) {
  rate3d::Map3dOptions o;
  o.facets = facets;
  o.point = point - 1;
  o.threads = threads;
  if (others == "auto")
    o.others_from_file = sys.n_points() > 1 && sys.dF.has_value();
  else if (others == "file" || others == "zero")
    o.others_from_file = others == "file";
  else
    throw InputError("others must be 'auto', 'zero' or 'file', got '" + others + "'");
  if (o.others_from_file && sys.n_points() == 1)
    throw InputError("others: 'file' has no effect with one point");
  throw_if_invalid(o.validate(sys), "map options");
  return o;
}

rate3d::Map3dAxis axis_from(const std::string& param, double from, double to, int n, int n_points,
                            const char* which) {
  rate3d::Map3dAxis a;
  a.param = rate3d::parse_map_3d_parameter(param, n_points);
  a.from = from;
  a.to = to;
  a.n = n;
  throw_if_invalid(a.validate(), which);
  return a;
}

void check_cells(double rows, double cols, const std::string& what) {
  if (rows * cols > static_cast<double>(rate3d::kMaxMap3dCells))
    throw InputError(what + " must be at most " + std::to_string(rate3d::kMaxMap3dCells) + " cells");
  check_memory(2 * 3.0 * rows * cols, "the map of " + what);  // the C++ map and its numpy copy
}

template <class T>
pyb::array_t<T> grid(const std::vector<T>& v, int rows, int cols) {
  pyb::array_t<T> a({static_cast<pyb::ssize_t>(rows), static_cast<pyb::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

pyb::array_t<double> array1(const std::vector<double>& v) {
  return pyb::array_t<double>(static_cast<pyb::ssize_t>(v.size()), v.data());
}

pyb::dict map_dict(const rate3d::Map3d& m, const rate3d::Map3dOptions& o) {
  pyb::dict d;
  d["x"] = array1(m.x);
  d["y"] = array1(m.y);
  d["count"] = grid(m.count, m.rows, m.cols);
  d["types"] = grid(m.types, m.rows, m.cols);
  pyb::array_t<bool> complete({static_cast<pyb::ssize_t>(m.rows), static_cast<pyb::ssize_t>(m.cols)});
  bool* c = complete.mutable_data();
  for (std::size_t i = 0; i < m.complete.size(); ++i) c[i] = m.complete[i] != 0;
  d["complete"] = complete;
  d["incomplete_cells"] = m.incomplete_cells;
  pyb::dict counts;
  for (const auto& [count, cells] : m.count_cells) counts[pyb::int_(count)] = cells;
  d["count_cells"] = counts;
  pyb::dict types;
  for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
    if (m.type_cells[mask] > 0) types[pyb::str(rate3d::type_mask_string(mask))] = m.type_cells[mask];
  d["type_cells"] = types;
  d["route"] = o.facets ? "faceted" : "exact";
  d["facets"] = o.facets;
  d["point"] = o.point + 1;
  d["others"] = o.others_from_file ? "file" : "zero";
  d["seconds"] = m.seconds;
  d["threads"] = m.threads;
  return d;
}

pyb::dict sphere_map_3d(const std::string& json_text, int n_beta, int n_gamma, double beta_from,
                        double beta_to, int facets, int point, const std::string& others,
                        int threads) {
  const rate3d::ContactSystem3d sys = rate3d::parse_contact_system_3d(json_text, "system");
  const rate3d::Map3dOptions o = map_options(sys, facets, point, others, threads);
  rate3d::SphereGrid g;
  g.n_beta = n_beta;
  g.n_gamma = n_gamma;
  g.beta_from = beta_from;
  g.beta_to = beta_to;
  throw_if_invalid(g.validate(), "sphere grid");
  check_cells(n_beta, n_gamma, std::to_string(n_beta) + " x " + std::to_string(n_gamma) +
                                   " (n_beta x n_gamma)");
  rate3d::Map3d m;
  {
    pyb::gil_scoped_release release;
    m = rate3d::compute_sphere_map_3d(sys, g, o);
  }
  pyb::dict d = map_dict(m, o);
  d["kind"] = "sphere";
  return d;
}

pyb::dict param_direction_map_3d(const std::string& json_text, const std::string& param,
                                 double from, double to, int n, int theta_n, double theta_from,
                                 double theta_to, double gamma, int facets, int point,
                                 const std::string& others, int threads) {
  const rate3d::ContactSystem3d sys = rate3d::parse_contact_system_3d(json_text, "system");
  const rate3d::Map3dOptions o = map_options(sys, facets, point, others, threads);
  const rate3d::Map3dAxis a = axis_from(param, from, to, n, sys.n_points(), "axis");
  if (theta_n < 1 || theta_n > 1000000)
    throw InputError("theta_n must be in [1, 1000000], got " + std::to_string(theta_n));
  check_cells(n, theta_n, std::to_string(n) + " x " + std::to_string(theta_n) + " (n x theta_n)");
  rate3d::Map3d m;
  {
    pyb::gil_scoped_release release;
    m = rate3d::compute_param_direction_map_3d(sys, a, theta_n, theta_from, theta_to, gamma, o);
  }
  pyb::dict d = map_dict(m, o);
  d["kind"] = "param-direction";
  d["param"] = a.param.name();
  d["gamma"] = gamma;
  return d;
}

pyb::dict param_param_map_3d(const std::string& json_text, const std::string& param1,
                             double from1, double to1, int n1, const std::string& param2,
                             double from2, double to2, int n2, int facets, int point,
                             const std::string& others, int threads) {
  const rate3d::ContactSystem3d sys = rate3d::parse_contact_system_3d(json_text, "system");
  const rate3d::Map3dOptions o = map_options(sys, facets, point, others, threads);
  const rate3d::Map3dAxis a1 = axis_from(param1, from1, to1, n1, sys.n_points(), "first axis");
  const rate3d::Map3dAxis a2 = axis_from(param2, from2, to2, n2, sys.n_points(), "second axis");
  check_cells(n1, n2, std::to_string(n1) + " x " + std::to_string(n2) + " (n1 x n2)");
  rate3d::Map3d m;
  {
    pyb::gil_scoped_release release;
    m = rate3d::compute_param_param_map_3d(sys, a1, a2, o);
  }
  pyb::dict d = map_dict(m, o);
  d["kind"] = "param-param";
  d["param1"] = a1.param.name();
  d["param2"] = a2.param.name();
  return d;
}

// ---- step solvers ----------------------------------------------------------------------------


pyb::dict solve_step_3d(const pyb::object& point, const pyb::object& P_T0, double P_N0, double g0,
                        const pyb::object& DF, const std::string& wear_law, double k_M,
                        const std::vector<std::string>& chain, int max_iterations, double tol,
                        double time_limit) {
  const rate3d::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  rate3d::Step3dChainOptions o;
  if (!chain.empty()) o.chain = chain;
  o.solver.max_iterations = max_iterations;
  o.solver.tol = tol;
  o.solver.tol_acceptable = tol;  // "solved" means step_3d_residual <= tol, nothing looser
  o.solver.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "solver options");
  rate3d::Step3dChainResult r;
  {
    pyb::gil_scoped_release release;
    r = rate3d::solve_step_3d(p, o);
  }
  pyb::list attempts;
  for (const auto& a : r.attempts) {
    pyb::dict ad;
    ad["solver"] = a.solver;
    ad["solved"] = a.status == Status::kSolved;
    ad["residual"] = a.residual;
    ad["iterations"] = a.iterations;
    ad["seconds"] = a.seconds;
    ad["message"] = a.message;
    attempts.append(ad);
  }
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
  const rate3d::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  if (n_starts < 0) throw InputError("n_starts must be >= 0, got " + std::to_string(n_starts));
  rate3d::check_multistart_cap(n_starts, "n_starts");
  rate3d::Step3dSolutionSet set;
  {
    pyb::gil_scoped_release release;
    set = rate3d::multistart_step_3d(p, n_starts, seed);
  }
  return step_set_dict(set);
}

pyb::dict solve_step_3d_faceted(const pyb::object& point, const pyb::object& P_T0, double P_N0,
                                double g0, const pyb::object& DF, const std::string& wear_law,
                                double k_M, int facets, int n_starts, std::uint64_t seed) {
  const rate3d::Step3dProblem p = step_problem(point, P_T0, P_N0, g0, DF, wear_law, k_M);
  if (n_starts < 1) throw InputError("n_starts must be >= 1, got " + std::to_string(n_starts));
  rate3d::check_multistart_cap(n_starts, "n_starts");
  rate3d::FacetedStep3dResult r;
  {
    pyb::gil_scoped_release release;
    r = rate3d::solve_step_3d_faceted(p, facets, n_starts, seed);
  }
  pyb::dict d = step_set_dict(r.set);
  d["facets"] = r.facets;
  d["size"] = r.size;
  d["lcp"] = r.lcp;
  d["nodes"] = r.nodes;
  d["seconds"] = r.seconds;
  return d;
}

// ---- fretting --------------------------------------------------------------------------------

using Sample = rate3d::Fretting3dSample;

template <class F>
pyb::array_t<double> column(const std::vector<Sample>& s, F get) {
  pyb::array_t<double> a(static_cast<pyb::ssize_t>(s.size()));
  auto m = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < s.size(); ++i) m(static_cast<pyb::ssize_t>(i)) = get(s[i]);
  return a;
}

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
  pyb::list types;
  for (const auto& x : s) types.append(std::string(rate3d::to_string(x.type)));
  d["type"] = types;
  return d;
}

pyb::dict sample_dict(const Sample& x) {
  pyb::dict d;
  d["step"] = x.step;
  d["t"] = x.t;
  d["F_T"] = np2(x.F_T);
  d["F_N"] = x.F_N;
  d["P_T"] = np2(x.P_T);
  d["P_N"] = x.P_N;
  d["g"] = x.g;
  d["w_T"] = np2(x.w_T);
  d["w_N"] = x.w_N;
  d["w_Ti"] = np2(x.w_Ti);
  d["w_w"] = x.w_w;
  d["type"] = std::string(rate3d::to_string(x.type));
  d["cycle"] = x.cycle;
  return d;
}

pyb::dict simulate_fretting_3d(const pyb::object& point, double F_N, double a_X, double a_Y,
                               double angle, double period, int cycles, int steps_per_cycle,
                               int ramp_steps, int lead_steps, const std::string& wear_law,
                               double k_M, const std::string& branch_rule, int record_every,
                               bool local_fallback) {
  rate3d::EllipticOrbit orbit;
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
  rate3d::Fretting3dOptions o;
  o.params = params_from(point);
  const auto w = rate::wear_law_from_string(wear_law);
  if (!w) throw InputError("wear_law must be 'archard' or 'mroz-stupkiewicz', got '" + wear_law + "'");
  o.wear = rate::WearModel{*w, k_M};
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
  rate3d::Fretting3dResult r;
  {
    pyb::gil_scoped_release release;
    r = rate3d::simulate_fretting_3d(orbit, o);
  }
  auto arr = [](const std::vector<double>& v) { return array1(v); };
  pyb::dict d;
  d["series"] = series_dict(r.series);
  d["final_state"] = sample_dict(r.final_state);
  d["outcome"] = std::string(rate3d::to_string(r.outcome));
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

void bind_three_d_more(pyb::module_& m) {
  m.def("sphere_map_3d", &sphere_map_3d, pyb::arg("json_text"), pyb::arg("n_beta"),
        pyb::arg("n_gamma"), pyb::arg("beta_from"), pyb::arg("beta_to"), pyb::arg("facets"),
        pyb::arg("point"), pyb::arg("others"), pyb::arg("threads"));
  m.def("param_direction_map_3d", &param_direction_map_3d, pyb::arg("json_text"),
        pyb::arg("param"), pyb::arg("from_"), pyb::arg("to"), pyb::arg("n"), pyb::arg("theta_n"),
        pyb::arg("theta_from"), pyb::arg("theta_to"), pyb::arg("gamma"), pyb::arg("facets"),
        pyb::arg("point"), pyb::arg("others"), pyb::arg("threads"));
  m.def("param_param_map_3d", &param_param_map_3d, pyb::arg("json_text"), pyb::arg("param1"),
        pyb::arg("from1"), pyb::arg("to1"), pyb::arg("n1"), pyb::arg("param2"), pyb::arg("from2"),
        pyb::arg("to2"), pyb::arg("n2"), pyb::arg("facets"), pyb::arg("point"),
        pyb::arg("others"), pyb::arg("threads"));
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
