#include "run_program.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <csignal>
#include <cerrno>
#include <chrono>
#include <thread>
#include <cstring>

extern char** environ;

namespace cpkit::cli {

ProgramRun run_program(const std::vector<std::string>& argv, bool stdout_to_stderr,
                       double time_limit_s) {
  ProgramRun out;
  if (argv.empty()) {
    out.error = "no program given";
    return out;
  }
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdout_to_stderr) posix_spawn_file_actions_adddup2(&actions, 2, 1);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    out.error = "cannot start " + argv[0] + ": " + std::strerror(rc);
    return out;
  }
  out.started = true;
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const pid_t w = waitpid(pid, &status, time_limit_s > 0 ? WNOHANG : 0);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      out.error = std::string("waitpid failed: ") + std::strerror(errno);
      return out;
    }
    if (w == 0) {  // still running (WNOHANG)
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (t > time_limit_s) {
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        out.exit_code = -1;
        out.error = "stopped after " + std::to_string(static_cast<int>(time_limit_s)) +
                    " s (time limit)";
        return out;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (!WIFEXITED(status)) out.error = "killed by signal " + std::to_string(WTERMSIG(status));
  return out;
}

std::string command_text(const std::vector<std::string>& argv) {
  std::string cmd;
  for (const auto& a : argv) {
    std::string q = "'";
    for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    cmd += (cmd.empty() ? "" : " ") + q + "'";
  }
  return cmd;
}

}  // namespace cpkit::cli
