#pragma once
/// \file map_axis.hpp
/// The axis of every grid map (one point, N points, 3-D): n values of one map parameter (a row of
/// the map parameter table, map_parameter_table.hpp) from `from` to `to` inclusive (n = 1: just
/// `from`). The map kinds space their values with different orders of floating-point operations
/// and accept different sizes; the spacing is the template's parameter, so that every kind keeps
/// its own values bit for bit.
#include <string>

#include "cpkit/rate_problem/maps/map_parameter_table.hpp"

namespace cpkit::rate {

/// How an axis computes value i (the same real number, rounded differently).
enum class AxisSpacing {
  kStepThenDivide,  ///< from + (to - from) * i / (n - 1): one-point and N-point maps, n <= 1e5
  kFractionFirst,   ///< from + (to - from) * (i / (n - 1)): 3-D maps, n <= 1e6
};

template <AxisSpacing Spacing>
struct GridAxis {
  MapParameterRef param;  ///< default: mu of every point
  double from = 0, to = 1;
  int n = 100;
  double value(int i) const noexcept {
    if (n <= 1) return from;
    if constexpr (Spacing == AxisSpacing::kStepThenDivide)
      return from + (to - from) * static_cast<double>(i) / (n - 1);
    else
      return from + (to - from) * (static_cast<double>(i) / (n - 1));
  }
  /// Empty when usable: n in range, finite ends, from < to unless n = 1 (each kind's words).
  std::string validate() const;
};

/// One-point and N-point maps (grid_map.hpp, system_grid_map.hpp).
using MapAxis = GridAxis<AxisSpacing::kStepThenDivide>;
using SystemMapAxis = MapAxis;
/// 3-D maps (sphere_map_3d.hpp).
using Map3dAxis = GridAxis<AxisSpacing::kFractionFirst>;

template <>
std::string MapAxis::validate() const;
template <>
std::string Map3dAxis::validate() const;

}  // namespace cpkit::rate
