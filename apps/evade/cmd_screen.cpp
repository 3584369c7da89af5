// `evade screen`: conjunction screening among many objects (paper 002, issue 6).
//   --method paper : the paper's adaptive Step rule (corrected reading), --trace prints its
//                    samples like the paper's Table 2;
//   --method robust: the screening that cannot miss an approach below the threshold
//                    (grid broad phase + bounded narrow phase + Brent TCA), on --threads.
// Objects come from the scenario's `objects` list, a CSV file (--objects) or a seeded
// synthetic LEO population (--population N --seed S). --json prints the result on stdout;
// progress of long screens goes to stderr. I/O lives here; the library is pure.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "cli.hpp"
#include "evade/conjunction/catalog.hpp"
#include "evade/conjunction/paper_step.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/core/epoch.hpp"

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
};

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

int run(const Options& o) {
  config::Scenario sc = load_scenario(o.common);
  EarthModel earth;
  earth.mu_m3ps2 = sc.get_double("earth.mu_m3ps2", 1e13, 1e15, earth.mu_m3ps2);
  earth.re_m = sc.get_double("earth.re_m", 1e6, 1e7, earth.re_m);
  earth.j2 = sc.get_double("earth.j2", 0.0, 1e-2, earth.j2);
  const std::string epoch_text = sc.get_string("epoch_utc", "2000-01-01 12:00:00");
  const double epoch_s = seconds_since_j2000_from_calendar(parse_calendar_utc(epoch_text));
  const double span_s = sc.get_double("span_s", 1e-3, 1e8);
  const GravityModel gravity = sc.get_enum("gravity", {"two_body", "two_body_j2"}, "two_body") ==
                                       "two_body_j2"
                                   ? GravityModel::kTwoBodyJ2
                                   : GravityModel::kTwoBody;
  PaperStepParams prm;
  prm.h_sim_s = sc.get_double("paper_step.h_sim_s", 1e-6, 1e6, prm.h_sim_s);
  prm.n_warning = sc.get_double("paper_step.n_warning", 1.0, 1e6, prm.n_warning);
  prm.m_warning_period = sc.get_double("paper_step.m_warning_period", 1.0, 1e6, prm.m_warning_period);
  prm.l_enlarge = sc.get_double("paper_step.l_enlarge", 1.0, 1e6, prm.l_enlarge);
  prm.l_reduce = sc.get_double("paper_step.l_reduce", 1.0, 1e6, prm.l_reduce);
  prm.validate();
  ScreenOptions so;
  so.threshold_m = sc.get_double("robust.threshold_m", 0.0, 1e8, so.threshold_m);
  so.step_s = sc.get_double("robust.step_s", 0.0, 1e5, so.step_s);  // 0 = auto
  so.leaf_s = sc.get_double("robust.leaf_s", 1e-6, 1e5, so.leaf_s);
  so.warning_multiple = prm.n_warning;
  so.gravity = gravity;
  so.earth = earth;
  so.threads = o.threads > 0 ? o.threads
                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  std::vector<SpaceObject> objects;
  std::string source;
  if (o.population > 0) {
    PopulationOptions pop;
    pop.count = static_cast<std::size_t>(o.population);
    pop.seed = static_cast<std::uint64_t>(o.seed);
    pop.span_s = span_s;
    pop.earth = earth;
    objects = synthetic_population(pop);
    source = "synthetic population N=" + std::to_string(o.population) + " seed=" + std::to_string(o.seed);
    for (std::size_t k = 0; k < sc.list_size("objects"); ++k) sc.mark_used("objects");
    sc.mark_used("objects");
  } else if (!o.objects_csv.empty()) {
    objects = objects_from_csv(read_file(o.objects_csv), earth);
    source = o.objects_csv;
    sc.mark_used("objects");
  } else {
    objects = objects_from_scenario(sc, earth);
    source = sc.source();
  }
  if (o.method == "paper") {
    sc.mark_used("robust");
  }
  sc.check_all_used();

  nlohmann::json out;
  out["command"] = "screen";
  out["method"] = o.method;
  out["objects_source"] = source;
  out["objects"] = objects.size();
  out["epoch_utc"] = epoch_text;
  out["span_s"] = span_s;
  out["scenario"] = sc.used();
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Conjunction> events;
  if (o.method == "paper") {
    validate_objects(objects, earth);
    if (objects.size() > 2000) {
      throw std::invalid_argument("--method paper checks all N^2 pairs at every step: " +
                                  std::to_string(objects.size()) + " objects outside [2, 2000]");
    }
    Ephemeris eph(objects, gravity, earth, so.integ);
    std::function<void(double)> progress;
    if (!o.quiet) progress = [](double f) { std::fprintf(stderr, "\rscreen (paper): %5.1f %%", 100.0 * f); };
    const PaperResult r = screen_paper(objects, span_s, prm, eph, o.trace, progress);
    if (!o.quiet) std::fprintf(stderr, "\n");
    events = r.events;
    out["steps"] = r.steps;
    if (o.trace) {
      nlohmann::json tr = nlohmann::json::array();
      for (const auto& row : r.trace) {
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
      out["trace"] = tr;
    }
  } else {
    if (o.trace) throw std::invalid_argument("--trace: only with --method paper");
    if (!o.quiet) {
      std::fprintf(stderr, "screen: %zu objects, %.0f s, threshold %.1f m, step %.1f s, %d threads\n",
                   objects.size(), span_s, so.threshold_m,
                   so.step_s > 0.0 ? so.step_s : auto_step_s(objects.size()), so.threads);
      so.progress = [](double f) { std::fprintf(stderr, "\rscreen: %5.1f %%", 100.0 * f); };
    }
    const ScreenResult r = screen_robust(objects, span_s, so);
    if (!o.quiet) std::fprintf(stderr, "\n");
    events = r.events;
    out["steps"] = r.stats.steps;
    out["stats"] = {{"grid_steps", r.stats.steps},
                    {"pairs_checked", r.stats.pairs_checked},
                    {"candidates", r.stats.candidates},
                    {"narrow_phase_intervals", r.stats.refined},
                    {"root_solves", r.stats.root_solves},
                    {"pairs_after_apogee_perigee", r.stats.pairs_after_apogee_perigee},
                    {"all_pairs", objects.size() * (objects.size() - 1) / 2},
                    {"threads", so.threads},
                    {"grid_step_s", so.step_s > 0.0 ? so.step_s : auto_step_s(objects.size())}};
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out["wall_time_s"] = wall_s;
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
  out["events"] = ev;
  if (!o.csv_path.empty()) {
    std::ofstream f(o.csv_path);
    if (!f) throw std::runtime_error("--csv: cannot write '" + o.csv_path + "'");
    f << events_to_csv(events, objects);
  }
  if (o.common.json) {
    print_json(out);
  } else {
    std::printf("%s screening of %zu objects over %.0f s: %zu events, %ld steps, %.3f s\n",
                o.method.c_str(), objects.size(), span_s, events.size(),
                out["steps"].get<long>(), wall_s);
    for (const auto& c : events) {
      std::printf("  %-10s %-10s TCA %s  miss %12.3f m  v_rel %9.3f m/s%s%s\n",
                  objects[c.i].name.c_str(), objects[c.j].name.c_str(),
                  utc_of(epoch_s, c.tca_s).c_str(), c.miss_m, c.rel_speed_mps,
                  c.collision ? "  COLLISION" : "", c.warning ? "  WARNING" : "");
    }
  }
  return 0;
}

const bool kRegistered = register_command(
    {"screen"}, "Conjunction screening among many objects (paper 002; adaptive or robust)",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      add_common_options(app, o->common, "seed2");
      app.add_option("--method", o->method, "paper (adaptive Step rule) or robust (no misses)")
          ->check(CLI::IsMember({"paper", "robust"}))
          ->capture_default_str();
      app.add_flag("--trace", o->trace, "record every sample of the paper method (Table 2 rows)");
      app.add_option("--csv", o->csv_path, "also write the events to this CSV file");
      app.add_option("--objects", o->objects_csv, "read the objects from a CSV file");
      app.add_option("--population", o->population, "screen a synthetic LEO population of N objects")
          ->check(CLI::Range(2L, 10000000L));
      app.add_option("--seed", o->seed, "seed of the synthetic population")->capture_default_str();
      app.add_option("--threads", o->threads, "worker threads (default: all cores)")
          ->check(CLI::Range(1, 256));
      app.add_flag("--quiet", o->quiet, "no progress on stderr");
      return [o]() { return run(*o); };
    });

}  // namespace
}  // namespace evade::cli
