#pragma once
// Siconos .dat side of friction_io.hpp, internal to cpkit_core (friction_io_dat.cpp): the two
// readers, each telling how many tokens it read before failing (`reached`), so that a file
// neither reads is reported by the reader that got further (read_friction_problem_file).
#include <cstddef>
#include <string>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::friction_dat {
FrictionContactProblem parse_local(const std::string& text, const std::string& origin,
                                   std::size_t& reached);
GlobalFrictionContactProblem parse_global(const std::string& text, const std::string& origin,
                                          std::size_t& reached);
}  // namespace cpkit::friction_dat
