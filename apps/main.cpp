// cpkit: the command-line program. Thin: parse, call the library, print.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "blas_threads.hpp"
#include "cli_common.hpp"
#include "cli_options.hpp"
#include "platform/mpi_session.hpp"
#include "run_echo.hpp"
#include "cpkit/core/errors.hpp"

namespace {

/// Runs the command line; returns the exit code. Under mpirun every rank runs it; only rank 0
/// prints errors (they are the same on every rank: the input is).
int run(int argc, char** argv) {
  using namespace cpkit::cli;
  using namespace cpkit;
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
  add_fc_command(app, ctx);
  check_all_option_values(app);  // no empty, non-finite or malformed numbers (cli_options.hpp)
  try {
    const std::string wrong = check_command_words(app, std::vector<std::string>(argv + 1, argv + argc));
    if (!wrong.empty()) {
      std::cerr << "cpkit: " << wrong << '\n';
      return kExitBadInput;
    }
    remember_command_line(app, std::vector<std::string>(argv + 1, argv + argc));
    // One spelling of the load increment, --dF (rate, step); --DF stays an accepted alias so
    // that scripts written for `cpkit step --DF` keep working (issue 27).
    std::vector<std::string> words(argv, argv + argc);
    std::vector<char*> word_ptrs;
    for (std::size_t k = 0; k < words.size(); ++k) {
      std::string& w = words[k];
      if (k > 0 && (w == "--DF" || w.rfind("--DF=", 0) == 0)) w.replace(0, 4, "--dF");
      word_ptrs.push_back(w.data());
      if (w == "--") {  // the rest are values
        for (++k; k < words.size(); ++k) word_ptrs.push_back(words[k].data());
      }
    }
    app.parse(argc, word_ptrs.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // The help of the subcommand that was being parsed (`cpkit fc bench FILE` without --out:
    // that of `cpkit fc bench`, which names --out), not the top-level one.
    std::string path = "cpkit";
    for (const CLI::App* cur = &app; !cur->get_subcommands().empty();) {
      cur = cur->get_subcommands().front();
      path += " " + cur->get_name();
    }
    std::cerr << "cpkit: " << e.what() << "\n(run '" << path << " --help' for usage)\n";
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

}  // namespace

int main(int argc, char** argv) {
  using namespace cpkit::cli;
  using namespace cpkit;
  use_one_blas_thread();
  try {
    mpi::init(&argc, &argv);
  } catch (const cpkit::InputError& e) {
    std::cerr << "cpkit: bad input: " << e.what() << '\n';
    return kExitBadInput;
  }
  if (mpi::rank() != 0) {
    // Other ranks stay quiet: rank 0 reports (the maps send every result to it).
    std::cout.setstate(std::ios::failbit);
    std::cerr.setstate(std::ios::failbit);
  }
  if (mpi::size() > 1 && !(argc > 1 && std::string(argv[1]) == "map")) {
    std::cerr << "cpkit: under mpirun only `cpkit map` runs (the grid maps of N-point systems "
                 "are distributed over the processes); run other commands without mpirun\n";
    mpi::finalize();
    return kExitBadInput;
  }
  const int code = run(argc, argv);
  mpi::finalize();
  return code;
}
