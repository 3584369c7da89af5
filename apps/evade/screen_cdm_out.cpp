// `evade screen ... --cdm-out DIR`: one CDM per event (screen_cdm_out.hpp). The message is
// built by assessment::cdm_from_event and the states by conjunction::event_states; this
// file parses the flags, turns TEME into EME2000 for the catalog path and writes the files.
#include "screen_cdm_out.hpp"

#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "evade/assessment/cdm_kvn.hpp"
#include "evade/assessment/cdm_xml.hpp"
#include "evade/conjunction/event_states.hpp"
#include "evade/core/epoch.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"
#include "number_list.hpp"

namespace evade::cli {
namespace {

using assessment::EventObject;
using assessment::ScreeningEvent;

// --cov-rtn-sigma-m R,T,N -> diag(R^2, T^2, N^2) position block, velocity block 0.
std::optional<Mat6> assumed_cov(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::vector<double> v = parse_number_list(text, ',');
  if (v.size() != 3 ||
      !(v[0] > 0.0 && v[1] > 0.0 && v[2] > 0.0) ||
      !(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) ||
      v[0] > 1e7 || v[1] > 1e7 || v[2] > 1e7)
    throw std::invalid_argument("--cov-rtn-sigma-m = '" + text +
                                "' is invalid: expected SIGMA_R_M,SIGMA_T_M,SIGMA_N_M, three "
                                "numbers in (0, 1e7] m");
  Mat6 c = Mat6::Zero();
  for (int k = 0; k < 3; ++k) c(k, k) = v[k] * v[k];
  return c;
}

double now_utc_j2000_s() {
  const double unix_s = std::chrono::duration<double>(
                            std::chrono::system_clock::now().time_since_epoch()).count();
  return unix_s - 946728000.0;  // 2000-01-01T12:00:00 UTC in Unix seconds
}

// "58002B" (TLE columns 10-17) -> "1958-002B" (CCSDS 508.0-B-1 YYYY-NNNP{PP}).
std::string intl_designator(const std::string& id) {
  if (id.size() >= 6 && id[2] != '-' && std::isdigit(static_cast<unsigned char>(id[0])) &&
      std::isdigit(static_cast<unsigned char>(id[1]))) {
    const int yy = std::stoi(id.substr(0, 2));
    return std::to_string(yy < 57 ? 2000 + yy : 1900 + yy) + "-" + id.substr(2);
  }
  return id;
}

// Writes one message; returns {file, pc}.
nlohmann::json write_one(const CdmOutOptions& o, const CdmRunInfo& run, ScreeningEvent& ev,
                         const assessment::EventCdmOptions& base, std::set<std::string>& used) {
  const std::optional<Mat6> cov = assumed_cov(o.cov_sigma);
  for (auto& ob : ev.obj) {
    ob.cov_rtn = cov;
    if (cov) ob.cov_comment = "assumed covariance (--cov-rtn-sigma-m " + o.cov_sigma +
                              "): diagonal RTN position sigmas, velocity terms 0; not from an orbit determination";
  }
  ev.tca_utc_j2000_s += run.epoch_utc_j2000_s;
  ev.screen_start_utc_j2000_s = run.epoch_utc_j2000_s;
  ev.screen_stop_utc_j2000_s = run.epoch_utc_j2000_s + run.span_s;
  ev.screen_threshold_m = run.threshold_m;
  std::string stem = assessment::cdm_event_file_stem(ev);
  for (int k = 2; !used.insert(stem).second; ++k) stem = assessment::cdm_event_file_stem(ev) + "-" + std::to_string(k);
  assessment::EventCdmOptions opt = base;
  opt.message_id = stem;
  if (opt.hbr_m <= 0.0) opt.hbr_m = ev.obj[0].radius_m + ev.obj[1].radius_m;
  if (cov && !(opt.hbr_m > 0.0))
    throw std::invalid_argument("--cov-rtn-sigma-m: the objects " + ev.obj[0].designator + " and " +
                                ev.obj[1].designator + " have no size: give --hbr-m");
  const assessment::EventCdm m = assessment::cdm_from_event(ev, opt);
  const std::string path = (std::filesystem::path(o.dir) / (stem + (o.format == "xml" ? ".xml" : ".cdm"))).string();
  std::ofstream f(path);
  f << (o.format == "xml" ? assessment::write_cdm_xml(m.cdm) : assessment::write_cdm_kvn(m.cdm));
  f.close();
  if (!f) throw std::runtime_error("--cdm-out: cannot write '" + path + "'");
  nlohmann::json j = {{"file", path}, {"message_id", stem}};
  j["pc"] = m.pc ? nlohmann::json(*m.pc) : nlohmann::json(nullptr);
  return j;
}

assessment::EventCdmOptions base_options(const CdmOutOptions& o, const CdmRunInfo& run) {
  assessment::EventCdmOptions opt;
  opt.creation_utc_j2000_s = now_utc_j2000_s();
  opt.hbr_m = o.hbr_m;
  opt.hbr_source = o.hbr_m > 0.0 ? "--hbr-m" : "sum of the two objects' radii (AREA_PC = pi r^2)";
  opt.header_comment = "evade screen: " + run.source;
  return opt;
}

nlohmann::json summary(const CdmOutOptions& o, nlohmann::json files) {
  if (!files.empty()) (void)std::fprintf(stderr, "evade screen: wrote %zu CDMs (%s) to %s\n", files.size(), o.format.c_str(), o.dir.c_str());
  return {{"dir", o.dir}, {"format", o.format}, {"count", files.size()},
          {"covariance", o.cov_sigma.empty() ? "not known (no Pc)" : "assumed RTN sigmas " + o.cov_sigma + " m"},
          {"files", std::move(files)}};
}

}  // namespace

void add_cdm_out_options(CLI::App& app, CdmOutOptions& o) {
  app.add_option("--cdm-out", o.dir, "write one CCSDS CDM per event into this directory (created)");
  app.add_option("--cdm-format", o.format, "CDM form: kvn or xml")
      ->check(CLI::IsMember({"kvn", "xml"}))
      ->capture_default_str();
  app.add_option("--cov-rtn-sigma-m", o.cov_sigma,
                 "with --cdm-out: assumed RTN position sigmas R,T,N [m] of every object; the CDMs then carry a Pc");
  app.add_option("--hbr-m", o.hbr_m, "with --cdm-out: hard-body radius for the Pc [m] (default: the objects' radii)")
      ->check(CLI::PositiveNumber);
}

void prepare_cdm_out(const CdmOutOptions& o, bool objects_have_radii) {
  if (o.dir.empty()) {
    if (!o.cov_sigma.empty() || o.hbr_m > 0.0 || o.format != "kvn")
      throw std::invalid_argument("--cdm-format, --cov-rtn-sigma-m and --hbr-m: only with --cdm-out DIR");
    return;
  }
  (void)assumed_cov(o.cov_sigma);
  if (o.hbr_m > 0.0 && o.cov_sigma.empty())
    throw std::invalid_argument("--hbr-m: only with --cov-rtn-sigma-m (without a covariance there is no Pc)");
  if (!o.cov_sigma.empty() && !objects_have_radii && !(o.hbr_m > 0.0))
    throw std::invalid_argument("--cov-rtn-sigma-m: catalog objects carry no size: give --hbr-m");
  std::error_code ec;
  std::filesystem::create_directories(o.dir, ec);
  if (ec || !std::filesystem::is_directory(o.dir))
    throw std::invalid_argument("--cdm-out: cannot create directory '" + o.dir + "': " +
                                (ec ? ec.message() : std::string("not a directory")));
  const std::filesystem::path probe = std::filesystem::path(o.dir) / ".evade-write-test";
  std::ofstream(probe.string()) << "";
  if (!std::filesystem::exists(probe)) throw std::invalid_argument("--cdm-out: cannot write into '" + o.dir + "'");
  std::filesystem::remove(probe, ec);
}

nlohmann::json write_population_cdms(const CdmOutOptions& o, const CdmRunInfo& run,
                                     const std::vector<conjunction::Conjunction>& events,
                                     const std::vector<conjunction::SpaceObject>& objects,
                                     const conjunction::ScreenOptions& so) {
  nlohmann::json files = nlohmann::json::array();
  if (o.dir.empty()) return nullptr;
  const assessment::EventCdmOptions base = base_options(o, run);
  const std::string how = so.gravity == evade::GravityModel::kTwoBody
                              ? "state at TCA by two-body motion (Kepler) from the screening epoch; EME2000 = evade's ECI"
                              : "state at TCA by two-body + J2 motion (DOP853) from the screening epoch; EME2000 = evade's ECI";
  std::set<std::string> used;
  for (const auto& c : events) {
    const auto st = conjunction::event_states(objects, c, so);
    ScreeningEvent ev;
    const std::size_t idx[2] = {c.i, c.j};
    for (int k = 0; k < 2; ++k) {
      EventObject& ob = ev.obj[k];
      ob.designator = ob.name = objects[idx[k]].name;
      ob.catalog_name = "EVADE";
      ob.state_eme2000 = st[k];
      ob.radius_m = o.hbr_m > 0.0 ? 0.0 : objects[idx[k]].size_m;
      ob.state_comment = how;
    }
    ev.tca_utc_j2000_s = c.tca_s;
    ev.miss_m = c.miss_m;
    ev.rel_speed_mps = c.rel_speed_mps;
    files.push_back(write_one(o, run, ev, base, used));
  }
  return summary(o, std::move(files));
}

nlohmann::json write_catalog_cdms(const CdmOutOptions& o, const CdmRunInfo& run,
                                  const conjunction::ScreenResult& r,
                                  const conjunction::Sgp4Screening& s,
                                  const std::vector<sgp4::MeanElements>& elements,
                                  const conjunction::ScreenOptions& so) {
  nlohmann::json files = nlohmann::json::array();
  if (o.dir.empty()) return nullptr;
  std::map<long, const sgp4::MeanElements*> by_id;
  for (const auto& m : elements) by_id.emplace(m.norad_id, &m);
  const assessment::EventCdmOptions base = base_options(o, run);
  std::set<std::string> used;
  for (const auto& c : r.events) {
    const auto st = conjunction::event_states(s.objects, c, so);
    ScreeningEvent ev;
    const std::size_t idx[2] = {c.i, c.j};
    for (int k = 0; k < 2; ++k) {
      EventObject& ob = ev.obj[k];
      const long id = s.norad_ids[idx[k]];
      const sgp4::MeanElements* m = by_id.count(id) ? by_id.at(id) : nullptr;
      ob.designator = std::to_string(id);
      ob.name = m && !m->name.empty() ? m->name : ob.designator;
      ob.international_designator = m ? intl_designator(m->object_id) : "";
      sgp4::teme_to_j2000(run.epoch_utc_j2000_s + c.tca_s, st[k].r_eci_m, st[k].v_eci_mps,
                          ob.state_eme2000.r_eci_m, ob.state_eme2000.v_eci_mps);
      ob.state_comment = "state at TCA by SGP4 (TEME, velocity = derivative of the position) "
                         "rotated to EME2000 (IAU-76/80, docs/ASSESSMENT.md)";
    }
    ev.tca_utc_j2000_s = c.tca_s;
    ev.miss_m = c.miss_m;
    ev.rel_speed_mps = c.rel_speed_mps;
    files.push_back(write_one(o, run, ev, base, used));
  }
  return summary(o, std::move(files));
}

}  // namespace evade::cli
