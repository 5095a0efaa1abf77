// Maps of a "dim": 3 system (docs/contact_3d.md) over the sphere of load directions and over
// parameters, as numpy grids; the 2-D maps are bind_maps.cpp. The system is the parsed
// _cpkit.ContactSystem3dData (bind_system.cpp). The GIL is released while C++ computes.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::py {
namespace {

/// Map options of a system: facets (0 exact), point (1-based, as the CLI's --point), the other
/// points' load rates ("auto": the file's dF when N > 1 and the file has one, as the CLI;
/// "zero"; "file").
rate::Map3dOptions map_options(const rate::ContactSystem3d& sys, int facets, int point,
                                 const std::string& others, int threads) {
  rate::Map3dOptions o;
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

rate::Map3dAxis axis_from(const std::string& param, double from, double to, int n, int n_points,
                            const char* which) {
  rate::Map3dAxis a;
  a.param = rate::parse_map_3d_parameter(param, n_points);
  a.from = from;
  a.to = to;
  a.n = n;
  throw_if_invalid(a.validate(), which);
  return a;
}

void check_cells(double rows, double cols, const std::string& what) {
  if (rows * cols > static_cast<double>(rate::kMaxMap3dCells))
    throw InputError(what + " must be at most " + std::to_string(rate::kMaxMap3dCells) + " cells");
  check_memory(2 * 3.0 * rows * cols, "the map of " + what);  // the C++ map and its numpy copy
}

template <class T>
pyb::array_t<T> grid(const std::vector<T>& v, int rows, int cols) {
  pyb::array_t<T> a({static_cast<pyb::ssize_t>(rows), static_cast<pyb::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

pyb::dict map_dict(const rate::Map3d& m, const rate::Map3dOptions& o) {
  pyb::dict d;
  d["x"] = to_numpy(m.x);
  d["y"] = to_numpy(m.y);
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
    if (m.type_cells[mask] > 0) types[pyb::str(rate::type_mask_string(mask))] = m.type_cells[mask];
  d["type_cells"] = types;
  d["route"] = o.facets ? "faceted" : "exact";
  d["facets"] = o.facets;
  d["point"] = o.point + 1;
  d["others"] = o.others_from_file ? "file" : "zero";
  d["seconds"] = m.seconds;
  d["threads"] = m.threads;
  return d;
}

pyb::dict sphere_map_3d(const rate::ContactSystem3d& sys, int n_beta, int n_gamma,
                        double beta_from, double beta_to, int facets, int point,
                        const std::string& others, int threads) {
  const rate::Map3dOptions o = map_options(sys, facets, point, others, threads);
  rate::SphereGrid g;
  g.n_beta = n_beta;
  g.n_gamma = n_gamma;
  g.beta_from = beta_from;
  g.beta_to = beta_to;
  throw_if_invalid(g.validate(), "sphere grid");
  check_cells(n_beta, n_gamma, std::to_string(n_beta) + " x " + std::to_string(n_gamma) +
                                   " (n_beta x n_gamma)");
  rate::Map3d m = without_gil([&] { return rate::compute_sphere_map_3d(sys, g, o); });
  pyb::dict d = map_dict(m, o);
  d["kind"] = "sphere";
  return d;
}

pyb::dict param_direction_map_3d(const rate::ContactSystem3d& sys, const std::string& param,
                                 double from, double to, int n, int theta_n, double theta_from,
                                 double theta_to, double gamma, int facets, int point,
                                 const std::string& others, int threads) {
  const rate::Map3dOptions o = map_options(sys, facets, point, others, threads);
  const rate::Map3dAxis a = axis_from(param, from, to, n, sys.n_points(), "axis");
  if (theta_n < 1 || theta_n > 1000000)
    throw InputError("theta_n must be in [1, 1000000], got " + std::to_string(theta_n));
  check_cells(n, theta_n, std::to_string(n) + " x " + std::to_string(theta_n) + " (n x theta_n)");
  rate::Map3d m = without_gil([&] {
    return rate::compute_param_direction_map_3d(sys, a, theta_n, theta_from, theta_to, gamma, o);
  });
  pyb::dict d = map_dict(m, o);
  d["kind"] = "param-direction";
  d["param"] = a.param.name();
  d["gamma"] = gamma;
  return d;
}

pyb::dict param_param_map_3d(const rate::ContactSystem3d& sys, const std::string& param1,
                             double from1, double to1, int n1, const std::string& param2,
                             double from2, double to2, int n2, int facets, int point,
                             const std::string& others, int threads) {
  const rate::Map3dOptions o = map_options(sys, facets, point, others, threads);
  const rate::Map3dAxis a1 = axis_from(param1, from1, to1, n1, sys.n_points(), "first axis");
  const rate::Map3dAxis a2 = axis_from(param2, from2, to2, n2, sys.n_points(), "second axis");
  check_cells(n1, n2, std::to_string(n1) + " x " + std::to_string(n2) + " (n1 x n2)");
  rate::Map3d m = without_gil([&] { return rate::compute_param_param_map_3d(sys, a1, a2, o); });
  pyb::dict d = map_dict(m, o);
  d["kind"] = "param-param";
  d["param1"] = a1.param.name();
  d["param2"] = a2.param.name();
  return d;
}

}  // namespace

void bind_maps_3d(pyb::module_& m) {
  m.def("sphere_map_3d", &sphere_map_3d, pyb::arg("system"), pyb::arg("n_beta"),
        pyb::arg("n_gamma"), pyb::arg("beta_from"), pyb::arg("beta_to"), pyb::arg("facets"),
        pyb::arg("point"), pyb::arg("others"), pyb::arg("threads"));
  m.def("param_direction_map_3d", &param_direction_map_3d, pyb::arg("system"),
        pyb::arg("param"), pyb::arg("from_"), pyb::arg("to"), pyb::arg("n"), pyb::arg("theta_n"),
        pyb::arg("theta_from"), pyb::arg("theta_to"), pyb::arg("gamma"), pyb::arg("facets"),
        pyb::arg("point"), pyb::arg("others"), pyb::arg("threads"));
  m.def("param_param_map_3d", &param_param_map_3d, pyb::arg("system"), pyb::arg("param1"),
        pyb::arg("from1"), pyb::arg("to1"), pyb::arg("n1"), pyb::arg("param2"), pyb::arg("from2"),
        pyb::arg("to2"), pyb::arg("n2"), pyb::arg("facets"), pyb::arg("point"),
        pyb::arg("others"), pyb::arg("threads"));
}

}  // namespace cpkit::py
