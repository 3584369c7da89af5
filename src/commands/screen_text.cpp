// The human text of `evade screen` (screen_command.hpp): one line per event with its TCA (UTC,
// to the millisecond), miss distance, relative speed, the Pc of its CDM when a covariance
// was given, and paper 002's flags (Wang Xiaoyu 2006, eq. 1-2) explained below the table.
#include <cmath>
#include <cstdio>
#include <string>

#include "evade/commands/screen_command.hpp"
#include "evade/core/epoch.hpp"
#include "evade/core/text_format.hpp"

namespace evade::commands {
namespace {

// " Pc 1.234e-05" for event k when its CDM carries a Pc; "" without a covariance.
std::string pc_column(const std::optional<commands::ScreenCdms>& cdm, std::size_t k) {
  if (!cdm || !cdm->covariance_known || k >= cdm->files.size()) return "";
  const std::optional<double>& pc = cdm->files[k].pc;
  return pc ? format_text("  Pc %9.3e", *pc) : std::string("  Pc       n/a");
}

std::string cdm_lines(const std::optional<commands::ScreenCdms>& cdm) {
  if (!cdm) return "";
  std::string s = format_text("CDMs: %zu (%s) in %s; covariance %s", cdm->files.size(),
                         cdm->format.c_str(), cdm->dir.c_str(), cdm->covariance.c_str());
  if (cdm->covariance_known)
    s += "; Pc = 2D probability of collision over the hard-body disk (Foster & Estes 1992)";
  return s + "\n";
}

}  // namespace

std::string utc_text_ms(double utc_j2000_s) {
  const double ms_total = std::round(utc_j2000_s * 1000.0);
  const double whole_s = std::floor(ms_total / 1000.0);
  const int ms = static_cast<int>(ms_total - whole_s * 1000.0);
  const CalendarUtc c = calendar_from_seconds_since_j2000(whole_s);
  return format_text("%04d-%02d-%02d %02d:%02d:%02d.%03d UTC", c.year, c.month, c.day, c.hour,
                c.minute, static_cast<int>(std::lround(c.second)), ms);
}

std::string to_text(const ScreenObjectsResult& r) {
  std::string s = format_text("%s screening of %zu objects over %.0f s from %s: %zu events, %ld steps, %.3f s wall time\n",
                         r.method.c_str(), r.objects.size(), r.span_s, utc_text_ms(r.epoch_j2000_s).c_str(),
                         r.events.size(), r.steps, r.wall_time_s);
  bool flagged = false;
  for (std::size_t k = 0; k < r.events.size(); ++k) {
    const conjunction::Conjunction& c = r.events[k];
    s += format_text("  %-10s %-10s TCA %s  miss %12.3f m  v_rel %9.3f m/s%s%s%s\n",
                r.objects[c.i].name.c_str(), r.objects[c.j].name.c_str(),
                utc_text_ms(r.epoch_j2000_s + c.tca_s).c_str(), c.miss_m, c.rel_speed_mps,
                pc_column(r.cdm, k).c_str(), c.collision ? "  COLLISION" : "", c.warning ? "  WARNING" : "");
    flagged = flagged || c.collision || c.warning;
  }
  if (r.method == "paper" && !r.events.empty())
    s += "(paper method: TCA and miss are those of the flagged sample of the adaptive step, not the exact closest approach)\n";
  if (flagged) {
    s += format_text("COLLISION: miss <= R_c = (L_i + dR_i) + (L_j + dR_j), the two objects' sizes plus position errors "
                "(paper 002, eq. 1-2): a distance flag, not a probability; WARNING: miss <= %g R_c\n",
                r.warning_multiple);
  }
  return s + cdm_lines(r.cdm);
}

std::string to_text(const ScreenCatalogResult& r) {
  std::string s = format_text("SGP4 screening of %ld objects (%ld rejected, %ld bad entries) from %s over %.0f s, "
                         "threshold %.1f m: %zu events, %.3f s wall time\n",
                         r.objects, static_cast<long>(r.rejections.size()), r.bad_entries,
                         utc_text_ms(r.start_j2000_s).c_str(), r.span_s, r.threshold_m, r.events.size(),
                         r.screen_wall_s);
  if (r.prefilter)
    s += format_text("  prefilter (perigee/apogee, then orbit path, against the primary): %ld and %ld of %ld "
                     "objects set aside, %ld kept without a radius bound, %ld propagated\n",
                     r.prefilter->removed_radius, r.prefilter->removed_path, r.prefilter->objects,
                     r.prefilter->unbounded, r.prefilter->kept);
  if (r.time_filter)
    s += format_text("  time filter: %ld of %ld objects never within the threshold, %ld screened in %ld windows "
                     "(%.0f s in all; %ld over the whole span)\n",
                     r.time_filter->removed, r.time_filter->objects, r.time_filter->screened,
                     r.time_filter->windows, r.time_filter->window_s, r.time_filter->unfiltered);
  for (std::size_t k = 0; k < r.events.size(); ++k) {
    const CatalogEvent& e = r.events[k];
    s += format_text("  %-24s %-24s TCA %s  miss %12.3f m  v_rel %9.3f m/s%s\n", e.name_i.c_str(),
                e.name_j.c_str(), utc_text_ms(r.start_j2000_s + e.tca_s).c_str(), e.miss_m,
                e.rel_speed_mps, pc_column(r.cdm, k).c_str());
  }
  return s + cdm_lines(r.cdm);
}

}  // namespace evade::commands
