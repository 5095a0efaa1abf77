#pragma once
/// \file timer.hpp
/// Wall-clock stopwatch used for SolveResult::seconds and time limits.
#include <chrono>

namespace cpkit {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }
  bool exceeded(double limit_s) const { return limit_s < 1e300 && seconds() > limit_s; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace cpkit
