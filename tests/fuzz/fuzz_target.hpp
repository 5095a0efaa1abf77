#pragma once
// Shared by the fuzz harnesses tests/fuzz/fuzz_<reader>.cpp (README.md): a reader either returns
// a valid result or throws cpkit::InputError. Anything else (another exception, a crash, a
// sanitizer report, a broken invariant) is a finding: exceptions propagate, invariants abort.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cpkit/core/errors.hpp"

namespace cpkit::fuzz {

/// The fuzz input as text (readers take std::string; embedded NUL bytes are kept).
inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Aborts with a message when an invariant of a successful read does not hold.
inline void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz invariant violated: %s\n", what);
    std::abort();
  }
}

/// Runs `read(text)`; an InputError is the reader's correct refusal, so it is swallowed, and
/// its message must be non-empty.
template <class Read>
void run_reader(const std::uint8_t* data, std::size_t size, Read&& read) {
  const std::string text = as_text(data, size);
  try {
    read(text);
  } catch (const InputError& e) {
    require(e.what()[0] != '\0', "InputError with an empty message");
  }
}

}  // namespace cpkit::fuzz
