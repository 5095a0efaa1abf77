// The N-point contact system in 2-D and 3-D: the one reader of the JSON system file
// (docs/file_formats.md), the points' fields read by each dimension's kernel, and validation.
#include "cpkit/rate_problem/system/contact_system.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/spd.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"
#include "json_fields.hpp"

namespace cpkit::rate {
namespace {

using nlohmann::json;
using detail::get_num;
using detail::point_name;
using detail::shown;

/// Relative asymmetry of A tolerated (rounding of a condensed FE stiffness); A is symmetrised.
constexpr double kSymTol = 1e-10;
/// Reciprocal condition estimate below which A is called numerically singular.
constexpr double kRcondMin = 1e-13;
/// Relative tolerance for "|P_T| = mu P_N" and "g = 0" when a state label and values are both
/// given (the tolerance of classify()).
constexpr double kClassifyTol = 1e-12;

bool near(double a, double b, double scale) {
  return std::abs(a - b) <= kClassifyTol * (1.0 + scale);
}

// ---- the 2-D kernel: vectors, A, a point given by its state label or its current values ----

Eigen::VectorXd get_vector(const json& v, std::size_t n, const std::string& field) {
  if (!v.is_array()) throw InputError(field + " must be an array of " + std::to_string(n) + " numbers");
  if (v.size() != n)
    throw InputError(field + " has " + std::to_string(v.size()) + " entries, need 2N = " +
                     std::to_string(n) + " (T_1, N_1, T_2, N_2, ...)");
  Eigen::VectorXd x(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    x(static_cast<Eigen::Index>(i)) = get_num(v[i], field + "[" + std::to_string(i) + "]");
  return x;
}

Eigen::MatrixXd get_matrix_2d(const json& v, std::size_t n) {
  if (!v.is_array())
    throw InputError("A must be an array of 2N = " + std::to_string(n) + " rows");
  if (v.size() != n)
    throw InputError("A has " + std::to_string(v.size()) + " rows, need 2N = " + std::to_string(n) +
                     " for the " + std::to_string(n / 2) + " points");
  Eigen::MatrixXd A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t r = 0; r < n; ++r) {
    const std::string row = "A[" + std::to_string(r) + "]";
    if (!v[r].is_array() || v[r].size() != n)
      throw InputError(row + " must be an array of 2N = " + std::to_string(n) + " numbers");
    for (std::size_t c = 0; c < n; ++c)
      A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
          get_num(v[r][c], row + "[" + std::to_string(c) + "]");
  }
  return A;
}

/// One entry of "points": parameters, then the state from the label or from the values.
SystemPoint parse_point(const json& v, std::size_t i, Criterion criterion) {
  const std::string pn = point_name(i);
  if (!v.is_object()) throw InputError(pn + ": must be an object, got " + shown(v));
  SystemPoint p;
  std::optional<std::string> state;
  std::optional<double> P_T, P_N, g;
  std::optional<int> sgn;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string& k = it.key();
    const std::string f = pn + ": " + k;
    if (detail::read_interface_key(k, *it, f, p)) continue;
    if (k == "P_T") P_T = get_num(*it, f);
    else if (k == "P_N") P_N = get_num(*it, f);
    else if (k == "g") g = get_num(*it, f);
    else if (k == "sgnPT") {
      const double s = get_num(*it, f);
      if (s != 1 && s != -1) throw InputError(f + " must be +1 or -1, got " + shown(*it));
      sgn = static_cast<int>(s);
    } else if (k == "state") {
      if (!it->is_string()) throw InputError(f + " must be a string (a, b, c or d), got " + shown(*it));
      state = it->get<std::string>();
    } else {
      throw InputError(pn + ": unknown key \"" + k +
                       "\" (known: state, mu, C_T, k_a, P_s, P_N, sgnPT, P_T, g)");
    }
  }
  ContactParameters par;  // the interface data only; A's block does not matter for classify
  static_cast<InterfaceParameters&>(par) = p;
  par.criterion = criterion;
  {
    const std::string m = par.validate();
    if (!m.empty()) throw InputError(pn + ": " + m);
  }
  if (!state) {
    if (!P_N || !g)
      throw InputError(pn + ": give either \"state\" (with P_N for c/d and sgnPT for d) or the "
                       "current values P_N, g (and P_T)");
    if (sgn) throw InputError(pn + ": sgnPT goes with \"state\": d; with values, P_T gives the sign");
    p.P_T = P_T.value_or(0.0);
    p.P_N = *P_N;
    p.g = *g;
    p.values_given = true;
    ContactConfiguration c;
    c.P_N = p.P_N;
    c.P_T = p.P_T;
    c.w_N = p.g;  // g = w_N - w^w
    try {
      p.state = classify(c, par, kClassifyTol);
    } catch (const InputError& e) {
      std::string m = e.what();
      const std::string prefix = "contact configuration: ";
      if (m.rfind(prefix, 0) == 0) m = m.substr(prefix.size());
      throw InputError(pn + ": the values P_T, P_N, g are inadmissible: " + m);
    }
    return p;
  }
  const auto label = state_from_string(*state);
  if (!label) throw InputError(pn + ": state must be a, b, c or d, got \"" + *state + "\"");
  p.state.label = *label;
  const bool contact = *label == StateLabel::kC || *label == StateLabel::kD;
  if (contact) {
    if (!P_N) throw InputError(pn + ": state " + *state + " needs P_N > 0");
    p.state.P_N = *P_N;
  } else if (P_N && *P_N != 0) {
    throw InputError(pn + ": state " + *state + " has P = 0, got P_N = " + shown(v["P_N"]));
  }
  if (*label == StateLabel::kD) {
    if (!sgn) throw InputError(pn + ": state d needs sgnPT (+1 or -1, the sliding direction)");
    p.state.sgn_PT = *sgn;
  } else if (sgn) {
    throw InputError(pn + ": sgnPT applies to state d only (this point is in state " + *state + ")");
  } else {
    p.state.sgn_PT = 0;
  }
  {
    const std::string m = p.state.validate(par);
    if (!m.empty()) throw InputError(pn + ": " + m);
  }
  // current values implied by the label, checked against the ones given
  p.P_N = p.state.P_N;
  double limit = p.mu * p.P_N;
  if (criterion == Criterion::kSoftening) limit -= par.k() * p.P_N * p.P_N;
  const double implied_PT = *label == StateLabel::kD ? p.state.sgn_PT * limit : 0.0;
  if (P_T) {
    if (*label == StateLabel::kD && !near(*P_T, implied_PT, std::abs(implied_PT)))
      throw InputError(pn + ": state d needs |P_T| = mu P_N = " + std::to_string(limit) +
                       " with the sign of sgnPT, got P_T = " + shown(v["P_T"]));
    if (*label == StateLabel::kC && !(std::abs(*P_T) < limit * (1 - kClassifyTol)))
      throw InputError(pn + ": state c needs |P_T| < mu P_N = " + std::to_string(limit) +
                       ", got P_T = " + shown(v["P_T"]));
    if (!contact && *P_T != 0)
      throw InputError(pn + ": state " + *state + " has P = 0, got P_T = " + shown(v["P_T"]));
    p.P_T = *P_T;
  } else {
    p.P_T = implied_PT;
  }
  if (*label == StateLabel::kA) {
    if (!g) throw InputError(pn + ": state a (open) needs its gap g < 0");
    if (!(*g < 0)) throw InputError(pn + ": state a (open) needs g < 0, got g = " + shown(v["g"]));
    p.g = *g;
  } else {
    if (g && *g != 0)
      throw InputError(pn + ": state " + *state + " is in contact (g = 0), got g = " + shown(v["g"]));
    p.g = 0;
  }
  p.values_given = P_T.has_value() && P_N.has_value() && g.has_value();
  return p;
}

/// A 2-D point's current values (P_T, P_N, g) against its state; empty when consistent.
std::string values_message(const SystemPoint& p, const ContactParameters& par, Criterion criterion) {
  if (!std::isfinite(p.P_T) || !std::isfinite(p.P_N) || !std::isfinite(p.g))
    return "P_T, P_N and g must be finite";
  if (p.state.label == StateLabel::kA && !(p.g < 0)) return "state a (open) needs g < 0";
  if (p.state.label != StateLabel::kA && p.g != 0)
    return "state " + std::string(to_string(p.state.label)) + " is in contact, needs g = 0";
  if ((p.state.label == StateLabel::kA || p.state.label == StateLabel::kB) &&
      (p.P_N != 0 || p.P_T != 0))
    return "state " + std::string(to_string(p.state.label)) + " has P = 0";
  if (p.state.label == StateLabel::kC || p.state.label == StateLabel::kD) {
    if (!near(p.P_N, p.state.P_N, std::abs(p.P_N))) return "P_N differs from the state's P_N";
    double limit = p.mu * p.P_N;
    if (criterion == Criterion::kSoftening) limit -= par.k() * p.P_N * p.P_N;
    if (p.state.label == StateLabel::kD && !near(p.P_T, p.state.sgn_PT * limit, std::abs(limit)))
      return "state d needs P_T = sgnPT mu P_N";
    if (p.state.label == StateLabel::kC && !(std::abs(p.P_T) < limit))
      return "state c needs |P_T| < mu P_N";
  }
  return {};
}

// ---- the 3-D kernel: vectors and rows with their layout, a point given by its state ----

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

Eigen::MatrixXd get_matrix_3d(const json& v, std::size_t n) {
  if (!v.is_array() || v.size() != n)
    throw InputError("A must be an array of 3N = " + std::to_string(n) + " rows (T_X, T_Y, N per point)");
  Eigen::MatrixXd A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t r = 0; r < n; ++r)
    A.row(static_cast<Eigen::Index>(r)) =
        get_vector(v[r], n, "A[" + std::to_string(r) + "]", "a row of A").transpose();
  return A;
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
    if (detail::read_interface_key(k, *it, f, p)) continue;
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
  ContactParameters3d par;  // the interface data and the ellipse; A's block is checked later
  static_cast<InterfaceParameters&>(par) = p;
  par.alpha = p.alpha;
  if (const std::string e = par.validate(); !e.empty()) throw InputError(pn + ": " + e);
  if (const std::string e = p.state.validate(par); !e.empty()) throw InputError(pn + ": " + e);
  return p;
}

/// The keys a file of dimension Dim may have, as the message lists them.
bool known_key(int dim, const std::string& k) {
  const bool both = k == "name" || k == "dim" || k == "A" || k == "points" || k == "dF";
  return both || (dim == 2 && (k == "patterns" || k == "criterion"));
}

}  // namespace

template <int Dim>
PointParametersOf<Dim> ContactSystemOf<Dim>::point_parameters(int i) const {
  if (i < 0 || i >= n_points())
    throw std::out_of_range("ContactSystem::point_parameters: point index " + std::to_string(i) +
                            " out of range [0, " + std::to_string(n_points()) + ")");
  const SystemPointOf<Dim>& p = points[static_cast<std::size_t>(i)];
  PointParametersOf<Dim> c;
  static_cast<InterfaceParameters&>(c) = p;
  const bool has_block = A.rows() >= Dim * i + Dim && A.cols() >= Dim * i + Dim;
  if constexpr (Dim == 2) {
    if (has_block) {
      c.a11 = A(2 * i, 2 * i);
      c.a12 = A(2 * i, 2 * i + 1);
      c.a22 = A(2 * i + 1, 2 * i + 1);
    }
    c.criterion = criterion;
  } else {
    if (has_block) c.A = A.template block<3, 3>(3 * i, 3 * i);
    c.alpha = p.alpha;
  }
  return c;
}

template <int Dim>
std::string ContactSystemOf<Dim>::validate() const {
  std::ostringstream msg;
  const int n = n_points();
  if (n < 1) return "points: the system needs at least one point";
  const Eigen::Index m = Dim * static_cast<Eigen::Index>(n);
  if (A.rows() != m || A.cols() != m) {
    msg << "A is " << A.rows() << " x " << A.cols() << ", need " << Dim << "N x " << Dim
        << "N = " << m << " x " << m << " for the " << n << " points";
    return msg.str();
  }
  if (!A.allFinite()) return "A has a NaN or infinite entry";
  const double amax = A.cwiseAbs().maxCoeff();
  for (Eigen::Index r = 0; r < m; ++r)
    for (Eigen::Index c = r + 1; c < m; ++c)
      if (std::abs(A(r, c) - A(c, r)) > kSymTol * amax) {
        msg << "A is not symmetric: A[" << r << "][" << c << "] = " << A(r, c) << " but A[" << c
            << "][" << r << "] = " << A(c, r) << " (rows and columns 0-based)";
        return msg.str();
      }
  // scale-free: A and A x 1e-300 get the same verdict (spd.hpp)
  if (const SpdVerdict spd = check_spd(A, kSymTol, kRcondMin); !spd.message.empty())
    return spd.message;
  for (int i = 0; i < n; ++i) {
    const SystemPointOf<Dim>& p = points[static_cast<std::size_t>(i)];
    const std::string pn = point_name(static_cast<std::size_t>(i));
    const PointParametersOf<Dim> par = point_parameters(i);
    std::string e = par.validate();
    if (!e.empty()) return pn + ": " + e;
    e = p.state.validate(par);
    if (!e.empty()) return pn + ": " + e;
    if constexpr (Dim == 2) {
      e = values_message(p, par, criterion);
      if (!e.empty()) return pn + ": " + e;
    }
  }
  auto check_vec = [&](const std::optional<Eigen::VectorXd>& v, const char* field) -> std::string {
    if (!v) return {};
    if (v->size() != m) {
      std::ostringstream s;
      s << field << " has " << v->size() << " entries, need " << Dim << "N = " << m;
      return s.str();
    }
    if (!v->allFinite()) return std::string(field) + " has a NaN or infinite entry";
    return {};
  };
  for (auto [v, field] : {std::pair{&dF, "dF"}, std::pair{&pattern1, "patterns[0]"},
                         std::pair{&pattern2, "patterns[1]"}}) {
    const std::string e = check_vec(*v, field);
    if (!e.empty()) return e;
  }
  if (pattern1.has_value() != pattern2.has_value()) return "patterns: give both e1 and e2";
  if (Dim == 3 && (pattern1 || criterion != Criterion::kCoulomb))
    return "3-D points take neither load patterns nor another criterion than Coulomb (38)";
  return {};
}

template <int Dim>
ContactSystemOf<Dim> parse_contact_system_of(const SystemFile& file) {
  const json& doc = file.document;  // an object (parse_system_file)
  try {
    for (auto it = doc.begin(); it != doc.end(); ++it)
      if (!known_key(Dim, it.key()))
        throw InputError("unknown key \"" + it.key() +
                         (Dim == 2 ? "\" (known: name, dim, A, points, dF, patterns, criterion)"
                                   : "\" (known for dim 3: name, dim, A, points, dF)"));
    if (file.dim != Dim)
      throw InputError(Dim == 2 ? "dim 3: three-dimensional points are read by the 3-D reader "
                                  "(docs/contact_3d.md); this command takes 2-D systems (dim 2) only"
                                : "dim must be 3 here (the 3-D reader)");
    ContactSystemOf<Dim> sys;
    if (doc.contains("name")) {
      if (!doc["name"].is_string()) throw InputError("name must be a string");
      sys.name = doc["name"].get<std::string>();
    }
    if (doc.contains("criterion")) {  // 2-D only (known_key)
      const json& c = doc["criterion"];
      std::string s;
      if (c.is_number_integer() || c.is_number_unsigned()) s = std::to_string(c.get<long long>());
      else if (c.is_string()) s = c.get<std::string>();
      const auto crit = criterion_from_string(s);
      if (!crit) throw InputError("criterion must be \"coulomb\" (38) or \"softening\" (35), got " + shown(c));
      sys.criterion = *crit;
    }
    if (!doc.contains("points")) throw InputError("missing \"points\" (one object per contact point)");
    if (!doc.contains("A"))
      throw InputError("missing \"A\" (the " + std::to_string(Dim) + "N x " + std::to_string(Dim) +
                       "N stiffness)");
    const json& pts = doc["points"];
    if (!pts.is_array() || pts.empty())
      throw InputError("points must be a non-empty array of point objects");
    const std::size_t n = Dim * pts.size();
    sys.points.reserve(pts.size());
    if constexpr (Dim == 2) {
      sys.A = get_matrix_2d(doc["A"], n);
      for (std::size_t i = 0; i < pts.size(); ++i)
        sys.points.push_back(parse_point(pts[i], i, sys.criterion));
      if (doc.contains("dF")) sys.dF = get_vector(doc["dF"], n, "dF");
      if (doc.contains("patterns")) {
        const json& p = doc["patterns"];
        if (!p.is_array() || p.size() != 2)
          throw InputError("patterns must be an array of two load patterns [e1, e2]");
        sys.pattern1 = get_vector(p[0], n, "patterns[0]");
        sys.pattern2 = get_vector(p[1], n, "patterns[1]");
      }
    } else {
      // A is judged before the points (its message first when both are wrong)
      sys.A = get_matrix_3d(doc["A"], n);
      throw_if_invalid(check_spd(sys.A, kSymTol, kRcondMin).message);
      symmetrize(sys.A);  // remove the rounding asymmetry kSymTol allows
      for (std::size_t i = 0; i < pts.size(); ++i) sys.points.push_back(parse_point(pts[i], i));
      if (doc.contains("dF")) sys.dF = get_vector(doc["dF"], n, "dF", "T_X, T_Y, N per point");
    }
    throw_if_invalid(sys.validate());
    if constexpr (Dim == 2) symmetrize(sys.A);  // after validate(), which judges the asymmetry
    return sys;
  } catch (const InputError& e) {
    throw InputError(file.source + ": " + e.what());
  }
}

template struct ContactSystemOf<2>;
template struct ContactSystemOf<3>;
template ContactSystem parse_contact_system_of<2>(const SystemFile&);
template ContactSystem3d parse_contact_system_of<3>(const SystemFile&);

ContactSystem parse_contact_system(const SystemFile& file) { return parse_contact_system_of<2>(file); }
ContactSystem parse_contact_system(const std::string& json_text, const std::string& source) {
  return parse_contact_system_of<2>(parse_system_file(json_text, source));
}
ContactSystem read_contact_system(const std::string& path) {
  return parse_contact_system_of<2>(read_system_file(path));
}
ContactSystem3d parse_contact_system_3d(const SystemFile& file) {
  return parse_contact_system_of<3>(file);
}
ContactSystem3d parse_contact_system_3d(const std::string& json_text, const std::string& source) {
  return parse_contact_system_of<3>(parse_system_file(json_text, source));
}
ContactSystem3d read_contact_system_3d(const std::string& path) {
  return parse_contact_system_of<3>(read_system_file(path));
}

}  // namespace cpkit::rate
