#pragma once
// Test helpers (not a test) for runs of `cpkit map` that are interrupted, resumed or
// distributed: shell commands in the background, waiting with a deadline, output comparison.
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace cpkit::test {

/// Exit code of a shell command (-1: killed by a signal).
inline int shell(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The cpkit program of this build, shell-quoted.
inline std::string cpkit_program() { return std::string("'") + CPKIT_BINARY_DIR + "/apps/cpkit'"; }

/// Starts `command` in the background; its exit code lands in `rc_file` when it ends.
inline void start_background(const std::string& command, const std::filesystem::path& rc_file,
                             const std::filesystem::path& log) {
  std::filesystem::remove(rc_file);
  shell("sh -c \"" + command + " > '" + log.string() + "' 2>&1; echo \\$? > '" +
        rc_file.string() + "'\" &");
}

/// Waits until pred() holds or `seconds` pass; returns pred().
template <class Pred>
bool wait_for(Pred pred, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!pred()) {
    if (std::chrono::steady_clock::now() > end) return pred();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

/// Finished chunk files in a map's checkpoint folder PREFIX.parts.
inline int chunk_files(const std::filesystem::path& parts) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(parts, ec))
    n += e.path().extension() == ".bin";
  return n;
}

inline std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// A map summary without the fields that describe the run rather than the map (timings, the
/// processes and threads used, the command line, the file names).
inline nlohmann::json map_result(const std::filesystem::path& json_file) {
  nlohmann::json j = nlohmann::json::parse(file_bytes(json_file));
  for (const char* k : {"seconds", "estimate", "ranks", "rank_cells", "resumed_cells", "run",
                        "threads", "files"})
    j.erase(k);
  return j;
}

}  // namespace cpkit::test
