// Maps of the one-point rate problem (docs/maps.md): the exact direction map and the grid maps,
// returned as numpy arrays (counts, type masks, axes) plus the exact sectors and critical values.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::py {
namespace {

rate::MapOptions map_options(const std::string& method, int threads) {
  rate::MapOptions o;
  const auto m = rate::rate_method_from_string(method);
  if (!m || (*m != rate::RateMethod::kEnumerate && *m != rate::RateMethod::kAnalytic))
    throw InputError("method must be 'enumerate' or 'analytic', got '" + method + "'");
  o.method = *m;
  o.threads = threads;
  throw_if_invalid(o.validate(), "map options");
  return o;
}

rate::MapAxis axis_from(const std::string& param, double from, double to, int n) {
  rate::MapAxis a;
  const auto p = rate::map_parameter_from_string(param);
  if (!p) {  // a name of the map parameter table for other maps: named as inapplicable
    const std::string base = param.substr(0, param.find('@'));
    for (const auto& row : rate::map_parameter_table())
      if (base == row.name) (void)rate::check_map_parameter(param, rate::kMapOnePoint, 1, "param");
    throw InputError("param must be one of " + rate::map_parameter_names(rate::kMapOnePoint) +
                     ", got '" + param + "'");
  }
  a.param = *p;
  a.from = from;
  a.to = to;
  a.n = n;
  throw_if_invalid(a.validate(), "axis '" + param + "'");
  return a;
}

template <class T>
pyb::array_t<T> grid(const std::vector<T>& v, pyb::ssize_t rows, pyb::ssize_t cols) {
  pyb::array_t<T> a({rows, cols});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

pyb::array_t<double> axis_values(const rate::MapAxis& a) {
  std::vector<double> v(static_cast<std::size_t>(a.n));
  for (int i = 0; i < a.n; ++i) v[static_cast<std::size_t>(i)] = a.value(i);
  return to_numpy(v);
}

pyb::dict summary_dict(const rate::RateSummary& s) {
  pyb::dict d;
  d["count"] = s.count;
  d["types"] = type_names(s.types);
  d["type_mask"] = s.types;
  d["reliable"] = s.reliable;
  return d;
}

pyb::list critical_values(const std::vector<rate::CriticalValue>& cv) {
  return list_of(cv, [](const rate::CriticalValue& c) {
    pyb::dict d;
    d["name"] = c.name;
    d["x"] = c.x;
    d["y"] = c.y;
    return d;
  });
}

pyb::dict direction_map(const pyb::object& params, const pyb::object& state,
                        const std::string& method) {
  const auto p = parameters_from(params);
  const auto s = state_from(state, p);
  const auto o = map_options(method, 1);
  rate::DirectionMap map = without_gil([&] { return rate::compute_direction_map(p, s, o); });
  pyb::dict d;
  d["sectors"] = list_of(map.sectors, [](const auto& sec) {
    pyb::dict sd = summary_dict(sec.summary);
    sd["theta_from"] = sec.theta_from;
    sd["theta_to"] = sec.theta_to;
    sd["consistent"] = sec.consistent;
    sd["check"] = summary_dict(sec.check);
    return sd;
  });
  d["critical"] = list_of(map.critical, [](const auto& c) {
    pyb::dict cd = summary_dict(c.summary);
    cd["theta"] = c.theta;
    cd["load"] = pyb::make_tuple(c.load.dF_T, c.load.dF_N);
    cd["conditions"] = c.conditions;
    cd["check"] = summary_dict(c.check);
    return cd;
  });
  d["evaluations"] = map.evaluations;
  d["disagreements"] = map.disagreements;
  d["inconsistent_sectors"] = map.inconsistent_sectors;
  d["unreliable"] = map.unreliable;
  d["cross_checked"] = map.cross_checked;
  return d;
}

pyb::dict param_direction_map(const pyb::object& params, const pyb::object& state,
                              const std::string& param, double from, double to, int n,
                              int theta_n, const std::string& method, int threads) {
  const auto p = parameters_from(params);
  const auto s = state_from(state, p);
  const auto o = map_options(method, threads);
  const auto axis = axis_from(param, from, to, n);
  if (theta_n < 1) throw InputError("theta_n must be at least 1, got " + std::to_string(theta_n));
  check_memory(3.0 * n * theta_n, "the map of " + std::to_string(n) + " x " +
                                      std::to_string(theta_n) + " (n x theta_n) cells");
  rate::ParamDirectionMap map =
      without_gil([&] { return rate::compute_param_direction_map(p, s, axis, theta_n, o); });
  pyb::dict d;
  d["param"] = param;
  d["x"] = axis_values(map.axis);
  d["theta"] = to_numpy(map.theta);
  d["count"] = grid(map.count, n, theta_n);
  d["types"] = grid(map.types, n, theta_n);
  d["disagree"] = map.disagree.empty() ? pyb::object(pyb::none())
                                       : pyb::object(grid(map.disagree, n, theta_n));
  d["disagreements"] = map.disagreements;
  d["unreliable"] = map.unreliable;
  d["cross_checked"] = map.cross_checked;
  d["critical_values"] = critical_values(map.critical_values);
  d["critical_directions"] = list_of(map.critical_directions, [](const auto& c) {
    pyb::dict e = summary_dict(c.summary);
    e["x"] = c.x;
    e["theta"] = c.theta;
    e["conditions"] = c.conditions;
    return e;
  });
  d["seconds"] = map.seconds;
  d["threads"] = map.threads;
  return d;
}

pyb::dict param_param_map(const pyb::object& params, const pyb::object& state,
                          const std::string& param1, double from1, double to1, int n1,
                          const std::string& param2, double from2, double to2, int n2,
                          const std::string& method, int threads) {
  const auto p = parameters_from(params);
  const auto s = state_from(state, p);
  const auto o = map_options(method, threads);
  const auto a1 = axis_from(param1, from1, to1, n1);
  const auto a2 = axis_from(param2, from2, to2, n2);
  check_memory(5.0 * n1 * n2, "the map of " + std::to_string(n1) + " x " + std::to_string(n2) +
                                  " (n1 x n2) cells");
  rate::ParamParamMap map =
      without_gil([&] { return rate::compute_param_param_map(p, s, a1, a2, o); });
  pyb::dict d;
  d["param1"] = param1;
  d["param2"] = param2;
  d["x"] = axis_values(map.axis1);
  d["y"] = axis_values(map.axis2);
  d["cls"] = grid(map.cls, n1, n2);
  d["min_count"] = grid(map.min_count, n1, n2);
  d["max_count"] = grid(map.max_count, n1, n2);
  d["types"] = grid(map.types, n1, n2);
  d["disagreements"] = map.disagreements;
  d["inconsistent_sectors"] = map.inconsistent_sectors;
  d["unreliable"] = map.unreliable;
  d["cross_checked"] = map.cross_checked;
  d["critical_curve"] = critical_values(map.critical_curve);
  d["seconds"] = map.seconds;
  d["threads"] = map.threads;
  return d;
}

}  // namespace

void bind_maps(pyb::module_& m) {
  m.def("direction_map", &direction_map);
  m.def("param_direction_map", &param_direction_map);
  m.def("param_param_map", &param_param_map);
  pyb::dict bits;
  for (int t = 0; t <= static_cast<int>(rate::SolutionType::kSlipMinus); ++t)
    bits[pyb::str(std::string(rate::to_string(static_cast<rate::SolutionType>(t))))] = 1 << t;
  m.attr("TYPE_BITS") = bits;
  pyb::list classes;
  for (auto c : {rate::UniquenessClass::kUniqueAll, rate::UniquenessClass::kNonUniqueSome,
                 rate::UniquenessClass::kNoSolutionSome})
    classes.append(std::string(rate::to_string(c)));
  m.attr("UNIQUENESS_CLASSES") = classes;
  // The one table of map parameters (map_parameter_table.hpp), as the CLI checks them.
  pyb::list params;
  for (const auto& r : rate::map_parameter_table()) {
    pyb::list dims;
    for (auto d : {rate::kMapOnePoint, rate::kMapNPoints, rate::kMap3d})
      if (r.dimensions & d) dims.append(std::string(rate::to_string(d)));
    pyb::dict row;
    row["name"] = r.name;
    row["dimensions"] = dims;
    row["per_point"] = r.per_point;
    row["applied"] = r.applied;
    row["validated"] = r.validated;
    params.append(row);
  }
  m.attr("MAP_PARAMETERS") = params;
}

}  // namespace cpkit::py
