// `evade plan cam` as a library call (include/evade/commands/plan_cam_command.hpp): the
// request read from a scenario or a CDM, the plan or the lead-time trade space
// (cam_planner.hpp; NLopt SLSQP, Kraft 1988), and the result's JSON and text forms.
#include "evade/commands/plan_cam_command.hpp"

#include <cstdio>
#include <stdexcept>

#include "evade/cam/cam_burn_plan.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/config/json_values.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/epoch.hpp"

namespace evade::commands {
namespace {

void read_tables(const config::Scenario& sc, PlanCamRequest* r) {
  config::read_params(sc, "assessment.", assessment::assess_params(), &r->assess_config);
  config::read_params(sc, "cam.", cam::cam_params(), &r->cam_config);
}

// The sweep's lead times; both ends checked as a single plan's lead would be.
std::vector<double> sweep_leads(const CamLeadSweep& s, const cam::CamRequest& req, const cam::CamConfig& cfg) {
  if (!(s.count >= 1 && s.count <= 10000) || !(s.first_lead_s <= s.last_lead_s))
    throw std::invalid_argument("lead sweep: expected first <= last and count in [1, 10000], found " +
                                std::to_string(s.first_lead_s) + ", " +
                                std::to_string(s.last_lead_s) + ", " + std::to_string(s.count));
  const double a = s.first_lead_s, b = s.last_lead_s;
  const int n = s.count;
  for (const double lead : {a, b}) {
    cam::CamRequest r = req;
    r.lead_s = lead;
    cam::validate_cam_request(r, cfg);
  }
  std::vector<double> leads;
  leads.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) leads.push_back(n == 1 ? a : a + (b - a) * k / (n - 1));
  return leads;
}

nlohmann::json outcome_json(const cam::EncounterOutcome& e) {
  return {{"pc", e.pc}, {"miss_m", e.miss_m}, {"tca_s", e.tca_s}, {"rel_speed_mps", e.rel_speed_mps}};
}

std::optional<double> burn_utc(const std::optional<double>& epoch_utc_j2000_s, const cam::CamPlan& p) {
  if (!epoch_utc_j2000_s) return std::nullopt;
  return *epoch_utc_j2000_s + p.burn_from_epoch_s;
}

std::string utc_text(double t_j2000_s) {
  return format_calendar_utc(calendar_from_seconds_since_j2000(t_j2000_s));
}

nlohmann::json recommended_json(const cam::RecommendedPc& r) {
  return {{"pc", r.pc}, {"method", r.method}, {"reason", r.why}};
}

nlohmann::json plan_json(const cam::CamPlan& p, const std::optional<double>& epoch_utc_j2000_s) {
  using config::vec_json;
  nlohmann::json j = {{"maneuver_needed", p.maneuver_needed}, {"lead_s", p.lead_s},
                      {"pc_target", p.pc_target}, {"dv_mps", p.dv_mps},
                      {"dv_rtn_mps", vec_json(p.dv_rtn_mps)}, {"dv_eci_mps", vec_json(p.dv_eci_mps)},
                      {"burn_from_epoch_s", p.burn_from_epoch_s},
                      {"tca_from_epoch_s", p.tca_from_epoch_s},
                      {"before", outcome_json(p.before)}, {"predicted", outcome_json(p.predicted)},
                      {"predicted_first_linearization", outcome_json(p.predicted_first)},
                      {"verified", outcome_json(p.verified)}, {"verified_ok", p.verified_ok},
                      {"relinearizations", p.relinearizations},
                      {"last_change_mps", p.last_change_mps}, {"search", p.search},
                      {"nlopt_result", p.nlopt_result}};
  j["before_recommended"] = recommended_json(p.before_recommended);
  j["verified_recommended"] = recommended_json(p.verified_recommended);
  j["target_corrections"] = p.target_corrections;
  j["pc_target_2d"] = p.pc_target_2d;
  j["primary_at_burn"] = {{"r_eci_m", vec_json(p.primary_at_burn.r_eci_m)},
                          {"v_eci_mps", vec_json(p.primary_at_burn.v_eci_mps)}};
  if (const std::optional<double> t = burn_utc(epoch_utc_j2000_s, p)) j["burn_utc"] = utc_text(*t);
  j["frames"] = "dv_rtn_mps: the primary's RTN at the burn (R radial, T along track, N orbit "
                "normal); dv_eci_mps: ECI (J2000 axes); tca_s: TCA minus the TCA without a burn";
  return j;
}

nlohmann::json sweep_json(const PlanCamResult& r) {
  nlohmann::json j = {{"source", r.source}, {"pc_max", r.request.pc_max},
                      {"min_miss_m", r.request.min_miss_m},
                      {"along_track_only", r.request.along_track_only}};
  j["rows"] = nlohmann::json::array();
  for (const cam::CamSweepRow& row : r.sweep)
    j["rows"].push_back(row.ok ? plan_json(row.plan, r.epoch_utc_j2000_s)
                               : nlohmann::json{{"lead_s", row.lead_s}, {"error", row.error}});
  return j;
}

std::string sweep_csv(const PlanCamResult& r) {
  std::string t =
      "lead_s,dv_mps,dv_r_mps,dv_t_mps,dv_n_mps,pc_before,pc_after,miss_before_m,"
      "miss_after_m,tca_shift_s,pc_before_recommended,pc_after_recommended,method_after,"
      "verified_ok,error\n";
  char b[512];
  for (const cam::CamSweepRow& row : r.sweep) {
    const cam::CamPlan& p = row.plan;
    if (!row.ok) {
      (void)std::snprintf(b, sizeof b, "%.6g,,,,,,,,,,,,,,\"", row.lead_s);
      t += b + row.error + "\"\n";
      continue;
    }
    (void)std::snprintf(b, sizeof b,
                        "%.6g,%.9g,%.9g,%.9g,%.9g,%.6e,%.6e,%.4f,%.4f,%.6g,%.6e,%.6e,%s,%d,\n",
                        row.lead_s, p.dv_mps, p.dv_rtn_mps.x(), p.dv_rtn_mps.y(),
                        p.dv_rtn_mps.z(), p.before.pc, p.verified.pc, p.before.miss_m,
                        p.verified.miss_m, p.verified.tca_s, p.before_recommended.pc,
                        p.verified_recommended.pc, p.verified_recommended.method.c_str(),
                        p.verified_ok ? 1 : 0);
    t += b;
  }
  return t;
}

std::string cam_burn_text(const cam::CamPlan& p) {
  char b[512];
  (void)std::snprintf(b, sizeof b,
                      "  dv RTN [%.6f, %.6f, %.6f] m/s  |dv| %.6f m/s  (the primary's RTN at "
                      "the burn: R radial, T along track, N orbit normal)\n"
                      "  dv ECI [%.6f, %.6f, %.6f] m/s  (J2000 axes)\n",
                      p.dv_rtn_mps.x(), p.dv_rtn_mps.y(), p.dv_rtn_mps.z(), p.dv_mps,
                      p.dv_eci_mps.x(), p.dv_eci_mps.y(), p.dv_eci_mps.z());
  std::string t = b;
  (void)std::snprintf(b, sizeof b, "  predicted: Pc %.6e  miss %.3f m\n", p.predicted.pc,
                      p.predicted.miss_m);
  t += b;
  (void)std::snprintf(b, sizeof b,
                      "  verified:  Pc %.6e  miss %.3f m  new TCA %+.6f s (two-body + J2 "
                      "propagation)\n",
                      p.verified.pc, p.verified.miss_m, p.verified.tca_s);
  t += b;
  (void)std::snprintf(b, sizeof b,
                      "  verified recommended Pc: %.6e by %s (%s)%s\n",
                      p.verified_recommended.pc, p.verified_recommended.method.c_str(),
                      p.verified_recommended.why.c_str(), p.verified_ok ? "" : "  NOT MET");
  t += b;
  if (p.target_corrections > 0) {
    (void)std::snprintf(b, sizeof b,
                        "  2D target corrected %d time(s) to %.6e so the recommended Pc meets "
                        "pc_max\n",
                        p.target_corrections, p.pc_target_2d);
    t += b;
  }
  return t;
}

std::string plan_text(const PlanCamResult& r, const cam::CamPlan& p) {
  char b[256];
  (void)std::snprintf(b, sizeof b, ": burn %.1f s before TCA", p.lead_s);
  std::string t = r.source + b;
  if (r.burn_utc_j2000_s) t += ", at " + utc_text(*r.burn_utc_j2000_s) + " UTC";
  (void)std::snprintf(b, sizeof b, "\n  before:    Pc %.6e  miss %.3f m\n", p.before.pc,
                      p.before.miss_m);
  t += b;
  (void)std::snprintf(b, sizeof b, "  recommended Pc before: %.6e by %s (%s)\n",
                      r.pc_before_recommended, r.pc_method_before.c_str(),
                      r.pc_method_reason.c_str());
  t += b;
  if (r.pc_method_before != "2d")
    t += "  note: the planner's model is the 2D Pc, which the usage checks reject for this "
         "encounter; whether a burn is needed and whether it meets pc_max are decided by the "
         "recommended Pc\n";
  if (!p.maneuver_needed) return t + "  no manoeuvre needed\n";
  return t + cam_burn_text(p);
}

}  // namespace

PlanCamRequest read_plan_cam_request(const config::Scenario& sc) {
  PlanCamRequest r;
  read_tables(sc, &r);
  r.conjunction = read_conjunction_scenario(sc);
  sc.check_all_used();
  r.source = "scenario " + sc.source();
  return r;
}

PlanCamRequest read_plan_cam_request_cdm(const config::Scenario& sc, const std::string& cdm_text,
                                         const std::string& cdm_name, double hbr_m) {
  PlanCamRequest r;
  read_tables(sc, &r);
  const ccsds::Cdm cdm = ccsds::read_cdm_text(cdm_text);
  r.conjunction = conjunction_from_cdm(cdm, hbr_m, config::read_earth(sc));
  r.epoch_utc_j2000_s =
      seconds_since_j2000_from_calendar(parse_calendar_utc(ccsds::cdm_value(cdm.relative, "TCA")));
  sc.check_all_used();
  r.source = "cdm " + cdm_name;
  return r;
}

namespace {

// The recommended Pc before the burn (pc_method_choice.hpp), after the planner has accepted
// the encounter (it refuses a zero relative speed before any escalation runs).
void add_recommended_pc(const PlanCamRequest& req, PlanCamResult* r) {
  const assessment::ConjunctionInput& in = req.conjunction;
  const assessment::PcChoice c = assessment::choose_pc(assessment::assess(in, req.assess_config), in.hbr_m, req.assess_config,
                               in.earth, in.obj[0].has_velocity_cov && in.obj[1].has_velocity_cov);
  r->pc_before_recommended = c.pc;
  r->pc_method_before = c.method;
  r->pc_method_reason = c.why;
}

}  // namespace

PlanCamResult run_plan_cam(const PlanCamRequest& req) {
  PlanCamResult r;
  r.source = req.source;
  r.request = req.cam;
  r.epoch_utc_j2000_s = req.epoch_utc_j2000_s;
  if (req.sweep) {
    r.sweep = cam::sweep_cam_lead(req.conjunction, sweep_leads(*req.sweep, req.cam, req.cam_config),
                             req.cam, req.assess_config, req.cam_config);
    add_recommended_pc(req, &r);
    return r;
  }
  r.plan = cam::plan_cam(req.conjunction, req.cam, req.assess_config, req.cam_config);
  r.burn_utc_j2000_s = burn_utc(req.epoch_utc_j2000_s, *r.plan);
  if (r.burn_utc_j2000_s) r.burn_unix_utime_us = cam::unix_utime_from_j2000(*r.burn_utc_j2000_s);
  r.pc_before_recommended = r.plan->before_recommended.pc;
  r.pc_method_before = r.plan->before_recommended.method;
  r.pc_method_reason = r.plan->before_recommended.why;
  return r;
}

nlohmann::json to_json(const PlanCamResult& r) {
  if (!r.plan) return sweep_json(r);
  nlohmann::json j = plan_json(*r.plan, r.epoch_utc_j2000_s);
  j["source"] = r.source;
  j["pc_before_recommended"] = {{"pc", r.pc_before_recommended}, {"method", r.pc_method_before},
                                {"reason", r.pc_method_reason}};
  return j;
}

std::string to_text(const PlanCamResult& r) { return r.plan ? plan_text(r, *r.plan) : sweep_csv(r); }

}  // namespace evade::commands
