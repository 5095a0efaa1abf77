#include "call_clock.hpp"

#include <atomic>
#include <chrono>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <x86intrin.h>
#define CPKIT_HAVE_TSC 1
#endif

namespace cpkit::capi {
namespace {

std::uint64_t steady_ns() noexcept {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

#ifdef CPKIT_HAVE_TSC
bool invariant_counter() noexcept {
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (__get_cpuid_max(0x80000000u, nullptr) < 0x80000007u) return false;
  __cpuid(0x80000007u, a, b, c, d);
  return (d >> 8) & 1u;
}

/// The counter's calibration, shared by every thread: the first steady_clock / counter pair
/// (taken together when the process first asks), then the rate once 10 ms have passed (0: not
/// yet).
/// A steady_clock read and the counter at the same moment: the counter read on both sides of
/// the clock read, the narrowest of a few tries kept (a thread preempted between two reads would
/// otherwise pair moments milliseconds apart and skew the rate by that much over 10 ms).
struct ClockPair {
  std::uint64_t ns = 0, ticks = 0, width = ~std::uint64_t{0};  ///< width: ticks between reads
};

ClockPair read_pair() noexcept {
  ClockPair best;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const std::uint64_t before = __rdtsc();
    const std::uint64_t ns = steady_ns();
    const std::uint64_t after = __rdtsc();
    if (after >= before && after - before < best.width)
      best = ClockPair{ns, before + (after - before) / 2, after - before};
  }
  return best;
}

struct Calibration {
  bool usable = invariant_counter();
  ClockPair first = read_pair();
  std::atomic<double> seconds_per_tick{0};
};

Calibration& calibration() noexcept {
  static Calibration c;
  return c;
}

/// Fixes the rate once 10 ms have passed since the first pair (`now_ns`: this call's steady_clock
/// read), from a fresh pair, when both pairs are narrower than 1/1000 of the span between them
/// (else a later call tries again: the span only grows).
void calibrate(Calibration& c, std::uint64_t now_ns) noexcept {
  if (now_ns - c.first.ns < 10'000'000) return;
  const ClockPair now = read_pair();
  if (now.ticks <= c.first.ticks || now.ns <= c.first.ns) return;
  const std::uint64_t span = now.ticks - c.first.ticks;
  if (c.first.width > span / 1000 || now.width > span / 1000) return;
  c.seconds_per_tick.store(1e-9 * static_cast<double>(now.ns - c.first.ns) /
                               static_cast<double>(span),
                           std::memory_order_release);
}
#endif

}  // namespace

CallClock::CallClock() noexcept {
#ifdef CPKIT_HAVE_TSC
  Calibration& c = calibration();
  if (c.usable && c.seconds_per_tick.load(std::memory_order_acquire) > 0) {
    counter_ = true;
    start_ticks_ = __rdtsc();
    return;
  }
#endif
  start_ticks_ = steady_ns();
}

double CallClock::seconds() const noexcept {
#ifdef CPKIT_HAVE_TSC
  Calibration& c = calibration();
  if (counter_) {
    const std::uint64_t now = __rdtsc();
    return now > start_ticks_ ? static_cast<double>(now - start_ticks_) *
                                    c.seconds_per_tick.load(std::memory_order_relaxed)
                              : 0.0;
  }
  const std::uint64_t now_ns = steady_ns();
  if (c.usable) calibrate(c, now_ns);
#else
  const std::uint64_t now_ns = steady_ns();
#endif
  return 1e-9 * static_cast<double>(now_ns - start_ticks_);
}

}  // namespace cpkit::capi
