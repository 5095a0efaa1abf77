// cpkit: the command-line program. Thin: parse, call the library, print.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "blas_threads.hpp"
#include "cli_common.hpp"
#include "cli_options.hpp"
#include "run_echo.hpp"
#include "cpkit/core/errors.hpp"

int main(int argc, char** argv) {
  using namespace cpkit::cli;
  use_one_blas_thread();
  CLI::App app{"cpkit: complementarity problems and contact, friction and wear models"};
  // Defaults are recorded so that JSON results can echo every option used (run_echo.hpp).
  app.option_defaults()->always_capture_default();
  app.set_version_flag("--version", std::string("cpkit ") + CPKIT_VERSION);
  app.require_subcommand(1);
  Context ctx;
  add_lcp_command(app, ctx);
  add_map_command(app, ctx);
  add_rate_command(app, ctx);
  add_step_command(app, ctx);
  add_simulate_command(app, ctx);
  check_all_option_values(app);  // no empty, non-finite or malformed numbers (cli_options.hpp)
  try {
    const std::string wrong = check_command_words(app, std::vector<std::string>(argv + 1, argv + argc));
    if (!wrong.empty()) {
      std::cerr << "cpkit: " << wrong << '\n';
      return kExitBadInput;
    }
    remember_command_line(app, std::vector<std::string>(argv + 1, argv + argc));
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "cpkit: " << e.what() << "\n(run 'cpkit --help' for usage)\n";
    return kExitBadInput;
  } catch (const cpkit::InputError& e) {
    std::cerr << "cpkit: bad input: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "cpkit: bad input: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cpkit: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
  return ctx.exit_code;
}
