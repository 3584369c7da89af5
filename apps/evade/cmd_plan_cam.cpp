// `evade plan cam`: the minimum-Δv collision-avoidance burn of the primary (object1), made
// --lead-s before TCA, after which Pc < --pc-max and the miss > --min-miss-m
// (evade::commands::run_plan_cam, plan_cam_command.hpp), verified by propagation. The
// conjunction comes from a scenario's `conjunction:` block (--scenario) or a CCSDS CDM
// (--cdm). --sweep-lead A:B:N prints the trade space (lead time against Δv, Pc before and
// after) as CSV, or JSON with --json. --publish sends the plan as evade_burn_plan_t on LCM
// (plan_output.hpp: the same path and options as the other planners), one impulse at the
// plan's epoch: the burn's utime, from the CDM's TCA minus the lead, or --epoch-utime (a
// scenario has no UTC); --plan-out writes it as a plan file (its t = 0 the burn).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "evade/config/json_values.hpp"
#include "number_list.hpp"
#include "plan_output.hpp"
#include "evade/cam/cam_burn_plan.hpp"
#include "evade/commands/plan_cam_command.hpp"

namespace evade::cli {
namespace {
namespace cmd_plan_cam {  // a name of its own: the CLI builds as unity batches too

using namespace evade::assessment;
using namespace evade::cam;
using namespace evade::commands;

struct Options {
  CommonOptions common;  // --scenario, --set, --json
  std::string cdm, sweep;
  double hbr_m = 0.0;
  CamRequest req;
  PlanOutputOptions out;
};

PlanCamRequest read_request(const Options& o) {
  if (o.common.scenario.empty() == o.cdm.empty())
    throw std::invalid_argument("give exactly one of --scenario, --cdm");
  if (!o.common.scenario.empty()) return read_plan_cam_request(load_scenario(o.common));
  config::Scenario sc = config::Scenario::empty("--cdm");
  for (const auto& a : o.common.sets) sc.apply_override(a);
  return read_plan_cam_request_cdm(sc, read_text_file(o.cdm, "--cdm"), o.cdm, o.hbr_m);
}

// --sweep-lead A:B:N.
CamLeadSweep parse_sweep(const std::string& text) {
  const std::vector<double> v = parse_number_list(text, ':');
  if (v.size() != 3 || !(v[2] >= 1.0 && v[2] <= 10000.0 && v[2] == std::floor(v[2])) ||
      !(v[0] <= v[1]))
    throw std::invalid_argument("--sweep-lead: expected A:B:N with A <= B and N in [1, 10000], found '" +
                                text + "'");
  return {v[0], v[1], static_cast<int>(v[2])};  // N an integer in [1, 10000], checked above
}

// --publish / --plan-out: the plan as a BurnPlan, at the burn's UTC when known.
int output(const Options& o, const PlanCamResult& r, const CamPlan& plan, nlohmann::json* j) {
  if (!plan_wanted(o.out)) return 0;
  PlanOutputOptions out = o.out;
  if (out.publish && out.epoch_utime_us == 0 && !r.burn_unix_utime_us)
    throw std::invalid_argument("--publish: the burn's time is unknown (a scenario has no UTC): "
                                "give --epoch-utime, the utime of the burn [us]");
  if (out.epoch_utime_us == 0 && r.burn_unix_utime_us) out.epoch_utime_us = *r.burn_unix_utime_us;
  const BurnPlan bp = make_cam_burn_plan(plan, plan_id(out));
  (*j)["plan"] = config::impulses_json(bp);
  return output_plan(out, bp, j);
}

int run(const Options& o) {
  PlanCamRequest req = read_request(o);
  req.cam = o.req;
  if (!o.sweep.empty()) req.sweep = parse_sweep(o.sweep);
  const PlanCamResult r = run_plan_cam(req);
  nlohmann::json j = to_json(r);
  const int uplink_rc = r.plan ? output(o, r, *r.plan, &j) : 0;
  if (o.common.json) print_json(j);
  else std::printf("%s", to_text(r).c_str());
  if (r.plan && !r.plan->verified_ok) {
    (void)std::fprintf(stderr,
                       "plan cam: the verification by propagation does not meet the request "
                       "(recommended Pc %.6e by %s, miss %.3f m)\n",
                       r.plan->verified_recommended.pc,
                       r.plan->verified_recommended.method.c_str(), r.plan->verified.miss_m);
    return 1;
  }
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--scenario", o->common.scenario, "scenario with a conjunction: block");
  app.add_option("--cdm", o->cdm, "a CCSDS CDM file (KVN or XML)");
  app.add_option("--set", o->common.sets, "override a scenario key (repeatable)");
  app.add_option("--hbr-m", o->hbr_m, "hard-body radius for --cdm [m]")->check(CLI::PositiveNumber);
  app.add_option("--lead-s", o->req.lead_s, "burn time before TCA [s]");
  app.add_option("--pc-max", o->req.pc_max, "Pc threshold [-]")->capture_default_str();
  app.add_option("--min-miss-m", o->req.min_miss_m, "smallest miss distance after the burn [m]");
  app.add_flag("--along-track-only", o->req.along_track_only, "burn along track only");
  app.add_option("--sweep-lead", o->sweep, "A:B:N: plan at N lead times from A to B [s] (trade space)");
  add_plan_output_options(app, o->out);
  app.add_flag("--json", o->common.json, "print a machine-readable JSON result on stdout");
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "cam"}, "Minimum-dv collision-avoidance burn for a Pc threshold", &setup});

}  // namespace cmd_plan_cam
}  // namespace
}  // namespace evade::cli
