// `evade propagate --tle/--omm` as a library call (see propagate_catalog_command.hpp): SGP4
// (Vallado, Crawford, Hujsak and Kelso, "Revisiting Spacetrack Report #3", 2006) for every
// object over the same instants, TEME or J2000.
#include "evade/commands/propagate_catalog_command.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "evade/config/json_values.hpp"
#include "evade/core/epoch.hpp"
#include "evade/sgp4/propagate_grid.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

#include "catalog_instants.hpp"

namespace evade::commands {
namespace {

constexpr double kMaxPropagateSpanS = 366.0 * 86400.0;  // one year of SGP4 is already far past its use
constexpr double kMaxStepsPerObject = 100000.0;

CatalogTrack propagate_object(const sgp4::MeanElements& m, double start_j2000_s,
                              const PropagateCatalogRequest& req, bool j2000) {
  CatalogTrack track;
  track.id = m.norad_id;
  track.name = m.name;
  track.epoch_j2000_s = sgp4::epoch_seconds_since_j2000(m);
  const sgp4::Sgp4Propagator prop(m, sgp4::OperationMode::kImproved);
  const double offset_s = start_j2000_s - track.epoch_j2000_s;
  for (long k = 0; k <= detail::last_instant(req); ++k) {
    const double t_s = detail::instant_s(req, k);
    CatalogState out;
    const sgp4::Sgp4Error e = detail::catalog_state(prop, offset_s, start_j2000_s, t_s, j2000, &out);
    if (e != sgp4::Sgp4Error::kNone) {
      track.error = e;
      track.error_t_s = t_s;
      break;
    }
    track.states.push_back(out);
  }
  return track;
}

nlohmann::json track_json(const CatalogTrack& t) {
  nlohmann::json obj;
  obj["id"] = t.id;
  obj["name"] = t.name;
  obj["epoch_utc"] = detail::utc_text(t.epoch_j2000_s);
  nlohmann::json states = nlohmann::json::array();
  for (const CatalogState& s : t.states) {
    states.push_back({{"t_s", s.t_s}, {"r_m", config::vec_json(s.r_m)},
                      {"v_mps", config::vec_json(s.v_mps)}});
  }
  if (t.error != sgp4::Sgp4Error::kNone) {
    obj["sgp4_error"] = {{"t_s", t.error_t_s},
                         {"code", static_cast<int>(t.error)},
                         {"text", sgp4_error_text(t.error)}};
  }
  obj["states"] = std::move(states);
  return obj;
}

}  // namespace

void check_propagate_catalog_request(const PropagateCatalogRequest& req) {
  if (!(req.span_s >= 0.0 && req.span_s <= kMaxPropagateSpanS))
    throw std::invalid_argument("--span-s = " + std::to_string(req.span_s) +
                                " is invalid: expected a number in [0, 31622400] s");
  if (!(req.step_s > 0.0) || req.span_s / req.step_s > kMaxStepsPerObject)
    throw std::invalid_argument("--step-s = " + std::to_string(req.step_s) +
                                " is invalid: expected a number > 0 with span/step <= 100000");
  (void)sgp4::frame_is_j2000(req.frame);  // the frame names' one check
}

PropagateCatalogResult run_propagate_catalog(const PropagateCatalogRequest& req) {
  PropagateCatalogResult r = detail::catalog_result_header(req);
  r.objects.reserve(req.catalog.objects.size());
  for (const auto& m : req.catalog.objects)
    r.objects.push_back(propagate_object(m, r.start_j2000_s, req, r.j2000));
  return r;
}

namespace detail {

PropagateCatalogResult catalog_result_header(const PropagateCatalogRequest& req) {
  check_propagate_catalog_request(req);
  const sgp4::Catalog& cat = req.catalog;
  if (cat.objects.empty())
    throw std::invalid_argument("no valid element set in the file (" +
                                std::to_string(cat.bad_entries) + " bad entries)");
  PropagateCatalogResult r;
  r.start_j2000_s = sgp4::latest_epoch_seconds_since_j2000(cat.objects);
  r.j2000 = req.frame == "eci";
  r.bad_entries = cat.bad_entries;
  for (const auto& is : cat.issues) r.issues.push_back(is.message());
  return r;
}

long last_instant(const PropagateCatalogRequest& req) {
  return static_cast<long>(req.span_s / req.step_s + 1e-9);
}

double instant_s(const PropagateCatalogRequest& req, long k) {
  return std::min(static_cast<double>(k) * req.step_s, req.span_s);
}

sgp4::Sgp4Error catalog_state(const sgp4::Sgp4Propagator& p, double offset_s, double start_j2000_s,
                        double t_s, bool j2000, CatalogState* out) {
  const sgp4::Sgp4State s = p.propagate_s(offset_s + t_s);
  if (s.error != sgp4::Sgp4Error::kNone) return s.error;
  *out = {t_s, s.r_teme_m, s.v_teme_mps};
  if (j2000) sgp4::teme_to_j2000(start_j2000_s + t_s, s.r_teme_m, s.v_teme_mps, out->r_m, out->v_mps);
  return sgp4::Sgp4Error::kNone;
}

std::string utc_text(double j2000_s) {
  return format_calendar_utc(calendar_from_seconds_since_j2000(j2000_s));
}

}  // namespace detail

nlohmann::json to_json(const PropagateCatalogResult& r) {
  nlohmann::json j;
  j["start_utc"] = detail::utc_text(r.start_j2000_s);
  j["frame"] = r.j2000 ? "J2000" : "TEME";
  j["bad_entries"] = r.bad_entries;
  j["issues"] = nlohmann::json::array();
  for (const auto& is : r.issues) j["issues"].push_back(is);
  j["objects"] = nlohmann::json::array();
  for (const auto& t : r.objects) j["objects"].push_back(track_json(t));
  return j;
}

}  // namespace evade::commands
