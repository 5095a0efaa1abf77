// Fuzz target: the `cpkit simulate` config reader (cpkit/rate_problem/simulation/simulate_config.hpp).
// Links against cpkit_rate_problem (it brings cpkit_core and nlohmann_json).
// Any input must end in success or cpkit::InputError: every other exception,
// crash, sanitizer report or failed invariant below is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/simulate_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  cpkit::rate::SimulateSettings s;
  try {
    cpkit::rate::parse_simulate_config(text, "fuzz", "/nonexistent", s);
    cpkit::rate::validate_simulate_settings(s);
  } catch (const cpkit::InputError&) {
    return 0;  // rejected with a message: the expected outcome for most inputs
  }
  // Accepted settings: building a small history must succeed and have the announced length
  // (large ones are skipped to keep the fuzzer fast; their size check ran above).
  if (s.load_type == "fretting") {
    const long long steps =
        static_cast<long long>(s.fretting.ramp_steps) + 1LL * s.fretting.cycles * s.fretting.steps_per_cycle;
    if (steps <= 100000) {
      const auto h = cpkit::rate::make_simulate_history(s);
      if (static_cast<long long>(h.points.size()) != steps) std::abort();
      if (!h.validate().empty()) std::abort();
    }
  } else if (s.load_type == "ramp" && s.ramp.steps <= 100000) {
    const auto h = cpkit::rate::make_simulate_history(s);
    if (h.points.size() < static_cast<std::size_t>(s.ramp.steps)) std::abort();
    if (!h.validate().empty()) std::abort();
  }
  return 0;
}
