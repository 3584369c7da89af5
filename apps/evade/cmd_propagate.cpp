// `evade propagate`: the foundation demo, one orbit with the chosen gravity model
// (evade/dynamics/propagate_command.hpp). With --tle or --omm it propagates every object of a
// catalog with SGP4 instead (evade/sgp4/propagate_catalog_command.hpp). Parse, call, print.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "evade/dynamics/propagate_command.hpp"
#include "evade/sgp4/propagate_catalog_command.hpp"

namespace evade::cli {
namespace {

struct CatalogFlags {
  std::string tle_path;  ///< --tle: TLE or 3LE text
  std::string omm_path;  ///< --omm: OMM KVN or XML, or GP JSON or CSV (detected from the text)
  sgp4::PropagateCatalogRequest request;  ///< --span-s, --step-s, --frame
};

struct PropagateOptions {
  CommonOptions common;
  CatalogFlags catalog;  ///< --tle/--omm path
};

void print(const std::string& text) { (void)std::fputs(text.c_str(), stdout); }

// Exit 0 when at least one entry was read (bad entries are listed on stderr and in the
// JSON), 2 when the file has no valid entry or a flag is out of range.
int run_catalog(const PropagateOptions& o) {
  if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
  sgp4::PropagateCatalogRequest req = o.catalog.request;
  sgp4::check_propagate_catalog_request(req);  // the flags before the file
  req.catalog = read_catalog_file(o.catalog.tle_path, o.catalog.omm_path);
  for (const auto& is : req.catalog.issues)
    (void)std::fprintf(stderr, "evade propagate: bad entry: %s\n", is.message().c_str());
  const sgp4::PropagateCatalogResult r = sgp4::run_propagate_catalog(req);
  if (o.common.json) print_json(sgp4::to_json(r));
  else print(sgp4::to_text(r));
  return 0;
}

int run_propagate(const PropagateOptions& o) {
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) return run_catalog(o);
  const config::Scenario sc = load_scenario(o.common);
  const dynamics::PropagateResult r = dynamics::run_propagate(dynamics::read_propagate_request(sc));
  if (o.common.json) print_json(dynamics::to_json(r));
  else print(dynamics::to_text(r));
  return 0;
}

void add_catalog_options(CLI::App& app, CatalogFlags& c) {
  auto* tle = app.add_option("--tle", c.tle_path, "TLE/3LE file: propagate every object with SGP4");
  auto* omm = app.add_option("--omm", c.omm_path, "CCSDS OMM (KVN or XML) or GP JSON/CSV file, as --tle");
  tle->excludes(omm);
  app.add_option("--span-s", c.request.span_s, "with --tle/--omm: time span from the latest element epoch [s]");
  app.add_option("--step-s", c.request.step_s, "with --tle/--omm: output step [s]");
  app.add_option("--frame", c.request.frame, "with --tle/--omm: teme or eci (J2000)");
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
