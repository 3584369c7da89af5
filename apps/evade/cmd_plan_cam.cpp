// `evade plan cam`: the minimum-Δv collision-avoidance burn of the primary (object1), made
// --lead-s before TCA, after which Pc < --pc-max and the miss > --min-miss-m
// (evade::assessment::plan_cam), verified by propagation. The conjunction comes from a
// scenario's `conjunction:` block (--scenario) or a CCSDS CDM (--cdm). --sweep-lead A:B:N
// prints the trade space (lead time against Δv, Pc before and after) as CSV, or JSON with
// --json. --publish sends the plan as evade_burn_plan_t on LCM (plan_output.hpp: the same
// path and options as the other planners), one impulse at the plan's epoch: the burn's utime,
// from the CDM's TCA minus the lead, or --epoch-utime (a scenario has no UTC); --plan-out
// writes it as a plan file (its t = 0 the burn).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "number_list.hpp"
#include "plan_output.hpp"
#include "evade/assessment/cam_burn_plan.hpp"
#include "evade/assessment/cam_planner.hpp"
#include "evade/assessment/conjunction_input.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/epoch.hpp"

namespace evade::cli {
namespace {

using namespace evade::assessment;

struct Options {
  std::string scenario, cdm, sweep;
  std::vector<std::string> sets;
  bool json = false;
  double hbr_m = 0.0;
  CamRequest req;
  PlanOutputOptions out;
};

struct Inputs {
  ConjunctionInput conj;
  AssessConfig acfg;
  CamConfig cfg;
  std::string source;
  bool epoch_known = false;
  double epoch_j2000_s = 0.0;  ///< UTC of the given states [s since J2000]
};

Inputs read_inputs(const Options& o) {
  if (o.scenario.empty() == o.cdm.empty())
    throw std::invalid_argument("give exactly one of --scenario, --cdm");
  config::Scenario sc = o.scenario.empty() ? config::Scenario::empty("--cdm")
                                           : config::Scenario::load(o.scenario);
  for (const auto& a : o.sets) sc.apply_override(a);
  Inputs in;
  config::read_params(sc, "assessment.", assess_params(), &in.acfg);
  config::read_params(sc, "cam.", cam_params(), &in.cfg);
  if (o.scenario.empty()) {
    const Cdm cdm = read_cdm_text(read_text_file(o.cdm, "--cdm"));
    in.conj = conjunction_from_cdm(cdm, o.hbr_m, config::read_earth(sc));
    in.epoch_j2000_s = seconds_since_j2000_from_calendar(parse_calendar_utc(cdm_value(cdm.relative, "TCA")));
    in.epoch_known = true;
    in.source = "cdm " + o.cdm;
  } else {
    in.conj = read_conjunction_scenario(sc);
    in.source = "scenario " + sc.source();
  }
  sc.check_all_used();
  return in;
}

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json outcome_json(const EncounterOutcome& e) {
  return {{"pc", e.pc}, {"miss_m", e.miss_m}, {"tca_s", e.tca_s}, {"rel_speed_mps", e.rel_speed_mps}};
}

nlohmann::json plan_json(const CamPlan& p, const Inputs& in) {
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
  j["primary_at_burn"] = {{"r_eci_m", vec_json(p.primary_at_burn.r_eci_m)},
                          {"v_eci_mps", vec_json(p.primary_at_burn.v_eci_mps)}};
  if (in.epoch_known)
    j["burn_utc"] = format_calendar_utc(calendar_from_seconds_since_j2000(in.epoch_j2000_s + p.burn_from_epoch_s));
  j["frames"] = "dv_rtn_mps: the primary's RTN at the burn (R radial, T along track, N orbit "
                "normal); dv_eci_mps: ECI (J2000 axes); tca_s: TCA minus the TCA without a burn";
  return j;
}

std::vector<double> parse_sweep(const std::string& text, const CamRequest& req, const CamConfig& cfg) {
  const std::vector<double> v = parse_number_list(text, ':');
  if (v.size() != 3 || !(v[2] >= 1.0 && v[2] <= 10000.0 && v[2] == std::floor(v[2])) ||
      !(v[0] <= v[1]))
    throw std::invalid_argument("--sweep-lead: expected A:B:N with A <= B and N in [1, 10000], found '" +
                                text + "'");
  const double a = v[0], b = v[1];
  const int n = static_cast<int>(v[2]);  // an integer in [1, 10000], checked above
  for (const double lead : {a, b}) {
    CamRequest r = req;
    r.lead_s = lead;
    validate_cam_request(r, cfg);
  }
  std::vector<double> leads;
  leads.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) leads.push_back(n == 1 ? a : a + (b - a) * k / (n - 1));
  return leads;
}

int run_sweep(const Options& o, const Inputs& in) {
  const std::vector<CamSweepRow> rows = sweep_cam_lead(
      in.conj, parse_sweep(o.sweep, o.req, in.cfg), o.req, in.acfg, in.cfg);
  if (o.json) {
    nlohmann::json j = {{"source", in.source}, {"pc_max", o.req.pc_max},
                        {"min_miss_m", o.req.min_miss_m}, {"along_track_only", o.req.along_track_only}};
    j["rows"] = nlohmann::json::array();
    for (const CamSweepRow& r : rows)
      j["rows"].push_back(r.ok ? plan_json(r.plan, in) : nlohmann::json{{"lead_s", r.lead_s}, {"error", r.error}});
    print_json(j);
    return 0;
  }
  std::printf("lead_s,dv_mps,dv_r_mps,dv_t_mps,dv_n_mps,pc_before,pc_after,miss_before_m,"
              "miss_after_m,tca_shift_s,verified_ok,error\n");
  for (const CamSweepRow& r : rows) {
    const CamPlan& p = r.plan;
    if (!r.ok) {
      std::printf("%.6g,,,,,,,,,,,\"%s\"\n", r.lead_s, r.error.c_str());
      continue;
    }
    std::printf("%.6g,%.9g,%.9g,%.9g,%.9g,%.6e,%.6e,%.4f,%.4f,%.6g,%d,\n", r.lead_s, p.dv_mps,
                p.dv_rtn_mps.x(), p.dv_rtn_mps.y(), p.dv_rtn_mps.z(), p.before.pc, p.verified.pc,
                p.before.miss_m, p.verified.miss_m, p.verified.tca_s, p.verified_ok ? 1 : 0);
  }
  return 0;
}

void print_text(const CamPlan& p, const Inputs& in) {
  std::printf("%s: burn %.1f s before TCA\n", in.source.c_str(), p.lead_s);
  std::printf("  before:    Pc %.6e  miss %.3f m\n", p.before.pc, p.before.miss_m);
  if (!p.maneuver_needed) {
    std::printf("  no manoeuvre needed\n");
    return;
  }
  std::printf("  dv RTN [%.6f, %.6f, %.6f] m/s  |dv| %.6f m/s\n", p.dv_rtn_mps.x(),
              p.dv_rtn_mps.y(), p.dv_rtn_mps.z(), p.dv_mps);
  std::printf("  predicted: Pc %.6e  miss %.3f m\n", p.predicted.pc, p.predicted.miss_m);
  std::printf("  verified:  Pc %.6e  miss %.3f m  new TCA %+.6f s (two-body + J2 propagation)\n",
              p.verified.pc, p.verified.miss_m, p.verified.tca_s);
}

int run(const Options& o) {
  const Inputs in = read_inputs(o);
  if (!o.sweep.empty()) return run_sweep(o, in);
  const CamPlan p = plan_cam(in.conj, o.req, in.acfg, in.cfg);
  nlohmann::json j = plan_json(p, in);
  j["source"] = in.source;
  int uplink_rc = 0;
  if (plan_wanted(o.out)) {
    PlanOutputOptions out = o.out;
    if (out.publish && out.epoch_utime_us == 0 && !in.epoch_known)
      throw std::invalid_argument("--publish: the burn's time is unknown (a scenario has no UTC): "
                                  "give --epoch-utime, the utime of the burn [us]");
    if (out.epoch_utime_us == 0 && in.epoch_known)
      out.epoch_utime_us = unix_utime_from_j2000(in.epoch_j2000_s + p.burn_from_epoch_s);
    const BurnPlan bp = make_cam_burn_plan(p, plan_id(out));
    j["plan"] = impulses_json(bp);
    uplink_rc = output_plan(out, bp, &j);
  }
  if (o.json) print_json(j); else print_text(p, in);
  if (!p.verified_ok) {
    (void)std::fprintf(stderr, "plan cam: the verification by propagation does not meet the request (Pc %.6e, miss %.3f m)\n",
                       p.verified.pc, p.verified.miss_m);
    return 1;
  }
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--scenario", o->scenario, "scenario with a conjunction: block");
  app.add_option("--cdm", o->cdm, "a CCSDS CDM file (KVN or XML)");
  app.add_option("--set", o->sets, "override a scenario key (repeatable)");
  app.add_option("--hbr-m", o->hbr_m, "hard-body radius for --cdm [m]")->check(CLI::PositiveNumber);
  app.add_option("--lead-s", o->req.lead_s, "burn time before TCA [s]");
  app.add_option("--pc-max", o->req.pc_max, "Pc threshold [-]")->capture_default_str();
  app.add_option("--min-miss-m", o->req.min_miss_m, "smallest miss distance after the burn [m]");
  app.add_flag("--along-track-only", o->req.along_track_only, "burn along track only");
  app.add_option("--sweep-lead", o->sweep, "A:B:N: plan at N lead times from A to B [s] (trade space)");
  add_plan_output_options(app, o->out);
  app.add_flag("--json", o->json, "print a machine-readable JSON result on stdout");
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "cam"}, "Minimum-dv collision-avoidance burn for a Pc threshold", &setup});

}  // namespace
}  // namespace evade::cli
