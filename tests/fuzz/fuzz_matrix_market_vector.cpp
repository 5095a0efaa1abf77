// Fuzz target: the Matrix Market vector reader (cpkit::parse_matrix_market_vector), the q of an
// LCP. README.md describes the pattern.
#include <cmath>
#include <cstdint>

#include "cpkit/core/io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [](const std::string& text) {
    const cpkit::Vec q = cpkit::parse_matrix_market_vector(text, "input.q.mtx");
    cpkit::fuzz::require(q.size() >= 1 && q.size() <= cpkit::kMaxMatrixMarketDimension,
                         "a vector size outside the documented limits");
    cpkit::fuzz::require(q.allFinite(), "a non-finite Matrix Market vector entry");
  });
  return 0;
}
