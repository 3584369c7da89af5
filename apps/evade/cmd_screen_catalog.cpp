// `evade screen --tle FILE | --omm FILE [--primary ID] [--span-s S] [--threshold-m D]
// [--step-s H] [--start UTC] [--threads N] [--json]`: reads the file (the only
// I/O), builds the SGP4 motion (conjunction::sgp4_screening), screens it with the robust
// screener (conjunction::screen_robust) and prints. Times count from the start (default: the
// latest element epoch in the file); positions are TEME (distances are frame-independent).
#include "cmd_screen_catalog.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/core/epoch.hpp"
#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::cli {
namespace {

using namespace evade::conjunction;

constexpr double kMaxSpanS = 31.0 * 86400.0;  // SGP4 element sets are stale after weeks

void check_options(const CatalogScreenOptions& o) {
  if (!(o.span_s > 0.0 && o.span_s <= kMaxSpanS))
    throw std::invalid_argument("--span-s = " + std::to_string(o.span_s) +
                                " is invalid: expected a number in (0, 2678400] s");
  if (!(o.threshold_m > 0.0 && o.threshold_m <= 1e8))
    throw std::invalid_argument("--threshold-m = " + std::to_string(o.threshold_m) +
                                " is invalid: expected a number in (0, 1e8] m");
  if (!(o.step_s == 0.0 || (o.step_s >= 1.0 && o.step_s <= 600.0)))
    throw std::invalid_argument("--step-s = " + std::to_string(o.step_s) +
                                " is invalid: expected 0 (automatic) or a number in [1, 600] s");
}

std::string utc(double j2000_s) { return format_calendar_utc(calendar_from_seconds_since_j2000(j2000_s)); }

// Index of --primary in the screened objects; names the reason when it is not there.
long primary_index(const CatalogScreenOptions& o, const Sgp4Screening& s) {
  if (o.primary_norad < 0) return -1;
  for (std::size_t k = 0; k < s.norad_ids.size(); ++k)
    if (s.norad_ids[k] == o.primary_norad) return static_cast<long>(k);
  for (const auto& r : s.rejected)
    if (r.norad_id == o.primary_norad)
      throw std::invalid_argument("--primary " + std::to_string(o.primary_norad) + ": rejected: " + r.reason);
  throw std::invalid_argument("--primary " + std::to_string(o.primary_norad) + ": no such object in the catalog");
}

nlohmann::json events_json(const ScreenResult& r, const Sgp4Screening& s) {
  nlohmann::json ev = nlohmann::json::array();
  for (const auto& c : r.events) {
    ev.push_back({{"norad_i", s.norad_ids[c.i]},
                  {"norad_j", s.norad_ids[c.j]},
                  {"name_i", s.objects[c.i].name},
                  {"name_j", s.objects[c.j].name},
                  {"tca_s", c.tca_s},
                  {"tca_utc", utc(s.start_j2000_s + c.tca_s)},
                  {"miss_m", c.miss_m},
                  {"rel_speed_mps", c.rel_speed_mps}});
  }
  return ev;
}

nlohmann::json stats_json(const ScreenStats& st, const ScreenOptions& so, std::size_t n) {
  return {{"grid_steps", st.steps},
          {"pairs_checked", st.pairs_checked},
          {"candidates", st.candidates},
          {"narrow_phase_intervals", st.refined},
          {"root_solves", st.root_solves},
          {"unproven_leaves", st.unproven_leaves},
          {"threads", so.threads},
          {"grid_step_s", so.step_s > 0.0 ? so.step_s : auto_step_s(n)}};
}

void print_text(const nlohmann::json& j) {
  std::printf("SGP4 screening of %ld objects (%ld rejected) from %s over %.0f s, threshold %.1f m: %zu events, %.3f s\n",
              j["objects"].get<long>(), j["rejected"].get<long>(), j["start_utc"].get<std::string>().c_str(),
              j["span_s"].get<double>(), j["threshold_m"].get<double>(), j["events"].size(),
              j["screen_wall_s"].get<double>());
  for (const auto& e : j["events"]) {
    std::printf("  %-24s %-24s TCA %s  miss %12.3f m  v_rel %9.3f m/s\n", e["name_i"].get<std::string>().c_str(),
                e["name_j"].get<std::string>().c_str(), e["tca_utc"].get<std::string>().c_str(),
                e["miss_m"].get<double>(), e["rel_speed_mps"].get<double>());
  }
}

}  // namespace

int run_screen_catalog(const CatalogScreenOptions& o) {
  check_options(o);
  const sgp4::Catalog cat = read_catalog_file(o.tle_path, o.omm_path);
  for (const auto& is : cat.issues) (void)std::fprintf(stderr, "evade screen: bad entry: %s\n", is.message().c_str());
  Sgp4MotionOptions mo;
  mo.span_s = o.span_s;
  if (!o.start_utc.empty()) {
    mo.start_at_latest_epoch = false;
    mo.start_j2000_s = seconds_since_j2000_from_calendar(parse_calendar_utc(o.start_utc));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const Sgp4Screening s = sgp4_screening(cat.objects, mo);
  const auto t1 = std::chrono::steady_clock::now();
  for (const auto& r : s.rejected) (void)std::fprintf(stderr, "evade screen: rejected: %s\n", r.message().c_str());
  if (s.objects.size() < 2)
    throw std::invalid_argument("fewer than two usable element sets (" + std::to_string(cat.bad_entries) +
                                " bad entries, " + std::to_string(s.rejected.size()) + " rejected)");
  ScreenOptions so;
  so.motion = s.motion;
  so.gravity = GravityModel::kTwoBodyJ2;
  so.earth = wgs72_earth();
  so.threshold_m = o.threshold_m;
  so.include_warning_radius = false;  // catalogs carry no sizes: the threshold alone
  so.step_s = o.step_s;
  so.threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  so.primary = primary_index(o, s);
  if (!o.quiet) so.progress = [](double f) { (void)std::fprintf(stderr, "\rscreen: %5.1f %%", 100.0 * f); };
  const ScreenResult r = screen_robust(s.objects, o.span_s, so);
  const auto t2 = std::chrono::steady_clock::now();
  if (!o.quiet) (void)std::fprintf(stderr, "\n");
  nlohmann::json j;
  j["command"] = "screen";
  j["motion"] = "sgp4";
  j["frame"] = s.motion->frame();
  j["source"] = o.tle_path.empty() ? o.omm_path : o.tle_path;
  j["start_utc"] = utc(s.start_j2000_s);
  j["span_s"] = o.span_s;
  j["threshold_m"] = o.threshold_m;
  j["objects"] = static_cast<long>(s.objects.size());
  j["bad_entries"] = cat.bad_entries;
  j["rejected"] = static_cast<long>(s.rejected.size());
  j["rejections"] = nlohmann::json::array();
  for (const auto& rj : s.rejected) j["rejections"].push_back(rj.message());
  if (so.primary >= 0) j["primary"] = o.primary_norad;
  j["stats"] = stats_json(r.stats, so, s.objects.size());
  j["motion_setup_wall_s"] = std::chrono::duration<double>(t1 - t0).count();
  j["screen_wall_s"] = std::chrono::duration<double>(t2 - t1).count();
  j["events"] = events_json(r, s);
  if (!o.cdm.dir.empty())
    j["cdm"] = write_catalog_cdms(o.cdm, {s.start_j2000_s, o.span_s, o.threshold_m, "catalog " + j["source"].get<std::string>()},
                                  r, s, cat.objects, so);
  if (o.json) print_json(j);
  else print_text(j);
  return 0;
}

}  // namespace evade::cli
