// `evade propagate`: the foundation demo, one orbit with the chosen gravity model
// (evade/dynamics/propagate_command.hpp). With --tle or --omm it propagates every object of a
// catalog with SGP4 instead (cmd_propagate_tle.cpp). Parse, call, print.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "cmd_propagate_tle.hpp"
#include "evade/dynamics/propagate_command.hpp"

namespace evade::cli {
namespace {

struct PropagateOptions {
  CommonOptions common;
  CatalogPropagateOptions catalog;  ///< --tle/--omm path
};

void print(const std::string& text) { (void)std::fputs(text.c_str(), stdout); }

int run_propagate(const PropagateOptions& o) {
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) {
    if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
    CatalogPropagateOptions c = o.catalog;
    c.json = o.common.json;
    return run_propagate_catalog(c);
  }
  const config::Scenario sc = load_scenario(o.common);
  const dynamics::PropagateResult r = dynamics::run_propagate(dynamics::read_propagate_request(sc));
  if (o.common.json) print_json(dynamics::to_json(r));
  else print(dynamics::to_text(r));
  return 0;
}

void add_catalog_options(CLI::App& app, CatalogPropagateOptions& c) {
  auto* tle = app.add_option("--tle", c.tle_path, "TLE/3LE file: propagate every object with SGP4");
  auto* omm = app.add_option("--omm", c.omm_path, "CCSDS OMM (KVN or XML) or GP JSON/CSV file, as --tle");
  tle->excludes(omm);
  app.add_option("--span-s", c.span_s, "with --tle/--omm: time span from the latest element epoch [s]");
  app.add_option("--step-s", c.step_s, "with --tle/--omm: output step [s]");
  app.add_option("--frame", c.frame, "with --tle/--omm: teme or eci (J2000)");
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<PropagateOptions>();
  add_common_options(app, o->common, "demo-leo");
  add_catalog_options(app, o->catalog);
  return [o]() { return run_propagate(*o); };
}

const bool kRegistered = register_command(
    {{"propagate"},
     "Propagate one orbit (two-body or two-body + J2): the foundation demo",
     &setup});

}  // namespace
}  // namespace evade::cli
