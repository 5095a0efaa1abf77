// N-point contact systems (rate_problem/system/): the Python ContactSystem is plain data that
// is handed over as the JSON of a system file, so that the one reader (parse_contact_system)
// validates it with its own messages (field and point named, docs/file_formats.md).
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::py {

rate::ContactSystem system_from_json(const std::string& json_text) {
  return rate::parse_contact_system(json_text, "system");
}

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

void bind_system(pyb::module_& m) {
  m.def("system_normalized", [](const std::string& json_text) {
    return system_to_dict(system_from_json(json_text));
  });
  m.def("system_from_file", [](const std::string& path) {
    return system_to_dict(rate::read_contact_system(path));
  });
}

}  // namespace cpkit::py
