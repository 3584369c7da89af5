// Minimal stand-in for apps/evade/main.cpp's registry (cli.hpp), so the publish test can run
// the real cmd_plan_observability.cpp in-process (memq:// delivers only within one LCM
// instance, which the test shares with the command through its lcm_override() seam).
#include <iostream>
#include <vector>

#include "cli.hpp"
#include "cli_stub.hpp"

namespace evade::cli {

std::vector<StubEntry>& stub_registry() {
  static std::vector<StubEntry> r;
  return r;
}

bool register_command(const std::vector<std::string>& path, const std::string& /*description*/,
                      Setup setup) {
  stub_registry().push_back({path, std::move(setup)});
  return true;
}

void add_common_options(CLI::App& app, CommonOptions& opts, const std::string& default_scenario) {
  opts.scenario = default_scenario;
  app.add_option("--scenario", opts.scenario);
  app.add_option("--set", opts.sets);
  app.add_flag("--json", opts.json);
}

config::Scenario load_scenario(const CommonOptions& opts) {
  config::Scenario s = config::Scenario::load(opts.scenario);
  for (const auto& a : opts.sets) s.apply_override(a);
  return s;
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

}  // namespace evade::cli
