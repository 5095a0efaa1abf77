// Fuzz target: the numpy .npy reader (cpkit::parse_npy_matrix, parse_npy_vector). README.md
// describes the pattern.
#include <cstdint>

#include "cpkit/core/io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [](const std::string& bytes) {
    const cpkit::Mat M = cpkit::parse_npy_matrix(bytes, "input.npy");
    // the data are exactly the shape's entries: never more than the bytes present
    cpkit::fuzz::require(static_cast<std::size_t>(M.size()) * 8 < bytes.size(),
                         "a .npy matrix larger than its file");
  });
  cpkit::fuzz::run_reader(data, size, [](const std::string& bytes) {
    const cpkit::Vec q = cpkit::parse_npy_vector(bytes, "input.npy");
    cpkit::fuzz::require(static_cast<std::size_t>(q.size()) * 8 < bytes.size(),
                         "a .npy vector larger than its file");
  });
  return 0;
}
