// `evade screen --tle FILE | --omm FILE` as a library call (screen_command.hpp): the SGP4
// motion of the catalog (sgp4_screening; Vallado, Crawford, Hujsak & Kelso 2006, AIAA
// 2006-6753), screened by the robust screener (screen_robust). Times count from the start
// (default: the latest element epoch); positions are TEME (distances are frame-independent).
#include <algorithm>
#include <chrono>
#include <optional>
#include <cstdio>
#include <stdexcept>
#include <thread>
#include <utility>

#include "evade/commands/screen_command.hpp"

#include "evade/config/read_params.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/commands/screening_events.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/core/epoch.hpp"

namespace evade::commands {
namespace {

constexpr double kMaxScreenSpanS = 31.0 * 86400.0;  // SGP4 element sets are stale after weeks

std::string utc(double j2000_s) { return format_calendar_utc(calendar_from_seconds_since_j2000(j2000_s)); }

// Index of the primary in the screened objects; names the reason when it is not there.
long primary_index(const ScreenCatalogRequest& req, const conjunction::Sgp4Screening& s) {
  return req.primary_norad < 0 ? -1 : static_cast<long>(conjunction::primary_index(s, req.primary_norad));
}

// The start of the screen (UTC s since J2000): --start, else the latest element epoch of the
// whole catalog (as sgp4_screening takes it), so that the prefilter does not move it.
double screen_start_j2000_s(const ScreenCatalogRequest& req) {
  if (!req.start_utc.empty()) return seconds_since_j2000_from_calendar(parse_calendar_utc(req.start_utc));
  return sgp4::latest_epoch_seconds_since_j2000(req.catalog.objects);
}

conjunction::Sgp4Screening catalog_motion(const ScreenCatalogRequest& req,
                             std::optional<conjunction::PrimaryPrefilterCounts>* counts) {
  conjunction::Sgp4MotionOptions mo;
  mo.span_s = req.span_s;
  mo.threads = req.threads > 0 ? req.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  mo.start_at_latest_epoch = false;
  mo.start_j2000_s = screen_start_j2000_s(req);
  if (req.ranks > 1 && req.sum_over_ranks) {  // each rank samples its share of the envelopes
    mo.part = req.rank;
    mo.parts = req.ranks;
    mo.sum_over_parts = req.sum_over_ranks;
  }
  std::vector<sgp4::MeanElements> kept;
  const bool filter = req.prefilter && req.primary_norad >= 0;
  if (filter) {
    counts->emplace();
    kept = conjunction::prefilter_primary(req.catalog.objects, req.primary_norad, mo.start_j2000_s,
                             req.span_s, req.robust.threshold_m, &**counts, mo.threads, req.path_filter);
  }
  conjunction::Sgp4Screening s = conjunction::sgp4_screening(filter ? kept : req.catalog.objects, mo);
  if (req.diagnostic)
    for (const auto& r : s.rejected) req.diagnostic("evade screen: rejected: " + r.message() + "\n");
  if (s.objects.size() < (filter ? 1u : 2u))  // the primary alone: nothing comes within D
    throw std::invalid_argument("fewer than two usable element sets (" + std::to_string(req.catalog.bad_entries) +
                                " bad entries, " + std::to_string(s.rejected.size()) + " rejected)");
  return s;
}

// The screen's options but for the motion and the primary (catalog_options adds them).
conjunction::ScreenOptions base_options(const ScreenCatalogRequest& req) {
  conjunction::ScreenOptions so = req.robust;
  so.threads = req.threads > 0 ? req.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (req.progress) {
    so.progress = [&req](double f) {
      char buf[64];
      (void)std::snprintf(buf, sizeof buf, "\rscreen: %5.1f %%", 100.0 * f);
      req.progress(buf);
    };
  }
  return so;
}

conjunction::ScreenOptions catalog_options(const ScreenCatalogRequest& req, const conjunction::Sgp4Screening& s) {
  conjunction::ScreenOptions so = base_options(req);
  so.motion = s.motion;
  so.primary = primary_index(req, s);
  return so;
}

std::vector<CatalogEvent> catalog_events(const conjunction::ScreenResult& r, const conjunction::Sgp4Screening& s) {
  std::vector<CatalogEvent> out;
  out.reserve(r.events.size());
  for (const auto& c : r.events) {
    out.push_back({s.norad_ids[c.i], s.norad_ids[c.j], s.objects[c.i].name, s.objects[c.j].name,
                   c.tca_s, utc(s.start_j2000_s + c.tca_s), c.miss_m, c.rel_speed_mps});
  }
  return out;
}

// Everything but the events, the statistics and the CDMs.
ScreenCatalogResult catalog_header(const ScreenCatalogRequest& req, const conjunction::Sgp4Screening& s,
                                   const conjunction::ScreenOptions& so) {
  ScreenCatalogResult res;
  res.frame = s.motion->frame();
  res.source = req.source;
  res.start_j2000_s = s.start_j2000_s;
  res.start_utc = utc(s.start_j2000_s);
  res.span_s = req.span_s;
  res.threshold_m = req.robust.threshold_m;
  res.objects = static_cast<long>(s.objects.size());
  res.bad_entries = req.catalog.bad_entries;
  for (const auto& rj : s.rejected) res.rejections.push_back(rj.message());
  if (so.primary >= 0) res.primary_norad = req.primary_norad;
  res.threads = so.threads;
  res.ranks = req.ranks;
  res.grid_step_s = so.step_s > 0.0 ? so.step_s : conjunction::auto_step_s(s.objects.size(), so);
  res.envelopes_sampled = s.envelopes_sampled;
  return res;
}

}  // namespace

conjunction::ScreenOptions catalog_screen_options() {
  conjunction::ScreenOptions so;
  so.gravity = GravityModel::kTwoBodyJ2;
  so.earth = conjunction::wgs72_earth();
  so.threshold_m = 5000.0;
  so.include_warning_radius = false;  // catalogs carry no sizes: the threshold alone
  so.step_s = 0.0;                    // auto_step_s(N)
  return so;
}

void ScreenCatalogRequest::validate() const {
  if (!(span_s > 0.0 && span_s <= kMaxScreenSpanS))
    throw std::invalid_argument("--span-s = " + std::to_string(span_s) +
                                " is invalid: expected a number in (0, 2678400] s");
  if (!(robust.threshold_m > 0.0 && robust.threshold_m <= 1e8))
    throw std::invalid_argument("--threshold-m = " + std::to_string(robust.threshold_m) +
                                " is invalid: expected a number in (0, 1e8] m");
  if (!(robust.step_s == 0.0 || (robust.step_s >= 1.0 && robust.step_s <= 600.0)))
    throw std::invalid_argument("--step-s = " + std::to_string(robust.step_s) +
                                " is invalid: expected 0 (automatic) or a number in [1, 600] s");
  commands::check_screen_cdm_options(cdm, false);  // catalog objects carry no radii
}

void apply_param_values(const std::vector<ParamValue>& values, ScreenCatalogRequest* req) {
  const std::pair<const char*, double*> fields[] = {
      {"span_s", &req->span_s}, {"robust.threshold_m", &req->robust.threshold_m}, {"robust.step_s", &req->robust.step_s}};
  for (const ParamValue& v : values) {
    const ParamSpec* spec = v.key == "span_s"
                                ? config::find_param_spec(screen_scenario_params(), "", v.key)
                                : config::find_param_spec(conjunction::screen_options_params(), "robust.", v.key);
    double* field = nullptr;
    for (const auto& [key, f] : fields) field = v.key == key ? f : field;
    if (spec == nullptr || field == nullptr) {
      throw config::ConfigError("command-line flags: unknown key '" + v.key +
                                "' (allowed span_s, robust.threshold_m, robust.step_s)");
    }
    if (!param_value_ok(*spec, v.value)) {
      throw config::ConfigError("command-line flags: " + param_error(v.key, param_value_text(v.value), *spec));
    }
    *field = v.value;
  }
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The result of a screen of s (events r, options so): header, events and CDMs.
ScreenCatalogResult catalog_result(const ScreenCatalogRequest& req, const conjunction::Sgp4Screening& s,
                                   const conjunction::ScreenOptions& so, const conjunction::ScreenResult& r) {
  ScreenCatalogResult res = catalog_header(req, s, so);
  res.stats = r.stats;
  res.events = catalog_events(r, s);
  if (!req.cdm.dir.empty() && req.rank == 0) {  // the other ranks hold only their part
    const commands::ScreenCdmRun run{s.start_j2000_s, req.span_s, req.robust.threshold_m, "catalog " + req.source};
    res.cdm = commands::screen_event_cdms(req.cdm, run,
                                            catalog_screening_events(r.events, s, req.catalog.objects, so));
  }
  return res;
}

// One satellite against the catalog: perigee/apogee filter, then each object inside the
// time filter's windows only (primary_window_screen.hpp).
ScreenCatalogResult run_windowed(const ScreenCatalogRequest& req) {
  const auto t0 = Clock::now();
  conjunction::PrimaryPrefilterCounts counts;
  const double start_s = screen_start_j2000_s(req);
  const conjunction::ScreenOptions base = base_options(req);
  const std::vector<sgp4::MeanElements> kept = conjunction::prefilter_primary(
      req.catalog.objects, req.primary_norad, start_s, req.span_s, req.robust.threshold_m, &counts, base.threads,
      req.path_filter);
  const auto t1 = Clock::now();
  const conjunction::PrimaryWindowScreen w = conjunction::screen_primary_windows(kept, req.primary_norad, start_s, req.span_s,
                                                       base, conjunction::TimeFilterOptions{req.robust.threshold_m});
  const auto t2 = Clock::now();
  if (req.progress) req.progress("\n");
  if (req.diagnostic)
    for (const auto& r : w.screening.rejected) req.diagnostic("evade screen: rejected: " + r.message() + "\n");
  conjunction::ScreenOptions so = catalog_options(req, w.screening);
  so.step_s = w.step_s;  // the grid step the windows used
  ScreenCatalogResult res = catalog_result(req, w.screening, so, w.result);
  res.prefilter = counts;
  res.time_filter = w.counts;
  res.motion_setup_wall_s = seconds(t0, t1);
  res.screen_wall_s = seconds(t1, t2);
  return res;
}

}  // namespace

ScreenCatalogResult run_screen_catalog(const ScreenCatalogRequest& req) {
  req.validate();
  if (req.primary_norad >= 0 && req.prefilter && req.time_filter && !req.robust_screener) return run_windowed(req);
  const auto t0 = Clock::now();
  std::optional<conjunction::PrimaryPrefilterCounts> prefilter;
  const conjunction::Sgp4Screening s = catalog_motion(req, &prefilter);
  const auto t1 = Clock::now();
  const conjunction::ScreenOptions so = catalog_options(req, s);
  const conjunction::ScreenResult r = req.robust_screener ? req.robust_screener(s.objects, req.span_s, so)
                                              : conjunction::screen_robust(s.objects, req.span_s, so);
  const auto t2 = Clock::now();
  if (req.progress) req.progress("\n");
  ScreenCatalogResult res = catalog_result(req, s, so, r);
  res.prefilter = prefilter;
  res.motion_setup_wall_s = seconds(t0, t1);
  res.screen_wall_s = seconds(t1, t2);
  return res;
}

nlohmann::json to_json(const ScreenCatalogResult& r) {
  nlohmann::json j;
  j["command"] = "screen";
  j["motion"] = "sgp4";
  j["frame"] = r.frame;
  j["source"] = r.source;
  j["start_utc"] = r.start_utc;
  j["span_s"] = r.span_s;
  j["threshold_m"] = r.threshold_m;
  j["objects"] = r.objects;
  j["bad_entries"] = r.bad_entries;
  j["rejected"] = static_cast<long>(r.rejections.size());
  j["rejections"] = r.rejections;
  if (r.primary_norad) j["primary"] = *r.primary_norad;
  if (r.prefilter)
    j["prefilter"] = {{"objects", r.prefilter->objects},
                      {"removed_perigee_apogee", r.prefilter->removed_radius},
                      {"removed_orbit_path", r.prefilter->removed_path},
                      {"orbit_path_tests", r.prefilter->path_tests},
                      {"kept_without_radius_bound", r.prefilter->unbounded},
                      {"deep_space_sampled", r.prefilter->sampled},
                      {"propagated", r.prefilter->kept},
                      {"primary_radius_bounded", r.prefilter->primary_bounded}};
  if (r.time_filter)
    j["time_filter"] = {{"objects", r.time_filter->objects},
                        {"removed", r.time_filter->removed},
                        {"screened", r.time_filter->screened},
                        {"screened_whole_span", r.time_filter->unfiltered},
                        {"windows", r.time_filter->windows},
                        {"window_total_s", r.time_filter->window_s},
                        {"sgp4_pair_evaluations", r.time_filter->evaluations}};
  j["stats"] = {{"grid_steps", r.stats.steps},
                {"pairs_checked", r.stats.pairs_checked},
                {"candidates", r.stats.candidates},
                {"narrow_phase_intervals", r.stats.refined},
                {"root_solves", r.stats.root_solves},
                {"unproven_leaves", r.stats.unproven_leaves},
                {"repeated_roots_merged", r.stats.repeated_roots_merged},
                {"threads", r.threads},
                {"ranks", r.ranks},
                {"grid_step_s", r.grid_step_s}};
  j["envelopes_sampled"] = r.envelopes_sampled;
  j["motion_setup_wall_s"] = r.motion_setup_wall_s;
  j["screen_wall_s"] = r.screen_wall_s;
  nlohmann::json ev = nlohmann::json::array();
  for (const auto& e : r.events) {
    ev.push_back({{"norad_i", e.norad_i}, {"norad_j", e.norad_j}, {"name_i", e.name_i},
                  {"name_j", e.name_j}, {"tca_s", e.tca_s}, {"tca_utc", e.tca_utc},
                  {"miss_m", e.miss_m}, {"rel_speed_mps", e.rel_speed_mps}});
  }
  j["events"] = std::move(ev);
  if (r.cdm) j["cdm"] = commands::to_json(*r.cdm);
  return j;
}

}  // namespace evade::commands
