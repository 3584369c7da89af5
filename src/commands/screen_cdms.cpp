// One CDM per screening event (see screen_cdms.hpp; CCSDS 508.0-B-1). The message itself is
// cdm_from_event's; this file builds the assumed covariance, the unique stems and the run's
// header fields.
#include "evade/core/epoch.hpp"
#include "evade/commands/screen_cdms.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <utility>

#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"

namespace evade::commands {
namespace {

double now_utc_j2000_s() {
  const double unix_s = std::chrono::duration<double>(
                            std::chrono::system_clock::now().time_since_epoch()).count();
  return unix_s - kJ2000UnixS;
}

commands::EventCdmOptions cdm_base_options(const ScreenCdmOptions& o, const ScreenCdmRun& run) {
  commands::EventCdmOptions opt;
  opt.creation_utc_j2000_s = o.creation_utc_j2000_s ? *o.creation_utc_j2000_s : now_utc_j2000_s();
  opt.hbr_m = o.hbr_m;
  opt.assess = o.assess;
  opt.hbr_source = o.hbr_m > 0.0 ? "--hbr-m" : "sum of the two objects' radii (AREA_PC = pi r^2)";
  opt.header_comment = "evade screen: " + run.source;
  return opt;
}

// The run's fields and the covariance of one event (its TCA already in UTC).
void complete_event(const ScreenCdmOptions& o, const ScreenCdmRun& run,
                    const std::optional<Mat6>& cov, commands::ScreeningEvent& ev) {
  for (auto& ob : ev.obj) {
    ob.cov_rtn = cov;
    if (cov) ob.cov_comment = "assumed covariance (--cov-rtn-sigma-m " + o.cov_rtn_sigma_text +
                              "): diagonal RTN position sigmas, velocity terms 0; not from an orbit determination";
    if (o.hbr_m > 0.0) ob.radius_m = 0.0;  // the given radius, not the objects' sizes
  }
  ev.screen_start_utc_j2000_s = run.epoch_utc_j2000_s;
  ev.screen_stop_utc_j2000_s = run.epoch_utc_j2000_s + run.span_s;
  ev.screen_threshold_m = run.threshold_m;
}

ScreenCdmFile one_message(const ScreenCdmOptions& o, const commands::ScreeningEvent& ev, bool cov,
                          const commands::EventCdmOptions& base, std::set<std::string>& used) {
  std::string stem = commands::cdm_event_file_stem(ev);
  for (int k = 2; !used.insert(stem).second; ++k) stem = commands::cdm_event_file_stem(ev) + "-" + std::to_string(k);
  commands::EventCdmOptions opt = base;
  opt.message_id = stem;
  if (opt.hbr_m <= 0.0) opt.hbr_m = ev.obj[0].radius_m + ev.obj[1].radius_m;
  if (cov && !(opt.hbr_m > 0.0))
    throw std::invalid_argument("--cov-rtn-sigma-m: the objects " + ev.obj[0].designator + " and " +
                                ev.obj[1].designator + " have no size: give --hbr-m");
  const commands::EventCdm m = commands::cdm_from_event(ev, opt);
  ScreenCdmFile f;
  f.path = (std::filesystem::path(o.dir) / (stem + (o.format == "xml" ? ".xml" : ".cdm"))).string();
  f.message_id = stem;
  f.text = o.format == "xml" ? ccsds::write_cdm_xml(m.cdm) : ccsds::write_cdm_kvn(m.cdm);
  f.pc = m.pc;
  if (m.pc) f.pc_method = m.pc_method;
  return f;
}

}  // namespace

std::optional<Mat6> assumed_rtn_covariance(const ScreenCdmOptions& o) {
  if (o.cov_rtn_sigma_text.empty()) return std::nullopt;
  const std::vector<double>& v = o.cov_rtn_sigma_m;
  if (v.size() != 3 ||
      !(v[0] > 0.0 && v[1] > 0.0 && v[2] > 0.0) ||
      !(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) ||
      v[0] > 1e7 || v[1] > 1e7 || v[2] > 1e7)
    throw std::invalid_argument("--cov-rtn-sigma-m = '" + o.cov_rtn_sigma_text +
                                "' is invalid: expected SIGMA_R_M,SIGMA_T_M,SIGMA_N_M, three "
                                "numbers in (0, 1e7] m");
  Mat6 c = Mat6::Zero();
  for (int k = 0; k < 3; ++k) c(k, k) = v[static_cast<std::size_t>(k)] * v[static_cast<std::size_t>(k)];
  return c;
}

void check_screen_cdm_options(const ScreenCdmOptions& o, bool objects_have_radii) {
  if (o.dir.empty()) {
    if (!o.cov_rtn_sigma_text.empty() || o.hbr_m > 0.0 || o.format != "kvn" || o.assess_given)
      throw std::invalid_argument(
          "--cdm-format, --cov-rtn-sigma-m, --hbr-m and --mc-max-samples: only with --cdm-out DIR");
    return;
  }
  (void)assumed_rtn_covariance(o);
  if (o.hbr_m > 0.0 && o.cov_rtn_sigma_text.empty())
    throw std::invalid_argument("--hbr-m: only with --cov-rtn-sigma-m (without a covariance there is no Pc)");
  if (o.assess_given && o.cov_rtn_sigma_text.empty())
    throw std::invalid_argument(
        "--mc-max-samples: only with --cov-rtn-sigma-m (without a covariance there is no Pc)");
  if (!o.cov_rtn_sigma_text.empty() && !objects_have_radii && !(o.hbr_m > 0.0))
    throw std::invalid_argument("--cov-rtn-sigma-m: catalog objects carry no size: give --hbr-m");
}

ScreenCdms screen_event_cdms(const ScreenCdmOptions& o, const ScreenCdmRun& run,
                             std::vector<commands::ScreeningEvent> events) {
  ScreenCdms out;
  out.dir = o.dir;
  out.format = o.format;
  out.covariance = o.cov_rtn_sigma_text.empty() ? "not known (no Pc)"
                                                : "assumed RTN sigmas " + o.cov_rtn_sigma_text + " m";
  const std::optional<Mat6> cov = assumed_rtn_covariance(o);
  out.covariance_known = cov.has_value();
  const commands::EventCdmOptions base = cdm_base_options(o, run);
  std::set<std::string> used;
  for (commands::ScreeningEvent& ev : events) {
    complete_event(o, run, cov, ev);
    ScreenCdmFile f = one_message(o, ev, cov.has_value(), base, used);
    if (o.sink) {
      o.sink(f);
      f.text.clear();  // written: memory does not grow with the messages' text
    }
    out.files.push_back(std::move(f));
  }
  return out;
}

nlohmann::json to_json(const ScreenCdms& c) {
  nlohmann::json files = nlohmann::json::array();
  for (const ScreenCdmFile& f : c.files) {
    nlohmann::json j = {{"file", f.path}, {"message_id", f.message_id}};
    j["pc"] = f.pc ? nlohmann::json(*f.pc) : nlohmann::json(nullptr);
    j["pc_method"] = f.pc ? nlohmann::json(f.pc_method) : nlohmann::json(nullptr);
    files.push_back(std::move(j));
  }
  return {{"dir", c.dir}, {"format", c.format}, {"count", c.files.size()},
          {"covariance", c.covariance}, {"files", std::move(files)}};
}

}  // namespace evade::commands
