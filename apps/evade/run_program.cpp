// Helper programs of the CLI through posix_spawnp and waitpid (see run_program.hpp).
#include "run_program.hpp"

#include <spawn.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>  // environ (g++ defines _GNU_SOURCE)

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "evade/config/scenario.hpp"

namespace evade::cli {

int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr) {
  if (argv.empty()) return -1;
  std::vector<std::string> owned = argv;  // posix_spawnp takes char* const[]
  std::vector<char*> args;
  args.reserve(owned.size() + 1);
  for (std::string& a : owned) args.push_back(a.data());
  args.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  if (posix_spawn_file_actions_init(&actions) != 0) return -1;
  int rc = 0;
  if (stdout_to_stderr)
    rc = posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  pid_t pid = -1;
  if (rc == 0) rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  // Only frees the action list; the child, if started, is unaffected by a failure here.
  (void)posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;

  int status = 0;
  pid_t done = -1;
  do {
    done = waitpid(pid, &status, 0);
  } while (done == -1 && errno == EINTR);
  if (done != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

std::string python_interpreter() {
  return ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
}

std::string plot_script(const std::string& name) {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("EVADE_SCRIPT_DIR"); env != nullptr && *env != '\0') {
    dirs.emplace_back(env);
  }
  for (const std::string& d : config::scenario_search_dirs()) dirs.push_back(d + "/../scripts");
  std::string searched;
  for (const std::string& dir : dirs) {
    std::string p = dir;  // not const: returned by move
    p.append("/").append(name);
    if (std::ifstream(p).good()) return p;
    searched.append(searched.empty() ? "" : ", ").append(dir);
  }
  throw std::runtime_error("plot script " + name + " not found (searched: " + searched + ")");
}

}  // namespace evade::cli
