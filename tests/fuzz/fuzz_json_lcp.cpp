// Fuzz target: the JSON LCP reader (cpkit::parse_lcp_json). README.md describes the pattern.
#include <cstdint>

#include "cpkit/core/io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [](const std::string& text) {
    // The origin's folder does not exist: "M_mtx"/"q_mtx" names relative to it cannot open.
    const cpkit::LcpProblem p = cpkit::parse_lcp_json(text, "/nonexistent-cpkit-fuzz/input.json");
    cpkit::fuzz::require(p.validate().empty(), "a JSON problem that does not validate");
    cpkit::fuzz::require(p.size() >= 1, "an empty JSON problem");
  });
  return 0;
}
