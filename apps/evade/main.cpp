// evade CLI entry point: builds the command tree from the registry and maps errors to
// exit codes (0 ok, 1 runtime failure, 2 bad input, including an unknown command, which
// gets the nearest command name as a suggestion).
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "evade/ccsds/catalog_formats.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::cli {
namespace {

// Filled at static-init time (constant-initialized, so usable from any translation unit's
// initializer).
struct Registry {
  static constexpr std::size_t kMaxCommands = 32;
  std::array<Command, kMaxCommands> commands{};
  std::size_t count = 0;
  bool rejected = false;  ///< a registration lacked a field, or did not fit
};

Registry& registry() noexcept {
  static Registry r;
  return r;
}

// The command tree of every registered command: groups ("plan") get a subcommand of their
// own. Returns each command's subcommand and runner.
std::vector<std::pair<CLI::App*, Runner>> build_commands(CLI::App& app) {
  const Registry& reg = registry();
  std::map<std::string, CLI::App*> groups;
  std::vector<std::pair<CLI::App*, Runner>> runners;
  for (std::size_t k = 0; k < reg.count; ++k) {
    const Command& c = reg.commands[k];
    CLI::App* parent = &app;
    const char* name = c.path[0];
    if (c.path[1] != nullptr) {
      auto it = groups.find(c.path[0]);
      if (it == groups.end()) {
        CLI::App* g = app.add_subcommand(c.path[0], std::string(c.path[0]) + " commands");
        g->require_subcommand(1);
        it = groups.emplace(c.path[0], g).first;
      }
      parent = it->second;
      name = c.path[1];
    }
    CLI::App* sub = parent->add_subcommand(name, c.description);
    runners.emplace_back(sub, c.setup(*sub));
  }
  return runners;
}

// Edit distance (insertions, deletions, substitutions) between a and b.
std::size_t levenshtein(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

struct CommandNames {
  std::vector<std::string> top;    // top-level names ("sim", "plan")
  std::vector<std::string> group;  // the second words of the group named by argv[1]
  std::vector<std::string> pairs;  // "plan cam", ...
};

CommandNames command_names(const std::string& w1) {
  const Registry& reg = registry();
  CommandNames n;
  for (std::size_t k = 0; k < reg.count; ++k) {
    const Command& c = reg.commands[k];
    if (std::find(n.top.begin(), n.top.end(), c.path[0]) == n.top.end()) {
      n.top.emplace_back(c.path[0]);
    }
    if (c.path[1] == nullptr) continue;
    n.pairs.push_back(std::string(c.path[0]) + " " + c.path[1]);
    if (w1 == c.path[0]) n.group.emplace_back(c.path[1]);
  }
  return n;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// The name of `names` nearest to typed within an edit distance of 2, or "".
std::string nearest(const std::string& typed, const std::vector<std::string>& names) {
  constexpr std::size_t kMaxDistance = 2;
  std::string best;
  std::size_t best_d = kMaxDistance + 1;
  for (const std::string& n : names) {
    const std::size_t d = levenshtein(typed, n);
    if (d < best_d) {
      best_d = d;
      best = n;
    }
  }
  return best;
}

// When the command words of argv name no registered command ("evade scren", "evade plan
// cma", "evade pln cam"), the message for it: the nearest registered name within an edit
// distance of 2 as a suggestion; "" when the words are a command (the parse error is then
// about something else, and CLI11's message says what).
std::string unknown_command_message(int argc, char** argv) {
  const auto word = [&](int i) -> std::string {
    return i < argc && argv[i][0] != '-' ? std::string(argv[i]) : std::string();
  };
  const std::string w1 = word(1), w2 = w1.empty() ? std::string() : word(2);
  if (w1.empty()) return "";
  const CommandNames names = command_names(w1);
  const bool known_top = contains(names.top, w1);
  // A known command: only a group's second word can be wrong ("plan cma").
  if (known_top && (names.group.empty() || w2.empty() || contains(names.group, w2))) return "";
  std::string typed = w1 + " " + w2;
  // Two words: "pln cam" may also be a two-word command with its first word mistyped.
  std::string best = w2.empty() ? std::string() : nearest(typed, names.pairs);
  if (best.empty() && !known_top) {
    typed = w1;
    best = nearest(w1, names.top);
  }
  std::string msg = "evade: unknown command '" + typed + "'";
  return best.empty() ? msg + " (see evade --help)" : msg + "; did you mean '" + best + "'?";
}

// The first argument no option or command took (a mistyped flag), with the command it was
// given to ("" and "" if none) and that command's parser. CLI11 checks required options before
// unexpected arguments, so `evade keygen --bogus` would otherwise only say "--out is required".
struct Unrecognized {
  std::string flag, path;
  const CLI::App* app = nullptr;
};
Unrecognized first_unrecognized(const CLI::App& app, const std::string& path) {
  for (const std::string& a : app.remaining()) {
    if (!a.empty() && a[0] == '-') return {a, path, &app};
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    Unrecognized r = first_unrecognized(*sub, path + " " + sub->get_name());
    if (!r.flag.empty()) return r;
  }
  return {};
}

// "unknown option" for u, with the command's nearest flag (edit distance <= 2) as a suggestion.
std::string unknown_option_message(const Unrecognized& u) {
  const std::string typed = u.flag.substr(0, u.flag.find('='));
  std::vector<std::string> flags;
  for (const CLI::Option* o : u.app->get_options()) {
    for (const std::string& l : o->get_lnames()) flags.push_back("--" + l);
  }
  const std::string best = nearest(typed, flags);
  const std::string msg = u.path + ": unknown option '" + u.flag + "'";
  return best.empty() ? msg + " (see " + u.path + " --help)"
                      : msg + "; did you mean '" + best + "'? (see " + u.path + " --help)";
}

// Diagnostics go to stderr; a failed print there has no recovery (there is nowhere else to
// report it), so the results of these std::fprintf(stderr, ...) are discarded explicitly.

// The exit code for a CLI11 parse error. --help and --version are ParseErrors too (exit 0);
// any other is bad input (2). A mistyped command reaches here as "A subcommand is required"
// (or an unexpected argument): say which word is no command, and which command was probably
// meant; a mistyped flag: name it, before any complaint about a missing one.
int parse_error_exit(CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  if (e.get_exit_code() != 0) {
    const std::string unknown = unknown_command_message(argc, argv);
    if (!unknown.empty()) {
      (void)std::fprintf(stderr, "%s\n", unknown.c_str());
      return 2;
    }
    const Unrecognized u = first_unrecognized(app, "evade");
    if (!u.flag.empty()) {
      (void)std::fprintf(stderr, "%s\n", unknown_option_message(u).c_str());
      return 2;
    }
  }
  const int rc = app.exit(e);
  return rc == 0 ? 0 : 2;
}

// Runs the parsed command; bad input (ConfigError, invalid_argument) exits 2.
int run_parsed(const std::vector<std::pair<CLI::App*, Runner>>& runners) {
  try {
    for (const auto& [sub, run] : runners) {
      if (sub->parsed()) return run();
    }
  } catch (const config::ConfigError& e) {
    (void)std::fprintf(stderr, "evade: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    (void)std::fprintf(stderr, "evade: invalid input: %s\n", e.what());
    return 2;
  }
  (void)std::fprintf(stderr, "evade: no command given (see --help)\n");
  return 2;
}

int run_cli(int argc, char** argv) {
  if (registry().rejected) {
    (void)std::fprintf(stderr, "evade: failed: a command registration was rejected (a field is "
                       "null, or more than %zu commands: raise Registry::kMaxCommands in "
                       "apps/evade/main.cpp)\n", Registry::kMaxCommands);
    return 1;
  }
  CLI::App app{"evade: onboard evasion guidance and planning (papers 000-004)", "evade"};
  app.set_version_flag("--version", std::string("evade ") + EVADE_VERSION);
  app.require_subcommand(1);
  const auto runners = build_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e, argc, argv);
  }
  return run_parsed(runners);
}

}  // namespace

bool register_command(const Command& command) noexcept {
  Registry& r = registry();
  if (r.count == Registry::kMaxCommands || command.path[0] == nullptr ||
      command.description == nullptr || command.setup == nullptr) {
    r.rejected = true;
    return false;
  }
  r.commands[r.count++] = command;
  return true;
}

void add_common_options(CLI::App& app, CommonOptions& opts, const std::string& default_scenario) {
  auto* s = app.add_option("--scenario", opts.scenario,
                           "scenario: a shipped name (e.g. seed0) or a path to a YAML file");
  if (default_scenario.empty()) {
    s->required();
  } else {
    opts.scenario = default_scenario;
    s->capture_default_str();
  }
  app.add_option("--set", opts.sets, "override a scenario key: --set key.path=value (repeatable)");
  app.add_flag("--json", opts.json, "print a machine-readable JSON result on stdout");
}

config::Scenario load_scenario(const CommonOptions& opts) {
  config::Scenario s = config::Scenario::load(opts.scenario);
  for (const auto& a : opts.sets) s.apply_override(a);
  return s;
}

std::string read_text_file(const std::string& path, const std::string& flag) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(flag + ": cannot open '" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

sgp4::Catalog read_catalog_file(const std::string& tle_path, const std::string& omm_path) {
  if (tle_path.empty()) return ccsds::read_catalog(read_text_file(omm_path, "--omm"), omm_path);
  return sgp4::read_tle(read_text_file(tle_path, "--tle"), tle_path);
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << '\n' << std::flush; }

void print_result(bool json, const nlohmann::json& j, const std::string& text) {
  if (json) {
    print_json(j);
  } else {
    std::cout << text << std::flush;
  }
}

}  // namespace evade::cli

// Nothing escapes main: a runtime failure anywhere (a command, or building the command
// tree) is reported and exits 1.
int main(int argc, char** argv) {
  try {
    return evade::cli::run_cli(argc, argv);
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "evade: failed: %s\n", e.what());
  } catch (...) {
    (void)std::fprintf(stderr, "evade: failed: unknown exception\n");
  }
  return 1;
}
