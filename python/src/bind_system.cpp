// N-point contact systems (rate_problem/system/): the parsed C++ systems as opaque Python objects
// (_cpkit.ContactSystemData, _cpkit.ContactSystem3dData), built ONCE from a system file's JSON
// text or path by the one reader (parse/read_contact_system[_3d]: its validation and messages,
// field and point named, docs/file_formats.md), then handed to every binding that takes a system
// without re-parsing (python/cpkit/system.py keeps them on the Python objects).
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::py {
namespace {

/// The normalised fields (A symmetrised, each point completed with its state) that the Python
/// ContactSystem shows.
pyb::dict system_to_dict(const rate::ContactSystem& s) {
  pyb::dict d;
  d["name"] = s.name;
  d["A"] = pyb::array_t<double>(pyb::cast(Mat(s.A)));
  d["criterion"] = std::string(s.criterion == rate::Criterion::kCoulomb ? "38" : "35");
  pyb::list points;
  for (const auto& p : s.points) {
    pyb::dict pd;
    pd["state"] = std::string(rate::to_string(p.state.label));
    pd["mu"] = p.mu;
    pd["C_T"] = p.C_T;
    pd["k_a"] = p.k_a;
    pd["P_s"] = p.P_s;
    pd["P_N"] = p.P_N;
    pd["P_T"] = p.P_T;
    pd["g"] = p.g;
    if (p.state.label == rate::StateLabel::kD) pd["sgnPT"] = p.state.sgn_PT;
    points.append(pd);
  }
  d["points"] = points;
  d["dF"] = s.dF ? pyb::object(to_numpy(*s.dF)) : pyb::object(pyb::none());
  if (s.pattern1 && s.pattern2)
    d["patterns"] = pyb::make_tuple(to_numpy(*s.pattern1), to_numpy(*s.pattern2));
  else
    d["patterns"] = pyb::none();
  return d;
}

}  // namespace

void bind_system(pyb::module_& m) {
  pyb::class_<rate::ContactSystem>(m, "ContactSystemData",
                                   "A parsed 2-D N-point system (rate::ContactSystem); opaque")
      .def_static("from_json", [](const std::string& json_text) {
        return rate::parse_contact_system(json_text, "system");
      })
      .def_static("from_file", &rate::read_contact_system)
      .def_property_readonly("n_points", &rate::ContactSystem::n_points)
      .def("to_dict", &system_to_dict);
  pyb::class_<rate::ContactSystem3d>(m, "ContactSystem3dData",
                                     "A parsed \"dim\": 3 system (rate::ContactSystem3d); opaque")
      .def_static("from_json", [](const std::string& json_text) {
        return rate::parse_contact_system_3d(json_text, "system");
      })
      .def_static("from_file", &rate::read_contact_system_3d)
      .def_property_readonly("n_points", &rate::ContactSystem3d::n_points)
      .def_property_readonly("name", [](const rate::ContactSystem3d& s) { return s.name; });
}

}  // namespace cpkit::py
