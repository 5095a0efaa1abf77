#pragma once
// Test helper (not a test): what a test does when a peer it needs is missing (python3-siconos,
// lrsnash, mpirun, numpy, matplotlib, the built `cpkit` program). Normally the check is skipped,
// saying why, and ctest reports the test as "Skipped" (exit 77 = SKIP_RETURN_CODE, set for every
// test program in tests/CMakeLists.txt). Where every peer is installed (CI), a missing peer is a
// failure instead: CPKIT_REQUIRE_PEERS=1, or CI=true unless CPKIT_REQUIRE_PEERS=0. The same
// switch is read by python/tests/run_pytest.py and tests/scripts/run_skippable.py.
#include <catch2/catch.hpp>

#include <cctype>
#include <cstdlib>
#include <iostream>
#include <string>

namespace cpkit::test {

/// True where a missing peer fails the test rather than skipping it.
inline bool peers_required() {
  const char* r = std::getenv("CPKIT_REQUIRE_PEERS");
  if (r != nullptr && *r != 0) return std::string(r) == "1";
  const char* ci = std::getenv("CI");
  return ci != nullptr && (std::string(ci) == "true" || std::string(ci) == "1");
}

inline constexpr const char* kRequiredBy = "(a missing peer fails where peers are required: CI=true or "
                                 "CPKIT_REQUIRE_PEERS=1)";

/// The checks skipped so far in this process; catch_main.cpp makes a run that passed with
/// skipped checks exit 77, so that ctest says "Skipped", not "Passed".
inline int& skipped_checks() {
  static int n = 0;
  return n;
}

/// Ends the whole test program for a missing peer: exit 77 (ctest: skipped), or exit 1 where
/// peers are required. For a program whose every case needs the peer; a program with other
/// cases uses CPKIT_SKIP_CHECK in the one case instead.
[[noreturn]] inline void skip_program(std::string reason) {
  while (!reason.empty() && std::isspace(static_cast<unsigned char>(reason.back()))) reason.pop_back();
  if (peers_required()) {
    std::cout << "FAILED: " << reason << " " << kRequiredBy << "\n";
    std::exit(1);
  }
  std::cout << "skipped: " << reason << "\n";
  std::exit(77);
}

}  // namespace cpkit::test

/// In a TEST_CASE, where a peer is missing: FAIL where peers are required, else WARN "skipped:
/// REASON" and count it (the program then exits 77). The caller returns after it.
#define CPKIT_SKIP_CHECK(reason)                                                       \
  do {                                                                                 \
    if (cpkit::test::peers_required()) FAIL(reason << " " << cpkit::test::kRequiredBy); \
    WARN("skipped: " << reason);                                                       \
    ++cpkit::test::skipped_checks();                                                   \
  } while (false)
