// Fuzz target: the Matrix Market matrix reader (cpkit::parse_matrix_market), the M of an LCP.
// README.md describes the pattern.
#include <cmath>
#include <cstdint>

#include "cpkit/core/io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [size](const std::string& text) {
    const cpkit::SparseMat m = cpkit::parse_matrix_market(text, "input.mtx");
    cpkit::fuzz::require(m.rows() >= 1 && m.rows() <= cpkit::kMaxMatrixMarketDimension &&
                             m.cols() >= 1 && m.cols() <= cpkit::kMaxMatrixMarketDimension,
                         "Matrix Market sizes outside the documented limits");
    // Each stored entry comes from a line of the file (mirrored once when symmetric).
    cpkit::fuzz::require(static_cast<std::size_t>(m.nonZeros()) <= 2 * size,
                         "more entries than the file holds");
    for (Eigen::Index k = 0; k < m.outerSize(); ++k)
      for (cpkit::SparseMat::InnerIterator it(m, k); it; ++it)
        cpkit::fuzz::require(std::isfinite(it.value()), "a non-finite Matrix Market entry");
  });
  return 0;
}
