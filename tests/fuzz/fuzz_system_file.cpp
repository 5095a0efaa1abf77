// Fuzz target: the system-file readers (2-D: system/contact_system.hpp; "dim": 3:
// three_d/system_3d.hpp), and for an accepted one-point 3-D system with a dF its exact rate
// problem. Any input must end in success or cpkit::InputError: every other exception, crash,
// sanitizer report or failed invariant below is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/three_d/point_rate_3d.hpp"
#include "cpkit/rate_problem/three_d/system_3d.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (cpkit::rate3d::is_3d_system(text)) {
      const auto sys = cpkit::rate3d::parse_contact_system_3d(text, "fuzz");
      if (sys.A.rows() != 3 * sys.n_points()) std::abort();
      if (sys.n_points() == 1 && sys.dF) {
        const auto s = cpkit::rate3d::solve_rate_3d(sys.point_parameters(0), sys.points[0].state, *sys.dF);
        if (!s.complete && s.message.empty()) std::abort();  // incomplete always says why
      }
    } else {
      const auto sys = cpkit::rate::parse_contact_system(text, "fuzz");
      if (sys.A.rows() != 2 * sys.n_points() || !sys.validate().empty()) std::abort();
    }
  } catch (const cpkit::InputError&) {
    return 0;  // rejected with a message
  }
  return 0;
}
