// `cpkit lcp solve|enumerate|verify`: each action lives in its own file.
#include "cli_common.hpp"
#include "lcp_actions.hpp"

namespace cpkit::cli {

void add_lcp_command(CLI::App& app, Context& ctx) {
  auto* lcp = app.add_subcommand("lcp", "Linear complementarity problems: solve, enumerate, verify");
  lcp->require_subcommand(1);
  add_lcp_solve(*lcp, ctx);
  add_lcp_enumerate(*lcp, ctx);
  add_lcp_verify(*lcp, ctx);
}

}  // namespace cpkit::cli
