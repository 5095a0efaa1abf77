#pragma once
// The wall time of one C API call for cpkit_info.seconds, read cheaply. A tiny solve takes
// ~0.05 us; two reads of steady_clock (a VM's kvm-clock: ~25-30 ns each) would double it.
// Where the CPU's time-stamp counter is invariant (x86-64, CPUID 0x80000007 EDX bit 8: constant
// rate, not stopped in sleep states), a read is ~10 ns, and its ticks are converted to seconds
// by a rate measured against steady_clock itself: the first calls of the process read
// steady_clock (as without the counter) and, once 10 ms have passed since the first, fix the
// rate (ticks per second over those >= 10 ms: ~1e-5 relative error from the clock's own
// jitter). Elsewhere (another architecture, no invariant counter), steady_clock throughout.
#include <cstdint>

namespace cpkit::capi {

class CallClock {
 public:
  CallClock() noexcept;
  /// Seconds since construction.
  double seconds() const noexcept;

 private:
  std::uint64_t start_ticks_ = 0;  ///< counter ticks, or steady_clock nanoseconds
  bool counter_ = false;           ///< start_ticks_ is a counter read
};

}  // namespace cpkit::capi
