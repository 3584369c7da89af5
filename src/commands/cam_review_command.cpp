// The ground's review of a proposed avoidance burn against a catalog (include/evade/commands/
// cam_review_command.hpp).
#include "evade/commands/cam_review_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

#include "evade/assessment/pc_2d.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/config/scenario.hpp"
#include "evade/conjunction/own_orbit_motion.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/core/epoch.hpp"
#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::commands {
namespace {
namespace cam_review_impl {  // names of its own: the module builds as unity batches

constexpr double kMaxSpanS = 7.0 * 86400.0;

std::string utc_text_of(double j2000_s) { return format_calendar_utc(calendar_from_seconds_since_j2000(j2000_s)); }

double number_at(const nlohmann::json& j, const char* key, const std::string& name) {
  if (!j.contains(key) || !j[key].is_number())
    throw std::invalid_argument(name + ": key '" + key + "' must be a number");
  const double v = j[key].get<double>();
  if (!std::isfinite(v)) throw std::invalid_argument(name + ": key '" + key + "' is not finite");
  return v;
}

std::vector<sgp4::MeanElements> others(const CamReviewRequest& req) {
  std::vector<sgp4::MeanElements> out;
  for (const sgp4::MeanElements& m : req.catalog.objects) {
    if (!req.own_designator.empty() && std::to_string(m.norad_id) == req.own_designator) continue;
    out.push_back(m);
  }
  return out;
}

// The closest approach of each catalog object to the own spacecraft (object 0).
std::map<std::size_t, conjunction::Conjunction> closest(const conjunction::ScreenResult& r) {
  std::map<std::size_t, conjunction::Conjunction> out;
  for (const conjunction::Conjunction& c : r.events) {
    const std::size_t other = c.i == 0 ? c.j : c.i;
    auto it = out.find(other);
    if (it == out.end() || c.miss_m < it->second.miss_m) out[other] = c;
  }
  return out;
}

conjunction::ScreenResult screen_own(const StateEci& own, const CamReviewRequest& req, double start_s,
                                     const conjunction::Sgp4Screening& s, int threads,
                                     double* perturbation_mps2) {
  auto motion = std::make_shared<conjunction::OwnOrbitMotion>(own, start_s, req.span_s,
                                                              req.conjunction.earth, s.motion);
  *perturbation_mps2 = std::max(*perturbation_mps2, motion->own_sampled_perturbation_mps2());
  std::vector<conjunction::SpaceObject> objects;
  objects.push_back({"own", motion->state_at(0, 0.0), 0.0, 0.0});
  objects.insert(objects.end(), s.objects.begin(), s.objects.end());
  conjunction::ScreenOptions so = catalog_screen_options();
  so.threshold_m = req.threshold_m;
  so.motion = motion;
  so.primary = 0;
  so.threads = threads;
  return conjunction::screen_robust(objects, req.span_s, so);
}

void check_request(const CamReviewRequest& req, double burn_s) {
  if (!(req.span_s > 0.0 && req.span_s <= kMaxSpanS))
    throw std::invalid_argument("--span-s must be in (0, 604800] s");
  if (!(req.threshold_m > 0.0 && req.threshold_m <= 1e6))
    throw std::invalid_argument("--threshold-m must be in (0, 1e6] m");
  if (!(burn_s < req.tca_j2000_s))
    throw std::invalid_argument("the proposal's burn (" + utc_text_of(burn_s) + ") is not before the CDM's TCA (" +
                                utc_text_of(req.tca_j2000_s) + ")");
  if (!(burn_s + req.span_s > req.tca_j2000_s))
    throw std::invalid_argument("--span-s ends before the CDM's TCA: the screening must reach past it");
  if (!req.proposal.dv_eci_mps.allFinite() || !(req.proposal.dv_eci_mps.norm() < 1e3))
    throw std::invalid_argument("the proposal's dv_eci_mps must be finite and below 1000 m/s");
}

CamReviewEncounter encounter(const CamReviewRequest& req, const conjunction::Sgp4Screening& s,
                             std::size_t k, const conjunction::Conjunction* before,
                             const conjunction::Conjunction* after, double start_s) {
  CamReviewEncounter e;
  e.norad_id = s.norad_ids[k - 1];
  e.name = s.objects[k - 1].name;
  e.before = before != nullptr;
  e.after = after != nullptr;
  const double hbr = req.conjunction.hbr_m;
  if (before != nullptr) {
    e.miss_before_m = before->miss_m;
    e.pc_max_before = pc_max_circular(before->miss_m, hbr);
  }
  const conjunction::Conjunction* c = after != nullptr ? after : before;
  if (after != nullptr) {
    e.miss_after_m = after->miss_m;
    e.pc_max_after = pc_max_circular(after->miss_m, hbr);
  }
  e.tca_after_s = c->tca_s;
  e.tca_utc = utc_text_of(start_s + c->tca_s);
  e.raised = e.pc_max_after > req.pc_red && e.pc_max_after > e.pc_max_before;
  return e;
}

}  // namespace cam_review_impl
}  // namespace

double pc_max_circular(double miss_m, double hbr_m) {
  if (!(miss_m > hbr_m)) return 1.0;
  const double sigma = miss_m / std::sqrt(2.0);  // the maximum of the circular case: sigma^2 = d^2 / 2
  return assessment::pc_max_alfano(assessment::PrincipalEncounter{miss_m, 0.0, sigma, sigma}, hbr_m).pc_max;
}

CamReviewProposal cam_review_proposal_from_json(const nlohmann::json& j, const std::string& name) {
  using cam_review_impl::number_at;
  if (!j.is_object()) throw std::invalid_argument(name + ": expected a JSON object (a proposal)");
  CamReviewProposal p;
  p.event_id = static_cast<std::int64_t>(number_at(j, "event_id", name));
  p.version = static_cast<std::int32_t>(number_at(j, "version", name));
  p.proposal_id = static_cast<std::int64_t>(number_at(j, "proposal_id", name));
  p.burn_utime = static_cast<std::int64_t>(number_at(j, "burn_utime", name));
  if (!j.contains("dv_eci_mps") || !j["dv_eci_mps"].is_array() || j["dv_eci_mps"].size() != 3)
    throw std::invalid_argument(name + ": key 'dv_eci_mps' must be an array of 3 numbers [m/s]");
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json& v = j["dv_eci_mps"][static_cast<std::size_t>(i)];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw std::invalid_argument(name + ": key 'dv_eci_mps' must be an array of 3 finite numbers [m/s]");
    p.dv_eci_mps(i) = v.get<double>();
  }
  if (p.burn_utime <= 0 || p.proposal_id <= 0)
    throw std::invalid_argument(name + ": the proposal has no burn (proposal_id and burn_utime must be > 0)");
  return p;
}

nlohmann::json to_json(const CamReviewProposal& p) {
  return {{"event_id", p.event_id},       {"version", p.version},
          {"proposal_id", p.proposal_id}, {"burn_utime", p.burn_utime},
          {"dv_eci_mps", {p.dv_eci_mps(0), p.dv_eci_mps(1), p.dv_eci_mps(2)}}};
}

CamReviewRequest read_cam_review_request(const std::string& cdm_text, const std::string& cdm_name,
                                         double hbr_m, const CamReviewProposal& proposal,
                                         sgp4::Catalog catalog, const std::string& catalog_source,
                                         const std::vector<ParamValue>& values) {
  CamReviewRequest req;
  const ccsds::Cdm cdm = ccsds::read_cdm_text(cdm_text);
  req.conjunction = conjunction_from_cdm(cdm, hbr_m, kEarthDefault);
  req.tca_j2000_s = seconds_since_j2000_from_calendar(parse_calendar_utc(ccsds::cdm_value(cdm.relative, "TCA")));
  req.own_designator = ccsds::cdm_value(cdm.object[0].metadata, "OBJECT_DESIGNATOR");
  req.proposal = proposal;
  req.catalog = std::move(catalog);
  req.catalog_source = catalog_source.empty() ? cdm_name : catalog_source;
  for (const ParamValue& v : values) {
    if (v.key == "uplink.pc_red") req.pc_red = v.value;
    else if (v.key == "span_s") req.span_s = v.value;
    else if (v.key == "robust.threshold_m") req.threshold_m = v.value;
    else throw config::ConfigError("evade cam review: no setting '" + v.key + "'");
  }
  return req;
}

CamReviewResult run_cam_review(const CamReviewRequest& req) {
  using namespace cam_review_impl;
  const double burn_s = seconds_since_j2000_from_unix_utime(req.proposal.burn_utime);
  check_request(req, burn_s);
  const int threads = req.threads > 0 ? req.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  conjunction::Sgp4MotionOptions mo;
  mo.span_s = req.span_s;
  mo.start_at_latest_epoch = false;
  mo.start_j2000_s = burn_s;
  mo.threads = threads;
  const conjunction::Sgp4Screening s = conjunction::sgp4_screening(others(req), mo);
  if (s.objects.empty()) throw std::invalid_argument(req.catalog_source + ": no usable element set");
  const StateEci at_tca = req.conjunction.obj[0].state;
  StateEci own = propagate_orbit(at_tca, burn_s - req.tca_j2000_s, GravityModel::kTwoBodyJ2,
                                 req.conjunction.earth, AdaptiveOptions::tight());
  CamReviewResult r;
  const auto before = closest(screen_own(own, req, burn_s, s, threads, &r.own_perturbation_mps2));
  own.v_eci_mps += req.proposal.dv_eci_mps;
  const auto after = closest(screen_own(own, req, burn_s, s, threads, &r.own_perturbation_mps2));
  r.proposal = req.proposal;
  r.burn_utc = utc_text_of(burn_s);
  r.span_s = req.span_s;
  r.threshold_m = req.threshold_m;
  r.pc_red = req.pc_red;
  r.hbr_m = req.conjunction.hbr_m;
  r.objects = static_cast<long>(s.objects.size());
  r.rejected = static_cast<long>(s.rejected.size());
  for (std::size_t k = 1; k <= s.objects.size(); ++k) {
    const auto b = before.find(k), a = after.find(k);
    if (b == before.end() && a == after.end()) continue;
    r.encounters.push_back(encounter(req, s, k, b == before.end() ? nullptr : &b->second,
                                     a == after.end() ? nullptr : &a->second, burn_s));
  }
  std::sort(r.encounters.begin(), r.encounters.end(), [](const CamReviewEncounter& x, const CamReviewEncounter& y) {
    return (x.after ? x.miss_after_m : 1e300) < (y.after ? y.miss_after_m : 1e300);
  });
  const auto raised = std::find_if(r.encounters.begin(), r.encounters.end(),
                                   [](const CamReviewEncounter& e) { return e.raised; });
  r.verdict = raised == r.encounters.end() ? "fly" : "veto";
  char buf[256];
  if (raised != r.encounters.end()) {
    (void)std::snprintf(buf, sizeof buf, "the burn brings %s to %.0f m at %s: max Pc %.3g above the red threshold %.3g",
                        raised->name.c_str(), raised->miss_after_m, raised->tca_utc.c_str(), raised->pc_max_after, req.pc_red);
  } else {
    (void)std::snprintf(buf, sizeof buf, "no close approach the burn creates or raises has a max Pc above %.3g", req.pc_red);
  }
  r.reason = buf;
  return r;
}

nlohmann::json to_json(const CamReviewResult& r) {
  nlohmann::json enc = nlohmann::json::array();
  for (const CamReviewEncounter& e : r.encounters) {
    nlohmann::json j = {{"norad_id", e.norad_id}, {"name", e.name}, {"tca_utc", e.tca_utc},
                        {"tca_from_burn_s", e.tca_after_s}, {"raised", e.raised}};
    j["miss_before_m"] = e.before ? nlohmann::json(e.miss_before_m) : nlohmann::json(nullptr);
    j["miss_after_m"] = e.after ? nlohmann::json(e.miss_after_m) : nlohmann::json(nullptr);
    j["pc_max_before"] = e.pc_max_before;
    j["pc_max_after"] = e.pc_max_after;
    enc.push_back(j);
  }
  return {{"verdict", r.verdict}, {"reason", r.reason}, {"proposal", to_json(r.proposal)},
          {"burn_utc", r.burn_utc}, {"span_s", r.span_s}, {"threshold_m", r.threshold_m},
          {"pc_red", r.pc_red}, {"hbr_m", r.hbr_m}, {"objects", r.objects}, {"rejected", r.rejected},
          {"own_perturbation_mps2", r.own_perturbation_mps2}, {"encounters", enc},
          {"pc_max", "the largest Pc of the miss over every circular covariance (Alfano 2005)"}};
}

std::string to_text(const CamReviewResult& r) {
  std::string t = "review of proposal " + std::to_string(r.proposal.proposal_id) + " (event " +
                  std::to_string(r.proposal.event_id) + "), burn at " + r.burn_utc + ": " + r.verdict +
                  " (" + r.reason + ")\n";
  char buf[256];
  for (const CamReviewEncounter& e : r.encounters) {
    (void)std::snprintf(buf, sizeof buf, "  %-28s miss %10s -> %10s m  max Pc %.3g -> %.3g%s\n", e.name.c_str(),
                        e.before ? std::to_string(std::lround(e.miss_before_m)).c_str() : "-",
                        e.after ? std::to_string(std::lround(e.miss_after_m)).c_str() : "-",
                        e.pc_max_before, e.pc_max_after, e.raised ? "  RAISED" : "");
    t += buf;
  }
  return t;
}

}  // namespace evade::commands
