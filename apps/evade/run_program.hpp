// Runs a helper program of the CLI (the plot scripts) without a shell: the arguments reach it
// as they are (no quoting, no word splitting, no expansion of a path's characters).
#pragma once

#include <string>
#include <vector>

namespace evade::cli {

/// Runs argv (argv[0] looked up through PATH unless it contains a '/') and waits for it. With
/// stdout_to_stderr its standard output goes to our stderr (so that a --json document on
/// stdout stays the only thing there). Returns its exit status, or -1 if it could not be
/// started or did not exit normally (killed by a signal).
int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr);

/// argv joined by spaces, for messages.
std::string command_line(const std::vector<std::string>& argv);

}  // namespace evade::cli
