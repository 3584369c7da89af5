// --publish of the planners (plan_output.hpp).
#include "plan_output.hpp"

#include <cstdio>
#include <stdexcept>

#include "evade/config/json_values.hpp"
#include "evade/guidance/plan_executor.hpp"

#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/commands/plan_file.hpp"

namespace evade::cli {

void add_plan_output_options(CLI::App& app, PlanOutputOptions& o) {
  app.add_flag("--publish", o.publish, "publish the plan as evade_burn_plan_t on LCM");
  app.add_option("--lcm-url", o.lcm_url, "LCM URL for --publish (default: LCM_DEFAULT_URL)");
  app.add_option("--channel", o.channel, "LCM channel for --publish")->capture_default_str();
  app.add_option("--seq", o.seq,
                 "seq field (plan id) of the published plan [-] (0: with --key, one above the "
                 "plan in force in the node's signed status)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--epoch-utime", o.epoch_utime_us,
                 "utime [us] of the plan's t = 0 (default: the publish time)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--frame", o.frame, "frame the node flies the plan in: rsw | eci")
      ->check(CLI::IsMember({"rsw", "eci"}))
      ->capture_default_str();
  app.add_option("--plan-out", o.plan_out,
                 "write the plan as a plan file (JSON) for `evade sim --plan FILE`");
  add_signing_flags(app, o.sign,
                    "with --publish: sign with this command key file (`evade keygen`) and "
                    "retransmit until the node acknowledges the plan: exit 0 accepted, 3 "
                    "rejected, 4 timeout",
                    false);
}

bool plan_wanted(const PlanOutputOptions& o) { return o.publish || !o.plan_out.empty(); }

std::int64_t plan_id(const PlanOutputOptions& o) { return o.seq; }

namespace {

// What was sent: channel, seq, send time, the plan's t = 0 (the send time unless
// --epoch-utime), frame and impulses.
nlohmann::json published_json(const PlanOutputOptions& o, const BurnPlan& plan,
                              std::int64_t utime) {
  return {{"channel", o.channel},
          {"seq", o.seq},
          {"utime", utime},
          {"epoch_utime", o.epoch_utime_us != 0 ? o.epoch_utime_us : utime},
          {"frame", o.frame},
          {"n_impulses", plan.n_impulses},
          {"impulses", config::impulses_json(plan)}};
}

int uplink_signed(const PlanOutputOptions& o, const BurnPlan& plan,
                  const lcm_link::PlanStamp& stamp, nlohmann::json* j) {
  GroundSigner signer(o.sign);
  const lcm_link::UplinkOptions u = uplink_options(o.sign, o.lcm_url);
  const lcm_link::UplinkResult r =
      lcm_link::uplink_plan(u, o.channel, plan, o.seq, stamp, signer.keys(), signer.arsn());
  (*j)["published"] = published_json(o, plan, r.first_utime);
  (*j)["published"]["seq"] = r.plan_id;
  (*j)["uplink"] = lcm_link::to_json(r, signer.keys().command.id);
  (void)std::fprintf(stderr, "evade: plan %lld %s (%s) after %d transmission(s)%s%s\n",
                     static_cast<long long>(r.plan_id), lcm_link::outcome_name(r.outcome),
                     r.reason.c_str(), r.transmissions, r.note.empty() ? "" : ": ",
                     r.note.c_str());
  return lcm_link::exit_code(r);
}

}  // namespace

int output_plan(const PlanOutputOptions& o, const BurnPlan& plan, nlohmann::json* j) {
  const guidance::PlanFrame frame =
      o.frame == "eci" ? guidance::PlanFrame::kEci : guidance::PlanFrame::kRsw;
  if (!o.plan_out.empty()) {
    commands::write_plan_file(o.plan_out, commands::PlanFile{plan, frame});
    (*j)["plan_file"] = o.plan_out;
  }
  if (!o.publish) {
    if (!o.sign.key_file.empty()) throw std::invalid_argument("--key applies only with --publish");
    return 0;
  }
  lcm_link::PlanStamp stamp;
  stamp.epoch_utime = o.epoch_utime_us;
  stamp.frame = frame;
  if (!o.sign.key_file.empty()) return uplink_signed(o, plan, stamp, j);
  (void)std::fprintf(stderr, "evade: publishing an unsigned plan (no --key): a guidance node "
                     "whose policy requires signed plans (the default) refuses it\n");
  const std::int64_t utime = lcm_link::publish_burn_plan(o.lcm_url, o.channel, plan, o.seq, stamp);
  (*j)["published"] = published_json(o, plan, utime);
  return 0;
}

}  // namespace evade::cli
