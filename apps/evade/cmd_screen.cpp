// `evade screen`: conjunction screening among many objects (paper 002, issue 6).
//   --method paper : the paper's adaptive Step rule (corrected reading), --trace prints its
//                    samples like the paper's Table 2;
//   --method robust: the screening that cannot miss an approach below the threshold
//                    (grid broad phase + bounded narrow phase + Brent TCA), on --threads;
//                    under `mpirun -np N` the grid steps are split between the ranks
//                    (distributed::screen_distributed) and rank 0 prints the merged events.
// Objects come from the scenario's `objects` list, a CSV file (--objects) or a seeded
// synthetic LEO population (--population N --seed S); with --tle or --omm a catalog moving by
// SGP4 is screened instead (cmd_screen_catalog.cpp). --json prints the result on stdout;
// progress of long screens goes to stderr. The scenario is read by
// conjunction::read_screen_scenario; I/O lives here; the screening library is pure.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "cmd_screen_catalog.hpp"
#include "screen_cdm_out.hpp"
#include "evade/conjunction/catalog.hpp"
#include "evade/conjunction/paper_step.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/screen_scenario.hpp"
#include "evade/core/epoch.hpp"
#include "evade/distributed/distributed_screen.hpp"

namespace evade::cli {
namespace {

using namespace evade::conjunction;

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
  const std::vector<const char*> catalog_only = {"--primary", "--span-s", "--threshold-m",
                                                 "--step-s", "--start"};
  const std::vector<const char*> objects_only = {"--population", "--objects", "--seed",
                                                 "--trace", "--csv"};
  for (const char* f : catalog ? objects_only : catalog_only) {
    if (!given(o, f)) continue;
    throw std::invalid_argument(
        std::string(f) + ": does not apply to " +
        (catalog ? "a catalog screen (--tle/--omm): it applies to a screen of scenario, "
                   "--objects or --population objects"
                 : "a screen of scenario, --objects or --population objects: it applies only "
                   "with --tle/--omm (set the span and threshold with --set span_s=..., "
                   "--set robust.threshold_m=...)"));
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

std::string utc_of(double epoch_j2000_s, double t_s) {
  return format_calendar_utc(calendar_from_seconds_since_j2000(epoch_j2000_s + t_s));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("--objects: cannot open '" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

struct Objects {
  std::vector<SpaceObject> list;
  std::string source;  ///< echoed as objects_source
};

// The objects: a synthetic population (--population), a CSV file (--objects) or the
// scenario's `objects` list (marked used when another source replaces it).
Objects load_objects(const Options& o, const config::Scenario& sc, const ScreenScenario& in) {
  Objects ob;
  if (o.population > 0) {
    PopulationOptions pop;
    pop.count = static_cast<std::size_t>(o.population);
    pop.seed = static_cast<std::uint64_t>(o.seed);
    pop.span_s = in.span_s;
    pop.earth = in.earth;
    ob.list = synthetic_population(pop);
    ob.source = "synthetic population N=" + std::to_string(o.population) + " seed=" + std::to_string(o.seed);
    (void)sc.list_size("objects");  // present but not a list is still an error
    sc.mark_used("objects");
  } else if (!o.objects_csv.empty()) {
    ob.list = objects_from_csv(read_file(o.objects_csv), in.earth);
    ob.source = o.objects_csv;
    sc.mark_used("objects");
  } else {
    ob.list = objects_from_scenario(sc, in.earth);
    ob.source = sc.source();
  }
  return ob;
}

nlohmann::json trace_json(const std::vector<TraceRow>& trace, double epoch_s) {
  nlohmann::json tr = nlohmann::json::array();
  for (const auto& row : trace) {
    tr.push_back({{"t_s", row.t_s},
                  {"utc", utc_of(epoch_s, row.t_s)},
                  {"step_s", row.step_s},
                  {"i", row.i},
                  {"j", row.j},
                  {"distance_m", row.distance_m},
                  {"radial_speed_mps", row.radial_speed_mps},
                  {"collision", row.collision},
                  {"warning", row.warning}});
  }
  return tr;
}

// --method paper: the adaptive Step rule over every pair (steps and trace into `out`).
std::vector<Conjunction> run_paper(const Options& o, const ScreenScenario& in,
                                   const std::vector<SpaceObject>& objects, nlohmann::json& out) {
  validate_objects(objects, in.earth);
  if (objects.size() > 2000) {
    throw std::invalid_argument("--method paper checks all N^2 pairs at every step: " +
                                std::to_string(objects.size()) + " objects outside [2, 2000]");
  }
  Ephemeris eph(objects, in.gravity, in.earth, in.robust.integ);
  std::function<void(double)> progress;
  if (!o.quiet) progress = [](double f) { (void)std::fprintf(stderr, "\rscreen (paper): %5.1f %%", 100.0 * f); };
  const PaperResult r = screen_paper(objects, in.span_s, in.paper_step, eph, o.trace, progress);
  if (!o.quiet) (void)std::fprintf(stderr, "\n");
  out["steps"] = r.steps;
  if (o.trace) out["trace"] = trace_json(r.trace, in.epoch_j2000_s);
  return r.events;
}

nlohmann::json stats_json(const ScreenStats& st, std::size_t n, const ScreenOptions& so, int ranks) {
  return {{"grid_steps", st.steps},
          {"pairs_checked", st.pairs_checked},
          {"candidates", st.candidates},
          {"narrow_phase_intervals", st.refined},
          {"root_solves", st.root_solves},
          {"pairs_after_apogee_perigee", st.pairs_after_apogee_perigee},
          {"unproven_leaves", st.unproven_leaves},
          {"all_pairs", n * (n - 1) / 2},
          {"threads", so.threads},
          {"ranks", ranks},
          {"grid_step_s", so.step_s > 0.0 ? so.step_s : auto_step_s(n)}};
}

// --method robust: the screening that cannot miss (steps and stats into `out`).
std::vector<Conjunction> run_robust(const Options& o, const ScreenScenario& in,
                                    const std::vector<SpaceObject>& objects, nlohmann::json& out,
                                    const distributed::MpiSession& mpi) {
  if (o.trace) throw std::invalid_argument("--trace: only with --method paper");
  ScreenOptions so = in.robust;
  so.threads = o.threads > 0 ? o.threads
                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (!o.quiet && mpi.rank() == 0) {
    (void)std::fprintf(stderr, "screen: %zu objects, %.0f s, threshold %.1f m, step %.1f s, %d threads, %d ranks\n",
                       objects.size(), in.span_s, so.threshold_m,
                       so.step_s > 0.0 ? so.step_s : auto_step_s(objects.size()), so.threads, mpi.size());
    so.progress = [](double f) { (void)std::fprintf(stderr, "\rscreen: %5.1f %%", 100.0 * f); };
  }
  const ScreenResult r = distributed::screen_distributed(objects, in.span_s, so, mpi);
  if (!o.quiet && mpi.rank() == 0) (void)std::fprintf(stderr, "\n");
  out["steps"] = r.stats.steps;
  out["stats"] = stats_json(r.stats, objects.size(), so, mpi.size());
  return r.events;
}

nlohmann::json events_json(const std::vector<Conjunction>& events,
                           const std::vector<SpaceObject>& objects, double epoch_s) {
  nlohmann::json ev = nlohmann::json::array();
  for (const auto& c : events) {
    ev.push_back({{"i", c.i},
                  {"j", c.j},
                  {"name_i", objects[c.i].name},
                  {"name_j", objects[c.j].name},
                  {"tca_s", c.tca_s},
                  {"tca_utc", utc_of(epoch_s, c.tca_s)},
                  {"miss_m", c.miss_m},
                  {"rel_speed_mps", c.rel_speed_mps},
                  {"collision", c.collision},
                  {"warning", c.warning}});
  }
  return ev;
}

void write_csv(const std::string& path, const std::vector<Conjunction>& events,
               const std::vector<SpaceObject>& objects) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("--csv: cannot write '" + path + "'");
  f << events_to_csv(events, objects);
}

void print_text(const Options& o, const ScreenScenario& in, const std::vector<SpaceObject>& objects,
                const std::vector<Conjunction>& events, long steps, double wall_s) {
  std::printf("%s screening of %zu objects over %.0f s: %zu events, %ld steps, %.3f s\n",
              o.method.c_str(), objects.size(), in.span_s, events.size(), steps, wall_s);
  for (const auto& c : events) {
    std::printf("  %-10s %-10s TCA %s  miss %12.3f m  v_rel %9.3f m/s%s%s\n",
                objects[c.i].name.c_str(), objects[c.j].name.c_str(),
                utc_of(in.epoch_j2000_s, c.tca_s).c_str(), c.miss_m, c.rel_speed_mps,
                c.collision ? "  COLLISION" : "", c.warning ? "  WARNING" : "");
  }
}

int run_catalog(const Options& o) {
  if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
  if (o.population > 0 || !o.objects_csv.empty())
    throw std::invalid_argument("--tle/--omm: not with --population or --objects");
  CatalogScreenOptions c = o.catalog;
  c.threads = o.threads;
  c.json = o.common.json;
  c.quiet = o.quiet;
  prepare_cdm_out(c.cdm, false);
  return run_screen_catalog(c);
}

int run(const Options& o) {
  refuse_inapplicable(o);
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) return run_catalog(o);
  const config::Scenario sc = load_scenario(o.common);
  const ScreenScenario in = read_screen_scenario(sc);
  const Objects ob = load_objects(o, sc, in);
  if (o.method == "paper") sc.mark_used("robust");
  sc.check_all_used();
  if (!o.catalog.cdm.dir.empty() && o.method != "robust")
    throw std::invalid_argument("--cdm-out: only with --method robust (the paper method flags samples, not TCAs)");
  prepare_cdm_out(o.catalog.cdm, true);
  const distributed::MpiSession mpi;  // one process unless started by mpirun

  nlohmann::json out;
  out["command"] = "screen";
  out["method"] = o.method;
  out["objects_source"] = ob.source;
  out["objects"] = ob.list.size();
  out["epoch_utc"] = in.epoch_utc;
  out["span_s"] = in.span_s;
  out["scenario"] = sc.used();
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Conjunction> events =
      o.method == "paper" ? run_paper(o, in, ob.list, out) : run_robust(o, in, ob.list, out, mpi);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (mpi.rank() != 0) return 0;  // rank 0 holds the merged result and prints it
  out["wall_time_s"] = wall_s;
  out["events"] = events_json(events, ob.list, in.epoch_j2000_s);
  if (!o.csv_path.empty()) write_csv(o.csv_path, events, ob.list);
  if (!o.catalog.cdm.dir.empty()) {
    const CdmRunInfo run{in.epoch_j2000_s, in.span_s, in.robust.threshold_m, "objects " + ob.source};
    out["cdm"] = write_population_cdms(o.catalog.cdm, run, events, ob.list, in.robust);
  }
  if (o.common.json) {
    print_json(out);
  } else {
    print_text(o, in, ob.list, events, out["steps"].get<long>(), wall_s);
  }
  return 0;
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
  app.add_option("--span-s", c.span_s, "with --tle/--omm: span from the start [s]")->capture_default_str();
  app.add_option("--threshold-m", c.threshold_m, "with --tle/--omm: report misses <= D [m]")
      ->capture_default_str();
  app.add_option("--step-s", c.step_s, "with --tle/--omm: grid step [s] (0 = automatic)");
  app.add_option("--start", c.start_utc, "with --tle/--omm: start UTC (default: latest element epoch)");
  add_cdm_out_options(app, c.cdm);
  for (const char* f : {"--primary", "--span-s", "--threshold-m", "--step-s", "--start",
                        "--population", "--objects", "--seed", "--trace", "--csv", "--method",
                        "--threads"}) {
    o->flags.emplace_back(f, app.get_option(f));
  }
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"screen"},
     "Conjunction screening among many objects (paper 002; adaptive or robust)",
     &setup});

}  // namespace
}  // namespace evade::cli
