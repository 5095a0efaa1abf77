// The table of map parameters (map_parameter_table.hpp) and the one check of a name against it.
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"

#include <algorithm>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

namespace {
constexpr unsigned kAll = kMapOnePoint | kMapNPoints | kMap3d;

/// How a row sets a quantity of one point of an N-point system (every point takes it) and of
/// a 3-D system. `field`: a member pointer (the interface's quantities are members of
/// InterfaceParameters, which every point's parameters derive from).
template <auto field>
bool set_point(SystemPoint& p, double v) {
  p.*field = v;
  return true;
}
template <auto field>
void set_point_3d(SystemPoint3d& p, double v) {
  p.*field = v;
}

/// How a row sets a quantity of the model of a one-point map.
template <auto field>
void set_one_point(ContactParameters& p, ContactState&, double v) {
  p.*field = v;
}
void set_one_point_a12_over_a11(ContactParameters& p, ContactState&, double v) {
  p.a12 = v * p.a11;
}
void set_one_point_normal_force(ContactParameters&, ContactState& st, double v) { st.P_N = v; }
void set_one_point_kappa(ContactParameters& p, ContactState& st, double v) {
  if (!(st.P_N > 0))
    throw InputError("map parameter kappa = k_a P_N / (3 P_s) needs P_N > 0 (state c or d)");
  p.k_a = 3.0 * p.P_s * v / st.P_N;
}

/// P_N: of the points in state c or d (a point in state a or b has none).
bool set_normal_force(SystemPoint& p, double v) {
  if (p.state.label != StateLabel::kC && p.state.label != StateLabel::kD) return false;
  p.state.P_N = v;
  p.P_N = v;
  return true;
}

std::string where_it_applies(unsigned dims) {
  std::string s;
  for (MapDimension d : {kMapOnePoint, kMapNPoints, kMap3d})
    if (dims & d) s += (s.empty() ? "" : ", ") + std::string(to_string(d)) + " maps";
  return s;
}
}  // namespace

std::string_view to_string(MapDimension d) noexcept {
  switch (d) {
    case kMapOnePoint: return "one-point";
    case kMapNPoints: return "N-point";
    case kMap3d: return "3-D";
  }
  return "?";
}

const std::vector<MapParameterRow>& map_parameter_table() {
  static const std::vector<MapParameterRow> table = {
      {"mu", kAll, true, "friction coefficient (of every point, or of point i)",
       "> 0, with the model (validate) at every grid value before any cell",
       set_one_point<&ContactParameters::mu>, set_point<&SystemPoint::mu>,
       set_point_3d<&SystemPoint3d::mu>},
      {"a11", kMapOnePoint, false, "A_11 of the 2x2 compliance block", "A positive definite",
       set_one_point<&ContactParameters::a11>},
      {"a12", kMapOnePoint, false, "A_12 (= A_21)", "A positive definite",
       set_one_point<&ContactParameters::a12>},
      {"a22", kMapOnePoint, false, "A_22", "A positive definite",
       set_one_point<&ContactParameters::a22>},
      {"a12/a11", kMapOnePoint, false, "A_12 = value * A_11 (A_11 kept)", "A positive definite",
       set_one_point_a12_over_a11},
      {"C_T", kAll, true, "tangential compliance", ">= 0", set_one_point<&ContactParameters::C_T>,
       set_point<&SystemPoint::C_T>, set_point_3d<&SystemPoint3d::C_T>},
      {"k_a", kAll, true, "Archard wear coefficient (k = k_a / (3 P_s))", ">= 0",
       set_one_point<&ContactParameters::k_a>, set_point<&SystemPoint::k_a>,
       set_point_3d<&SystemPoint3d::k_a>},
      {"P_s", kAll, true, "hardness (k = k_a / (3 P_s))", "> 0",
       set_one_point<&ContactParameters::P_s>, set_point<&SystemPoint::P_s>,
       set_point_3d<&SystemPoint3d::P_s>},
      {"P_N", kMapOnePoint | kMapNPoints, true,
       "normal force of the points in state c or d (a sliding point stays on its friction limit)",
       "> 0; N points: point i must be in state c or d, and some point for P_N",
       set_one_point_normal_force, set_normal_force},
      {"kappa", kMapOnePoint, false, "kappa = k_a P_N / (3 P_s): sets k_a = 3 P_s kappa / P_N",
       "needs P_N > 0 (state c or d)", set_one_point_kappa},
      {"coupling", kMapNPoints, false,
       "A(c) = D + c (A - D): the points' own 2x2 blocks kept, the blocks between points scaled",
       "A(c) positive definite"},
      {"alpha_X", kMap3d, true, "half-axis alpha_X of the wear ellipse", "> 0", nullptr, nullptr,
       [](SystemPoint3d& p, double v) { p.alpha(0) = v; }},
      {"alpha_Y", kMap3d, true, "half-axis alpha_Y of the wear ellipse", "> 0", nullptr, nullptr,
       [](SystemPoint3d& p, double v) { p.alpha(1) = v; }},
  };
  return table;
}

std::string MapParameterRef::name() const {
  return point > 0 ? row->name + ("@" + std::to_string(point)) : std::string(row->name);
}

MapParameterRef map_parameter(std::string_view name) {
  const auto& table = map_parameter_table();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const MapParameterRow& r) { return name == r.name; });
  if (it == table.end()) throw InputError("unknown map parameter '" + std::string(name) + "'");
  return MapParameterRef{&*it, 0};
}

std::optional<MapParameterRef> map_parameter_from_string(std::string_view name) {
  // The spellings one-point maps accepted before the table (scripts still use them).
  static constexpr std::pair<const char*, const char*> kOlderSpellings[] = {
      {"ratio", "a12/a11"}, {"a12_a11", "a12/a11"}, {"CT", "C_T"}, {"C_t", "C_T"},
      {"ka", "k_a"},        {"Ps", "P_s"},          {"PN", "P_N"}};
  for (const auto& [old, now] : kOlderSpellings)
    if (name == old) name = now;
  for (const auto& r : map_parameter_table())
    if (name == r.name && (r.dimensions & kMapOnePoint)) return MapParameterRef{&r, 0};
  return std::nullopt;
}

void apply_map_parameter(const MapParameterRef& p, double value, ContactParameters& params,
                         ContactState& state) {
  if (!p.row->set_one_point)
    throw InputError("map parameter '" + p.name() + "' does not apply to one-point maps");
  p.row->set_one_point(params, state, value);
}

std::string map_parameter_names(MapDimension dimension, int n_points) {
  std::string s, at;
  for (const auto& r : map_parameter_table()) {
    if (!(r.dimensions & dimension)) continue;
    s += (s.empty() ? "" : ", ") + std::string(r.name);
    if (r.per_point && dimension != kMapOnePoint) at += (at.empty() ? "" : ", ") + std::string(r.name) + "@i";
  }
  if (!at.empty())
    s += ", or one point's " + at + " with i = 1.." + std::to_string(std::max(1, n_points));
  return s;
}

MapParameterRef check_map_parameter(std::string_view text, MapDimension dimension, int n_points,
                                    const std::string& context) {
  const std::string s(text);
  const auto at = text.find('@');
  const std::string_view base = text.substr(0, at);
  const auto& table = map_parameter_table();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const MapParameterRow& r) { return base == r.name; });
  const std::string kind(to_string(dimension));
  const std::string pre = context.empty() ? "" : context + ": ";
  if (it == table.end())
    throw InputError(pre + "unknown map parameter '" + s + "' for a " + kind +
                     " map (accepted: " + map_parameter_names(dimension, n_points) + ")");
  if (!(it->dimensions & dimension))
    throw InputError(pre + "map parameter '" + std::string(base) + "' does not apply to " +
                     kind + " maps (it applies to " + where_it_applies(it->dimensions) +
                     "; accepted here: " + map_parameter_names(dimension, n_points) + ")");
  MapParameterRef ref{&*it, 0};
  if (at == std::string_view::npos) return ref;
  if (!it->per_point || dimension == kMapOnePoint)
    throw InputError(pre + "map parameter '" + s + "': " + it->name +
                     (dimension == kMapOnePoint ? " of a one-point map has no point number"
                                                : " applies to the whole system, not to one point"));
  const std::string digits(text.substr(at + 1));
  const bool numeric = !digits.empty() && digits.size() <= 9 &&
                       std::all_of(digits.begin(), digits.end(),
                                   [](char c) { return c >= '0' && c <= '9'; });
  const long i = numeric ? std::stol(digits) : 0;
  if (i < 1 || i > n_points)
    throw InputError(pre + "map parameter '" + s + "': the point number must be 1.." +
                     std::to_string(n_points) + " (the system has " + std::to_string(n_points) +
                     " points)");
  ref.point = static_cast<int>(i);
  return ref;
}

}  // namespace cpkit::rate
