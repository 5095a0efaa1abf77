#pragma once
/// \file map_presets.hpp
/// Named map set-ups: the paper's Fig. 5 [Stromberg et al. 1996, Sec. 4.3] and a state-d case
/// in which Lambda (eqn (51)) changes sign inside the map.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::rate {

enum class MapKind { kDirection, kParamDirection, kParamParam };
std::string_view to_string(MapKind k) noexcept;  ///< "direction", "param-direction", "param-param"
std::optional<MapKind> map_kind_from_string(std::string_view s) noexcept;

struct MapPreset {
  std::string name;
  std::string description;
  ContactParameters params;
  ContactState state;
  MapKind kind = MapKind::kDirection;  ///< default kind (the CLI's --kind overrides)
  MapAxis axis;                        ///< default first axis of grid maps
  MapAxis axis2;                       ///< default second axis of param-param maps
  int theta_n = 360;                   ///< default direction resolution of param-direction maps
};

/// fig5a: state b, a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 1 (< a11/a12 = 2: unique);
/// fig5b: the same with mu = 3 (> 2: three solutions in one sector);
/// state-d: state d (P_N = 1, s = +1, k_a = 1.5, P_s = 1, so kappa = 0.5), mu = 1.5, default
///   map mu x direction over mu in [0.2, 2.5]: Lambda = 1.25 - 1.09375 mu changes sign at
///   mu = 8/7;
/// state-d-mu-kappa: the same state, mu x kappa (param-param).
const std::vector<MapPreset>& map_presets();
std::optional<MapPreset> find_map_preset(std::string_view name);

}  // namespace cpkit::rate
