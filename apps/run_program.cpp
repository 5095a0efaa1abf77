#include "run_program.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace cpkit::cli {

ProgramRun run_program(const std::vector<std::string>& argv, bool stdout_to_stderr) {
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
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      out.error = std::string("waitpid failed: ") + std::strerror(errno);
      return out;
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
