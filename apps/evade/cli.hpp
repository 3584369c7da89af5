// The evade CLI's command registry and the options every command shares.
//
// A command lives in apps/evade/cmd_<name>.cpp and registers itself at static-init time:
//
//   evade::cli::Runner setup(CLI::App& app) {
//     auto opts = std::make_shared<MyOptions>();
//     evade::cli::add_common_options(app, opts->common);
//     app.add_option("--seed", opts->seed, "... [-]");  // a number: its unit in brackets
//     return [opts]() { return run_my_command(*opts); };   // returns the exit code
//   }
//   const bool kRegistered = evade::cli::register_command(
//       {{"plan", "observability"}, "Observability-minimizing burn (paper 004)", &setup});
//
// The registration is plain pointers into a fixed table, so static initialization cannot
// throw (an exception there would end the process before main could report it); setup
// runs, and may throw, from main.
//
// Diagnostics and progress go to stderr as `(void)std::fprintf(stderr, ...)`: a failed print
// there has no recovery (there is nowhere else to report it) and must not change a command's
// result, so its return value is discarded explicitly.
//
// Help texts: a number's help ends with its unit in brackets ("[s]", "[m/s^2]", "[-]" for a
// count or an id), and the option keeps a numeric type so that CLI11 shows INT or FLOAT (ctest
// cli.NumericFlagsShowTypeAndUnit).
//
// Exit codes (README.md "Exit codes"): 0 success; 1 runtime failure; 2 bad input
// (config::ConfigError or std::invalid_argument thrown by the command, or a CLI11 parse
// error; an unknown command gets the nearest registered one as a suggestion) — the message
// names the key, the value and what is allowed; 3 and 4 for a signed command the node
// refused or did not acknowledge.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/sgp4/catalog.hpp"

namespace evade::cli {

/// --scenario, --set, --json: shared by every command that reads a scenario.
struct CommonOptions {
  std::string scenario;            ///< shipped name or path
  std::vector<std::string> sets;   ///< key.path=value overrides, applied in order
  bool json = false;               ///< machine-readable result on stdout
};

using Runner = std::function<int()>;
/// Adds a command's options to its subcommand; returns what runs the command.
using Setup = Runner (*)(CLI::App&);

/// One command of the CLI, as registered (string literals and a function: no allocation).
struct Command {
  std::array<const char*, 2> path;  ///< {"sim"} or {"plan", "threat-area"} (group, name)
  const char* description;
  Setup setup;
};

/// Registers a command. Returns true so it can initialize a static; false if the table is
/// full (main then refuses to run and says so).
bool register_command(const Command& command) noexcept;

/// Adds --scenario (required unless default_scenario is given), --set and --json.
void add_common_options(CLI::App& app, CommonOptions& opts,
                        const std::string& default_scenario = "");

/// Loads the scenario named by --scenario and applies every --set, in order.
config::Scenario load_scenario(const CommonOptions& opts);

/// The whole text of a file; std::invalid_argument "FLAG: cannot open 'PATH'" if it cannot
/// be read.
std::string read_text_file(const std::string& path, const std::string& flag);

/// The catalog of --tle TLE_PATH (two- or three-line element sets) or, when TLE_PATH is empty,
/// of --omm OMM_PATH (OMM KVN/XML, GP JSON/CSV); malformed entries are the catalog's issues.
sgp4::Catalog read_catalog_file(const std::string& tle_path, const std::string& omm_path);

/// Prints a JSON document on stdout (pretty, 2-space indent) followed by a newline.
void print_json(const nlohmann::json& j);

/// A command's result on stdout: its JSON with --json, else its text.
void print_result(bool json, const nlohmann::json& j, const std::string& text);

}  // namespace evade::cli
