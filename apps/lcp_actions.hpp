#pragma once
#include "cli_common.hpp"

namespace cpkit::cli {

void add_lcp_solve(CLI::App& lcp, Context& ctx);      // lcp_solve_command.cpp
void add_lcp_enumerate(CLI::App& lcp, Context& ctx);  // lcp_enumerate_command.cpp
void add_lcp_verify(CLI::App& lcp, Context& ctx);     // lcp_verify_command.cpp

}  // namespace cpkit::cli
