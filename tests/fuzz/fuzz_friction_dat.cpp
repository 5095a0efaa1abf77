// Fuzz target: the Siconos FrictionContact and GlobalFrictionContact .dat readers
// (cpkit::parse_friction_dat, cpkit::parse_global_friction_dat). README.md describes the pattern.
#include <cstdint>

#include "cpkit/core/friction_io.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [size](const std::string& text) {
    const cpkit::FrictionContactProblem p = cpkit::parse_friction_dat(text, "input.dat");
    cpkit::fuzz::require(p.validate().empty(), "a friction problem that does not validate");
    // Every entry of q and mu is a token of the file: 4 n_c numbers, at least 2 bytes each.
    cpkit::fuzz::require(static_cast<std::size_t>(p.contacts()) * 4 <= size, "n_c larger than the file");
  });
  cpkit::fuzz::run_reader(data, size, [size](const std::string& text) {
    const cpkit::GlobalFrictionContactProblem p = cpkit::parse_global_friction_dat(text, "input.dat");
    cpkit::fuzz::require(p.validate().empty(), "a global friction problem that does not validate");
    cpkit::fuzz::require(static_cast<std::size_t>(p.dofs() + 4 * p.contacts()) <= size,
                         "sizes larger than the file");
  });
  return 0;
}
