// The 3-D rate problem (docs/contact_3d.md): one point (exact or faceted) and N points from a
// "dim": 3 system (faceted); the 2-D one is bind_rate.cpp, N points in 2-D bind_system_rate.cpp.
// Results are plain dicts of numbers, 2-vectors as numpy arrays.
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "point3d_from.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::py {
namespace {

using rate::ContactParameters3d;

pyb::dict rates_dict(const rate::Rates3d& r) {
  pyb::dict d;
  put_tn(d, "dP", r.dP_T, r.dP_N);
  put_wear(d, "dw", r.dw_T, r.dw_N, r.dw_Ti, r.dw_w);
  return d;
}

pyb::dict set_dict(const rate::RateSolutionSet3d& set) {
  pyb::list sols = list_of(set.solutions, [](const auto& s) {
    pyb::dict sd;
    sd["type"] = std::string(rate::to_string(s.type));
    sd["kind"] = s.ray ? "ray" : "point";
    sd["at"] = rates_dict(s.at);
    if (s.ray) {
      sd["direction"] = rates_dict(s.direction);
      sd["origin_included"] = s.origin_included;
    }
    put_slip(sd, s.type, s.slip_direction, s.slip_angle);
    return sd;
  });
  pyb::dict d;
  d["solutions"] = sols;
  d["complete"] = set.complete;
  d["message"] = set.message;
  return d;
}

pyb::dict solve_rate_3d(const pyb::object& point, const std::string& state, const pyb::object& P_T,
                        double P_N, const pyb::object& dF, int facets) {
  const ContactParameters3d p = params_from(point);
  rate::ContactState3d s;
  if (state.size() != 1 || state[0] < 'a' || state[0] > 'd')
    throw InputError("state must be 'a', 'b', 'c' or 'd', got '" + state + "'");
  s.state = state[0];
  s.P_T = vec2(P_T, "P_T");
  s.P_N = P_N;
  const Eigen::Vector3d load = vec3(dF, "dF");
  pyb::dict d;
  if (facets > 0) {
    if (s.state != 'b') throw InputError("facets apply to the grazing state b (a, c, d are linear)");
    rate::RateSolutionSet3d r =
        without_gil([&] { return rate::solve_rate_3d_faceted(p, load, facets); });
    d = set_dict(r);
    d["facets"] = r.facets;
    d["route"] = "faceted";
  } else {
    if (const std::string e = s.validate(p); !e.empty()) throw InputError("state: " + e);
    rate::RateSolutionSet3d r = without_gil([&] { return rate::solve_rate_3d(p, s, load); });
    d = set_dict(r);
    d["facets"] = 0;
    d["route"] = "exact";
  }
  return d;
}

pyb::dict solve_system_rate_3d(const rate::ContactSystem3d& sys, const pyb::object& dF, int facets) {
  Eigen::VectorXd load;
  if (dF.is_none()) {
    if (!sys.dF) throw InputError("no load rate: give dF (3N numbers) or put \"dF\" in the system");
    load = *sys.dF;
  } else {
    const auto v = dF.cast<std::vector<double>>();
    if (static_cast<int>(v.size()) != 3 * sys.n_points())
      throw InputError("dF must hold 3N = " + std::to_string(3 * sys.n_points()) + " numbers, got " +
                       std::to_string(v.size()));
    load = Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
  }
  rate::SystemRateSet3d r =
      without_gil([&] { return rate::solve_system_rate_3d_faceted(sys, load, facets); });
  pyb::dict d;
  d["solutions"] = list_of(r.solutions, [](const auto& s) {
    pyb::dict sd;
    sd["types"] = list_of(s.types, [](auto t) { return std::string(rate::to_string(t)); });
    sd["rates"] = list_of(s.rates, rates_dict);
    return sd;
  });
  d["complete"] = r.complete;
  d["message"] = r.message;
  d["facets"] = r.facets;
  d["route"] = "faceted";
  return d;
}

}  // namespace

void bind_rate_3d(pyb::module_& m) {
  m.def("solve_rate_3d", &solve_rate_3d, pyb::arg("point"), pyb::arg("state"), pyb::arg("P_T"),
        pyb::arg("P_N"), pyb::arg("dF"), pyb::arg("facets"));
  m.def("solve_system_rate_3d", &solve_system_rate_3d, pyb::arg("system"), pyb::arg("dF"),
        pyb::arg("facets"));
}

}  // namespace cpkit::py
