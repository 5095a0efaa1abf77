#pragma once
// Runs the built `cpkit` program from a test and captures its exit code, stdout and stderr.
// Shared by every test of the command line (tests/apps/*, tests/lcp/test_fb_newton_cli.cpp).
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace cpkit::test {

struct CliRun {
  int code = -1;    ///< exit code (-1: killed by a signal)
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

/// A scratch directory unique to this test process (created on first use).
inline std::filesystem::path scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::random_device rd;
    auto d = std::filesystem::temp_directory_path() /
             ("cpkit_test_" + std::to_string(rd()) + "_" + std::to_string(rd()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `cpkit ARGS` (ARGS is passed through the shell: quote paths yourself).
inline CliRun run_cpkit(const std::string& args) {
  const auto out = scratch_dir() / "stdout.txt";
  const auto err = scratch_dir() / "stderr.txt";
  const std::string cmd = std::string("'") + CPKIT_BINARY_DIR + "/apps/cpkit' " + args + " > '" +
                          out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace cpkit::test
