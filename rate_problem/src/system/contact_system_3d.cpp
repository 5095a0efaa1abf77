// The "dim": 3 system file (contact_system_3d.hpp).
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

#include <nlohmann/json.hpp>

#include "json_fields.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/spd.hpp"

namespace cpkit::rate {
namespace {

/// A point's material (friction, compliance, wear, ellipse); A's block is the caller's.
ContactParameters3d material_of(const SystemPoint3d& pt) {
  ContactParameters3d p;
  static_cast<InterfaceParameters&>(p) = pt;
  p.alpha = pt.alpha;
  return p;
}

using nlohmann::json;
using rate::detail::get_num;
using rate::detail::point_name;
using rate::detail::shown;

/// Relative asymmetry of A tolerated (rounding of a condensed FE stiffness; as the 2-D file).
constexpr double kSymTol = 1e-10;
/// Reciprocal condition estimate below which A is called numerically singular (as the 2-D file).
constexpr double kRcondMin = 1e-13;

Eigen::VectorXd get_vector(const json& v, std::size_t n, const std::string& field,
                           const char* layout) {
  if (!v.is_array() || v.size() != n)
    throw InputError(field + " must be an array of " + std::to_string(n) + " numbers (" + layout +
                     "), got " + shown(v));
  Eigen::VectorXd x(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    x(static_cast<Eigen::Index>(i)) = get_num(v[i], field + "[" + std::to_string(i) + "]");
  return x;
}

SystemPoint3d parse_point(const json& v, std::size_t i) {
  const std::string pn = point_name(i);
  if (!v.is_object()) throw InputError(pn + ": must be an object, got " + shown(v));
  SystemPoint3d p;
  std::string state = "b";
  bool state_given = false, P_T_given = false, P_N_given = false;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string& k = it.key();
    const std::string f = pn + ": " + k;
    if (rate::detail::read_interface_key(k, *it, f, p.mu, p.C_T, p.k_a, p.P_s)) continue;
    if (k == "alpha") p.alpha = get_vector(*it, 2, f, "alpha_X, alpha_Y");
    else if (k == "P_T") p.state.P_T = get_vector(*it, 2, f, "P_TX, P_TY"), P_T_given = true;
    else if (k == "P_N") p.state.P_N = get_num(*it, f), P_N_given = true;
    else if (k == "state") {
      if (!it->is_string() || it->get<std::string>().size() != 1)
        throw InputError(f + " must be \"a\", \"b\", \"c\" or \"d\", got " + shown(*it));
      state = it->get<std::string>();
      state_given = true;
    } else {
      throw InputError(pn + ": unknown key \"" + k +
                       "\" (known for dim 3: state, mu, C_T, k_a, P_s, alpha, P_N, P_T)");
    }
  }
  if (!state_given) throw InputError(pn + ": give \"state\" (a, b, c or d)");
  p.state.state = state[0];
  if ((state == "c" || state == "d") && !P_N_given)
    throw InputError(pn + ": state " + state + " needs P_N");
  if (state == "d" && !P_T_given)
    throw InputError(pn + ": state d needs P_T = [P_TX, P_TY] on the ellipse ||P_T|| = mu P_N");
  const ContactParameters3d par = material_of(p);
  if (const std::string e = par.validate(); !e.empty()) throw InputError(pn + ": " + e);
  if (const std::string e = p.state.validate(par); !e.empty()) throw InputError(pn + ": " + e);
  return p;
}

}  // namespace

ContactParameters3d ContactSystem3d::point_parameters(int i) const {
  const SystemPoint3d& pt = points.at(static_cast<std::size_t>(i));
  ContactParameters3d p = material_of(pt);
  p.A = A.block<3, 3>(3 * i, 3 * i);
  return p;
}

ContactSystem3d parse_contact_system_3d(const rate::SystemFile& file) {
  const json& doc = file.document;
  const std::string& source = file.source;
  try {
    if (!doc.is_object()) throw InputError("the system file must be a JSON object");
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      const std::string& k = it.key();
      if (k != "name" && k != "dim" && k != "A" && k != "points" && k != "dF")
        throw InputError("unknown key \"" + k + "\" (known for dim 3: name, dim, A, points, dF)");
    }
    if (file.dim != 3) throw InputError("dim must be 3 here (the 3-D reader)");
    ContactSystem3d sys;
    if (doc.contains("name")) {
      if (!doc["name"].is_string()) throw InputError("name must be a string");
      sys.name = doc["name"].get<std::string>();
    }
    if (!doc.contains("points")) throw InputError("missing \"points\" (one object per contact point)");
    if (!doc.contains("A")) throw InputError("missing \"A\" (the 3N x 3N stiffness)");
    const json& pts = doc["points"];
    if (!pts.is_array() || pts.empty())
      throw InputError("points must be a non-empty array of point objects");
    const std::size_t n = 3 * pts.size();
    const json& Aj = doc["A"];
    if (!Aj.is_array() || Aj.size() != n)
      throw InputError("A must be an array of 3N = " + std::to_string(n) + " rows (T_X, T_Y, N per point)");
    sys.A.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r)
      sys.A.row(static_cast<Eigen::Index>(r)) =
          get_vector(Aj[r], n, "A[" + std::to_string(r) + "]", "a row of A").transpose();
    // as the 2-D file: symmetric to 1e-10 relative, positive definite judged scale-free (spd.hpp)
    throw_if_invalid(check_spd(sys.A, kSymTol, kRcondMin).message);
    symmetrize(sys.A);  // remove the rounding asymmetry kSymTol allows
    for (std::size_t i = 0; i < pts.size(); ++i) sys.points.push_back(parse_point(pts[i], i));
    if (doc.contains("dF")) sys.dF = get_vector(doc["dF"], n, "dF", "T_X, T_Y, N per point");
    return sys;
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
}

ContactSystem3d parse_contact_system_3d(const std::string& json_text, const std::string& source) {
  return parse_contact_system_3d(rate::parse_system_file(json_text, source));
}

ContactSystem3d read_contact_system_3d(const std::string& path) {
  return parse_contact_system_3d(rate::read_system_file(path));
}

}  // namespace cpkit::rate
