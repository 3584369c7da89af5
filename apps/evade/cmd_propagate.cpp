// `evade propagate`: the foundation demo, one orbit with the chosen gravity model
// (evade/commands/propagate_command.hpp). With --tle or --omm it propagates every object of a
// catalog with SGP4 instead, written as it goes (evade/commands/propagate_catalog_stream.hpp):
// --json one streamed JSON document, --csv one row per state. Parse, call, print.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "evade/commands/propagate_command.hpp"
#include "evade/commands/propagate_catalog_stream.hpp"

namespace evade::cli {
namespace {
namespace cmd_propagate {  // a name of its own: the CLI builds as unity batches too

struct CatalogFlags {
  std::string tle_path;  ///< --tle: TLE or 3LE text
  std::string omm_path;  ///< --omm: OMM KVN or XML, or GP JSON or CSV (detected from the text)
  commands::PropagateCatalogRequest request;  ///< --span-s, --step-s, --frame
  bool csv = false;                       ///< --csv: one row per state
  int threads = 0;                        ///< --threads (0: the hardware's)
};

struct PropagateOptions {
  CommonOptions common;
  CatalogFlags catalog;  ///< --tle/--omm path
};

void print(const std::string& text) { (void)std::fputs(text.c_str(), stdout); }

void write_stdout(const char* data, std::size_t size) {
  if (std::fwrite(data, 1, size, stdout) != size)
    throw std::runtime_error("evade propagate: writing the states to stdout failed");
}

// Exit 0 when at least one entry was read (bad entries are listed on stderr and in the
// JSON), 2 when the file has no valid entry or a flag is out of range.
int run_catalog(const PropagateOptions& o) {
  if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
  if (o.common.json && o.catalog.csv) throw std::invalid_argument("--json and --csv: choose one");
  commands::PropagateCatalogRequest req = o.catalog.request;
  commands::check_propagate_catalog_request(req);  // the flags before the file
  req.catalog = read_catalog_file(o.catalog.tle_path, o.catalog.omm_path);
  for (const auto& is : req.catalog.issues)
    (void)std::fprintf(stderr, "evade propagate: bad entry: %s\n", is.message().c_str());
  const commands::StateFormat f = o.common.json  ? commands::StateFormat::kJson
                              : o.catalog.csv ? commands::StateFormat::kCsv
                                              : commands::StateFormat::kNone;
  static char buffer[1 << 20];  // full buffering of the stream: 1 MiB writes
  (void)std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);  // before any output: cannot fail
  const commands::StreamedCatalog r =
      commands::stream_propagate_catalog(req, f, o.catalog.threads, &write_stdout);
  if (f == commands::StateFormat::kNone) print(commands::to_text(r));
  for (const commands::StreamedTrack& t : r.objects)
    if (f == commands::StateFormat::kCsv && t.error != sgp4::Sgp4Error::kNone)
      (void)std::fprintf(stderr, "evade propagate: object %ld stopped at t = %.3f s: %s\n", t.id,
                         t.error_t_s, sgp4::sgp4_error_text(t.error));
  return 0;
}

int run_propagate(const PropagateOptions& o) {
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) return run_catalog(o);
  const config::Scenario sc = load_scenario(o.common);
  const commands::PropagateResult r = commands::run_propagate(commands::read_propagate_request(sc));
  if (o.common.json) print_json(commands::to_json(r));
  else print(commands::to_text(r));
  return 0;
}

void add_catalog_options(CLI::App& app, CatalogFlags& c) {
  auto* tle = app.add_option("--tle", c.tle_path, "TLE/3LE file: propagate every object with SGP4");
  auto* omm = app.add_option("--omm", c.omm_path, "CCSDS OMM (KVN or XML) or GP JSON/CSV file, as --tle");
  tle->excludes(omm);
  app.add_option("--span-s", c.request.span_s, "with --tle/--omm: time span from the latest element epoch [s]");
  app.add_option("--step-s", c.request.step_s, "with --tle/--omm: output step [s]");
  app.add_option("--frame", c.request.frame, "with --tle/--omm: teme or eci (J2000)");
  app.add_flag("--csv", c.csv, "with --tle/--omm: one CSV row per state instead of the text summary");
  app.add_option("--threads", c.threads, "with --tle/--omm: worker threads (0: one per core) [-]")
      ->check(CLI::Range(0, 256));
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

}  // namespace cmd_propagate
}  // namespace
}  // namespace evade::cli
