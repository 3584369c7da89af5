// evade CLI entry point: builds the command tree from the registry and maps errors to
// exit codes (0 ok, 1 runtime failure, 2 bad input).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "cli.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::cli {
namespace {

struct Entry {
  std::vector<std::string> path;
  std::string description;
  Setup setup;
};

std::vector<Entry>& registry() {
  static std::vector<Entry> r;
  return r;
}

}  // namespace

bool register_command(const std::vector<std::string>& path, const std::string& description,
                      Setup setup) {
  registry().push_back({path, description, std::move(setup)});
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
  if (tle_path.empty()) return sgp4::read_catalog(read_text_file(omm_path, "--omm"), omm_path);
  return sgp4::read_tle(read_text_file(tle_path, "--tle"), tle_path);
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

}  // namespace evade::cli

int main(int argc, char** argv) {
  using namespace evade::cli;
  CLI::App app{"evade: onboard evasion guidance and planning (papers 000-004)", "evade"};
  app.set_version_flag("--version", std::string("evade ") + EVADE_VERSION);
  app.require_subcommand(1);

  std::map<std::string, CLI::App*> groups;
  std::vector<std::pair<CLI::App*, Runner>> runners;
  for (auto& e : registry()) {
    CLI::App* parent = &app;
    std::string prefix;
    for (std::size_t i = 0; i + 1 < e.path.size(); ++i) {
      prefix += e.path[i] + "/";
      auto it = groups.find(prefix);
      if (it == groups.end()) {
        CLI::App* g = parent->add_subcommand(e.path[i], e.path[i] + " commands");
        g->require_subcommand(1);
        it = groups.emplace(prefix, g).first;
      }
      parent = it->second;
    }
    CLI::App* sub = parent->add_subcommand(e.path.back(), e.description);
    runners.emplace_back(sub, e.setup(*sub));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, run] : runners) {
      if (sub->parsed()) return run();
    }
  } catch (const evade::config::ConfigError& e) {
    std::fprintf(stderr, "evade: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "evade: invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "evade: failed: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "evade: no command given (see --help)\n");
  return 2;
}
