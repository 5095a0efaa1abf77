// Fuzz target: the Siconos .dat reader (cpkit::parse_lcp_dat). README.md describes the pattern.
#include <cstdint>

#include "cpkit/core/io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [size](const std::string& text) {
    const cpkit::LcpProblem p = cpkit::parse_lcp_dat(text, "input.dat");
    cpkit::fuzz::require(p.validate().empty(), "a .dat problem that does not validate");
    // Every entry of q is a token of the file, so n can never exceed the input's size.
    cpkit::fuzz::require(static_cast<std::size_t>(p.size()) <= size, "n larger than the file");
  });
  return 0;
}
