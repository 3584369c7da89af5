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

/// The one interpreter of the plot scripts: /usr/bin/python3 (where scripts/setup installs
/// matplotlib) when it exists, else python3 from PATH.
std::string python_interpreter();

/// The plot script `name` (e.g. "plot_sim.py"): $EVADE_SCRIPT_DIR, then <dir>/../scripts of
/// every scenario search directory (the source tree's scripts/; an installed tree's
/// <prefix>/share/evade/scripts). Throws std::runtime_error naming what was searched.
std::string plot_script(const std::string& name);

}  // namespace evade::cli
