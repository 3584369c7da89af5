// `evade screen` of objects (scenario, CSV, synthetic population) as a library call; see
// screen_command.hpp. Paper 002 (Wang Xiaoyu 2006): --method paper is its adaptive Step
// rule (paper_step.hpp), --method robust the no-miss screener (robust_screen.hpp).
#include "evade/commands/screen_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "evade/commands/screen_objects.hpp"
#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/commands/screening_events.hpp"
#include "evade/core/epoch.hpp"

namespace evade::commands {
namespace {

std::string utc_of(double epoch_s, double t_s) {
  return format_calendar_utc(calendar_from_seconds_since_j2000(epoch_s + t_s));
}

std::string percent(const char* label, double f) {
  char buf[64];
  (void)std::snprintf(buf, sizeof buf, "\r%s: %5.1f %%", label, 100.0 * f);
  return buf;
}

// The objects: a synthetic population, CSV text or the scenario's `objects` list (marked
// used when another source replaces it).
void load_objects(const config::Scenario& sc, const ScreenObjectsSource& src,
                  ScreenObjectsRequest& req) {
  const ScreenScenario& in = req.scenario;
  if (src.population > 0) {
    conjunction::PopulationOptions pop;
    pop.count = static_cast<std::size_t>(src.population);
    pop.seed = static_cast<std::uint64_t>(src.seed);
    pop.span_s = in.span_s;
    pop.earth = in.earth;
    req.objects = conjunction::synthetic_population(pop);
    req.objects_source = "synthetic population N=" + std::to_string(src.population) +
                         " seed=" + std::to_string(src.seed);
    (void)sc.list_size("objects");  // present but not a list is still an error
    sc.mark_used("objects");
  } else if (!src.objects_csv_path.empty()) {
    req.objects = objects_from_csv(src.objects_csv_text, in.earth);
    req.objects_source = src.objects_csv_path;
    sc.mark_used("objects");
  } else {
    req.objects = objects_from_scenario(sc, in.earth);
    req.objects_source = sc.source();
  }
}

// --method paper: the adaptive Step rule over every pair.
void run_paper(const ScreenObjectsRequest& req, ScreenObjectsResult& r) {
  const ScreenScenario& in = req.scenario;
  conjunction::validate_objects(req.objects, in.earth);
  if (req.objects.size() > 2000) {
    throw std::invalid_argument("--method paper checks all N^2 pairs at every step: " +
                                std::to_string(req.objects.size()) + " objects outside [2, 2000]");
  }
  conjunction::Ephemeris eph(req.objects, in.gravity, in.earth, in.robust.integ);
  std::function<void(double)> progress;
  if (req.progress) progress = [&req](double f) { req.progress(percent("screen (paper)", f)); };
  conjunction::PaperResult p = conjunction::screen_paper(req.objects, in.span_s, in.paper_step, eph, req.trace, progress);
  if (req.progress) req.progress("\n");
  r.steps = p.steps;
  r.events = std::move(p.events);
  r.traced = req.trace;
  r.trace = std::move(p.trace);
}

// --method robust: the screening that cannot miss, on req.threads (and req.ranks).
void run_robust(const ScreenObjectsRequest& req, ScreenObjectsResult& r) {
  const ScreenScenario& in = req.scenario;
  conjunction::ScreenOptions so = in.robust;
  so.threads = req.threads > 0 ? req.threads
                               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const double grid_step_s = so.step_s > 0.0 ? so.step_s : conjunction::auto_step_s(req.objects.size());
  if (req.progress) {
    char buf[256];
    (void)std::snprintf(buf, sizeof buf, "screen: %zu objects, %.0f s, threshold %.1f m, step %.1f s, %d threads, %d ranks\n",
                        req.objects.size(), in.span_s, so.threshold_m, grid_step_s, so.threads, req.ranks);
    req.progress(buf);
    so.progress = [&req](double f) { req.progress(percent("screen", f)); };
  }
  conjunction::ScreenResult s = req.robust_screener ? req.robust_screener(req.objects, in.span_s, so)
                                       : conjunction::screen_robust(req.objects, in.span_s, so);
  if (req.progress) req.progress("\n");
  r.steps = s.stats.steps;
  r.robust = true;
  r.stats = s.stats;
  r.threads = so.threads;
  r.ranks = req.ranks;
  r.grid_step_s = grid_step_s;
  r.events = std::move(s.events);
}

nlohmann::json trace_json(const std::vector<conjunction::TraceRow>& trace, double epoch_s) {
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

nlohmann::json stats_json(const ScreenObjectsResult& r) {
  const conjunction::ScreenStats& st = r.stats;
  const std::size_t n = r.objects.size();
  return {{"grid_steps", st.steps},
          {"pairs_checked", st.pairs_checked},
          {"candidates", st.candidates},
          {"narrow_phase_intervals", st.refined},
          {"root_solves", st.root_solves},
          {"pairs_after_apogee_perigee", st.pairs_after_apogee_perigee},
          {"unproven_leaves", st.unproven_leaves},
          {"repeated_roots_merged", st.repeated_roots_merged},
          {"all_pairs", n * (n - 1) / 2},
          {"threads", r.threads},
          {"ranks", r.ranks},
          {"grid_step_s", r.grid_step_s}};
}

nlohmann::json events_json(const ScreenObjectsResult& r) {
  nlohmann::json ev = nlohmann::json::array();
  for (const auto& c : r.events) {
    ev.push_back({{"i", c.i},
                  {"j", c.j},
                  {"name_i", r.objects[c.i].name},
                  {"name_j", r.objects[c.j].name},
                  {"tca_s", c.tca_s},
                  {"tca_utc", utc_of(r.epoch_j2000_s, c.tca_s)},
                  {"miss_m", c.miss_m},
                  {"rel_speed_mps", c.rel_speed_mps},
                  {"collision", c.collision},
                  {"warning", c.warning}});
  }
  return ev;
}

}  // namespace

void ScreenObjectsRequest::validate() const {
  if (!cdm.dir.empty() && method != "robust")
    throw std::invalid_argument("--cdm-out: only with --method robust (the paper method flags samples, not TCAs)");
  commands::check_screen_cdm_options(cdm, true);
  if (method != "paper" && trace) throw std::invalid_argument("--trace: only with --method paper");
}

ScreenObjectsRequest read_screen_objects_request(const config::Scenario& sc,
                                                 const ScreenObjectsSource& src) {
  ScreenObjectsRequest req;
  req.method = src.method;
  req.scenario = read_screen_scenario(sc);
  load_objects(sc, src, req);
  if (src.method == "paper") sc.mark_used("robust");
  sc.check_all_used();
  req.scenario_used = sc.used();
  return req;
}

ScreenObjectsResult run_screen_objects(const ScreenObjectsRequest& req) {
  req.validate();
  ScreenObjectsResult r;
  r.method = req.method;
  r.objects_source = req.objects_source;
  r.objects = req.objects;
  r.epoch_utc = req.scenario.epoch_utc;
  r.epoch_j2000_s = req.scenario.epoch_j2000_s;
  r.span_s = req.scenario.span_s;
  r.scenario_used = req.scenario_used;
  r.warning_multiple = req.scenario.paper_step.n_warning;
  const auto t0 = std::chrono::steady_clock::now();
  if (req.method == "paper") run_paper(req, r);
  else run_robust(req, r);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!req.cdm.dir.empty() && req.rank == 0) {
    const ScreenScenario& in = req.scenario;
    const commands::ScreenCdmRun run{in.epoch_j2000_s, in.span_s, in.robust.threshold_m,
                                       "objects " + req.objects_source};
    r.cdm = commands::screen_event_cdms(
        req.cdm, run, object_screening_events(r.events, req.objects, in.robust, in.epoch_j2000_s));
  }
  return r;
}

nlohmann::json to_json(const ScreenObjectsResult& r) {
  nlohmann::json out;
  out["command"] = "screen";
  out["method"] = r.method;
  out["objects_source"] = r.objects_source;
  out["objects"] = r.objects.size();
  out["epoch_utc"] = r.epoch_utc;
  out["span_s"] = r.span_s;
  out["scenario"] = r.scenario_used;
  out["steps"] = r.steps;
  if (r.robust) out["stats"] = stats_json(r);
  if (r.traced) out["trace"] = trace_json(r.trace, r.epoch_j2000_s);
  out["wall_time_s"] = r.wall_time_s;
  out["events"] = events_json(r);
  if (r.cdm) out["cdm"] = commands::to_json(*r.cdm);
  return out;
}

}  // namespace evade::commands
