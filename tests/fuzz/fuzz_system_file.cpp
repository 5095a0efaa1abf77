// Fuzz target: the system-file readers as the commands use them: the file read once and its
// dimension told (system/system_file.hpp), then the 2-D reader (system/contact_system.hpp) or
// the "dim": 3 one (parse_contact_system_3d), and for an accepted one-point 3-D system with a dF
// its exact rate problem. Any input must end in success or cpkit::InputError: every other
// exception, crash, sanitizer report or failed invariant below is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "fuzz_target.hpp"

using cpkit::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [](const std::string& text) {
    const cpkit::rate::SystemFile file = cpkit::rate::parse_system_file(text, "fuzz");
    require(file.dim == 2 || file.dim == 3, "dim is 2 or 3");
    if (file.dim == 3) {
      const auto sys = cpkit::rate::parse_contact_system_3d(file);
      require(sys.A.rows() == 3 * sys.n_points() && sys.A.cols() == sys.A.rows(), "A is 3N x 3N");
      require(sys.A == sys.A.transpose(), "A is returned exactly symmetric");
      if (sys.n_points() == 1 && sys.dF) {
        const auto s = cpkit::rate::solve_rate_3d(sys.point_parameters(0), sys.points[0].state, *sys.dF);
        require(s.complete || !s.message.empty(), "an incomplete answer says why");
      }
    } else {
      const auto sys = cpkit::rate::parse_contact_system(file);
      require(sys.A.rows() == 2 * sys.n_points() && sys.validate().empty(), "the 2-D system validates");
      require(sys.A == sys.A.transpose(), "A is returned exactly symmetric");
    }
  });
  return 0;
}
