// Named map set-ups (docs/maps.md).
#include "cpkit/rate_problem/maps/map_presets.hpp"

namespace cpkit::rate {

std::string_view to_string(MapKind k) noexcept {
  switch (k) {
    case MapKind::kDirection: return "direction";
    case MapKind::kParamDirection: return "param-direction";
    case MapKind::kParamParam: return "param-param";
  }
  return "?";
}

std::optional<MapKind> map_kind_from_string(std::string_view s) noexcept {
  if (s == "direction") return MapKind::kDirection;
  if (s == "param-direction") return MapKind::kParamDirection;
  if (s == "param-param") return MapKind::kParamParam;
  return std::nullopt;
}

namespace {
MapPreset fig5(const char* name, double mu) {
  MapPreset p;
  p.name = name;
  p.params.a11 = 1;
  p.params.a12 = 0.5;
  p.params.a22 = 1;
  p.params.C_T = 0.25;
  p.params.mu = mu;
  p.state.label = StateLabel::kB;
  p.state.P_N = 0;
  p.kind = MapKind::kDirection;
  p.axis = MapAxis{map_parameter("mu"), 0.1, 4.0, 400};
  p.axis2 = MapAxis{map_parameter("C_T"), 0.0, 1.0, 200};
  return p;
}
}  // namespace

const std::vector<MapPreset>& map_presets() {
  static const std::vector<MapPreset> presets = [] {
    std::vector<MapPreset> v;
    MapPreset a = fig5("fig5a", 1.0);
    a.description = "Fig. 5(a): state b, a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 1 < a11/a12";
    v.push_back(a);
    MapPreset b = fig5("fig5b", 3.0);
    b.description = "Fig. 5(b): state b, a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 3 > a11/a12";
    v.push_back(b);

    MapPreset d;
    d.name = "state-d";
    d.description =
        "state d (P_N = 1, sgn P_T = +1, kappa = 0.5), a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, "
        "mu = 1.5; mu x direction over [0.2, 2.5]: Lambda = 0 at mu = 8/7";
    d.params.a11 = 1;
    d.params.a12 = 0.5;
    d.params.a22 = 1;
    d.params.C_T = 0.25;
    d.params.k_a = 1.5;
    d.params.P_s = 1;
    d.params.mu = 1.5;
    d.state.label = StateLabel::kD;
    d.state.P_N = 1;
    d.state.sgn_PT = +1;
    d.kind = MapKind::kParamDirection;
    d.axis = MapAxis{map_parameter("mu"), 0.2, 2.5, 400};
    d.axis2 = MapAxis{map_parameter("kappa"), 0.0, 2.0, 200};
    v.push_back(d);

    MapPreset dk = d;
    dk.name = "state-d-mu-kappa";
    dk.description = "the state-d model, mu in [0.1, 2] x kappa in [0, 2] (param-param)";
    dk.kind = MapKind::kParamParam;
    dk.axis = MapAxis{map_parameter("mu"), 0.1, 2.0, 200};
    dk.axis2 = MapAxis{map_parameter("kappa"), 0.0, 2.0, 200};
    v.push_back(dk);
    return v;
  }();
  return presets;
}

std::optional<MapPreset> find_map_preset(std::string_view name) {
  for (const auto& p : map_presets())
    if (p.name == name) return p;
  return std::nullopt;
}

}  // namespace cpkit::rate
