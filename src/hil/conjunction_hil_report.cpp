// What a conjunction HIL run shows (conjunction_hil.hpp; docs/AUTONOMY.md AUT-11): the truth's
// closest approach from the run's samples, its 2D Pc with the uplinked covariances
// (assessment::assess_encounter_2d, the node's and `evade assess`'s code), the node's decisions
// and the ground's commands on the simulator's clock.
#include <cmath>
#include <limits>
#include <memory>

#include "evade/assessment/assess_params.hpp"
#include "evade/assessment/encounter_2d.hpp"
#include "evade/hil/conjunction_hil.hpp"

namespace evade::hil {
namespace {

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// The truth's 2D Pc at its closest approach with the last CDM's covariances (ECI).
nlohmann::json truth_pc(const ConjunctionHilCase& c, const HilClosest& cl) {
  const autonomy::ConjunctionEvent& e = c.cdms.back().uplink.event;
  auto ws = std::make_unique<assessment::Pc2dWorkspace>();
  assessment::Encounter2d out;
  const assessment::Encounter2dStatus s = assessment::assess_encounter_2d(
      cl.own, e.cov1_eci, cl.other, e.cov2_eci, e.hbr_m,
      assessment::encounter_2d_config(assessment::AssessConfig{}), c.sim.earth, ws.get(), &out);
  if (s != assessment::Encounter2dStatus::kOk)
    return {{"status", assessment::encounter_2d_status_name(s)}};
  return {{"status", "ok"}, {"pc_2d", out.pc.pc}, {"usage_flags", out.failed}};
}

// From the ground's receipt (the node's answer) of the version that decided to the node's first
// decision of it (no action, proposed, needs ground, refused), on the simulator's clock.
nlohmann::json latency(const ConjunctionHilRun& r) {
  nlohmann::json j = nlohmann::json::array();
  for (const HilUplink& u : r.uplinks) {
    if (u.version == 0) continue;
    for (const HilProposal& p : r.proposals) {
      const std::string st = p.message.at("state");
      if (p.message.at("version").get<std::int32_t>() != u.version || st == "assessing") continue;
      j.push_back({{"version", u.version}, {"sent_s", u.t_sent_s}, {"answered_s", u.t_answered_s},
                   {"decided_s", p.t_s}, {"state", st},
                   {"receipt_to_decision_s", p.t_s - u.t_sent_s}});
      break;
    }
  }
  return j;
}

nlohmann::json burns_json(const ConjunctionHilCase& c, const sim::PlanRunResult& s, double* dv_total) {
  nlohmann::json j = nlohmann::json::array();
  *dv_total = 0.0;
  for (const sim::DeliveredBurn& b : s.burns) {
    *dv_total += b.dv_eci_mps.norm();
    j.push_back({{"t_start_s", b.t_start_s}, {"t_end_s", b.t_end_s},
                 {"before_tca_s", c.tca_s - 0.5 * (b.t_start_s + b.t_end_s)},
                 {"dv_eci_mps", vec_json(b.dv_eci_mps)}, {"dv_mps", b.dv_eci_mps.norm()}});
  }
  return j;
}

// The node's last proposal that carried a burn (proposed, scheduled, executed or vetoed).
nlohmann::json onboard(const ConjunctionHilRun& r) {
  nlohmann::json last;
  for (const HilProposal& p : r.proposals)
    if (p.message.at("proposal_id").get<std::int64_t>() != 0) last = p.message;
  if (last.is_null()) return nullptr;
  return {{"state", last.at("state")}, {"pc", last.at("pc")}, {"post_pc", last.at("post_pc")},
          {"post_miss_m", last.at("post_miss_m")}, {"dv_rsw_mps", last.at("dv_rsw_mps")}};
}

}  // namespace

HilClosest hil_closest_approach(const sim::PlanRunResult& r) {
  HilClosest best;
  best.miss_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const sim::PlanRunSample& s = r.samples[i];
    const Vec3 d = s.other.r_eci_m - s.satellite.r_eci_m;
    const Vec3 w = s.other.v_eci_mps - s.satellite.v_eci_mps;
    // Straight-line relative motion up to half the spacing of the samples either side.
    const double h = i + 1 < r.samples.size() ? 0.5 * (r.samples[i + 1].t_s - s.t_s)
                                               : (i > 0 ? 0.5 * (s.t_s - r.samples[i - 1].t_s) : 0.0);
    const double ww = w.squaredNorm();
    const double tau = ww > 0.0 ? std::max(-h, std::min(h, -d.dot(w) / ww)) : 0.0;
    const double miss = (d + tau * w).norm();
    if (miss < best.miss_m) best = {s.t_s + tau, miss, s.satellite, s.other};
  }
  return best;
}

nlohmann::json to_json(const ConjunctionHilCase& c, const ConjunctionHilRun& r) {
  nlohmann::json cdms = nlohmann::json::array();
  for (const HilCdm& h : c.cdms)
    cdms.push_back({{"t_send_s", h.t_send_s}, {"file", h.file_name}, {"version", h.uplink.event.version},
                    {"event_id", h.uplink.event.event_id}, {"miss_m", h.miss_m}, {"pc", h.pc},
                    {"pc_method", h.pc_method},
                    {"veto_deadline_before_tca_s", 1e-6 * static_cast<double>(h.uplink.event.tca_us -
                                                                              h.uplink.event.veto_deadline_us)}});
  nlohmann::json ups = nlohmann::json::array();
  for (const HilUplink& u : r.uplinks)
    ups.push_back({{"what", u.what}, {"t_sent_s", u.t_sent_s}, {"t_answered_s", u.t_answered_s},
                   {"outcome", lcm_link::outcome_name(u.result.outcome)}, {"reason", u.result.reason},
                   {"detail", u.result.detail}, {"transmissions", u.result.transmissions}});
  nlohmann::json props = nlohmann::json::array();
  for (const HilProposal& p : r.proposals) props.push_back({{"t_s", p.t_s}, {"proposal", p.message}});
  double dv = 0.0;
  const nlohmann::json burns = burns_json(c, r.sim, &dv);
  const HilClosest cl = hil_closest_approach(r.sim);
  const autonomy::ConjunctionEvent& e = c.cdms.back().uplink.event;
  nlohmann::json truth = {{"miss_without_burn_m", c.config.miss_m}, {"miss_m", cl.miss_m},
                          {"tca_s", cl.t_s}, {"tca_shift_s", cl.t_s - c.tca_s}};
  truth.update(truth_pc(c, cl));
  return {{"run", hil_run_name(c.run)},
          {"tca_s", c.tca_s},
          {"rate_hz", c.sim.rate_hz},
          {"thresholds", {{"pc_red", e.pc_red}, {"pc_target", e.pc_target}}},
          {"cdms", cdms},
          {"uplinks", ups},
          {"proposals", props},
          {"proposals_verified", r.proposals_verified},
          {"proposals_ignored", r.proposals_ignored},
          {"burns", burns},
          {"dv_total_mps", dv},
          {"onboard", onboard(r)},
          {"truth", truth},
          {"decision_latency", latency(r)},
          {"cycles", r.sim.cycles},
          {"wall_s", r.wall_s},
          {"faster_than_real_time", r.wall_s > 0.0 ? c.sim.duration_s / r.wall_s : 0.0}};
}

}  // namespace evade::hil
