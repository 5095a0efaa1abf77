#pragma once
/// \file step_state.hpp
/// The known state at the start of a step, one type for 2-D and 3-D: the tangential force is a
/// scalar in 2-D (StepState) and a 2-vector (X, Y) in 3-D (Step3dState).
#include <type_traits>

namespace cpkit::rate {

template <class Tangent>
struct StepStateOf {
  Tangent P_T0 = zero();  ///< tangential contact force
  double P_N0 = 0;        ///< normal contact force, >= 0
  double g0 = 0;          ///< gap function w_N - w^w, <= 0 (0 in contact); P_N0 g0 = 0

 private:
  static Tangent zero() {
    if constexpr (std::is_arithmetic_v<Tangent>)
      return 0;
    else
      return Tangent::Zero();
  }
};

}  // namespace cpkit::rate
