// `evade screen`: conjunction screening among many objects (paper 002, issue 6).
//   --method paper : the paper's adaptive Step rule (corrected reading), --trace prints its
//                    samples like the paper's Table 2;
//   --method robust: the screening that cannot miss an approach below the threshold
//                    (grid broad phase + bounded narrow phase + Brent TCA), on --threads;
//                    under `mpirun -np N` the grid steps are split between the ranks
//                    (distributed::screen_distributed) and rank 0 prints the merged events.
// Objects come from the scenario's `objects` list, a CSV file (--objects) or a seeded
// synthetic LEO population (--population N --seed S); with --tle or --omm a catalog moving by
// SGP4 is screened instead (cmd_screen_catalog.cpp). The screening, its JSON and its text are
// the library's (conjunction/screen_command.hpp); here: flags, files, printing. --json
// prints the result on stdout; progress of long screens goes to stderr.
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "param_flag_option.hpp"
#include "cmd_screen_catalog.hpp"
#include "screen_cdm_out.hpp"
#include "evade/commands/screen_objects.hpp"
#include "evade/config/read_params.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/distributed/distributed_screen.hpp"

namespace evade::cli {
namespace {
namespace cmd_screen {  // a name of its own: the CLI builds as unity batches too

using namespace evade::conjunction;
using namespace evade::commands;

struct Options {
  CommonOptions common;
  std::string method = "robust";
  bool trace = false;
  std::string csv_path;
  std::string objects_csv;
  long population = 0;
  long seed = 1;
  int threads = 0;  // 0: hardware concurrency
  bool quiet = false;
  CatalogScreenOptions catalog;  ///< --tle/--omm path (its .cdm: --cdm-out, both paths)
  /// The flags as parsed (owned by the command's CLI::App, alive while the command runs):
  /// which were given, to refuse one that does not apply to the mode.
  std::vector<std::pair<std::string, const CLI::Option*>> flags;
};

bool given(const Options& o, const std::string& flag) {
  for (const auto& f : o.flags) {
    if (f.first == flag) return f.second->count() > 0;
  }
  return false;
}

// No flag is silently ignored: one that does not apply to the mode it is given in is refused
// (exit 2), naming the flag and the mode.
void refuse_inapplicable(const Options& o) {
  const bool catalog = !o.catalog.tle_path.empty() || !o.catalog.omm_path.empty();
  const std::vector<const char*> catalog_only = {"--primary", "--start", "--no-prefilter",
                                                 "--no-time-filter", "--no-path-filter"};
  const std::vector<const char*> objects_only = {"--population", "--objects", "--seed",
                                                 "--trace", "--csv"};
  for (const char* f : catalog ? objects_only : catalog_only) {
    if (!given(o, f)) continue;
    throw std::invalid_argument(
        std::string(f) + ": does not apply to " +
        (catalog ? "a catalog screen (--tle/--omm): it applies to a screen of scenario, "
                   "--objects or --population objects"
                 : "a screen of scenario, --objects or --population objects: it applies only "
                   "with --tle/--omm"));
  }
  if (catalog && o.method != "robust") {
    throw std::invalid_argument("--method: does not apply to a catalog screen (--tle/--omm) except "
                                "as robust, its only method");
  }
  if (!catalog && given(o, "--seed") && !given(o, "--population")) {
    throw std::invalid_argument("--seed: applies only with --population (the seed of the synthetic population)");
  }
  if (!catalog && o.method == "paper" && given(o, "--threads")) {
    throw std::invalid_argument("--threads: does not apply to --method paper (one thread)");
  }
}

void write_csv(const std::string& path, const ScreenObjectsResult& r) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("--csv: cannot write '" + path + "'");
  f << events_to_csv(r.events, r.objects);
}

int run_catalog(const Options& o) {
  if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
  if (o.population > 0 || !o.objects_csv.empty())
    throw std::invalid_argument("--tle/--omm: not with --population or --objects");
  CatalogScreenOptions c = o.catalog;
  c.threads = o.threads;
  c.json = o.common.json;
  c.quiet = o.quiet;
  commands::check_screen_cdm_options(screen_cdm_options(c.cdm), false);
  create_cdm_dir(c.cdm.dir);
  return run_catalog_screen(c);
}

// The request of a screen of scenario, --objects or --population objects.
ScreenObjectsRequest objects_request(const Options& o, const config::Scenario& sc) {
  ScreenObjectsSource src;
  src.method = o.method;
  src.population = o.population;
  src.seed = o.seed;
  if (o.population <= 0 && !o.objects_csv.empty()) {
    src.objects_csv_path = o.objects_csv;
    src.objects_csv_text = read_text_file(o.objects_csv, "--objects");
  }
  ScreenObjectsRequest req = read_screen_objects_request(sc, src);
  req.trace = o.trace;
  req.threads = o.threads;
  req.cdm = screen_cdm_options(o.catalog.cdm);
  return req;
}

int run(const Options& o) {
  refuse_inapplicable(o);
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) return run_catalog(o);
  config::Scenario sc = load_scenario(o.common);
  for (const ParamValue& v : o.catalog.param_values) sc.set_value(v);  // flags win
  ScreenObjectsRequest req = objects_request(o, sc);
  req.validate();
  create_cdm_dir(req.cdm.dir);
  const distributed::MpiSession mpi;  // one process unless started by mpirun
  req.ranks = mpi.size();
  req.rank = mpi.rank();
  req.robust_screener = [&mpi](const std::vector<SpaceObject>& objects, double span_s, const ScreenOptions& so) {
    return distributed::screen_distributed(objects, span_s, so, mpi);
  };
  if (!o.quiet && mpi.rank() == 0) req.progress = [](const std::string& s) { (void)std::fputs(s.c_str(), stderr); };
  const ScreenObjectsResult r = run_screen_objects(req);
  if (mpi.rank() != 0) return 0;  // rank 0 holds the merged result and prints it
  if (!o.csv_path.empty()) write_csv(o.csv_path, r);
  if (r.cdm) write_cdm_files(*r.cdm);
  if (o.common.json) print_json(to_json(r));
  else (void)std::fputs(to_text(r).c_str(), stdout);
  return 0;
}

// The parameter flags (evade/config/param_flags.hpp), in both modes: a catalog screen's span,
// threshold and grid step (defaults 86400 s, 5000 m, automatic), else overrides of the
// scenario's keys.
void add_parameter_flags(CLI::App& app, CatalogScreenOptions& c) {
  const auto add = [&](const auto& table, const char* prefix, const char* key) {
    (void)add_param_flag(app, table, prefix, key, &c.param_values);  // registered on app
  };
  add(screen_scenario_params(), "", "span_s");
  add(screen_options_params(), "robust.", "robust.threshold_m");
  add(screen_options_params(), "robust.", "robust.step_s");
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_common_options(app, o->common, "seed2");
  app.add_option("--method", o->method, "paper (adaptive Step rule) or robust (no misses)")
      ->check(CLI::IsMember({"paper", "robust"}))
      ->capture_default_str();
  app.add_flag("--trace", o->trace, "record every sample of the paper method (Table 2 rows)");
  app.add_option("--csv", o->csv_path, "also write the events to this CSV file");
  app.add_option("--objects", o->objects_csv, "read the objects from a CSV file");
  app.add_option("--population", o->population, "screen a synthetic LEO population of N objects [-]")
      ->check(CLI::Range(2L, 10000000L));
  app.add_option("--seed", o->seed, "seed of the synthetic population [-]")->capture_default_str();
  app.add_option("--threads", o->threads, "worker threads [-] (default: all cores)")
      ->check(CLI::Range(1, 256));
  app.add_flag("--quiet", o->quiet, "no progress on stderr");
  CatalogScreenOptions& c = o->catalog;
  auto* tle = app.add_option("--tle", c.tle_path, "TLE/3LE file: screen the catalog with SGP4 motion");
  auto* omm = app.add_option("--omm", c.omm_path, "CCSDS OMM (KVN or XML) or GP JSON/CSV file, as --tle");
  tle->excludes(omm);
  app.add_option("--primary", c.primary_norad, "with --tle/--omm: screen this NORAD id against the catalog [-]");
  add_parameter_flags(app, c);
  app.add_option("--start", c.start_utc, "with --tle/--omm: start UTC, ISO 8601 (YYYY-MM-DD[Thh:mm:ss[.f]][Z|+hh:mm|-hh:mm]; default: latest element epoch)");
  app.add_flag("--no-prefilter", c.no_prefilter,
               "with --primary: propagate every object (no perigee/apogee filter first)");
  app.add_flag("--no-time-filter", c.no_time_filter,
               "with --primary: screen every object kept by the perigee/apogee filter over the whole span");
  app.add_flag("--no-path-filter", c.no_path_filter,
               "with --primary: keep every object the perigee/apogee filter keeps (no orbit-path filter)");
  add_cdm_out_options(app, c.cdm);
  for (const char* f : {"--primary", "--span-s", "--threshold-m", "--step-s", "--start", "--no-prefilter",
                        "--no-time-filter", "--no-path-filter", "--population", "--objects", "--seed", "--trace",
                        "--csv", "--method", "--threads"}) {
    o->flags.emplace_back(f, app.get_option(f));
  }
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"screen"},
     "Conjunction screening among many objects (paper 002; adaptive or robust)",
     &setup});

}  // namespace cmd_screen
}  // namespace
}  // namespace evade::cli
