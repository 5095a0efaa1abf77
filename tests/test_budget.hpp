#pragma once
// Test helper (not a test): how many members of a seeded random family a test runs.
// The Release suite runs every family at full size. Under AddressSanitizer + UBSan
// (scripts/run-sanitizers.sh; code runs 10-20x slower there) a family runs a smaller prefix of
// the same seeds: that run is there to catch memory and undefined-behaviour errors on every code
// path, which the first members already walk; the statistics (counts of decided cases, agreement
// rates) are asserted at full size in the Release suite. A loop that keeps a minimum count of
// decided cases scales that minimum with the same helper, so no check becomes vacuous.
// Detected from the compiler (GCC's __SANITIZE_ADDRESS__, Clang's __has_feature), never from an
// environment variable, so a Release run cannot be shortened by accident. The CMake option
// CPKIT_TEST_SANITIZED_SIZES compiles the small sizes into a Release build, to check at Release
// speed that every minimum count still holds on the shorter prefix.

namespace cpkit::test {

#if defined(__SANITIZE_ADDRESS__) || defined(CPKIT_TEST_SANITIZED_SIZES)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

/// `release` members in the Release suite, `sanitized` (smaller, at least 1) under the sanitizers.
constexpr int family_size(int release, int sanitized) {
  return kSanitizedBuild ? (sanitized < 1 ? 1 : sanitized) : release;
}

}  // namespace cpkit::test
